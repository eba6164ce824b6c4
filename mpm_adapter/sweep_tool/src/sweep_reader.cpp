#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <regex>
#include <set>

#include "acst_common/files.hpp"
#include "acst_common/json_fields.hpp"
#include "acst_common/json_file.hpp"
#include "acst_common/plain_stem.hpp"
#include "acst_sweep/sweep.hpp"
#include "acst_sweep/sweep_case.hpp"

namespace acst::mpm {

namespace f = common::fields;
using nlohmann::json;

namespace {

// A description that expands to more cases than max_sweep_cases is a mistake (a product of
// long lists, or a generated list of entries): refused before a scene is made, not after
// building millions of them.
void require_case_count_within_cap(const json& cases) {
  const double total = sweep_case_count(cases);
  if (total > max_sweep_cases)
    f::fail("/cases", "its " + std::to_string(cases.size()) + " entries make " + f::shown(total) +
                          " cases (each entry one, or its 'vary' lists' product); at most " + f::shown(max_sweep_cases) +
                          " are allowed");
}

// A variable sets one pointer ("path") or several at once ("paths", each value an array with one
// entry per pointer: a width that moves the footing's centre with it).
struct Variable {
  std::string name;
  std::vector<std::string> pointers;
  std::vector<json> values;
  std::vector<std::string> labels;  // what the case's name shows for each value
};

// How a value shows in a case name: numbers as the shortest text that reads back, plain stems as
// they are; anything else needs a label.
std::string label_of(const json& v) {
  if (v.is_number()) {
    const double x = v.get<double>();
    char text[32];
    if (std::fabs(x) < 1e15 && x == std::round(x)) {
      std::snprintf(text, sizeof text, "%.0f", x);
      return text;
    }
    for (int digits = 1; digits <= 17; ++digits) {
      std::snprintf(text, sizeof text, "%.*g", digits, x);
      if (std::strtod(text, nullptr) == x) break;
    }
    return text;
  }
  if (v.is_string() && common::is_plain_stem(v.get<std::string>())) return v.get<std::string>();
  return "";
}

Variable read_variable(const json& j, const std::string& p) {
  f::allow_keys(j, {"name", "path", "paths", "values", "labels"}, p);
  for (const char* k : {"name", "values"})
    if (!j.contains(k)) f::fail(p, std::string("'") + k + "' is required");
  Variable v;
  v.name = f::string(j["name"], p + "/name");
  if (!common::is_plain_stem(v.name) || v.name.find('.') != std::string::npos)
    f::fail(p + "/name", "'" + v.name + "' is not a variable name (letters, digits, '_' and '-')");
  // The variables are columns of the table beside its own (docs/sweeps.md, "The table").
  if (is_table_column(v.name))
    f::fail(p + "/name", "'" + v.name + "' is a column of the sweep's table (case, group, status, q_ult_kPa, ...; "
                         "docs/sweeps.md, \"The table\"): name the variable otherwise");
  const bool several = f::one_of(j, {"path", "paths"}, p) == "paths";
  if (several) {
    if (!j["paths"].is_array() || j["paths"].empty()) f::fail(p + "/paths", "expected a non-empty array of JSON pointers");
    for (std::size_t k = 0; k < j["paths"].size(); ++k) v.pointers.push_back(f::string(j["paths"][k], p + "/paths/" + std::to_string(k)));
  } else {
    v.pointers.push_back(f::string(j["path"], p + "/path"));
  }
  if (!j["values"].is_array() || j["values"].empty()) f::fail(p + "/values", "expected a non-empty array of values");
  v.values.assign(j["values"].begin(), j["values"].end());
  for (std::size_t k = 0; several && k < v.values.size(); ++k)
    if (!v.values[k].is_array() || v.values[k].size() != v.pointers.size())
      f::fail(p + "/values/" + std::to_string(k), "expected an array of " + std::to_string(v.pointers.size()) + " values, one per path");
  if (j.contains("labels")) {
    const json& l = j["labels"];
    if (!l.is_array() || l.size() != v.values.size())
      f::fail(p + "/labels", "expected an array of " + std::to_string(v.values.size()) + " labels, one per value");
    for (std::size_t k = 0; k < l.size(); ++k)
      v.labels.push_back(common::require_plain_stem(f::string(l[k], p + "/labels/" + std::to_string(k)),
                                                    p + "/labels/" + std::to_string(k)));
  } else {
    for (std::size_t k = 0; k < v.values.size(); ++k) {
      v.labels.push_back(label_of(several ? v.values[k][0] : v.values[k]));
      if (v.labels.back().empty())
        f::fail(p + "/values/" + std::to_string(k), "a value that is not a number or a plain name needs 'labels'");
    }
  }
  return v;
}

// The case's name: the template with every {variable} replaced by the value's label.
std::string expand_name(const std::string& pattern, const std::map<std::string, std::string>& labels,
                        const std::string& p) {
  std::string name;
  std::set<std::string> used;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    if (pattern[i] != '{') {
      name += pattern[i];
      continue;
    }
    const std::size_t close = pattern.find('}', i);
    if (close == std::string::npos) f::fail(p, "'{' without '}' in '" + pattern + "'");
    const std::string var = pattern.substr(i + 1, close - i - 1);
    const auto it = labels.find(var);
    if (it == labels.end()) f::fail(p, "'{" + var + "}' names no variable of this entry's 'vary'");
    name += it->second;
    used.insert(var);
    i = close;
  }
  for (const auto& [var, label] : labels)
    if (!used.count(var)) f::fail(p, "'" + pattern + "' does not show the variable '" + var + "' ({" + var + "}), so its cases would share a name");
  return common::require_plain_stem(name, p);
}

// The pointer/value pairs of a "set" object, checked as pointers.
std::vector<std::pair<std::string, json>> read_set(const json& j, const std::string& p) {
  f::object(j, p);
  std::vector<std::pair<std::string, json>> out;
  for (const auto& item : j.items()) out.emplace_back(item.key(), item.value());
  return out;
}

class BaseScenes {
 public:
  explicit BaseScenes(std::string dir) : dir_(std::move(dir)) {}
  // The base scene's JSON and its file (relative names inside it are read from its folder).
  const std::pair<std::string, json>& get(const json& name, const std::string& p) {
    const std::string file = common::resolve(dir_, f::string(name, p));
    auto it = cache_.find(file);
    if (it != cache_.end()) return it->second;
    json j = f::read_json_file(file, "the base scene", p);
    f::object(j, p);
    return cache_.emplace(file, std::make_pair(file, std::move(j))).first->second;
  }

