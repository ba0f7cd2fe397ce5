#include "hinf/models/generated_model.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "hinf/core/checks.hpp"
#include "hinf/core/errors.hpp"

namespace hinf {

namespace {

constexpr const char* kFormat = "hinf_cpp.generated_model/1";

// A key of model.json as T; InputError naming the file and the key otherwise.
template <class T>
T read_key(const nlohmann::json& j, const char* key, const std::string& source) {
  if (!j.contains(key)) throw InputError(str_cat(source, ": the key \"", key, "\" is missing"));
  try {
    return j.at(key).get<T>();
  } catch (const nlohmann::json::exception&) {
    throw InputError(str_cat(source, ": the key \"", key, "\" has the wrong type (", j.at(key).type_name(), ")"));
  }
}

// InputError unless `function` takes inputs of the shapes `inputs` and returns `outputs`.
void check_signature(const GeneratedFunction& function, const std::vector<std::pair<int, int>>& inputs,
                     const std::vector<std::pair<int, int>>& outputs, const std::string& source) {
  const auto shapes = [](const std::vector<std::pair<int, int>>& list) {
    std::string text;
    for (const auto& [rows, cols] : list) text += str_cat(text.empty() ? "" : ", ", "(", rows, ", ", cols, ")");
    return text;
  };
  std::vector<std::pair<int, int>> found_in, found_out;
  for (int i = 0; i < function.n_in(); ++i) found_in.emplace_back(function.input_rows(i), function.input_cols(i));
  for (int i = 0; i < function.n_out(); ++i) found_out.emplace_back(function.output_rows(i), function.output_cols(i));
  require(found_in == inputs && found_out == outputs, source, ": the generated function '", function.name(),
          "' takes ", shapes(found_in), " and returns ", shapes(found_out), ", but the description needs ",
          shapes(inputs), " -> ", shapes(outputs), ": the library and model.json do not belong together;",
          " export the model again");
}

}  // namespace

GeneratedModel::GeneratedModel(const std::string& metadata_path, const std::map<std::string, double>& parameters)
    : metadata_path_(metadata_path) {
  namespace fs = std::filesystem;
  const std::string source = str_cat("the model description '", metadata_path, "'");
  std::ifstream file(metadata_path);
  if (!file)
    throw InputError(str_cat(source, " cannot be read: ", fs::exists(metadata_path) ? "no permission" : "no such file",
                             " (write it with hinf_cpp.symbolic.SymbolicModel.export)"));
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(file);
  } catch (const nlohmann::json::exception& e) {
    throw InputError(str_cat(source, " is not JSON: ", e.what()));
  }
  require(j.is_object() && j.value("format", std::string()) == kFormat, source, " is not a model description (its",
          " \"format\" must be \"", kFormat, "\"): write it with hinf_cpp.symbolic.SymbolicModel.export");

  ModelStructure& s = structure_;
  s.name = read_key<std::string>(j, "name", source);
  s.n = read_key<int>(j, "n", source);
  s.m = read_key<int>(j, "m", source);
  s.nw = read_key<int>(j, "nw", source);
  check_dimensions(s);
  s.state_names = read_key<std::vector<std::string>>(j, "state_names", source);
  s.position_indices = read_key<std::vector<int>>(j, "position_indices", source);
  s.heading_index = read_key<int>(j, "heading_index", source);
  s.noise_channels = read_key<std::vector<int>>(j, "noise_channels", source);
  s.constant_input_matrices = read_key<bool>(j, "constant_input_matrices", source);
  s.state_dependent_inputs = read_key<bool>(j, "state_dependent_inputs", source);
  check_structure(s);
  const bool has_measurement = read_key<bool>(j, "measurement", source);
  const bool has_split = read_key<bool>(j, "error_split", source);

