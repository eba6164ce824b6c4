#pragma once
// Small readers for JSON input: each checks the type and range of one value and throws an
// InputError whose message starts with the JSON path and says what is allowed.
#include <cmath>
#include <initializer_list>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "acst_common/input_error.hpp"
#include "acst_common/name_table.hpp"

namespace acst::common::fields {

using nlohmann::json;

[[noreturn]] inline void fail(const std::string& path, const std::string& what) {
  throw InputError((path.empty() ? std::string("/") : path) + ": " + what);
}

inline std::string join(std::initializer_list<const char*> names) {
  std::string s;
  for (const char* n : names) s += (s.empty() ? "" : ", ") + std::string(n);
  return s;
}

inline std::string shown(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// Arrays and objects nested deeper than this are refused while parsing: no input of the project
// comes near it, and a deeper document (a file of '[') would overflow the stack of every
// recursive walk that follows (copy, dump, comparison).
inline constexpr std::size_t max_json_depth = 100;

namespace detail {

// Builds the document from the parser's events (nlohmann's SAX interface) and keeps the JSON
// path of the value being read, so that an error found in the text (a number beyond the range of
// a double, too deep a nesting, a syntax error) says where it is.
class PathKeepingBuilder {
 public:
  json root;

  bool null() { return value(nullptr); }
  bool boolean(bool v) { return value(v); }
  bool number_integer(json::number_integer_t v) { return value(v); }
  bool number_unsigned(json::number_unsigned_t v) { return value(v); }
  bool number_float(json::number_float_t v, const json::string_t&) { return value(v); }
  bool string(json::string_t& v) { return value(std::move(v)); }
  bool binary(json::binary_t& v) { return value(json::binary(std::move(v))); }  // not in JSON text
  bool start_object(std::size_t) { return open(json::object()); }
  bool start_array(std::size_t) { return open(json::array()); }
  bool key(json::string_t& k) {
    open_.back().key = k;
    return true;
  }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool parse_error(std::size_t, const std::string&, const json::exception& e) {
    std::string msg = e.what();
    const auto bracket = msg.find("] ");
    if (msg.rfind("[json.exception", 0) == 0 && bracket != std::string::npos) msg = msg.substr(bracket + 2);
    throw InputError(where() + msg);
  }

 private:
  struct Open {
    json* node;
    std::string key;  // of the member being read, in an object
  };
  std::vector<Open> open_;  // the containers around the value being read, outermost first

  json* place(json&& v) {
    if (open_.empty()) return &(root = std::move(v));
    json& parent = *open_.back().node;
    if (!parent.is_array()) return &(parent[open_.back().key] = std::move(v));
    parent.push_back(std::move(v));
    return &parent.back();
  }
  bool value(json&& v) {
    place(std::move(v));
    return true;
  }
  bool open(json&& container) {
    if (open_.size() >= max_json_depth)
      throw InputError(where() + "arrays and objects are nested deeper than " + std::to_string(max_json_depth) + " levels");
    open_.push_back({place(std::move(container)), {}});
    return true;
  }
  bool close() {
    open_.pop_back();
    return true;
  }
  // "at /experiments/3/weight: " (the start of a deep path only), or "" at the top.
  std::string where() const {
    std::string p;
    for (std::size_t i = 0; i < open_.size() && p.size() < 160; ++i) {
      const json& n = *open_[i].node;
      // An open container inside an array is its last element; the value being read comes next.
      p += "/" + (n.is_array() ? std::to_string(n.size() - (i + 1 < open_.size() ? 1 : 0)) : open_[i].key);
    }
    if (p.size() >= 160) p = p.substr(0, 160) + "...";
    return p.empty() ? std::string() : "at " + p + ": ";
  }
};

}  // namespace detail

// The one JSON parser of the project: `text` as a document, or an InputError that says why not
// and where inside the document ("at /experiments/3/weight: number overflow parsing '1e999'"):
// a syntax error with its line and column, a number beyond the range of a double, nesting deeper
// than max_json_depth. The callers below put the document's own path in front.
inline json parse_document(const std::string& text) {
  detail::PathKeepingBuilder builder;
  json::sax_parse(text, &builder);
  return std::move(builder.root);
}

// Parses `text`; a syntax error, a number beyond the range of a double or too deep a nesting
// fails at `path`, naming `what` ("the scene", "the material file 'x.json'").
inline json parse(const std::string& text, const std::string& path, const std::string& what) {
  try {
    return parse_document(text);
  } catch (const InputError& e) {
    fail(path, what + " is not valid JSON: " + e.what());
  }
}

inline const json& object(const json& j, const std::string& path) {
  if (!j.is_object()) fail(path, std::string("expected a JSON object, got ") + j.type_name());
  return j;
}

// Rejects keys not in `allowed`, naming the allowed ones.
inline void allow_keys(const json& j, std::initializer_list<const char*> allowed, const std::string& path) {
  object(j, path);
  for (const auto& item : j.items()) {
    bool ok = false;
    for (const char* a : allowed) ok = ok || item.key() == a;
    if (!ok) fail(path + "/" + item.key(), "unknown key (allowed here: " + join(allowed) + ")");
  }
}

// The same for a list of names built at run time.
inline void allow_keys(const json& j, const std::vector<std::string>& allowed, const std::string& path) {
  object(j, path);
  for (const auto& item : j.items()) {
    bool ok = false;
    for (const std::string& a : allowed) ok = ok || item.key() == a;
    if (ok) continue;
    std::string list;
    for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
    fail(path + "/" + item.key(), "unknown key (allowed here: " + list + ")");
  }
}

// Exactly one of the keys (or at most one when `required` is false); returns it or "".
inline std::string one_of(const json& j, std::initializer_list<const char*> keys, const std::string& path,
                          bool required = true) {
  std::string found;
  for (const char* k : keys) {
    if (!j.contains(k)) continue;
    if (!found.empty()) fail(path + "/" + k, "give only one of " + join(keys) + " (also found " + found + ")");
    found = k;
  }
  if (found.empty() && required) fail(path, "one of " + join(keys) + " is required");
  return found;
}

struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;
  bool contains(double v) const {
    return std::isfinite(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  std::string text() const {
    auto end = [](double v) { return std::isinf(v) ? std::string(v < 0 ? "-inf" : "inf") : shown(v); };
    return std::string(lo_open || std::isinf(lo) ? "(" : "[") + end(lo) + ", " + end(hi) +
           (hi_open || std::isinf(hi) ? ")" : "]");
  }
};
inline Range positive() { return {0.0, std::numeric_limits<double>::infinity(), true, true}; }
inline Range any() { return {}; }

inline double number(const json& v, const std::string& path, const Range& r = any(), const std::string& unit = "") {
  if (!v.is_number()) fail(path, std::string("expected a number") + (unit.empty() ? "" : " (" + unit + ")") + ", got " + v.type_name());
  const double x = v.get<double>();
  if (!r.contains(x)) fail(path, shown(x) + " is out of range; allowed: " + r.text() + (unit.empty() ? "" : " " + unit));
  return x;
}

inline long long integer(const json& v, const std::string& path, long long lo, long long hi) {
  if (!v.is_number_integer() && !(v.is_number() && std::floor(v.get<double>()) == v.get<double>()))
    fail(path, std::string("expected an integer in [") + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                   (v.is_number() ? shown(v.get<double>()) : v.type_name()));
  const double x = v.get<double>();
  if (x < lo || x > hi)
    fail(path, shown(x) + " is out of range; allowed: integers in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return static_cast<long long>(x);
}

inline std::string string(const json& v, const std::string& path) {
  if (!v.is_string()) fail(path, std::string("expected a string, got ") + v.type_name());
  return v.get<std::string>();
}

// A string that names one of a fixed set of choices, {{"name", value}, ...} given here or a
// table of name_table.hpp; returns the value it names, else fails with the path and the names
// allowed.
template <class T, class Table = std::initializer_list<Named<T>>>
T choice(const json& j, const std::string& path, const Table& choices) {
  const std::string name = string(j, path);
  if (const auto value = value_in(choices, name)) return *value;
  fail(path, "'" + name + "' is not one of " + names_in(choices));
}

inline bool boolean(const json& v, const std::string& path) {
  if (!v.is_boolean()) fail(path, std::string("expected true or false, got ") + v.type_name());
  return v.get<bool>();
}

inline std::vector<double> numbers(const json& v, const std::string& path, std::size_t size, const std::string& what) {
  if (!v.is_array() || v.size() != size)
    fail(path, "expected an array of " + std::to_string(size) + " numbers (" + what + ")" +
                   (v.is_array() ? ", got " + std::to_string(v.size()) + " entries" : std::string(", got ") + v.type_name()));
  std::vector<double> out;
  for (std::size_t i = 0; i < size; ++i) out.push_back(number(v[i], path + "/" + std::to_string(i)));
  return out;
}

}  // namespace acst::common::fields
