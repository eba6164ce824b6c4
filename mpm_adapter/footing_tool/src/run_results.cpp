#include "acst_footing_tool/run_results.hpp"

#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>

#include "acst_common/files.hpp"
#include "acst_footing_tool/fields.hpp"
#include "acst_footing_tool/first_peak.hpp"
#include "acst_footing_tool/load_record.hpp"
#include "acst_footing_tool/output.hpp"

namespace acst::mpm {
namespace {

using json = nlohmann::ordered_json;

void contour_pair(const RunContext& run, const std::string& tag, const std::string& when, const Snapshot& s) {
  const Scene& scene = run.scene;
  const std::string& dir = run.options.output_dir;
  for (const std::string& w :
       {write_contour_figure(dir, "shear_strain_" + tag, scene.name + ": shear strain at " + when,
                             "max shear strain (engineering)", scene.cell_size, s.x, s.y, s.shear_strain),
        write_contour_figure(dir, "displacement_" + tag, scene.name + ": displacement at " + when, "|u| [m]",
                             scene.cell_size, s.x, s.y, s.displacement)})
    if (!w.empty()) std::fprintf(stderr, "warning: %s\n", w.c_str());
}

// The soil left and right of the footing at the peak and at the end (fields.hpp, SideMeasures).
json sides_json(const RunContext& run) {
  if (!run.scene.footing) return nullptr;
  const Particles& P = run.sim.particles();
  std::vector<double> gamma_now(P.n);
  for (std::size_t i = 0; i < P.n; ++i) gamma_now[i] = max_shear_strain(&P.strain[3 * i]);
  const auto side = [&](const SideMeasures& m) {
    return json{{"sheared_area_left_m2", m.sheared_area_left},
                {"sheared_area_right_m2", m.sheared_area_right},
                {"heave_left_m", m.heave_left},
                {"heave_right_m", m.heave_right}};
  };
  const double c = run.scene.footing->centre_x;
  const bool mirror = run.scene.footing->symmetric_half;
  const Snapshot& peak = run.state.peak;
  return {{"sheared_above_gamma", sheared_area_gamma},
          {"at_peak", side(side_measures(P, peak.y, peak.shear_strain, c, mirror))},
          {"at_end", side(side_measures(P, P.y, gamma_now, c, mirror))}};
}

std::string footing_contact_name(const Scene& scene) {
  if (!scene.footing) return "none";
  return scene.footing->contact == FootingContact::penalty ? "penalty" : "node_rows";
}

double max_penetration(const RunState& st) {
  double deepest = 0.0;
  for (const LoadRecord& r : st.history) deepest = std::max(deepest, r.penetration_m);
  return deepest;
}

}  // namespace

void write_tracks(const RunContext& run) {
  const auto& tracks = run.scene.output.particle_histories;
  for (std::size_t k = 0; k < tracks.size(); ++k)
    common::write_file_atomically(run.path("particle_" + tracks[k].name + ".csv"),
                                  track_csv_text(run.scene, static_cast<int>(k), run.state.tracks));
}

void write_results(const RunContext& run, RunSummary& sum) {
  const Scene& scene = run.scene;
  const RunState& st = run.state;
  common::write_file_atomically(run.path("load_settlement.csv"), load_csv_text(scene, run.rows()));
  std::remove(run.path("load_settlement.partial.csv").c_str());
  write_tracks(run);
  if (!st.history.empty()) sum.residual_V = st.history.back().V_kN_per_m;
  sum.Q_ult = st.peak.V_kN_per_m;
  sum.S_ult_over_B = st.peak.S_over_B;
  sum.S_ult = st.peak.S_over_B * run.B;
  sum.peak_reached = scene.footing && sum.residual_V < 0.98 * sum.Q_ult;
  std::vector<double> S, V;
  for (const LoadRecord& r : st.history) S.push_back(r.S_over_B), V.push_back(r.V_kN_per_m);
  const std::optional<std::size_t> first = first_peak(S, V);
  // The whole record is judged (it is checkpointed, so a resumed run judges its whole run too).
  double max_ratio = 0.0;
  const LoadRecord* worst = nullptr;
  for (const LoadRecord& r : st.history)
    if (kinetic_ratio(scene, r) > max_ratio) max_ratio = kinetic_ratio(scene, r), worst = &r;
  if (max_ratio > scene.quasi_static.kinetic_ratio_limit) sum.warnings.push_back(quasi_static_message(scene, *worst));
  if (run.options.plot && scene.footing) {
    const std::string w = write_load_figure(scene, run.options.output_dir, "load_settlement.csv");
    if (!w.empty()) sum.warnings.push_back(w);
    if (!scene.output.particle_histories.empty()) {
      const std::string h = write_history_figure(scene, run.options.output_dir);
      if (!h.empty()) sum.warnings.push_back(h);
    }
    if (scene.output.contours_at_peak && !st.peak.x.empty())
      contour_pair(run, "peak", "Q_ult (S/B = " + std::to_string(st.peak.S_over_B).substr(0, 5) + ")", st.peak);
  }
  const double B = run.B;
  json phases = json::object();  // where the steps' time went (docs/mpm.md, "Outputs")
  for (std::size_t k = 0; k < step_phase_count; ++k) phases[step_phase_names[k]] = run.sim.phase_seconds()[k];
  const json summary = {{"scene", scene.name},
                        {"particles", run.sim.particles().n},
                        {"steps", run.sim.step_count()},
                        {"time_s", run.sim.time()},
                        {"wall_s", sum.wall_s},
                        {"threads", thread_count(scene.solver.threads)},
                        {"particle_steps_per_s", sum.particle_steps_per_s},
                        {"step_phase_seconds", phases},
                        {"Q_ult_kN_per_m", sum.Q_ult},
                        {"q_ult_kPa", sum.Q_ult / B},
                        {"S_ult_m", sum.S_ult},
                        {"S_ult_over_B", sum.S_ult_over_B},
                        {"peak_reached", sum.peak_reached},
                        {"q_first_peak_kPa", first ? json(V[*first] / B) : nullptr},
                        {"S_first_peak_over_B", first ? json(S[*first]) : nullptr},
                        {"residual_V_kN_per_m", sum.residual_V},
                        {"final_S_over_B", run.S_over_B()},
                        {"footing_contact", footing_contact_name(scene)},
                        {"symmetric_half", scene.footing && scene.footing->symmetric_half},
                        {"max_kinetic_ratio", max_ratio},
                        {"kinetic_ratio_limit", scene.quasi_static.kinetic_ratio_limit},
                        {"quasi_static", max_ratio <= scene.quasi_static.kinetic_ratio_limit},
                        {"max_penetration_m", max_penetration(st)},
                        {"sides", sides_json(run)}};
  common::write_file_atomically(run.path("summary.json"), summary.dump(2) + "\n");
}

}  // namespace acst::mpm
