#include "acst_sweep/sweep_case.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "acst_common/csv_table.hpp"
#include "acst_common/files.hpp"
#include "acst_common/json_fields.hpp"
#include "acst_common/json_file.hpp"
#include "acst_common/result_folder.hpp"
#include "acst_footing_tool/checkpoint.hpp"
#include "acst_footing_tool/first_peak.hpp"
#include "acst_footing_tool/runner.hpp"

namespace acst::mpm {
namespace fs = std::filesystem;
using nlohmann::json;
using nlohmann::ordered_json;

namespace {

// The columns of acst_mpm's load record that the row needs, in record order.
struct LoadCurve {
  std::vector<double> S_over_B, V, H, M, q;
};

LoadCurve read_load_record(const std::string& path) {
  LoadCurve c;
  if (!fs::exists(path)) return c;
  const common::CsvTable t = common::parse_csv_table(common::read_input_file(path));
  c.S_over_B = t.values("S_over_B"), c.V = t.values("V_kN_per_m"), c.H = t.values("H_kN_per_m");
  c.M = t.values("M_kNm_per_m"), c.q = t.values("q_kPa");
  return c;
}

// q at S/B = x by linear interpolation between the record's rows; null past its ends.
json q_at(const LoadCurve& c, double x) {
  for (std::size_t i = 1; i < c.S_over_B.size(); ++i) {
    const double a = c.S_over_B[i - 1], b = c.S_over_B[i];
    if (x < a || x > b || !(b > a)) continue;
    const double t = (x - a) / (b - a);
    return c.q[i - 1] + t * (c.q[i] - c.q[i - 1]);
  }
  if (!c.S_over_B.empty() && c.S_over_B.back() == x) return c.q.back();
  return nullptr;
}

constexpr const char* load_at_prefix = "q_at_S_over_B_";

std::string load_at_column(double s) {
  return load_at_prefix + common::fields::shown(s) + "_kPa";
}

// The columns of case_row and run_case besides the variables, and the prefixes of those whose
// names are made: the side measures of acst_mpm's summary (sheared_area_left_at_peak_m2, ...)
// and q at the gathered settlements. A column added to the row is added here.
constexpr const char* table_columns[] = {
    "case", "group", "status", "material", "relative_density_pct", "void_ratio", "bedding_angle_deg",
    "inclination_deg", "B_m", "soil_width_m", "half_domain", "cell_m", "particles_per_cell", "q_ult_kPa",
    "S_ult_over_B", "H_at_peak_kN_per_m", "M_at_peak_kNm_per_m", "q_first_peak_kPa", "S_first_peak_over_B",
    "final_S_over_B", "peak_reached", "quasi_static", "max_kinetic_ratio", "steps", "particles", "wall_s", "threads",
    "load_file", "resumed", "message"};
constexpr const char* table_column_prefixes[] = {load_at_prefix, "sheared_area_", "heave_"};

// The row's columns from acst_mpm's summary.json of the case: the side measures
// ("sides": {"at_peak": {"heave_left_m": ...}, ...} as heave_left_at_peak_m, ...) and a few
// figures of the run. A kept case's summary may have been edited or damaged: one of another
// shape is refused naming the file and the field (it ended in the library's own error, such as
// basic_string::substr, naming nothing).
void add_summary_columns(ordered_json& row, const std::string& summary_file) {
  namespace f = common::fields;
  const json summary = f::read_json_file(summary_file, "the run's summary");
  try {
    f::object(summary, "");
    if (summary.contains("sides") && !summary["sides"].is_null()) {  // null: a scene without a footing
      const json& sides = f::object(summary["sides"], "/sides");
      for (const char* when : {"at_peak", "at_end"}) {
        if (!sides.contains(when)) continue;
        const std::string at = std::string("/sides/") + when;
        for (const auto& item : f::object(sides[when], at).items()) {
          const std::string& key = item.key();
          const std::size_t unit = key.rfind('_');  // "_m2", "_m"
          if (unit == std::string::npos || unit == 0)
            f::fail(at + "/" + key, "expected a measure named with its unit (heave_left_m, sheared_area_left_m2)");
          row[key.substr(0, unit) + "_" + when + key.substr(unit)] = item.value();
        }
        // How one-sided the mechanism is: |A_left - A_right| / (A_left + A_right) of the soil
        // sheared past 5 % (0 for a symmetric one, 1 for one side only).
        const std::string l = std::string("sheared_area_left_") + when + "_m2", r = std::string("sheared_area_right_") + when + "_m2";
        if (row.contains(l) && row.contains(r) && row[l].is_number() && row[r].is_number()) {
          const double a = row[l].get<double>(), b = row[r].get<double>();
          row[std::string("sheared_area_asymmetry_") + when] = a + b > 0.0 ? ordered_json(std::fabs(a - b) / (a + b)) : ordered_json();
        }
      }
    }
  } catch (const common::InputError& e) {
    throw common::InputError("the run's summary '" + summary_file + "': " + e.what());
  }
  for (const char* k : {"quasi_static", "max_kinetic_ratio", "steps", "particles", "wall_s", "threads"})
    if (summary.contains(k)) row[k] = summary[k];
}

}  // namespace

bool is_table_column(const std::string& name) {
  for (const char* c : table_columns)
    if (name == c) return true;
  for (const char* prefix : table_column_prefixes)
    if (name.rfind(prefix, 0) == 0) return true;
  return false;
}

std::string case_folder(const std::string& sweep_dir, const std::string& name) {
  return (fs::path(sweep_dir) / sweep_cases_folder / name).string();
}

std::string case_partial_folder(const std::string& sweep_dir, const std::string& name) {
  return (fs::path(sweep_dir) / sweep_cases_folder / ("." + name + ".partial")).string();
}

json case_fingerprint(const SweepCase& c) {
  json materials = json::object();
  for (const MaterialSpec& m : c.scene.materials) materials[m.name] = json::parse(m.json_text);
  json fingerprint = {{"scene", json::parse(c.scene.text)}, {"materials", materials}};
#ifdef ACST_SWEEP_MARCH_NATIVE
  fingerprint["build"] = {{"march_native", true}};  // absent in the default build, whose records predate it
#endif
  return fingerprint;
}

ordered_json case_row(const SweepCase& c, const std::string& dir, CaseStatus status, const std::string& message,
                      const std::vector<double>& load_at_S_over_B) {
  const Scene& s = c.scene;
  std::string groups;
  for (const std::string& g : c.groups) groups += (groups.empty() ? "" : " ") + g;
  ordered_json row = {{"case", c.name}, {"group", groups}, {"status", name_of(status)}};
  for (const auto& item : c.varied.items()) row[item.key()] = item.value();
  const BodySpec& body = s.bodies.front();
  for (const MaterialSpec& m : s.materials)
    if (m.name == body.material) row["material"] = m.source == "inline" ? m.name : fs::path(m.source).stem().string();
  if (body.relative_density)
    row["relative_density_pct"] = 100.0 * *body.relative_density;
  else if (body.void_ratio)
    row["void_ratio"] = *body.void_ratio;
  row["bedding_angle_deg"] = body.bedding_angle_deg;
  if (s.footing) {
    const FootingSpec& ft = *s.footing;
    row["inclination_deg"] = ft.inclination_deg;
    row["B_m"] = ft.width;
    row["soil_width_m"] = ft.symmetric_half ? 2.0 * (body.x_max - ft.centre_x) : body.x_max - body.x_min;
    row["half_domain"] = ft.symmetric_half;
  }
  row["cell_m"] = s.cell_size;
  row["particles_per_cell"] = body.particles_per_cell;

  const std::string record = (fs::path(dir) / "load_settlement.csv").string();
  const std::string failed = (fs::path(dir) / "load_settlement.failed.csv").string();
  const std::string load_file = fs::exists(record) ? record : failed;
  LoadCurve curve = read_load_record(load_file);
  const double end_S_over_B = curve.S_over_B.empty() ? 0.0 : curve.S_over_B.back();
  // A failed run's last moments (an ejected particle, a material failure) throw the contact load
  // about by several times: the rows within failure_approach of its end do not count.
  if (status == CaseStatus::failed) {
    std::size_t keep = 0;
    while (keep < curve.S_over_B.size() && curve.S_over_B[keep] <= end_S_over_B - failure_approach_S_over_B) ++keep;
    for (auto* v : {&curve.S_over_B, &curve.V, &curve.H, &curve.M, &curve.q}) v->resize(keep);
  }
  const auto peak = std::max_element(curve.V.begin(), curve.V.end());
  if (peak != curve.V.end()) {
    const std::size_t k = static_cast<std::size_t>(peak - curve.V.begin());
    row["q_ult_kPa"] = curve.q[k];
    row["S_ult_over_B"] = curve.S_over_B[k];
    row["H_at_peak_kN_per_m"] = curve.H[k];
    row["M_at_peak_kNm_per_m"] = curve.M[k];
    if (const auto f = first_peak(curve.S_over_B, curve.V)) {
      row["q_first_peak_kPa"] = curve.q[*f];
      row["S_first_peak_over_B"] = curve.S_over_B[*f];
    } else {
      row["q_first_peak_kPa"] = nullptr;  // the load rose to the end of the record
      row["S_first_peak_over_B"] = nullptr;
    }
    for (double x : load_at_S_over_B) row[load_at_column(x)] = q_at(curve, x);
    row["final_S_over_B"] = end_S_over_B;
    // acst_mpm's rule (runner.cpp): the load has fallen 2 % below its largest value. A run that
    // failed after that has a peak that stands (docs/sweeps.md, "Findings").
    row["peak_reached"] = curve.V.back() < 0.98 * *peak;
  }
  const std::string summary_file = (fs::path(dir) / "summary.json").string();
  if (status == CaseStatus::done && fs::exists(summary_file)) add_summary_columns(row, summary_file);
  row["load_file"] = fs::exists(load_file) ? fs::path(load_file).filename().string() : "";
  row["message"] = message;
  return row;
}

namespace {

// Whether the partial folder holds an interrupted run of this very case to resume: its checkpoint
// and the fingerprint beside it, equal to the case's. A fingerprint file that cannot be read is
// no such run; `note` then says why the folder is not resumed.
bool resumable(const std::string& checkpoint, const std::string& fingerprint_path, const json& fingerprint,
               std::string& note) {
  if (!fs::exists(checkpoint) || !fs::exists(fingerprint_path)) return false;
  try {
    return common::fields::read_json_file(fingerprint_path, "the interrupted run's fingerprint") == fingerprint;
  } catch (const common::InputError& e) {
    note = std::string(e.what()) + ": its checkpoint was discarded and the case ran afresh";
    return false;
  }
}

// A fresh partial folder with the case's fingerprint beside it (acst_mpm starts a new run only
// in a folder of its own files, so the fingerprint is not inside).
void start_partial(const std::string& partial, const std::string& fingerprint_path, const json& fingerprint) {
  fs::remove_all(partial);
  fs::create_directories(partial);
  common::write_file_atomically(fingerprint_path, fingerprint.dump() + "\n");
}

}  // namespace

ordered_json run_case(const SweepCase& c, const CaseRunOptions& options, const std::vector<double>& load_at_S_over_B,
                      const std::string& rerun_note) {
  const std::string partial = case_partial_folder(options.sweep_dir, c.name);
  const std::string checkpoint = (fs::path(partial) / "checkpoint.bin").string();
  const std::string fingerprint_path = partial + ".json";
  const json fingerprint = case_fingerprint(c);
  RunOptions run;
  run.output_dir = partial;
  run.quiet = true;
  run.plot = options.plot;
  run.stop_at = options.stop_at;
  // An interrupted run of this very case goes on; anything else there is an earlier case's.
  std::string note;
  if (resumable(checkpoint, fingerprint_path, fingerprint, note)) {
    run.resume_from = checkpoint;
    fs::create_directories(partial);
  } else {
    start_partial(partial, fingerprint_path, fingerprint);
  }

  Scene scene = c.scene;
  if (options.threads > 0) scene.solver.threads = options.threads;
  CaseStatus status = CaseStatus::done;
  std::string message;
  RunSummary summary;
  try {
    try {
      summary = run_scene(scene, run);
    } catch (const CheckpointError& e) {
      // Refused before the run wrote anything: the checkpoint is only a shortcut.
      note = std::string(e.what()) + ": discarded, the case ran afresh";
      run.resume_from.clear();
      start_partial(partial, fingerprint_path, fingerprint);
      summary = run_scene(scene, run);
    }
  } catch (const std::exception& e) {
    status = CaseStatus::failed;
    message = e.what();
  }
  if (summary.interrupted)  // its checkpoint and fingerprint stay in place for the next run
    return case_row(c, "", CaseStatus::pending,
                    "stopped by the budget after " + std::to_string(summary.steps) +
                        " steps; the next run resumes it from its checkpoint",
                    load_at_S_over_B);
  if (!rerun_note.empty()) message = rerun_note + (message.empty() ? "" : "; " + message);
  // The run's message names files by where they were written; they are read where they end up.
  const std::string published = case_folder(options.sweep_dir, c.name);
  for (std::size_t at = message.find(partial); at != std::string::npos; at = message.find(partial, at + published.size()))
    message.replace(at, partial.size(), published);
  if (!note.empty()) message += (message.empty() ? "" : "; ") + note;
  ordered_json row = case_row(c, partial, status, message, load_at_S_over_B);
  row["resumed"] = !run.resume_from.empty();
  fs::remove(checkpoint);  // a finished case is never resumed; its checkpoint is the largest file
  const ordered_json record = {{"fingerprint", fingerprint}, {"row", row}};
  common::write_file_atomically((fs::path(partial) / sweep_case_record).string(), record.dump(2) + "\n");
  // Where an earlier folder of the case (a failed run, retried) could not be removed after the
  // exchange, it stays as the hidden partial folder, which the case's next run starts afresh.
  (void)common::publish_folder(partial, published);
  fs::remove(fingerprint_path);
  return row;
}

}  // namespace acst::mpm
