#include "step_reader.hpp"

#include "acst/scene_units.hpp"
#include "acst_common/files.hpp"
#include "acst_common/json_fields.hpp"
#include "acst_driver/lab_data.hpp"
#include "acst_driver/presets.hpp"
#include "acst_driver/strain_path.hpp"

namespace acst::driver {

using nlohmann::json;
namespace f = common::fields;

namespace {

constexpr double percent = 0.01;  // strain in the scene is in percent
using units::strain_from_scene;

const std::vector<std::string> presets = {
    "drained_triaxial_compression", "drained_triaxial_extension", "undrained_triaxial_compression",
    "undrained_triaxial_extension", "plane_strain_compression",  "isotropic_compression",
    "isotropic_unloading",          "oedometric",                "constant_p_shear",
    "true_triaxial",                "pq",                        "strain_path_csv"};

std::string preset_list() {
  std::string s;
  for (const auto& p : presets) s += (s.empty() ? "" : ", ") + p;
  return s;
}

const f::Range strain_magnitude{0.0, 100.0, true, false};   // (0, 100] percent
const f::Range signed_strain{-100.0, 100.0, false, false};  // [-100, 100] percent

double nonzero_signed_strain(const json& j, const std::string& path) {
  const double v = f::number(j, path, signed_strain, "% axial strain");
  if (v == 0.0) f::fail(path, "must not be zero (positive = compression, negative = extension), in [-100, 100] %");
  return v;
}

std::vector<ExitCondition> read_exits(const json& j, const std::string& path) {
  struct Key {
    const char* name;
    ExitQuantity quantity;
    bool above;
  };
  static const Key keys[] = {
      {"q_above", ExitQuantity::q, true},
      {"q_below", ExitQuantity::q, false},
      {"stress_ratio_above", ExitQuantity::stress_ratio, true},
      {"stress_ratio_below", ExitQuantity::stress_ratio, false},
      {"p_above", ExitQuantity::p, true},
      {"p_below", ExitQuantity::p, false},
      {"axial_strain_pct_above", ExitQuantity::axial_strain_pct, true},
      {"axial_strain_pct_below", ExitQuantity::axial_strain_pct, false},
      {"volumetric_strain_pct_above", ExitQuantity::volumetric_strain_pct, true},
      {"volumetric_strain_pct_below", ExitQuantity::volumetric_strain_pct, false},
      {"excess_pore_pressure_above", ExitQuantity::excess_pore_pressure, true},
      {"excess_pore_pressure_below", ExitQuantity::excess_pore_pressure, false},
  };
  f::allow_keys(j, {"q_above", "q_below", "stress_ratio_above", "stress_ratio_below", "p_above", "p_below",
                    "axial_strain_pct_above", "axial_strain_pct_below", "volumetric_strain_pct_above",
                    "volumetric_strain_pct_below", "excess_pore_pressure_above", "excess_pore_pressure_below"},
                path);
  if (j.empty()) f::fail(path, "an empty exit object: give at least one condition (for example q_above)");
  std::vector<ExitCondition> out;
  for (const Key& k : keys) {
    if (!j.contains(k.name)) continue;
    ExitCondition c;
    c.quantity = k.quantity;
    c.above = k.above;
    c.key = k.name;
    c.path = path + "/" + k.name;
    const f::Range r = k.quantity == ExitQuantity::p ? f::positive() : f::any();
    c.threshold = f::number(j[k.name], c.path, r, k.quantity == ExitQuantity::p ? "kPa" : "");
    out.push_back(c);
  }
  return out;
}

// "control": {"11": {"strain_pct": 5}, "lateral": {"stress": 0}, "shear": {"stress": 0}}.
ControlRows read_component_control(const json& j, const std::string& path) {
  f::allow_keys(j, {"11", "22", "33", "12", "13", "23", "axial", "lateral", "shear"}, path);
  ControlRows rows;
  std::array<std::string, 6> set_by;
  auto apply = [&](const std::string& key, const std::vector<int>& components) {
    const std::string p = path + "/" + key;
    const json& spec = j[key];
    f::allow_keys(spec, {"stress", "stress_to", "strain_pct", "strain_to_pct"}, p);
    const std::string kind = f::one_of(spec, {"stress", "stress_to", "strain_pct", "strain_to_pct"}, p);
    const bool stress = kind.rfind("stress", 0) == 0;
    const bool absolute = kind.find("_to") != std::string::npos;
    const double v = f::number(spec[kind], p + "/" + kind, f::any(), stress ? "kPa" : "%");
    for (int c : components) {
      if (!set_by[c].empty())
        f::fail(p, std::string("component ") + component_name(c) + " is already controlled by '" + set_by[c] + "'");
      set_by[c] = key;
      if (stress)
        set_stress_row(rows, c, c, v, absolute);
      else
        set_strain_row(rows, c, c, strain_from_scene(v, c), absolute);
    }
  };
  static const std::pair<const char*, std::vector<int>> groups[] = {
      {"axial", {0}}, {"lateral", {1, 2}}, {"shear", {3, 4, 5}}, {"11", {0}}, {"22", {1}},
      {"33", {2}},    {"12", {3}},         {"13", {4}},          {"23", {5}}};
  for (const auto& [key, components] : groups)
    if (j.contains(key)) apply(key, components);
  for (int c = 0; c < 6; ++c)
    if (set_by[c].empty())
      f::fail(path, std::string("component ") + component_name(c) +
                        " is not controlled: give it a stress or a strain (every component must be controlled; "
                        "nothing defaults to sigma = 0)");
  return rows;
}

// "constraints": six rows {"stress": [6], "strain_pct": [6], "change" | "to": value}.
ControlRows read_constraints(const json& j, const std::string& path) {
  if (!j.is_array() || j.size() != 6)
    f::fail(path, "expected an array of exactly 6 constraints (one per unknown), got " +
                      (j.is_array() ? std::to_string(j.size()) + " entries" : std::string(j.type_name())));
  ControlRows rows;
  for (int i = 0; i < 6; ++i) {
    const std::string p = path + "/" + std::to_string(i);
    const json& row = j[i];
    f::allow_keys(row, {"stress", "strain_pct", "change", "to"}, p);
    if (row.contains("stress")) {
      const auto a = f::numbers(row["stress"], p + "/stress", 6, "coefficients of d sigma_11 ... d sigma_23 in kPa");
      for (int k = 0; k < 6; ++k) rows.A(i, k) = a[k];
    }
    if (row.contains("strain_pct")) {
      const auto b = f::numbers(row["strain_pct"], p + "/strain_pct", 6,
                                "coefficients of d eps_11, d eps_22, d eps_33, d gamma_12, d gamma_13, d gamma_23 in %");
      // b . d(strain in %, engineering shear) = B . d(eps as a tensor fraction)
      for (int k = 0; k < 6; ++k) rows.B(i, k) = b[k] / units::scene_strain_factor(k);
    }
    if (rows.A.row(i).isZero() && rows.B.row(i).isZero())
      f::fail(p, "a constraint needs a non-zero 'stress' or 'strain_pct' coefficient");
    const std::string kind = f::one_of(row, {"change", "to"}, p);
    rows.value[i] = f::number(row[kind], p + "/" + kind);
    rows.absolute[i] = kind == "to";
    rows.names[i] = "constraint " + std::to_string(i);
  }
  return rows;
}

// strain_path_csv: the file's table, its segments (strain_path.hpp).
std::vector<Segment> read_strain_path(const std::string& file, const std::string& path, int increments_per_row) {
  LabCurve table;
  try {
    table = read_commented_csv(file);
  } catch (const std::exception& e) {
    f::fail(path, e.what());
  }
  return strain_path_segments(table, file, path, increments_per_row);
}

int read_increments(const json& j, const std::string& path) {
  if (!j.contains("increments")) f::fail(path + "/increments", "required: the number of increments of the step (>= 1)");
  return static_cast<int>(f::integer(j["increments"], path + "/increments", 1, max_step_increments));
}

Step read_preset_step(const json& j, const std::string& path, const std::string& base_dir) {
  Step s;
  s.path = path;
  s.kind = f::string(j["preset"], path + "/preset");
  const std::string& k = s.kind;
  auto keys = [&](std::initializer_list<const char*> extra) {
    std::vector<const char*> all = {"preset", "increments", "exit", "description"};
    all.insert(all.end(), extra);
    for (const auto& item : j.items()) {
      bool ok = false;
      for (const char* a : all) ok = ok || item.key() == a;
      if (!ok) {
        std::string list;
        for (const char* a : all) list += (list.empty() ? "" : ", ") + std::string(a);
        f::fail(path + "/" + item.key(), "unknown key for preset " + k + " (allowed: " + list + ")");
      }
    }
  };
  auto required = [&](const char* key) -> const json& {
    if (!j.contains(key)) f::fail(path + "/" + key, std::string("required by preset ") + k);
    return j[key];
  };
  const std::string p = path + "/";
  ControlRows rows;
  if (k == "drained_triaxial_compression" || k == "drained_triaxial_extension" ||
      k == "undrained_triaxial_compression" || k == "undrained_triaxial_extension") {
    keys({"axial_strain_pct"});
    const double e = f::number(required("axial_strain_pct"), p + "axial_strain_pct", strain_magnitude,
                               "% (magnitude; the preset gives the sense)");
    const bool compression = k.find("compression") != std::string::npos;
    s.undrained = k.rfind("undrained", 0) == 0;
    rows = triaxial_rows((compression ? 1.0 : -1.0) * e * percent, !s.undrained);
  } else if (k == "plane_strain_compression") {
    keys({"axial_strain_pct"});
    rows = plane_strain_rows(f::number(required("axial_strain_pct"), p + "axial_strain_pct", strain_magnitude, "%") * percent);
  } else if (k == "isotropic_compression" || k == "isotropic_unloading") {
    keys({"p_to"});
    rows = isotropic_rows(f::number(required("p_to"), p + "p_to", f::positive(), "kPa"));
  } else if (k == "oedometric") {
    keys({"axial_strain_pct", "axial_stress_to"});
    const std::string which = f::one_of(j, {"axial_strain_pct", "axial_stress_to"}, path);
    rows = which == "axial_stress_to"
               ? oedometric_rows(f::number(j[which], p + which, f::positive(), "kPa"), true)
               : oedometric_rows(nonzero_signed_strain(j[which], p + which) * percent, false);
  } else if (k == "constant_p_shear" || k == "true_triaxial") {
    const bool tt = k == "true_triaxial";
    if (tt)
      keys({"axial_strain_pct", "b", "hold"});
    else
      keys({"axial_strain_pct", "b"});
    const double e = nonzero_signed_strain(required("axial_strain_pct"), p + "axial_strain_pct");
    const double b = tt ? f::number(required("b"), p + "b", {0.0, 1.0}, "")
                        : (j.contains("b") ? f::number(j["b"], p + "b", {0.0, 1.0}, "") : 0.0);
    bool hold_p = !tt;
    if (tt && j.contains("hold")) {
      const std::string h = f::string(j["hold"], p + "hold");
      if (h != "p" && h != "sigma_3") f::fail(p + "hold", "'" + h + "' is not allowed (allowed: sigma_3, p)");
      hold_p = h == "p";
    }
    rows = true_triaxial_rows(e * percent, b, hold_p);
  } else if (k == "pq") {
    keys({"p_to", "p_change", "q_to", "q_change"});
    const std::string pk = f::one_of(j, {"p_to", "p_change"}, path);
    const std::string qk = f::one_of(j, {"q_to", "q_change"}, path);
    const double pv = f::number(j[pk], p + pk, pk == "p_to" ? f::positive() : f::any(), "kPa");
    const double qv = f::number(j[qk], p + qk, f::any(), "kPa (q = sigma_11 - sigma_33)");
    rows = pq_rows(pv, pk == "p_to", qv, qk == "q_to");
  } else if (k == "strain_path_csv") {
    keys({"file", "increments_per_row"});
    if (j.contains("increments")) f::fail(p + "increments", "not used by strain_path_csv (use increments_per_row)");
    const std::string file = common::resolve(base_dir, f::string(required("file"), p + "file"));
    const int per_row = j.contains("increments_per_row")
                            ? static_cast<int>(f::integer(j["increments_per_row"], p + "increments_per_row", 1, max_step_increments))
                            : 1;
    s.segments = read_strain_path(file, p + "file", per_row);
  } else {
    f::fail(path + "/preset", "unknown preset '" + k + "' (allowed: " + preset_list() + ")");
  }
  if (k != "strain_path_csv") s.segments.push_back({rows, read_increments(j, path)});
  if (j.contains("exit")) s.exits = read_exits(j["exit"], path + "/exit");
  return s;
}

Step read_step(const json& j, const std::string& path, const std::string& base_dir) {
  f::object(j, path);
  const std::string kind = f::one_of(j, {"preset", "control", "constraints"}, path);
  if (kind == "preset") return read_preset_step(j, path, base_dir);
  f::allow_keys(j, {kind.c_str(), "increments", "exit", "undrained", "newton_guess_strain_pct", "description"}, path);
  Step s;
  s.path = path;
  s.kind = kind;
  const ControlRows rows = kind == "control" ? read_component_control(j["control"], path + "/control")
                                             : read_constraints(j["constraints"], path + "/constraints");
  s.segments.push_back({rows, read_increments(j, path)});
  if (j.contains("exit")) s.exits = read_exits(j["exit"], path + "/exit");
  if (j.contains("undrained")) s.undrained = f::boolean(j["undrained"], path + "/undrained");
  if (j.contains("newton_guess_strain_pct")) {
    const auto g = f::numbers(j["newton_guess_strain_pct"], path + "/newton_guess_strain_pct", 6,
                              "eps_11, eps_22, eps_33, gamma_12, gamma_13, gamma_23 in %");
    Sym guess;
    for (int k = 0; k < 6; ++k) guess[k] = strain_from_scene(g[k], k);
    s.newton_guess = guess;
  }
  return s;
}

}  // namespace

const std::vector<std::string>& preset_names() { return presets; }

std::vector<Block> read_steps(const json& steps, const std::string& path, const std::string& base_dir) {
  if (!steps.is_array() || steps.empty())
    f::fail(path, std::string("expected a non-empty array of steps, got ") +
                      (steps.is_array() ? "an empty array" : steps.type_name()));
  std::vector<Block> blocks;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const std::string p = path + "/" + std::to_string(i);
    const json& j = steps[i];
    Block b;
    b.path = p;
    if (j.is_object() && j.contains("repeat")) {
      f::allow_keys(j, {"repeat"}, p);
      const std::string rp = p + "/repeat";
      const json& r = f::object(j["repeat"], rp);
      f::allow_keys(r, {"cycles", "steps", "exit", "description"}, rp);
      b.repeat = true;
      b.path = rp;
      if (!r.contains("cycles")) f::fail(rp + "/cycles", "required: the number of cycles (>= 1)");
      b.cycles = static_cast<int>(f::integer(r["cycles"], rp + "/cycles", 1, 1000000));
      if (!r.contains("steps")) f::fail(rp + "/steps", "required: the steps of one cycle");
      const json& inner = r["steps"];
      if (!inner.is_array() || inner.empty()) f::fail(rp + "/steps", "expected a non-empty array of steps");
      for (std::size_t k = 0; k < inner.size(); ++k) {
        const std::string sp = rp + "/steps/" + std::to_string(k);
        if (inner[k].is_object() && inner[k].contains("repeat"))
          f::fail(sp + "/repeat", "repeat blocks cannot be nested");
        b.steps.push_back(read_step(inner[k], sp, base_dir));
      }
      if (r.contains("exit")) b.exits = read_exits(r["exit"], rp + "/exit");
    } else {
      b.steps.push_back(read_step(j, p, base_dir));
    }
    blocks.push_back(std::move(b));
  }
  return blocks;
}

}  // namespace acst::driver
