#pragma once
// The footing tests' shared measures: loads averaged over periods of steps (as the runner records
// them), their mean over a settlement window, and Prandtl's scene on weightless Tresca soil with
// the load it carries (mpm_footing_test, mpm_follow_footing_test).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "mpm_scenes.hpp"

namespace mpm_test {

struct Period {  // loads averaged over one period of steps, as the runner records them
  double S = 0, V = 0, H = 0, M = 0, penetration = 0;
};

// Steps until `done`, averaging V, H (kN/m) and M (kN m/m) over periods of `every` steps.
template <class Done>
std::vector<Period> run(acst::mpm::Simulation& s, int every, Done done) {
  std::vector<Period> out;
  Period acc;
  int n = 0;
  while (!done(s)) {
    s.step();
    const acst::mpm::Reaction& r = s.reaction(acst::mpm::reaction_footing);
    acc.V += -r.fy / 1000.0;
    acc.H += r.fx / 1000.0;
    acc.M += s.contact().moment / 1000.0;
    acc.penetration = std::max(acc.penetration, s.contact().max_penetration);
    if (++n == every) {
      acc.S = s.footing().settlement();
      acc.V /= n, acc.H /= n, acc.M /= n;
      out.push_back(acc);
      acc = Period{};
      n = 0;
    }
  }
  return out;
}

inline double mean_q(const std::vector<Period>& rows, double B, double from_S, double to_S) {
  double sum = 0;
  int n = 0;
  for (const Period& r : rows)
    if (r.S >= from_S && r.S <= to_S) sum += r.V / B, ++n;
  return n > 0 ? sum / n : NAN;
}

// B = 1 m, soil 4 B x 2 B (Prandtl's mechanism reaches 1.5 B from the centre and 0.7 B deep),
// s_u = 10 kPa, E = 1000 s_u unless given, no weight; the grid's rows fixed or following the
// footing; XPIC(4) every 20 steps unless given.
inline std::string tresca(double h, const std::string& interface, double speed, const std::string& contact = "penalty",
                          bool follow_footing = false, double E = 10000, int xpic_every = 20) {
  return R"({"name": "prandtl", "grid": {"cell_size": )" + std::to_string(h) +
         (follow_footing ? R"(, "follow_footing": true)" : "") + R"(},
    "materials": {"clay": {"model": "von_mises", "parameters": {"E": )" + std::to_string(E) + R"(, "nu": 0.3, "undrained_shear_strength": 10}}},
    "bodies": [{"material": "clay", "x_range": [0, 4], "y_range": [0, 2], "density": 1000}],
    "footing": {"width": 1.0, "centre_x": 2.0, "speed": )" + std::to_string(speed) + R"(, "interface": ")" + interface + R"(", "contact": ")" + contact + R"("},
    "solver": {"grid_damping": 2, "particle_update": "XPIC", "xpic_order": 4, "xpic_every": )" + std::to_string(xpic_every) + R"(},
    "stop": {"S_over_B": 0.1}})";
}

// q = V/B averaged over S/B 0.02-0.05 on the Tresca scene: past failure (E = 1000 s_u fails by
// S/B 0.015), before the footing is embedded deeper than half a cell at h = B/10. At 0.02 m/s the
// velocity filtering of XPIC every 20 steps resists like a viscosity: with the rows following it
// adds 4 % of Prandtl's load against FLIP alone (docs/footing-study.md, "What Prandtl's load measures").
inline double prandtl_q(double h, const std::string& interface, bool follow_footing = false) {
  acst::mpm::Simulation s = build(tresca(h, interface, 0.02, "penalty", follow_footing));
  return mean_q(run(s, 20, [](const acst::mpm::Simulation& x) { return x.footing().settlement() >= 0.05; }), 1.0, 0.02,
                0.05);
}

// q = V/B where the scene is what Prandtl's solution describes (docs/footing-study.md, "What Prandtl's load
// measures"): a stiff soil (E = 10^4 s_u) that collapses by S/B 0.003, before the footing has
// changed the geometry, and the particle update's filter every 500 steps instead of 20, from where
// on the footing's speed no longer changes the load. Every step's load, averaged over S/B 0.005-0.01;
// the grid's rows follow the footing.
inline double prandtl_q_rigid_plastic(double h, const std::string& interface) {
  acst::mpm::Simulation s = build(tresca(h, interface, 0.02, "penalty", true, 1e5, 500));
  return mean_q(run(s, 1, [](const acst::mpm::Simulation& x) { return x.footing().settlement() >= 0.01; }), 1.0, 0.005,
                0.01);
}

// Weightless Drucker-Prager soil matched to Mohr-Coulomb in plane strain (phi = psi = 30 deg,
// c = 10 kPa, E = 10^4 c) under a rough footing (B = 1 m) at the Kimura scenes' 0.045 m/s, on the
// right half of the Kimura footing's 14 B x 7 B domain with its graded grid (3 B window):
// Prandtl's mechanism for phi = 30 reaches 4.8 B from the centre and 1.9 B deep. q = V/B averaged
// over S/B 0.03-0.06, past collapse (by S/B 0.02), against c N_c = 301.4 kPa
// (studies/footing_frictional.py runs the Kimura footing itself, B = 0.9 m).
inline double frictional_prandtl_q(double h) {
  const std::string scene = R"({"name": "frictional_prandtl", "grid": {"cell_size": )" + std::to_string(h) + R"(, "graded": {}},
    "materials": {"sand": {"model": "drucker_prager", "parameters": {"E": 100000, "nu": 0.3, "friction_angle_deg": 30, "cohesion": 10}}},
    "bodies": [{"material": "sand", "x_range": [0, 14], "y_range": [0, 7], "density": 1600}],
    "footing": {"width": 1.0, "centre_x": 7.0, "speed": 0.045, "interface": "rough", "symmetric_half": true},
    "solver": {"grid_damping": 0.5, "particle_update": "XPIC", "xpic_order": 4, "xpic_every": 20},
    "stop": {"S_over_B": 0.06}})";
  acst::mpm::Simulation s = build(scene);
  return mean_q(run(s, 20, [](const acst::mpm::Simulation& x) { return x.footing().settlement() >= 0.06; }), 1.0, 0.03,
                0.06);
}

// The largest change between the mean q of adjacent windows of 0.005 B ending between S/B 0.03 and
// 0.07 (B = 1 m), where with fixed rows at h = B/10 the first node row joins a node-row footing.
inline double largest_window_change(const std::vector<Period>& rows) {
  double worst = 0;
  for (double S = 0.03; S <= 0.07 + 1e-9; S += 0.001) {
    const double before = mean_q(rows, 1.0, S - 0.005, S), after = mean_q(rows, 1.0, S, S + 0.005);
    worst = std::max(worst, std::fabs(after - before) / before);
  }
  return worst;
}

}  // namespace mpm_test
