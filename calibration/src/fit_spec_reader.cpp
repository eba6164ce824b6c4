// Fit description JSON -> FitSpec. Every error names the JSON path and what is allowed; the lab
// files are read here (missing or malformed files are reported against the experiment's path).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <set>
#include <sstream>

#include "acst/json_input.hpp"
#include "acst/parameters.hpp"
#include "acst_calibration/fit_spec.hpp"
#include "acst_common/files.hpp"
#include "acst_common/json_fields.hpp"
#include "acst_common/json_file.hpp"
#include "acst_common/name_table.hpp"
#include "acst_common/plain_stem.hpp"
#include "acst_driver/lab_data.hpp"
#include "acst_driver/material_object.hpp"

namespace acst::calibration {

using nlohmann::json;
namespace f = common::fields;

namespace {

std::string list(const char* const* begin, const char* const* end) {
  std::string s;
  for (auto it = begin; it != end; ++it) s += (s.empty() ? "" : ", ") + std::string(*it);
  return s;
}

// The constants a fit may vary: the sand's, and the options elastic_anisotropy and
// peak_pressure_exponent; not the density bounds (they define Dr), the guards or the discrete
// lode_form.
constexpr const char* fittable_names[] = {"G0", "nu", "Mc", "c",   "e_Gamma", "lambda_c", "xi", "d1",
                                          "m",  "h1", "h2", "n",   "e_A",     "F0",       "k_f", "elastic_anisotropy",
                                          "peak_pressure_exponent"};

// Checks one parameter value against the material's ranges, the other constants as in the base.
void check_in_range(const Parameters& base, const ParameterInfo& info, double value, const std::string& path) {
  Parameters p = base;
  p.*info.member = value;
  try {
    validate(p);
  } catch (const ParameterRangeError& e) {
    if (e.parameter == info.name) f::fail(path, e.what());
  } catch (const InputError& e) {
    f::fail(path, e.what());
  }
}

FittedParameter read_parameter(const std::string& name, const json& j, const std::string& path,
                               const Parameters& base) {
  const auto* begin = std::begin(fittable_names);
  const auto* end = std::end(fittable_names);
  if (std::find_if(begin, end, [&](const char* n) { return name == n; }) == end)
    f::fail(path, "unknown or unfittable parameter '" + name + "' (fittable: " + list(begin, end) + ")");
  const ParameterInfo& info = *parameter_info(name);
  if (base.variant == Variant::isotropic && info.fabric)
    f::fail(path, "the isotropic model has no fabric: '" + name + "' cannot be fitted (use \"model\": \"ACST\")");
  f::allow_keys(j, {"start", "bounds", "per_group", "group_start"}, path);
  FittedParameter p;
  p.name = name;
  p.path = path;
  if (!j.contains("bounds")) f::fail(path + "/bounds", "required: [lower, upper]");
  const auto b = f::numbers(j["bounds"], path + "/bounds", 2, "lower and upper bound");
  p.lower = b[0];
  p.upper = b[1];
  if (!(p.lower < p.upper)) f::fail(path + "/bounds", "the lower bound " + f::shown(p.lower) + " must be below the upper bound " + f::shown(p.upper));
  check_in_range(base, info, p.lower, path + "/bounds/0");
  check_in_range(base, info, p.upper, path + "/bounds/1");
  const f::Range inside{p.lower, p.upper, true, true};
  p.start = j.contains("start") ? f::number(j["start"], path + "/start", inside)
                                : base.*info.member;
  if (!inside.contains(p.start))
    f::fail(path + "/start", "the material's value " + f::shown(p.start) + " is not strictly inside the bounds " +
                                 inside.text() + "; give a start");
  if (j.contains("per_group")) p.per_group = f::boolean(j["per_group"], path + "/per_group");
  if (j.contains("group_start")) {
    if (!p.per_group) f::fail(path + "/group_start", "only for a parameter with \"per_group\": true");
    f::object(j["group_start"], path + "/group_start");
    for (const auto& item : j["group_start"].items())
      p.group_start[item.key()] = f::number(item.value(), path + "/group_start/" + item.key(), inside);
  }
  return p;
}

std::pair<double, double> strain_range(const driver::LabCurve& lab, const std::string& path) {
  std::istringstream in(lab.text("strain_range_pct"));
  double lo = NAN, hi = NAN;
  if (!(in >> lo >> hi) || !(lo < hi))
    f::fail(path, "the lab file '" + lab.path + "' has no usable 'strain_range_pct: lo hi' header; give strain_range_pct");
  return {lo, hi};
}

// A condition from the lab file's header, held to the range the same key has in the description
// (a header of 1e999 reads as infinity).
double header_number(const driver::LabCurve& lab, const char* key, const std::string& path, const char* spec_key,
                     const f::Range& allowed) {
  const double v = lab.number(key);
  if (std::isnan(v))
    f::fail(path, std::string("the lab file '") + lab.path + "' has no numeric '" + key + "' header; give " + spec_key);
  if (!allowed.contains(v))
    f::fail(path, std::string("the lab file '") + lab.path + "' has '" + key + ": " + lab.text(key) +
                      "', out of range; allowed: " + allowed.text() + "; give " + spec_key);
  return v;
}

// Which column of a peak_friction table holds each quantity: `columns` names them; the defaults
// are phi_deg, b and omega_deg, and b and the bedding angle fall back to one value for the
// table when it has no such column. Every named column must exist.
template <class KeyPath>
void read_table_columns(const json& e, const KeyPath& key_path, const driver::LabCurve& lab, ExperimentSpec& x) {
  const char* roles[] = {"phi_deg", "b", "bedding_angle_deg", "sigma3_kPa", "void_ratio"};
  std::string* fields[] = {&x.phi_column, &x.b_column, &x.bedding_column, &x.sigma3_column, &x.void_ratio_column};
  if (e.contains("columns")) {
    const std::string cp = key_path("columns");
    f::object(e["columns"], cp);
    f::allow_keys(e["columns"], {"phi_deg", "b", "bedding_angle_deg", "sigma3_kPa", "void_ratio"}, cp);
    for (std::size_t r = 0; r < std::size(roles); ++r)
      if (e["columns"].contains(roles[r])) {
        *fields[r] = f::string(e["columns"][roles[r]], cp + "/" + roles[r]);
        if (lab.column(*fields[r]).empty())
          f::fail(cp + "/" + roles[r], "'" + x.data_file + "' has no column '" + *fields[r] + "'");
      }
  }
  if (lab.column(x.phi_column).empty())
    f::fail(key_path("data"), "'" + x.data_file + "' has no '" + x.phi_column + "' column (name the peak friction angle's in /columns/phi_deg)");
  // The default columns are optional: without them the experiment's one value is used.
  if (x.b_column == "b" && lab.column("b").empty()) x.b_column.clear();
  if (x.bedding_column == "omega_deg" && lab.column("omega_deg").empty()) x.bedding_column.clear();
}

ExperimentSpec read_gap_closing(const json& j, const std::string& path, const json& defaults, const std::string& base_dir);

ExperimentSpec read_experiment(const json& j, const std::string& path, const json& defaults, const std::string& base_dir) {
  if (j.contains("test") && j["test"] == name_of(TestType::gap_closing)) return read_gap_closing(j, path, defaults, base_dir);
  f::allow_keys(j, {"id", "data", "test", "group", "sigma3_kPa", "void_ratio", "void_ratio_at_kPa",
                    "bedding_angle_deg", "b", "strain_range_pct", "strain_increment_pct", "max_cutbacks", "weight", "fit",
                    "stress_measure", "rows", "columns", "peak_search_strain_pct", "description"},
                path);
  // Defaults first, then the experiment's own keys.
  json e = defaults;
  for (const auto& item : j.items()) e[item.key()] = item.value();
  auto key_path = [&](const char* k) { return (j.contains(k) ? path : std::string("/defaults")) + "/" + k; };

  ExperimentSpec x;
  x.path = path;
  if (!e.contains("data")) f::fail(path + "/data", "required: the lab data file");
  const std::string name = f::string(e["data"], key_path("data"));
  x.data_file = common::resolve(base_dir, name);
  driver::LabCurve lab;
  try {
    lab = driver::read_commented_csv(x.data_file, true);  // tables have text columns
  } catch (const std::exception& err) {
    f::fail(key_path("data"), err.what());
  }
  // The id names the experiment's curve files and reaches their gnuplot scripts.
  x.id = e.contains("id") ? common::require_plain_stem(f::string(e["id"], key_path("id")), key_path("id"))
                          : common::require_plain_stem(std::filesystem::path(name).stem().string(),
                                                       path + "/id (not given; the data file's name would be used)");

  if (e.contains("test")) {
    const std::string name = f::string(e["test"], key_path("test"));
    const auto test = common::value_in(test_type_names, name);
    if (!test) f::fail(key_path("test"), "unknown test type '" + name + "' (allowed: " + common::names_in(test_type_names) + ")");
    if (is_gap_closing(*test)) f::fail(key_path("test"), "a gap_closing test is named in the experiment itself, not in /defaults");
    x.test = *test;
  } else {
    const std::string kind = lab.text("kind").substr(0, lab.text("kind").find(' '));
    if (kind == "TC") x.test = TestType::drained_triaxial_compression;
    else if (kind == "PSC") x.test = TestType::plane_strain_compression;
    else f::fail(path + "/test", "required (the lab file's kind '" + lab.text("kind") + "' does not name a test)");
  }
  const bool table = is_table_test(x.test);
  // A group names a parameter file of its own (NAME_parameters_GROUP.json).
  if (e.contains("group")) x.group = common::require_plain_stem(f::string(e["group"], key_path("group")), key_path("group"));

  if (table) read_table_columns(e, key_path, lab, x);
  const f::Range sigma3_range = f::positive(), void_ratio_range{0.0, 2.97, true, true}, angle_range{0.0, 180.0};
  if (x.sigma3_column.empty())
    x.sigma3_kPa = e.contains("sigma3_kPa") ? f::number(e["sigma3_kPa"], key_path("sigma3_kPa"), sigma3_range, "kPa")
                                            : header_number(lab, "sigma3_kPa", path, "sigma3_kPa", sigma3_range);
  else if (e.contains("sigma3_kPa"))
    f::fail(key_path("sigma3_kPa"), "the table's column '" + x.sigma3_column + "' gives it (/columns/sigma3_kPa)");
  if (x.void_ratio_column.empty())
    x.void_ratio = e.contains("void_ratio") ? f::number(e["void_ratio"], key_path("void_ratio"), void_ratio_range)
                                            : header_number(lab, "e0", path, "void_ratio", void_ratio_range);
  else if (e.contains("void_ratio"))
    f::fail(key_path("void_ratio"), "the table's column '" + x.void_ratio_column + "' gives it (/columns/void_ratio)");
  // With the confining stress per row, a row below void_ratio_at_kPa starts at its own stress
  // with the void ratio as given (problem.cpp); a single stress must not lie below it.
  if (e.contains("void_ratio_at_kPa"))
    x.void_ratio_at_kPa = x.sigma3_column.empty()
        ? f::number(e["void_ratio_at_kPa"], key_path("void_ratio_at_kPa"), {0.0, x.sigma3_kPa, true, false}, "kPa (at most sigma3_kPa)")
        : f::number(e["void_ratio_at_kPa"], key_path("void_ratio_at_kPa"), f::positive(), "kPa");
  if (e.contains("b")) {
    if (x.test != TestType::true_triaxial && !(table && x.b_column.empty()))
      f::fail(key_path("b"), "only for the true_triaxial test, and for a peak_friction table without a b column");
    x.b = f::number(e["b"], key_path("b"), {0.0, 1.0});
  }
  if (e.contains("weight")) x.weight = f::number(e["weight"], key_path("weight"), {0.0, 1e6, false, false});
  if (e.contains("strain_increment_pct"))
    x.strain_increment_pct = f::number(e["strain_increment_pct"], key_path("strain_increment_pct"), {1e-4, 1.0}, "%");
  if (e.contains("max_cutbacks")) x.max_cutbacks = f::integer(e["max_cutbacks"], key_path("max_cutbacks"), 1, 1000000000);

  if (!table) {
    x.bedding_angle_deg = e.contains("bedding_angle_deg")
        ? f::number(e["bedding_angle_deg"], key_path("bedding_angle_deg"), angle_range, "deg")
        : header_number(lab, "bedding_angle_deg", path, "bedding_angle_deg", angle_range);
    try {
      lab = driver::read_lab_curve(x.data_file);
    } catch (const std::exception& err) {
      f::fail(key_path("data"), std::string(err.what()) + " (a " + name_of(x.test) + " test needs a lab curve)");
    }
    if (e.contains("strain_range_pct")) {
      const auto r = f::numbers(e["strain_range_pct"], key_path("strain_range_pct"), 2, "lowest and highest axial strain in %");
      if (!(r[0] >= 0.0 && r[0] < r[1])) f::fail(key_path("strain_range_pct"), "needs 0 <= lower < upper");
      x.strain_lo_pct = r[0];
      x.strain_hi_pct = r[1];
    } else {
      std::tie(x.strain_lo_pct, x.strain_hi_pct) = strain_range(lab, path);
    }
    if (e.contains("fit")) {
      if (!e["fit"].is_array() || e["fit"].empty()) f::fail(key_path("fit"), "expected a non-empty array of \"stress\", \"volumetric\"");
      x.fit_stress = x.fit_volumetric = false;
      for (std::size_t i = 0; i < e["fit"].size(); ++i) {
        const std::string a = f::string(e["fit"][i], key_path("fit") + "/" + std::to_string(i));
        const auto axis = common::value_in(axis_names, a);
        if (axis == Axis::stress) x.fit_stress = true;
        else if (axis == Axis::volumetric) x.fit_volumetric = true;
        else f::fail(key_path("fit") + "/" + std::to_string(i), "'" + a + "' is not an axis (allowed: stress, volumetric)");
      }
    }
    if (e.contains("stress_measure")) {
      const std::string m = f::string(e["stress_measure"], key_path("stress_measure"));
      const auto measure = common::value_in(stress_measure_names, m);
      if (!measure) f::fail(key_path("stress_measure"), "'" + m + "' is not allowed (stress_ratio = sigma1'/sigma3', q_kPa)");
      x.stress_measure = *measure;
    }
    for (const char* k : {"rows", "columns"})
      if (j.contains(k)) f::fail(path + "/" + k, "only for table tests (peak_friction)");
  } else {
    if (x.bedding_column.empty())
      x.bedding_angle_deg = e.contains("bedding_angle_deg")
          ? f::number(e["bedding_angle_deg"], key_path("bedding_angle_deg"), angle_range, "deg")
          : header_number(lab, "bedding_angle_deg", path, "bedding_angle_deg", angle_range);
    else if (e.contains("bedding_angle_deg"))
      f::fail(key_path("bedding_angle_deg"), "the table's column '" + x.bedding_column + "' gives it (/columns/bedding_angle_deg)");
    if (x.b_column.empty() && !e.contains("b"))
      f::fail(path + "/b", "required: the table has no b column (/columns/b)");
    if (e.contains("rows")) {
      f::object(e["rows"], key_path("rows"));
      for (const auto& item : e["rows"].items()) {
        const std::string rp = key_path("rows") + "/" + item.key();
        if (lab.column(item.key()).empty()) f::fail(rp, "the table has no column '" + item.key() + "'");
        if (!item.value().is_array() || item.value().empty()) f::fail(rp, "expected a non-empty array of numbers");
        for (std::size_t k = 0; k < item.value().size(); ++k)
          x.row_filter[item.key()].push_back(f::number(item.value()[k], rp + "/" + std::to_string(k)));
      }
    }
    if (e.contains("peak_search_strain_pct"))
      x.peak_search_strain_pct = f::number(e["peak_search_strain_pct"], key_path("peak_search_strain_pct"), {0.5, 50.0}, "%");
    for (const char* k : {"strain_range_pct", "fit", "stress_measure"})
      if (j.contains(k)) f::fail(path + "/" + k, "not used by table tests (the peak is searched up to peak_search_strain_pct)");
  }
  return x;
}

// A gap_closing test: two lab curves, each run as a curve experiment of its own file's kind and
// conditions with this experiment's group and run settings; one value is compared, the closing
// ratio of the gap in sigma1'/sigma3' (first minus second) between two axial strains.
ExperimentSpec read_gap_closing(const json& j, const std::string& path, const json& defaults, const std::string& base_dir) {
  f::allow_keys(j, {"id", "test", "data", "at_axial_strain_pct", "scale", "weight", "group", "void_ratio_at_kPa",
                    "strain_increment_pct", "max_cutbacks", "description"},
                path);
  ExperimentSpec x;
  x.path = path;
  x.test = TestType::gap_closing;
  if (!j.contains("id")) f::fail(path + "/id", "required for a gap_closing test (its two data files give no one name)");
  x.id = common::require_plain_stem(f::string(j["id"], path + "/id"), path + "/id");
  if (!j.contains("data") || !j["data"].is_array() || j["data"].size() != 2)
    f::fail(path + "/data", "required: [FIRST, SECOND], the two lab curves whose gap in sigma1'/sigma3' (first minus second) closes");
  if (!j.contains("at_axial_strain_pct"))
    f::fail(path + "/at_axial_strain_pct", "required: [FROM, TO], the axial strains in % the gap is taken at");
  const auto at = f::numbers(j["at_axial_strain_pct"], path + "/at_axial_strain_pct", 2, "the two axial strains in %");
  if (!(at[0] > 0.0 && at[0] < at[1] && at[1] <= 50.0))
    f::fail(path + "/at_axial_strain_pct", "needs 0 < FROM < TO <= 50 %; got [" + f::shown(at[0]) + ", " + f::shown(at[1]) + "]");
  x.gap_from_pct = at[0];
  x.gap_to_pct = at[1];
  if (j.contains("scale")) x.closing_scale = f::number(j["scale"], path + "/scale", {0.0, 100.0, true, false});
  if (j.contains("weight")) x.weight = f::number(j["weight"], path + "/weight", {0.0, 1e6, false, false});
  // The keys both tests share; the rest of /defaults (strain ranges, axes) belongs to curve fits.
  json shared = json::object(), shared_defaults = json::object();
  for (const char* k : {"group", "void_ratio_at_kPa", "strain_increment_pct", "max_cutbacks"}) {
    if (j.contains(k)) shared[k] = j[k];
    else if (defaults.contains(k)) shared_defaults[k] = defaults[k];
  }
  for (std::size_t i = 0; i < 2; ++i) {
    json t = shared;
    t["data"] = j["data"][i];
    t["id"] = x.id + (i == 0 ? "_first" : "_second");
    t["fit"] = {"stress"};
    t["strain_range_pct"] = {0.0, 1e9};  // every point: the closing reads the curve where it needs it
    const std::string dp = path + "/data/" + std::to_string(i);
    if (!t["data"].is_string()) f::fail(dp, "expected the lab curve's file name (a string)");
    ExperimentSpec test;
    try {
      test = read_experiment(t, path, shared_defaults, base_dir);
    } catch (const common::InputError& e) {
      f::fail(dp, "the test '" + t["data"].get<std::string>() + "': " + e.what());
    }
    if (is_table_test(test.test)) f::fail(dp, "a gap_closing test compares two lab curves, not tables");
    x.group = test.group;
    x.gap_tests.push_back(std::move(test));
  }
  return x;
}

void read_optimizer(const json& j, OptimizerSettings& o) {
  const std::string p = "/optimizer";
  f::allow_keys(j, {"design_points", "starts", "max_iterations", "abandon_factor", "abandon_after", "xtol", "gtol", "ftol",
                     "fd_step", "penalty", "threads", "seed"}, p);
  if (j.contains("design_points")) o.design_points = static_cast<int>(f::integer(j["design_points"], p + "/design_points", 0, 1000));
  if (j.contains("starts")) o.starts = static_cast<int>(f::integer(j["starts"], p + "/starts", 1, 100));
  if (j.contains("max_iterations")) o.max_iterations = static_cast<int>(f::integer(j["max_iterations"], p + "/max_iterations", 1, 10000));
  if (j.contains("abandon_factor"))
    o.abandon_factor = f::number(j["abandon_factor"], p + "/abandon_factor", {0.0, 1e12}, "(0: never; otherwise at least 1)");
  if (o.abandon_factor > 0.0 && o.abandon_factor < 1.0)
    f::fail(p + "/abandon_factor", "must be 0 (never abandon) or at least 1 (a fit is compared with the best before it); got " +
                                       f::shown(o.abandon_factor));
  if (j.contains("abandon_after")) o.abandon_after = static_cast<int>(f::integer(j["abandon_after"], p + "/abandon_after", 1, 10000));
  if (j.contains("xtol")) o.xtol = f::number(j["xtol"], p + "/xtol", {0.0, 0.1, true, false});
  if (j.contains("gtol")) o.gtol = f::number(j["gtol"], p + "/gtol", {0.0, 0.1, true, false});
  if (j.contains("ftol")) o.ftol = f::number(j["ftol"], p + "/ftol", {0.0, 0.1, true, false});
  if (j.contains("fd_step")) o.fd_step = f::number(j["fd_step"], p + "/fd_step", {1e-8, 0.1}, "(scaled parameters)");
  if (j.contains("penalty")) o.penalty = f::number(j["penalty"], p + "/penalty", {1.0, 1e6}, "(normalised residual per point)");
  if (j.contains("threads")) o.threads = static_cast<int>(f::integer(j["threads"], p + "/threads", 0, 1024));
  if (j.contains("seed")) o.seed = static_cast<unsigned>(f::integer(j["seed"], p + "/seed", 0, 4294967295LL));
  if (o.starts > o.design_points + 1)
    f::fail(p + "/starts", std::to_string(o.starts) + " local fits need at least " + std::to_string(o.starts - 1) +
                               " design points besides the start (design_points is " + std::to_string(o.design_points) + ")");
}

void read_weights(const json& j, FitSpec& s) {
  f::allow_keys(j, {"types", "axes"}, "/weights");
  if (j.contains("types")) {
    f::object(j["types"], "/weights/types");
    for (const auto& item : j["types"].items()) {
      const std::string p = "/weights/types/" + item.key();
      const auto type = common::value_in(test_type_names, item.key());
      if (!type) f::fail(p, "unknown test type (allowed: " + common::names_in(test_type_names) + ")");
      s.type_weights[*type] = f::number(item.value(), p, {0.0, 1e6, true, false});
    }
  }
  if (j.contains("axes")) {
    f::allow_keys(j["axes"], {"stress", "volumetric"}, "/weights/axes");
    if (j["axes"].contains("stress")) s.stress_axis_weight = f::number(j["axes"]["stress"], "/weights/axes/stress", {0.0, 1e6});
    if (j["axes"].contains("volumetric"))
      s.volumetric_axis_weight = f::number(j["axes"]["volumetric"], "/weights/axes/volumetric", {0.0, 1e6});
    const double sum = s.stress_axis_weight + s.volumetric_axis_weight;
    if (!(sum > 0.0)) f::fail("/weights/axes", "at least one axis needs a positive weight");
    s.stress_axis_weight /= sum;
    s.volumetric_axis_weight /= sum;
  }
}

// cross_validation: {"folds": {"NAME": [experiment ids]}}: disjoint folds of existing experiments,
// each leaving some to fit.
void read_folds(const json& j, FitSpec& s) {
  const std::string p = "/cross_validation";
  f::object(j, p);
  f::allow_keys(j, {"folds"}, p);
  if (!j.contains("folds")) f::fail(p + "/folds", "required: {\"FOLD\": [experiment ids]}");
  f::object(j["folds"], p + "/folds");
  if (j["folds"].empty()) f::fail(p + "/folds", "name at least one fold");
  std::set<std::string> ids, used;
  for (const ExperimentSpec& x : s.experiments) ids.insert(x.id);
  for (const auto& item : j["folds"].items()) {
    const std::string fp = p + "/folds/" + item.key();
    Fold fold;
    fold.name = common::require_plain_stem(item.key(), fp);
    if (!item.value().is_array() || item.value().empty()) f::fail(fp, "expected a non-empty array of experiment ids");
    for (std::size_t k = 0; k < item.value().size(); ++k) {
      const std::string id = f::string(item.value()[k], fp + "/" + std::to_string(k));
      if (!ids.count(id)) f::fail(fp + "/" + std::to_string(k), "no experiment has the id '" + id + "'");
      if (!used.insert(id).second) f::fail(fp + "/" + std::to_string(k), "'" + id + "' is in two folds");
      fold.experiments.push_back(id);
    }
    if (fold.experiments.size() == s.experiments.size()) f::fail(fp, "leaves no experiment to fit");
    s.folds.push_back(std::move(fold));
  }
}

FitSpec parse(const json& j, const std::string& base_dir, const std::string& default_name) {
  f::allow_keys(j, {"description", "name", "material", "parameters", "experiments", "defaults", "weights", "optimizer", "output",
                    "cross_validation"},
                "");
  for (const char* key : {"material", "parameters", "experiments"})
    if (!j.contains(key)) f::fail(std::string("/") + key, "required key is missing");
  FitSpec s;
  s.base_dir = base_dir;
  // The name starts every output file's name and reaches the overview's gnuplot script.
  s.name = j.contains("name") ? common::require_plain_stem(f::string(j["name"], "/name"), "/name")
                              : common::require_plain_stem(default_name.empty() ? "fit" : default_name,
                                                           "/name (not given; the description file's name would be used)");
  if (j.contains("description")) s.description = f::string(j["description"], "/description");

  s.material = driver::read_material_object(j["material"], "/material", base_dir).object;
  Parameters base;
  try {
    f::allow_keys(s.material, {"model", "parameters", "integrator"}, "/material");
    const Variant v = s.material.contains("model") ? variant_from_json(s.material["model"], "/model") : Variant::anisotropic;
    if (!s.material.contains("parameters")) f::fail("/material/parameters", "required object is missing");
    base = parameters_from_json(s.material["parameters"], v, "/parameters");
    if (s.material.contains("integrator")) options_from_json(s.material["integrator"], "/integrator");
  } catch (const InputError& e) {
    f::fail("/material", e.what());
  }

  f::object(j["parameters"], "/parameters");
  for (const auto& item : j["parameters"].items())
    s.parameters.push_back(read_parameter(item.key(), item.value(), "/parameters/" + item.key(), base));

  const json defaults = j.contains("defaults") ? f::object(j["defaults"], "/defaults") : json::object();
  if (!j["experiments"].is_array() || j["experiments"].empty()) f::fail("/experiments", "expected a non-empty array of experiments");
  std::set<std::string> ids;
  for (std::size_t i = 0; i < j["experiments"].size(); ++i) {
    const std::string p = "/experiments/" + std::to_string(i);
    ExperimentSpec x = read_experiment(f::object(j["experiments"][i], p), p, defaults, base_dir);
    if (!ids.insert(x.id).second) f::fail(p + "/id", "the id '" + x.id + "' is used twice; give each experiment its own id");
    if (std::find(s.groups.begin(), s.groups.end(), x.group) == s.groups.end()) s.groups.push_back(x.group);
    s.experiments.push_back(std::move(x));
  }
  for (const FittedParameter& p : s.parameters)
    for (const auto& [group, value] : p.group_start)
      if (std::find(s.groups.begin(), s.groups.end(), group) == s.groups.end())
        f::fail(p.path + "/group_start/" + group, "no experiment is in the group '" + group + "'");

  if (j.contains("weights")) read_weights(j["weights"], s);
  std::map<TestType, double> used;
  for (const ExperimentSpec& x : s.experiments) used[x.test] = s.type_weights.count(x.test) ? s.type_weights[x.test] : 1.0;
  for (const auto& [type, w] : s.type_weights)
    if (!used.count(type)) f::fail(std::string("/weights/types/") + name_of(type), "no experiment has this test type");
  double sum = 0.0;
  for (const auto& [type, w] : used) sum += w;
  if (!(sum > 0.0)) f::fail("/weights/types", "at least one test type in use needs a positive weight");
  for (auto& [type, w] : used) w /= sum;
  s.type_weights = used;

  if (j.contains("optimizer")) read_optimizer(f::object(j["optimizer"], "/optimizer"), s.optimizer);
  if (j.contains("output")) {
    f::allow_keys(j["output"], {"directory", "reference_group"}, "/output");
    if (j["output"].contains("directory")) s.output_dir = f::string(j["output"]["directory"], "/output/directory");
    if (j["output"].contains("reference_group")) s.reference_group = f::string(j["output"]["reference_group"], "/output/reference_group");
  }
  if (j.contains("cross_validation")) read_folds(j["cross_validation"], s);
  if (s.output_dir.empty()) s.output_dir = "results/calibration/" + s.name;
  if (s.reference_group.empty()) s.reference_group = s.groups.front();
  if (std::find(s.groups.begin(), s.groups.end(), s.reference_group) == s.groups.end())
    f::fail("/output/reference_group", "no experiment is in the group '" + s.reference_group + "'");
  return s;
}

}  // namespace

FitSpec parse_fit_spec(const std::string& text, const std::string& base_dir, const std::string& default_name) {
  return parse(f::parse(text, "", "the fit description"), base_dir, default_name);
}

FitSpec read_fit_spec(const std::string& path) {
  const std::filesystem::path p(path);
  FitSpec s = parse(f::read_json_file(path, "the fit description"), p.parent_path().string(), p.stem().string());
  s.source = path;
  return s;
}

double experiment_weight(const FitSpec& spec, std::size_t k) {
  const ExperimentSpec& x = spec.experiments[k];
  double inside = 0.0;
  for (const ExperimentSpec& y : spec.experiments)
    if (y.test == x.test) inside += y.weight;
  return inside > 0.0 ? spec.type_weights.at(x.test) * x.weight / inside : 0.0;
}

}  // namespace acst::calibration