 private:
  std::string dir_;
  std::map<std::string, std::pair<std::string, json>> cache_;
};

}  // namespace

double sweep_case_count(const json& cases) {
  double total = 0.0;
  for (const json& c : cases) {
    double n = 1.0;
    if (c.is_object() && c.contains("vary") && c["vary"].is_array())
      for (const json& v : c["vary"])
        if (v.is_object() && v.contains("values") && v["values"].is_array()) n *= static_cast<double>(v["values"].size());
    total += n;
  }
  return total;
}

void set_at_pointer(json& scene, const std::string& pointer, const json& value, const std::string& where) {
  json::json_pointer ptr;
  try {
    ptr = json::json_pointer(pointer);
  } catch (const json::exception&) {
    f::fail(where, "'" + pointer + "' is not a JSON pointer (such as /footing/inclination_deg)");
  }
  if (ptr.empty()) f::fail(where, "the pointer '' would replace the whole scene");
  const json::json_pointer parent = ptr.parent_pointer();
  // contains() throws, not answers, for a token that cannot index an array (such as '' or a
  // number past size_t): both mean the scene has no such member.
  bool found = false;
  try {
    found = scene.contains(parent);
  } catch (const json::exception&) {
  }
  if (!found) f::fail(where, "'" + pointer + "': the scene has no " + parent.to_string());
  json& holder = scene.at(parent);
  const std::string last = ptr.back();
  if (value.is_null()) {  // null removes the member (as in a JSON merge patch)
    if (!holder.is_object()) f::fail(where, "'" + pointer + "': null removes a member of an object; " + parent.to_string() + " is not one");
    holder.erase(last);
  } else if (holder.is_array()) {
    std::size_t index = 0;
    bool digits = !last.empty() && last.size() < 10;
    for (char ch : last) digits = digits && ch >= '0' && ch <= '9';
    if (digits) index = std::stoul(last);
    if (!digits || index >= holder.size())
      f::fail(where, "'" + pointer + "': " + parent.to_string() + " has elements 0 to " + std::to_string(holder.size() - 1));
    holder[index] = value;
  } else if (holder.is_object()) {
    holder[last] = value;
  } else {
    f::fail(where, "'" + pointer + "': " + parent.to_string() + " is a " + holder.type_name() + ", not an object or array");
  }
}

