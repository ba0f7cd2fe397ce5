#include "hinf/io/model_kinds.hpp"

#include <algorithm>
#include <filesystem>
#include <mutex>

#include "hinf/models/generated_model.hpp"
#include "hinf/models/ship.hpp"
#include "hinf/models/vehicles.hpp"
#include "io/model_sections.hpp"
#include "io/toml_table.hpp"

namespace hinf {

// ---- SectionReader ----

SectionReader::SectionReader(detail::TableReader& table, std::string source, std::string where)
    : table_(&table), source_(std::move(source)), where_(std::move(where)) {}

bool SectionReader::has(const std::string& key) const { return table_->has(key); }
double SectionReader::number_or(const std::string& key, double fallback) const {
  return table_->number_or(key, fallback);
}
std::string SectionReader::string(const std::string& key) const { return table_->string(key); }
std::string SectionReader::string_or(const std::string& key, const std::string& fallback) const {
  return table_->string_or(key, fallback);
}
Mat SectionReader::matrix(const std::string& key, int rows, int cols) const {
  require(rows >= 1 && cols >= 1, "SectionReader::matrix: rows and cols must be >= 1, got ", rows, " x ", cols);
  return table_->matrix(key, rows, cols, false);
}
std::map<std::string, double> SectionReader::numbers(const std::string& key) const {
  const toml::node* node = table_->get(key);
  if (node == nullptr) fail(key, "is required");
  const toml::table* values = node->as_table();
  if (values == nullptr) fail(key, "expected a table of name = number, got " + detail::type_name(*node));
  std::map<std::string, double> numbers;
  for (auto&& [name, value] : *values)
    numbers[std::string(name.str())] = table_->as_number(value, str_cat(key, ".", name.str()));
  return numbers;
}
void SectionReader::fail(const std::string& key, const std::string& problem) const { table_->fail(key, problem); }
void SectionReader::fail_section(const std::string& problem) const {
  throw InputError(str_cat(source_, ": ", where_, " ", problem));
}

namespace detail {

TableReader& table_of(const SectionReader& section) { return *section.table_; }

void check_preset(const SectionReader& section, const std::string& kind, const std::string& preset) {
  const std::string name = section.string_or("preset", preset);
  if (name != preset)
    section.fail("preset", str_cat("unknown preset \"", name, "\" of kind = \"", kind, "\": the preset is \"", preset,
                                   "\"; change single parameters by their keys"));
}

}  // namespace detail

namespace {

PythonModelHook& python_model_hook() {
  static PythonModelHook hook;
  return hook;
}

// ---- the built-in kinds whose sections hold more than numbers ----

// kind = "linear": A, B and D set the model's dimensions (n = rows of A, m = columns of B,
// nw = columns of D, D = I by default); C (p x n) adds one noise channel per output.
ModelKind linear_kind() {
  ModelKind kind{"linear", {"A", "B", "D", "C"}, nullptr, nullptr, ""};
  kind.read = [](const SectionReader& section) -> ModelPtr {
    detail::TableReader& r = detail::table_of(section);
    auto dimensions = [&r](const char* key, const char* shape) {
      const toml::node* node = r.get(key);
      if (node == nullptr) r.fail(key, str_cat("is required: an ", shape, " nested list"));
      const toml::array* rows = node->as_array();
      const toml::array* first = rows != nullptr && !rows->empty() ? rows->get(0)->as_array() : nullptr;
      std::string found;
      if (rows == nullptr) found = detail::type_name(*node);
      else if (rows->empty()) found = "an empty array";
      else if (first == nullptr) found = "a first row that is " + detail::type_name(*rows->get(0));
      else if (first->empty()) found = "an empty first row";
      if (!found.empty()) r.fail(key, str_cat("expected an ", shape, " nested list, got ", found));
      return std::make_pair(static_cast<int>(rows->size()), static_cast<int>(first->size()));
    };
    const int n = dimensions("A", "n x n").first;
    const Mat A = r.matrix("A", n, n, false);
    const Mat B = r.matrix("B", n, dimensions("B", "n x m").second, false);
    Mat D = Mat::Identity(n, n);
    if (r.has("D")) D = r.matrix("D", n, dimensions("D", "n x nw").second, false);
    Mat C;
    if (r.has("C")) C = r.matrix("C", dimensions("C", "p x n").first, n, false);
    return std::make_shared<LinearModel>(A, B, D, C);
  };
  kind.write = [](const Model& model) -> std::optional<Section> {
    const auto* linear = dynamic_cast<const LinearModel*>(&model);
    if (linear == nullptr) return std::nullopt;
    Section section{{"A", linear->A()}, {"B", linear->B()}, {"D", linear->process_D()}};
    if (linear->measurement_C().size() > 0) section.emplace_back("C", linear->measurement_C());
    return section;
  };
  return kind;
}

// kind = "casadi": file names the model's description (model.json, written by
// hinf_cpp.models.SymbolicModel.export), relative to the scenario file's folder; parameters
// sets parameter values by name.
ModelKind casadi_kind() {
  ModelKind kind{"casadi", {"file", "parameters"}, nullptr, nullptr, "file"};
  kind.read = [](const SectionReader& section) -> ModelPtr {
    std::filesystem::path file = section.string("file");
    std::error_code ec;
    if (file.is_relative() && std::filesystem::is_regular_file(section.source(), ec))
      file = std::filesystem::path(section.source()).parent_path() / file;
    const std::map<std::string, double> parameters =
        section.has("parameters") ? section.numbers("parameters") : std::map<std::string, double>{};
    try {
      return std::make_shared<GeneratedModel>(file.lexically_normal().string(), parameters);
    } catch (const InputError& e) {
      section.fail("file", e.what());
    }
  };
  kind.write = [](const Model& model) -> std::optional<Section> {
    const auto* generated = dynamic_cast<const GeneratedModel*>(&model);
    if (generated == nullptr) return std::nullopt;
    return Section{{"file", std::filesystem::absolute(generated->metadata_path()).lexically_normal().string()},
                   {"parameters", generated->parameters()}};
  };
  return kind;
}

// kind = "python": callable names a model made by Python code (the hook); no file form.
ModelKind python_kind() {
  ModelKind kind{"python", {"callable"}, nullptr, nullptr, "callable"};
  kind.read = [](const SectionReader& section) -> ModelPtr {
    const std::string callable = section.string("callable");
    if (!python_model_hook())
      section.fail("kind", "\"python\" names a model made by Python code (" + callable +
                               "): run this scenario with hinf-cpp, or export the model as kind = \"casadi\" for"
                               " hinf-sim");
    ModelPtr model = python_model_hook()(callable, section.source());
    if (model == nullptr) section.fail("callable", "'" + callable + "' made no model");
    return model;
  };
  return kind;
}

// kind = "fossen_vessel": the mass and damping matrices M and D (3 x 3), the supply vessel by
// default (preset = "supply_vessel").
ModelKind fossen_vessel_kind() {
  ModelKind kind{"fossen_vessel", {"preset", "M", "D"}, nullptr, nullptr, ""};
  kind.read = [](const SectionReader& section) -> ModelPtr {
    detail::check_preset(section, "fossen_vessel", "supply_vessel");
    FossenVesselParameters p = FossenVesselParameters::supply_vessel();
    if (section.has("M")) p.M = section.matrix("M", 3, 3);
    if (section.has("D")) p.D = section.matrix("D", 3, 3);
    try {
      return std::make_shared<FossenVessel>(p);
    } catch (const InputError& e) {
      section.fail_section(e.what());
    }
  };
  kind.write = [](const Model& model) -> std::optional<Section> {
    const auto* vessel = dynamic_cast<const FossenVessel*>(&model);
    if (vessel == nullptr) return std::nullopt;
    return Section{{"M", vessel->parameters().M}, {"D", vessel->parameters().D}};
  };
  return kind;
}

// ---- the table ----

struct KindTable {
  std::mutex mutex;
  std::vector<std::shared_ptr<const ModelKind>> kinds;
};

// The built-in kinds, one line each.
KindTable& kind_table() {
  static KindTable table{{},
                         {
                             std::make_shared<const ModelKind>(
                                 parameter_kind<ShipModel, ShipParameters>("ship", kShipParameterKeys)),
                             std::make_shared<const ModelKind>(linear_kind()),
                             std::make_shared<const ModelKind>(casadi_kind()),
                             std::make_shared<const ModelKind>(python_kind()),
                             std::make_shared<const ModelKind>(fossen_vessel_kind()),
                             std::make_shared<const ModelKind>(
                                 parameter_kind<Hovercraft, HovercraftParameters>("hovercraft", kHovercraftParameterKeys)),
                             std::make_shared<const ModelKind>(
                                 parameter_kind<PlanarVtol, PlanarVtolParameters>("pvtol", kPlanarVtolParameterKeys)),
                             std::make_shared<const ModelKind>(parameter_kind<Auv, AuvParameters>(
                                 "auv", kAuvParameterKeys, AuvParameters::sirene(), "sirene")),
                         }};
  return table;
}

std::vector<std::shared_ptr<const ModelKind>> registered_kinds() {
  KindTable& table = kind_table();
  std::lock_guard<std::mutex> lock(table.mutex);
  return table.kinds;
}

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

}  // namespace

void register_model_kind(ModelKind kind) {
  require(!kind.name.empty(), "register_model_kind: the kind needs a name");
  require(static_cast<bool>(kind.read), "register_model_kind: the kind \"", kind.name, "\" needs a reader");
  require(!contains(kind.keys, "kind"), "register_model_kind: \"kind\" is not one of a kind's keys");
  KindTable& table = kind_table();
  std::lock_guard<std::mutex> lock(table.mutex);
  for (const auto& known : table.kinds)
    require(known->name != kind.name, "register_model_kind: the model kind \"", kind.name, "\" is taken");
  table.kinds.push_back(std::make_shared<const ModelKind>(std::move(kind)));
}

std::vector<std::string> model_kind_names() {
  std::vector<std::string> names;
  for (const auto& kind : registered_kinds()) names.push_back(kind->name);
  return names;
}

void set_python_model_hook(PythonModelHook hook) { python_model_hook() = std::move(hook); }

namespace detail {

namespace {

// Everything about a model section that is checked without reading the model: the kind, each
// key's kind, and trust. Returns the kind (kinds keeps it alive); every problem throws.
const ModelKind& check_section(const toml::table& table, const std::string& source, const std::string& where,
                               bool allow_code, std::vector<std::shared_ptr<const ModelKind>>& kinds) {
  const auto fail = [&source, &where](const std::string& key, const std::string& problem) {
    return InputError(str_cat(source, ": ", where, " ", key, ": ", problem));
  };
  const toml::node* node = table.get("kind");
  if (node == nullptr) throw fail("kind", "is required");
  if (node->as_string() == nullptr) throw fail("kind", "expected a string, got " + type_name(*node));
  const std::string name = node->as_string()->get();
  kinds = registered_kinds();
  const ModelKind* kind = nullptr;
  std::string names;
  for (const auto& k : kinds) {
    if (k->name == name) kind = k.get();
    names += str_cat(names.empty() ? "" : ", ", "\"", k->name, "\"");
  }
  if (kind == nullptr) throw fail("kind", str_cat("unknown model kind \"", name, "\": use one of ", names));
  // A key of another kind is refused naming the kinds it belongs to; any other unknown key by
  // the TableReader, with the list of the kind's keys.
  for (auto&& [k, v] : table) {
    const std::string key(k.str());
    if (key == "kind" || contains(kind->keys, key)) continue;
    std::string owners;
    for (const auto& other : kinds)
      if (contains(other->keys, key)) owners += str_cat(owners.empty() ? "" : " or ", "kind = \"", other->name, "\"");
    if (!owners.empty()) throw fail(key, str_cat("is a key of ", owners, ", not of kind = \"", name, "\""));
  }
  std::vector<std::string> known{"kind"};
  known.insert(known.end(), kind->keys.begin(), kind->keys.end());
  TableReader reader(table, where, source, known);
  const SectionReader section(reader, source, where);
  if (!kind->code_key.empty() && !allow_code) {
    const std::string program = reader.has(kind->code_key) ? str_cat(" (", reader.string(kind->code_key), ")") : "";
    section.fail(kind->code_key, str_cat("kind = \"", name, "\" loads and runs a program", program,
                                         ", and reading a file runs no code unless you allow it: if you trust this "
                                         "file, pass --trust-code (hinf-sim, hinf-cpp), trust_code=True (Python) or "
                                         "set HINF_TRUST_CODE=1"));
  }
  return *kind;
}

}  // namespace

bool section_runs_code(const toml::table& table) {
  const toml::node* node = table.get("kind");
  if (node == nullptr || node->as_string() == nullptr) return false;
  for (const auto& kind : registered_kinds())
    if (kind->name == node->as_string()->get()) return !kind->code_key.empty();
  return false;
}

void check_model_section(const toml::table& table, const std::string& source, const std::string& where,
                         bool allow_code) {
  std::vector<std::shared_ptr<const ModelKind>> kinds;
  check_section(table, source, where, allow_code, kinds);
}

ModelPtr read_model_section(const toml::table& table, const std::string& source, const std::string& where,
                            bool allow_code) {
  std::vector<std::shared_ptr<const ModelKind>> kinds;  // keeps the kind alive while it reads
  const ModelKind& kind = check_section(table, source, where, allow_code, kinds);
  std::vector<std::string> known{"kind"};
  known.insert(known.end(), kind.keys.begin(), kind.keys.end());
  TableReader reader(table, where, source, known);
  const SectionReader section(reader, source, where);
  ModelPtr model = kind.read(section);
  if (model == nullptr) section.fail_section(str_cat("kind = \"", kind.name, "\" made no model"));
  return model;
}

toml::table model_section(const Model& model) {
  for (const auto& kind : registered_kinds()) {
    if (!kind->write) continue;
    const std::optional<Section> section = kind->write(model);
    if (!section) continue;
    toml::table table{{"kind", kind->name}};
    for (const auto& [key, value] : *section) {
      if (const auto* number = std::get_if<double>(&value)) table.insert(key, *number);
      else if (const auto* text = std::get_if<std::string>(&value)) table.insert(key, *text);
      else if (const auto* matrix = std::get_if<Mat>(&value)) table.insert(key, matrix_toml(*matrix));
      else {
        toml::table numbers;
        for (const auto& [name, x] : std::get<std::map<std::string, double>>(value)) numbers.insert(name, x);
        table.insert(key, std::move(numbers));
      }
    }
    return table;
  }
  throw InputError(str_cat("the model '", model.name(), "' has no scenario-file form (only the registered model",
                           " kinds have one: ", [] {
                             std::string names;
                             for (const std::string& name : model_kind_names())
                               names += str_cat(names.empty() ? "" : ", ", name);
                             return names;
                           }(),
                           "; a model implemented in Python has none)"));
}

}  // namespace detail

}  // namespace hinf