  // Parameters: the defaults, then the values given by name.
  const auto described = read_key<nlohmann::json>(j, "parameters", source);
  require(described.is_array(), source, ": \"parameters\" must be a list of {\"name\", \"default\"}");
  std::vector<double> values;
  for (const nlohmann::json& entry : described) {
    parameter_names_.push_back(read_key<std::string>(entry, "name", source + " (a parameter)"));
    values.push_back(read_key<double>(entry, "default", source + " (a parameter)"));
  }
  for (const auto& [name, value] : parameters) {
    std::size_t k = 0;
    while (k < parameter_names_.size() && parameter_names_[k] != name) ++k;
    if (k == parameter_names_.size()) {
      std::string known;
      for (const std::string& p : parameter_names_) known += (known.empty() ? "" : ", ") + p;
      throw InputError(str_cat("the model '", s.name, "' has no parameter '", name, "' (its parameters: ",
                               known.empty() ? "none" : known, ")"));
    }
    require(std::isfinite(value), "the parameter '", name, "' of the model '", s.name, "' must be finite, got ",
            value);
    values[k] = value;
  }
  p_ = Eigen::Map<const Vec>(values.data(), static_cast<Eigen::Index>(values.size()));

  // The library: a file beside model.json, never a path elsewhere (a description file must not
  // be able to point at any library on the machine).
  const std::string library_name = read_key<std::string>(j, "library", source);
  if (library_name.empty() || library_name.find('/') != std::string::npos || library_name == "." ||
      library_name == "..")
    throw InputError(str_cat(source, ": \"library\" = \"", library_name,
                             "\" must be the file name of a library beside model.json, without a folder (export the "
                             "model again with SymbolicModel.export)"));
  const fs::path library = fs::path(metadata_path).parent_path() / library_name;
  load_functions(GeneratedLibrary::open(library.string()), has_measurement, has_split, "", source);
}

GeneratedModel::GeneratedModel(GeneratedLibraryPtr library, ModelStructure structure, bool measurement,
                               bool error_split, std::vector<std::string> parameter_names, Vec parameter_values,
                               const std::string& function_prefix)
    : structure_(std::move(structure)), parameter_names_(std::move(parameter_names)), p_(std::move(parameter_values)) {
  require(library != nullptr, "GeneratedModel: the library is null");
  const std::string source = str_cat("the model '", structure_.name, "' of '", library->path(), "'");
  check_structure(structure_);
  require(static_cast<Eigen::Index>(parameter_names_.size()) == p_.size(), source, ": ", parameter_names_.size(),
          " parameter names for ", p_.size(), " values");
  for (Eigen::Index k = 0; k < p_.size(); ++k)
    require(std::isfinite(p_[k]), "the parameter '", parameter_names_[static_cast<std::size_t>(k)],
            "' of the model '", structure_.name, "' must be finite, got ", p_[k]);
  load_functions(library, measurement, error_split, function_prefix, source);
}

void GeneratedModel::load_functions(const GeneratedLibraryPtr& lib, bool measurement, bool error_split,
                                    const std::string& prefix, const std::string& source) {
  const ModelStructure& s = structure_;
  const int n = s.n, m = s.m, nw = s.nw, k = static_cast<int>(p_.size());
  const std::pair<int, int> t_shape{1, 1}, q_shape{n, 1}, u_shape{m, 1}, p_shape{k, 1};
  auto load = [&](const char* name, const std::vector<std::pair<int, int>>& in,
                  const std::vector<std::pair<int, int>>& out) {
    auto function = std::make_unique<GeneratedFunction>(lib, prefix + name);
    check_signature(*function, in, out, source);
    return function;
  };
  f_ = load("f", {t_shape, q_shape, p_shape}, {{n, 1}});
  dfdq_ = load("dfdq", {t_shape, q_shape, p_shape}, {{n, n}});
  G_ = load("G", {t_shape, q_shape, p_shape}, {{n, m}});
  D_ = load("D", {t_shape, q_shape, p_shape}, {{n, nw}});
  dGudq_ = load("dGudq", {t_shape, q_shape, u_shape, p_shape}, {{n, n}});
  if (measurement) {
    C_ = std::make_unique<GeneratedFunction>(lib, prefix + "C");
    const int p_y = C_->output_rows(0);
    check_signature(*C_, {t_shape, p_shape}, {{p_y, n}}, source);
    require(static_cast<int>(s.noise_channels.size()) == p_y, source, ": C has ", p_y, " rows but ",
            s.noise_channels.size(), " noise channels are named (one per measured output)");
  }
  if (error_split) error_split_ = load("error_split", {t_shape, q_shape, u_shape, q_shape, p_shape}, {{n, n}, {n, 1}});
}