namespace {

KeepSpec read_keep(const json& k, const std::string& p) {
  f::allow_keys(k, {"maps", "rows", "map_cell_over_B", "map_window_over_B"}, p);
  KeepSpec keep;
  if (k.contains("maps")) {
    if (!k["maps"].is_array()) f::fail(p + "/maps", "expected an array of map names (FIELD_SB0.500, FIELD_peak)");
    for (std::size_t i = 0; i < k["maps"].size(); ++i) {
      const std::string q = p + "/maps/" + std::to_string(i);
      const std::string map = common::require_plain_stem(f::string(k["maps"][i], q), q);
      // A map is kept as MAP.csv beside the case's record, summary, load record and histories: a
      // name of another form (load_settlement, particle_A) replaced one of them with a raster.
      static const std::regex map_stem(R"(.+_(SB[0-9]+(\.[0-9]+)?|peak))");
      if (!std::regex_match(map, map_stem))
        f::fail(q, "'" + map + "' is not a map's name: FIELD_SB0.500 (the field at an S/B) or FIELD_peak (at the peak), "
                   "as the case's scene writes its maps");
      keep.maps.push_back(map);
    }
  }
  if (k.contains("rows")) keep.rows = static_cast<std::size_t>(f::integer(k["rows"], p + "/rows", 2, 1000000));
  if (k.contains("map_cell_over_B"))
    keep.map_cell_over_B = f::number(k["map_cell_over_B"], p + "/map_cell_over_B", {0.005, 1.0, false, false});
  if (k.contains("map_window_over_B")) {
    const std::vector<double> w = f::numbers(k["map_window_over_B"], p + "/map_window_over_B", 2, "width and depth in B");
    for (std::size_t i = 0; i < 2; ++i)
      f::number(k["map_window_over_B"][i], p + "/map_window_over_B/" + std::to_string(i), {0.1, 100.0, false, false});
    keep.map_width_over_B = w[0], keep.map_depth_over_B = w[1];
  }
  return keep;
}

// gather/panels, checked against the cases made and the maps kept.
std::vector<PanelFigure> read_panels(const json& a, const std::string& p, const SweepSpec& s) {
  if (!a.is_array()) f::fail(p, "expected an array of figures");
  if (!s.keep) f::fail(p, "panel figures are drawn from the kept results: give /gather/keep too");
  std::set<std::string> names, case_names, groups;
  for (const SweepCase& c : s.cases) {
    case_names.insert(c.name);
    groups.insert(c.groups.begin(), c.groups.end());
  }
  static const std::map<std::string, PanelKind> kinds{
      {"load", PanelKind::load}, {"map", PanelKind::map}, {"histories", PanelKind::histories}, {"load_path", PanelKind::load_path}};
  std::vector<PanelFigure> out;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const std::string q = p + "/" + std::to_string(i);
    const json& e = a[i];
    f::allow_keys(e, {"name", "title", "kind", "cases", "map", "column"}, q);
    for (const char* k : {"name", "kind", "cases"})
      if (!e.contains(k)) f::fail(q, std::string("'") + k + "' is required");
    PanelFigure fig;
    fig.name = common::require_plain_stem(f::string(e["name"], q + "/name"), q + "/name");
    if (!names.insert(fig.name).second) f::fail(q + "/name", "a second figure named '" + fig.name + "'");
    if (groups.count(fig.name)) f::fail(q + "/name", "'" + fig.name + "' is a group's figure already");
    if (e.contains("title")) fig.title = f::string(e["title"], q + "/title");
    const std::string kind = f::string(e["kind"], q + "/kind");
    const auto k = kinds.find(kind);
    if (k == kinds.end()) f::fail(q + "/kind", "'" + kind + "': expected load, map, histories or load_path");
    fig.kind = k->second;
    if (!e["cases"].is_array() || e["cases"].empty()) f::fail(q + "/cases", "expected a non-empty array of case names");
    // One panel (or curve) a case: 300 drew nothing, with only gnuplot's warning.
    if (e["cases"].size() > max_panel_cases)
      f::fail(q + "/cases", std::to_string(e["cases"].size()) + " cases; allowed: at most " + std::to_string(max_panel_cases) +
                                " a figure (split them over several figures)");
    for (std::size_t m = 0; m < e["cases"].size(); ++m) {
      const std::string c = f::string(e["cases"][m], q + "/cases/" + std::to_string(m));
      if (!case_names.count(c)) f::fail(q + "/cases/" + std::to_string(m), "'" + c + "' names no case of this sweep");
      fig.cases.push_back(c);
    }
    if (fig.kind == PanelKind::map) {
      if (!e.contains("map")) f::fail(q, "a map figure needs 'map', one of /gather/keep/maps");
      fig.map = f::string(e["map"], q + "/map");
      if (std::find(s.keep->maps.begin(), s.keep->maps.end(), fig.map) == s.keep->maps.end())
        f::fail(q + "/map", "'" + fig.map + "' is not among /gather/keep/maps");
    } else if (e.contains("map")) {
      f::fail(q + "/map", "only a figure of kind map takes 'map'");
    }
    if (e.contains("column")) {
      if (fig.kind != PanelKind::histories) f::fail(q + "/column", "only a figure of kind histories takes 'column'");
      fig.column = common::require_plain_stem(f::string(e["column"], q + "/column"), q + "/column");
    }
    out.push_back(std::move(fig));
  }
  return out;
}

