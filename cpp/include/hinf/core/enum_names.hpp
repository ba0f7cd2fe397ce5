// The names of closed choices (enums) at the input/output edge: scenario files, results files,
// the command lines and the Python bindings. Everything else compares the enums themselves.
//
// Each enum E declares its table once, next to its definition:
//     template <> struct EnumNames<Method> {
//       static constexpr const char* what = "solver method";
//       static constexpr std::array<std::pair<Method, const char*>, 3> names{{...}};
//     };
// and gets to_string(E) and from_string<E>(name) (an InputError listing the names).
#pragma once

#include <array>
#include <string>
#include <utility>

#include "hinf/core/errors.hpp"

namespace hinf {

template <class E>
struct EnumNames;  // specialized for every enum with names

template <class E>
std::string to_string(E value) {
  for (const auto& [item, name] : EnumNames<E>::names)
    if (item == value) return name;
  return "unknown";
}

// The quoted names, "a", "b" or "c".
template <class E>
std::string quoted_names() {
  std::string list;
  const std::size_t count = EnumNames<E>::names.size();
  for (std::size_t i = 0; i < count; ++i) {
    if (i > 0) list += i + 1 == count ? " or " : ", ";
    list += str_cat("\"", EnumNames<E>::names[i].second, "\"");
  }
  return list;
}

template <class E>
E from_string(const std::string& name) {
  for (const auto& [item, item_name] : EnumNames<E>::names)
    if (name == item_name) return item;
  throw InputError(str_cat("unknown ", EnumNames<E>::what, " \"", name, "\": use ", quoted_names<E>()));
}

}  // namespace hinf
