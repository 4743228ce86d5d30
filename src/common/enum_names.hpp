// One way to name an enum's values for files and messages: a table of {value, name} pairs,
// looked up both ways. Every enum with a name in a file format has one such table (the
// rotation treatments, the material models, the return branches).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace dda {

template <class E>
struct EnumName {
  E value;
  std::string_view name;  // a string literal (so its data() ends with a NUL)
};

template <class E, std::size_t N>
constexpr std::string_view name_in(const EnumName<E> (&table)[N], E value) {
  for (const EnumName<E>& entry : table) {
    if (entry.value == value) return entry.name;
  }
  return "?";  // unreachable while every value has a row
}

template <class E, std::size_t N>
constexpr std::optional<E> value_in(const EnumName<E> (&table)[N], std::string_view name) {
  for (const EnumName<E>& entry : table) {
    if (entry.name == name) return entry.value;
  }
  return std::nullopt;
}

// "\"a\", \"b\", ...": the known names, for an error message.
template <class E, std::size_t N>
std::string quoted_names(const EnumName<E> (&table)[N]) {
  std::string out;
  for (const EnumName<E>& entry : table) {
    out += (out.empty() ? "\"" : ", \"") + std::string(entry.name) + "\"";
  }
  return out;
}

}  // namespace dda
