#pragma once
// Small MPM scenes for the verification tests, built from JSON text like user scenes.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "acst_footing_tool/build_simulation.hpp"

namespace mpm_test {

// A rectangle of linear elastic soil (E kPa, nu) on a fixed base with smooth sides.
inline std::string elastic_block(double width, double depth, double h, double E, double nu, double density,
                                 const std::string& extra, const std::string& solver = "{}") {
  return R"({"name": "test", "grid": {"cell_size": )" + std::to_string(h) +
         R"(}, "materials": {"soil": {"model": "linear_elastic", "parameters": {"E": )" + std::to_string(E) +
         R"(, "nu": )" + std::to_string(nu) + R"(}}}, "bodies": [{"material": "soil", "x_range": [0, )" +
         std::to_string(width) + R"(], "y_range": [0, )" + std::to_string(depth) + R"(], "density": )" +
         std::to_string(density) + R"(}], "solver": )" + solver + (extra.empty() ? "" : ", " + extra) + "}";
}

// A scene on 0.1 m cells with the delivered ACST set as material "sand"; `rest` is the JSON
// members after "materials" (bodies, loads, footing, stop, and any extra).
inline std::string delivered_sand_scene(const std::string& rest) {
  const std::string sand = std::string(ACST_SOURCE_DIR) + "/data/parameters/toyoura_acst_calibrated.json";
  return R"({"name": "t", "grid": {"cell_size": 0.1}, "materials": {"sand": ")" + sand + R"("}, )" + rest + "}";
}

// A small dense-sand footing (2 x 1 m, a 0.4 m footing, weight and surcharge) for 300 steps,
// with `extra` members.
inline std::string small_sand_footing(const std::string& extra) {
  return delivered_sand_scene(R"("bodies": [{"material": "sand", "x_range": [0, 2], "y_range": [0, 1], "density": 1600,
         "relative_density_pct": 85, "bedding_angle_deg": 0}], "gravity": 9.8,
         "initial_stress": {"type": "geostatic", "K0": 0.4}, "surcharge_kPa": 1,
         "footing": {"width": 0.4, "centre_x": 1.0, "speed": 0.05}, "stop": {"steps": 300})" + extra);
}

// A row of dense sand (1.2 x 0.1 m, bedding 30 deg) between smooth walls on a smooth base under a
// smooth platen over its whole width, at 100 kPa, for 600 steps with XPIC every step: compressed
// homogeneously; `extra` members.
inline std::string compressed_sand_row(const std::string& extra) {
  return delivered_sand_scene(R"("bodies": [{"material": "sand", "x_range": [0, 1.2], "y_range": [0, 0.1], "density": 1600,
         "relative_density_pct": 85, "bedding_angle_deg": 30}], "gravity": 0,
         "initial_stress": {"type": "isotropic", "p_kPa": 100}, "walls": {"base": "smooth", "sides": "smooth"},
         "footing": {"width": 1.2, "centre_x": 0.6, "speed": 0.05, "interface": "smooth"},
         "solver": {"xpic_every": 1}, "stop": {"steps": 600})" + extra);
}

inline acst::mpm::Simulation build(const std::string& json) {
  return acst::mpm::build_simulation(acst::mpm::parse_scene(json));
}

// How far two runs' particles are apart: the largest stress difference over the largest stress
// (and that scale, kPa), the largest state-variable difference over max(1, |value|).
struct ParticleGap {
  double stress = 0.0, state = 0.0, scale = 0.0;
};
inline ParticleGap particle_gap(const acst::mpm::Particles& a, const acst::mpm::Particles& b) {
  ParticleGap g;
  for (double s : a.stress) g.scale = std::max(g.scale, std::fabs(s));
  for (std::size_t k = 0; k < a.stress.size(); ++k) g.stress = std::max(g.stress, std::fabs(a.stress[k] - b.stress[k]) / g.scale);
  for (std::size_t k = 0; k < a.statev.size(); ++k)
    g.state = std::max(g.state, std::fabs(a.statev[k] - b.statev[k]) / std::max(1.0, std::fabs(a.statev[k])));
  return g;
}

// The spread (largest minus smallest) of a particle field after `steps` steps of a scene.
// `field(sim)`: a per-particle array of the simulation.
template <class Field>
double spread_after(const std::string& scene, int steps, Field&& field) {
  acst::mpm::Simulation sim = build(scene);
  for (int k = 0; k < steps; ++k) sim.step();
  const std::vector<double>& v = field(sim);
  return *std::max_element(v.begin(), v.end()) - *std::min_element(v.begin(), v.end());
}

// Two scenes run `steps` steps give the same particles to the bit (stress, state, positions).
inline void expect_identical_runs(const std::string& a_scene, const std::string& b_scene, int steps) {
  acst::mpm::Simulation a = build(a_scene), b = build(b_scene);
  for (int k = 0; k < steps; ++k) a.step(), b.step();
  EXPECT_EQ(a.particles().stress, b.particles().stress);
  EXPECT_EQ(a.particles().statev, b.particles().statev);
  EXPECT_EQ(a.particles().x, b.particles().x);
  EXPECT_EQ(a.clock().time, b.clock().time);
}

// The reader's message for a bad scene, or "accepted".
inline std::string parse_error(const std::string& json) {
  try {
    acst::mpm::parse_scene(json);
  } catch (const acst::common::InputError& e) {
    return e.what();
  }
  return "accepted";
}

}  // namespace mpm_test