SweepSpec sweep_from_document(const json& j, const std::string& file, const std::string& extra_set) {
  f::allow_keys(j, {"name", "description", "base", "set", "cases", "gather", "findings", "bands"}, "");
  SweepSpec s;
  s.file = file;
  s.text = j.dump();
  s.name = common::require_plain_stem(
      j.contains("name") ? f::string(j["name"], "/name") : std::filesystem::path(file).stem().string(), "/name");
  if (j.contains("description")) s.description = f::string(j["description"], "/description");
  if (j.contains("gather")) {
    const json& g = j["gather"];
    f::allow_keys(g, {"load_at_S_over_B", "figures", "case_figures", "keep", "panels"}, "/gather");
    if (g.contains("keep")) s.keep = read_keep(g["keep"], "/gather/keep");
    if (g.contains("case_figures")) {
      const json& c = g["case_figures"];
      if (!c.is_array()) f::fail("/gather/case_figures", "expected an array of file names of a case's folder");
      for (std::size_t k = 0; k < c.size(); ++k) {
        const std::string q = "/gather/case_figures/" + std::to_string(k);
        s.case_figures.push_back(common::require_plain_stem(f::string(c[k], q), q));
      }
    }
    if (g.contains("load_at_S_over_B")) {
      if (!g["load_at_S_over_B"].is_array()) f::fail("/gather/load_at_S_over_B", "expected an array of S/B values");
      s.load_at_S_over_B.clear();
      for (std::size_t k = 0; k < g["load_at_S_over_B"].size(); ++k)
        s.load_at_S_over_B.push_back(f::number(g["load_at_S_over_B"][k], "/gather/load_at_S_over_B/" + std::to_string(k),
                                               {0.0, 5.0, true, false}));
    }
    if (g.contains("figures")) s.figures = f::boolean(g["figures"], "/gather/figures");
  }
  auto common_set = j.contains("set") ? read_set(j["set"], "/set") : std::vector<std::pair<std::string, json>>{};
  if (!extra_set.empty())
    for (auto& item : read_set(f::parse(extra_set, "--set", "the value of --set"), "--set")) common_set.push_back(std::move(item));
  if (!j.contains("cases") || !j["cases"].is_array() || j["cases"].empty())
    f::fail("/cases", "expected a non-empty array of cases");
  require_case_count_within_cap(j["cases"]);

  BaseScenes bases(file.empty() ? "" : std::filesystem::path(file).parent_path().string());
  std::set<std::string> names;
  for (std::size_t i = 0; i < j["cases"].size(); ++i) {
    const std::string p = "/cases/" + std::to_string(i);
    const json& c = j["cases"][i];
    f::allow_keys(c, {"name", "group", "base", "set", "vary"}, p);
    if (!c.contains("name")) f::fail(p, "'name' is required");
    const std::string pattern = f::string(c["name"], p + "/name");
    std::vector<std::string> groups{"all"};
    if (c.contains("group")) {
      const json& g = c["group"];
      groups.clear();
      if (g.is_array()) {
        if (g.empty()) f::fail(p + "/group", "expected a group name or a non-empty array of them");
        for (std::size_t k = 0; k < g.size(); ++k)
          groups.push_back(common::require_plain_stem(f::string(g[k], p + "/group/" + std::to_string(k)), p + "/group/" + std::to_string(k)));
      } else {
        groups.push_back(common::require_plain_stem(f::string(g, p + "/group"), p + "/group"));
      }
    }
    if (!c.contains("base") && !j.contains("base")) f::fail(p, "'base' is required (here or at the top of the description)");
    const auto& [base_file, base] = c.contains("base") ? bases.get(c["base"], p + "/base") : bases.get(j["base"], "/base");
    const auto case_set = c.contains("set") ? read_set(c["set"], p + "/set") : std::vector<std::pair<std::string, json>>{};
    std::vector<Variable> vars;
    if (c.contains("vary")) {
      if (!c["vary"].is_array()) f::fail(p + "/vary", "expected an array of variables");
      for (std::size_t k = 0; k < c["vary"].size(); ++k) {
        vars.push_back(read_variable(c["vary"][k], p + "/vary/" + std::to_string(k)));
        for (std::size_t m = 0; m + 1 < vars.size(); ++m)
          if (vars[m].name == vars.back().name) f::fail(p + "/vary/" + std::to_string(k) + "/name", "'" + vars.back().name + "' is varied twice");
      }
    }
    std::size_t count = 1;  // within max_sweep_cases: counted before
    for (const Variable& v : vars) count *= v.values.size();
    // Every combination of the variables' values; the last variable changes fastest.
    for (std::size_t n = 0; n < count; ++n) {
      json scene = base;
      for (const auto& [ptr, value] : common_set) set_at_pointer(scene, ptr, value, "/set (or --set)");
      for (const auto& [ptr, value] : case_set) set_at_pointer(scene, ptr, value, p + "/set");
      SweepCase sc;
      sc.groups = groups;
      sc.origin = p;
      // The case's pick of each variable's values (mixed radix, the last variable fastest).
      std::vector<std::size_t> pick(vars.size());
      for (std::size_t k = vars.size(), rest = n; k-- > 0; rest /= vars[k].values.size()) pick[k] = rest % vars[k].values.size();
      std::map<std::string, std::string> labels;
      for (std::size_t k = 0; k < vars.size(); ++k) {
        const Variable& v = vars[k];
        for (std::size_t m = 0; m < v.pointers.size(); ++m)
          set_at_pointer(scene, v.pointers[m], v.pointers.size() > 1 ? v.values[pick[k]][m] : v.values[pick[k]],
                         p + "/vary/" + std::to_string(k));
        labels[v.name] = v.labels[pick[k]];
        sc.varied[v.name] = v.values[pick[k]];
      }
      sc.name = expand_name(pattern, labels, p + "/name");
      if (!names.insert(sc.name).second) f::fail(p + "/name", "a second case named '" + sc.name + "'");
      scene["name"] = sc.name;
      try {
        sc.scene = parse_scene(scene.dump(), base_file);
      } catch (const common::InputError& e) {
        f::fail(p, "case '" + sc.name + "': its scene (" + base_file + " with the overrides) is invalid: " + e.what());
      }
      s.cases.push_back(std::move(sc));
    }
  }
  if (j.contains("findings")) {
    std::vector<std::string> case_names;
    for (const SweepCase& c : s.cases) case_names.push_back(c.name);
    s.findings = read_findings(j["findings"], "/findings", case_names);
  }
  if (j.contains("bands")) s.bands = read_bands(j["bands"], "/bands");
  if (j.contains("gather") && j["gather"].contains("panels")) s.panels = read_panels(j["gather"]["panels"], "/gather/panels", s);
  return s;
}

}  // namespace

SweepSpec parse_sweep(const std::string& json_text, const std::string& file, const std::string& extra_set) {
  return sweep_from_document(f::parse(json_text, "", "the sweep description"), file, extra_set);
}

SweepSpec read_sweep(const std::string& path, const std::string& extra_set) {
  const json j = f::read_json_file(path, "the sweep description");
  try {
    return sweep_from_document(j, path, extra_set);
  } catch (const common::InputError& e) {  // an error inside the document: its path, after the file's
    throw common::InputError(path + ": " + e.what());
  }
}

}  // namespace acst::mpm
