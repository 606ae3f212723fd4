// An enum's names in a case file, in one table per enum: to and from the name, and the list of valid names
// for messages. One mechanism instead of a to_string/parse pair written per enum:
//   constexpr EnumTable<Method, 2> kMethods = {{{Method::A, "a"}, {Method::B, "b"}}};
//   enum_name(kMethods, Method::A) == "a";  enum_from_name(kMethods, "b") == Method::B;
//   enum_names_list(kMethods) == "a or b"
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <utility>

namespace contact {

template <class E, std::size_t N>
using EnumTable = std::array<std::pair<E, const char*>, N>;

// the name of v ("?" for a value not in the table)
template <class E, std::size_t N>
const char* enum_name(const EnumTable<E, N>& table, E v) {
  for (const auto& [value, name] : table)
    if (value == v) return name;
  return "?";
}

// the value named name, or nothing
template <class E, std::size_t N>
std::optional<E> enum_from_name(const EnumTable<E, N>& table, const std::string& name) {
  for (const auto& [value, n] : table)
    if (name == n) return value;
  return std::nullopt;
}

// "a, b or c"
template <class E, std::size_t N>
std::string enum_names_list(const EnumTable<E, N>& table) {
  std::string out;
  for (std::size_t k = 0; k < N; ++k) out += (k == 0 ? "" : k + 1 == N ? " or " : ", ") + std::string(table[k].second);
  return out;
}

}  // namespace contact
