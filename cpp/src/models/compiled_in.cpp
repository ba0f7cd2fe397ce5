#include "models/compiled_in.hpp"

#include <map>
#include <mutex>
#include <stdexcept>

#include "hinf/core/errors.hpp"

namespace hinf::detail {

namespace {

// One library object per description, made on first use.
GeneratedLibraryPtr library_of(const hinf_generated_model& description) {
  static std::mutex mutex;
  static std::map<const hinf_generated_model*, GeneratedLibraryPtr> libraries;
  std::lock_guard<std::mutex> lock(mutex);
  GeneratedLibraryPtr& library = libraries[&description];
  if (!library) {
    std::map<std::string, void*> symbols;
    for (const hinf_generated_symbol* s = description.symbols; s->name != nullptr; ++s)
      symbols[s->name] = reinterpret_cast<void*>(s->address);
    library = GeneratedLibrary::compiled_in(str_cat("<compiled in: ", description.name, ">"), std::move(symbols));
  }
  return library;
}

ModelStructure structure_of(const hinf_generated_model& d) {
  ModelStructure s;
  s.name = d.name;
  s.n = d.n;
  s.m = d.m;
  s.nw = d.nw;
  s.state_names.assign(d.state_names, d.state_names + d.n);
  s.position_indices.assign(d.position_indices, d.position_indices + d.position_count);
  s.heading_index = d.heading_index;
  s.noise_channels.assign(d.noise_channels, d.noise_channels + d.noise_count);
  s.constant_input_matrices = d.constant_input_matrices != 0;
  s.state_dependent_inputs = d.state_dependent_inputs != 0;
  return s;
}

}  // namespace

std::shared_ptr<const GeneratedModel> compiled_in_model(const hinf_generated_model& description,
                                                        const NamedValues& parameters) {
  const std::vector<std::string> names(description.parameter_names,
                                       description.parameter_names + description.parameter_count);
  Vec values(description.parameter_count);
  std::vector<bool> given(names.size(), false);
  for (const auto& [name, value] : parameters) {
    std::size_t k = 0;
    while (k < names.size() && names[k] != name) ++k;
    if (k == names.size() || given[k])
      throw std::logic_error(str_cat("the built-in model '", description.name, "' has ",
                                     k == names.size() ? "no parameter '" : "the parameter given twice: '", name,
                                     "' (its statement and its class disagree)"));
    given[k] = true;
    values[static_cast<Eigen::Index>(k)] = value;
  }
  for (std::size_t k = 0; k < names.size(); ++k)
    if (!given[k])
      throw std::logic_error(str_cat("the built-in model '", description.name, "': the parameter '", names[k],
                                     "' of its statement is not given (its statement and its class disagree)"));
  return std::make_shared<const GeneratedModel>(library_of(description), structure_of(description),
                                                description.measurement != 0, description.error_split != 0, names,
                                                values, description.prefix);
}

NamedValues compiled_in_defaults(const hinf_generated_model& description) {
  NamedValues defaults;
  for (int k = 0; k < description.parameter_count; ++k)
    defaults.emplace_back(description.parameter_names[k], description.parameter_defaults[k]);
  return defaults;
}

}  // namespace hinf::detail
