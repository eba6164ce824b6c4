#pragma once
// A closed set of values (an enum class) and the names they have in the input and output files,
// held in one table {{"name", value}, ...}: reading, writing and the lists of what is allowed in
// the messages all go by it, so they cannot disagree.
#include <iterator>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>

namespace acst::common {

template <class T>
using Named = std::pair<const char*, T>;

// The name of `value`; "?" for a value the table lacks (a table left behind by its enum).
template <class Table, class T>
const char* name_in(const Table& table, T value) {
  for (const auto& [name, v] : table)
    if (v == value) return name;
  return "?";
}

// The value that `name` names, if any.
template <class Table>
auto value_in(const Table& table, const std::string& name) -> std::optional<std::decay_t<decltype(std::begin(table)->second)>> {
  for (const auto& [n, v] : table)
    if (name == n) return v;
  return std::nullopt;
}

// "a, b, c": the names in the table's order, for a message that says what is allowed.
template <class Table>
std::string names_in(const Table& table) {
  std::string s;
  for (const auto& [name, v] : table) s += (s.empty() ? "" : ", ") + std::string(name);
  return s;
}

}  // namespace acst::common