std::map<std::string, double> GeneratedModel::parameters() const {
  std::map<std::string, double> out;
  for (std::size_t k = 0; k < parameter_names_.size(); ++k)
    out[parameter_names_[k]] = p_[static_cast<Eigen::Index>(k)];
  return out;
}

std::vector<std::pair<std::string, double>> GeneratedModel::named_parameters() const {
  std::vector<std::pair<std::string, double>> named;
  for (std::size_t k = 0; k < parameter_names_.size(); ++k)
    named.emplace_back(parameter_names_[k], p_[static_cast<Eigen::Index>(k)]);
  return named;
}

void GeneratedModel::evaluate(const GeneratedFunction& function, std::initializer_list<const double*> inputs,
                              MatRef out) const {
  // The generated code writes dense column-major rows x cols: straight into `out` when it is
  // contiguous, else through a temporary (a block of a larger matrix, as FleetModel passes).
  if (out.outerStride() == out.rows() || out.cols() <= 1) {
    double* result = out.data();
    function.eval(inputs.begin(), &result);
    return;
  }
  Mat dense(out.rows(), out.cols());
  double* result = dense.data();
  function.eval(inputs.begin(), &result);
  out = dense;
}

void GeneratedModel::f(double t, const ConstVecRef& q, VecRef out) const {
  double* result = out.data();
  const double* inputs[] = {&t, q.data(), p_.data()};
  f_->eval(inputs, &result);
}

void GeneratedModel::dfdq(double t, const ConstVecRef& q, MatRef out) const {
  evaluate(*dfdq_, {&t, q.data(), p_.data()}, out);
}

Mat GeneratedModel::G(double t, const ConstVecRef& q) const {
  Mat out(n(), m());
  evaluate(*G_, {&t, q.data(), p_.data()}, out);
  return out;
}

Mat GeneratedModel::D(double t, const ConstVecRef& q) const {
  Mat out(n(), nw());
  evaluate(*D_, {&t, q.data(), p_.data()}, out);
  return out;
}

void GeneratedModel::dGudq(double t, const ConstVecRef& q, const ConstVecRef& u, MatRef out) const {
  evaluate(*dGudq_, {&t, q.data(), u.data(), p_.data()}, out);
}

void GeneratedModel::error_split(double t, const ConstVecRef& q_d, const ConstVecRef& u_d, const ConstVecRef& q_e,
                                 MatRef A, VecRef alpha) const {
  if (!error_split_) {
    Model::error_split(t, q_d, u_d, q_e, A, alpha);
    return;
  }
  Mat A_dense(n(), n());
  double* results[] = {A_dense.data(), alpha.data()};
  const double* inputs[] = {&t, q_d.data(), u_d.data(), q_e.data(), p_.data()};
  error_split_->eval(inputs, results);
  A = A_dense;
}

Mat GeneratedModel::C(double t) const {
  if (!C_) return Model::C(t);
  Mat out(C_->output_rows(0), n());
  evaluate(*C_, {&t, p_.data()}, out);
  return out;
}

bool GeneratedModel::same_as(const Model& other) const {
  const auto* generated = dynamic_cast<const GeneratedModel*>(&other);
  return generated != nullptr && generated->library_path() == library_path() &&
         generated->parameter_names_ == parameter_names_ && generated->p_ == p_;
}

}  // namespace hinf
