#include "acst_footing_tool/load_record.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "acst_footing_tool/fields.hpp"

namespace acst::mpm {
namespace {

LoadRecord current(const RunContext& run, double V, double H, double M, double penetration) {
  const Simulation& sim = run.sim;
  LoadRecord r;
  r.step = sim.step_count();
  r.time = sim.time();
  r.settlement = sim.footing().settlement();
  r.S_over_B = run.S_over_B();
  r.V_kN_per_m = V;
  r.H_kN_per_m = H;
  r.M_kNm_per_m = M;
  r.penetration_m = penetration;
  r.q_kPa = V / run.B;
  r.kinetic_J_per_m = sim.kinetic_energy();
  r.footing_work_J_per_m = sim.footing().motion().work;
  return r;
}

void keep_peak(const RunContext& run, const LoadRecord& r, Snapshot& s) {
  s.S_over_B = r.S_over_B;
  s.V_kN_per_m = r.V_kN_per_m;
  const Particles& P = run.sim.particles();
  s.x = P.x;
  s.y = P.y;
  s.shear_strain.resize(P.n);
  s.displacement.resize(P.n);
  for (std::size_t i = 0; i < P.n; ++i) {
    s.shear_strain[i] = max_shear_strain(&P.strain[3 * i]);
    s.displacement[i] = std::hypot(P.x[i] - P.x_initial[i], P.y[i] - P.y_initial[i]);
  }
}

}  // namespace

void record_step(RunContext& run) {
  RunState& st = run.state;
  const Reaction& f = run.sim.reaction(reaction_footing);
  const double V = -f.fy / 1000.0, H = f.fx / 1000.0;  // N/m -> kN/m
  const double M = run.sim.contact().moment / 1000.0, depth = run.sim.contact().max_penetration;
  st.sum_V += V;
  st.sum_H += H;
  st.sum_M += M;
  st.max_penetration = std::max(st.max_penetration, depth);
  if (run.scene.output.every_step_csv) {
    st.every_step.push_back(current(run, V, H, M, depth));
    record_tracks(run);  // the histories follow the load record's rows: every step here
  }
  if (++st.period_steps == run.scene.solver.xpic_every) close_period(run);
}

void close_period(RunContext& run) {
  RunState& st = run.state;
  const Scene& scene = run.scene;
  const double n = static_cast<double>(st.period_steps);
  const LoadRecord r = current(run, st.sum_V / n, st.sum_H / n, st.sum_M / n, st.max_penetration);
  st.history.push_back(r);
  if (scene.quasi_static.stop_on_excess && kinetic_ratio(scene, r) > scene.quasi_static.kinetic_ratio_limit)
    throw SimulationError(quasi_static_message(scene, r) + " (quasi_static/on_excess 'stop')");
  st.sum_V = st.sum_H = st.sum_M = st.max_penetration = 0.0;
  st.period_steps = 0;
  if (!scene.output.every_step_csv) record_tracks(run);
  if (scene.footing && r.V_kN_per_m > st.peak.V_kN_per_m) keep_peak(run, r, st.peak);
}

void record_tracks(RunContext& run) {
  for (std::size_t k = 0; k < run.sim.particles().tracked.size(); ++k)
    run.state.tracks.push_back(track_record(run.sim, static_cast<int>(k), run.S_over_B()));
}

double kinetic_ratio(const Scene& scene, const LoadRecord& r) {
  if (!scene.footing || r.S_over_B < scene.quasi_static.check_from_S_over_B || r.footing_work_J_per_m <= 0.0) return 0.0;
  return r.kinetic_J_per_m / r.footing_work_J_per_m;
}

std::string quasi_static_message(const Scene& scene, const LoadRecord& r) {
  char text[320];
  std::snprintf(text, sizeof text,
                "not quasi-static: the kinetic energy is %.3g of the footing's work at S/B %.4f, above "
                "quasi_static/kinetic_ratio_limit %.3g; slow the footing or lower solver/mass_scaling",
                kinetic_ratio(scene, r), r.S_over_B, scene.quasi_static.kinetic_ratio_limit);
  return text;
}

}  // namespace acst::mpm
