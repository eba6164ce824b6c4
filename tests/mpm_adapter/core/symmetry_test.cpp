// The symmetric half domain (footing/symmetric_half, docs/mpm.md "Symmetric half domain"): a
// vertical footing on a scene that is its own mirror image gives the same load curve from the
// soil right of its centre line as from the whole, on Tresca soil and on anisotropic ACST sand
// (bedding planes vertical); scenes that are not symmetric are refused with the JSON path.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "mpm_scenes.hpp"

using namespace acst::mpm;

namespace {

struct Curve {
  std::vector<double> q;  // kPa, averaged over periods of 20 steps
  double H_max = 0, M_max = 0, kinetic = 0;
  std::size_t particles = 0;
};

Curve run(const std::string& scene, double B, double to_S) {
  Simulation s = mpm_test::build(scene);
  Curve c;
  c.particles = s.particles().n;
  double sum = 0;
  int n = 0;
  while (s.footing().settlement() < to_S) {
    s.step();
    const Reaction& r = s.reaction(reaction_footing);
    sum += -r.fy / 1000.0 / B;
    c.H_max = std::max(c.H_max, std::fabs(r.fx));
    c.M_max = std::max(c.M_max, std::fabs(s.contact().moment));
    if (++n == 20) c.q.push_back(sum / n), sum = 0, n = 0;
  }
  c.kinetic = s.kinetic_energy();
  return c;
}

// Largest |q_half - q_full| / q_full over the periods past the first tenth of the peak load.
double worst_difference(const Curve& full, const Curve& half) {
  const double peak = *std::max_element(full.q.begin(), full.q.end());
  double worst = 0;
  for (std::size_t i = 0; i < std::min(full.q.size(), half.q.size()); ++i)
    if (full.q[i] > 0.1 * peak) worst = std::max(worst, std::fabs(half.q[i] - full.q[i]) / full.q[i]);
  return worst;
}

std::string tresca(bool half) {
  return std::string(R"({"name": "prandtl", "grid": {"cell_size": 0.1},
    "materials": {"clay": {"model": "von_mises", "parameters": {"E": 10000, "nu": 0.3, "undrained_shear_strength": 10}}},
    "bodies": [{"material": "clay", "x_range": [0, 4], "y_range": [0, 2], "density": 1000}],
    "footing": {"width": 1.0, "centre_x": 2.0, "speed": 0.02, "symmetric_half": )") +
         (half ? "true" : "false") + R"(}, "solver": {"grid_damping": 2}, "stop": {"S_over_B": 0.1}})";
}

std::string sand(bool half, double bedding_deg = 90, double centre_x = 1.2, double inclination_deg = 0) {
  return R"({"name": "small", "grid": {"cell_size": 0.15},
    "materials": {"sand": ")" + std::string(ACST_SOURCE_DIR) + R"(/data/parameters/toyoura_acst_calibrated.json"},
    "bodies": [{"material": "sand", "x_range": [0, 2.4], "y_range": [0, 1.2], "density": 1600,
                "relative_density_pct": 85.6, "bedding_angle_deg": )" + std::to_string(bedding_deg) + R"(}],
    "gravity": 9.8, "initial_stress": {"type": "geostatic", "K0": 0.4}, "surcharge_kPa": 1,
    "footing": {"width": 0.3, "centre_x": )" + std::to_string(centre_x) + R"(, "speed": 0.1, "inclination_deg": )" +
         std::to_string(inclination_deg) + R"(, "symmetric_half": )" + (half ? "true" : "false") + R"(},
    "stop": {"S_over_B": 0.2}})";
}

}  // namespace

// Stated tolerance (the issue's): 1 % of q along the curve. The mirror-image walls make the half
// domain's grid fields those of the whole, so the curves agree far closer than that.
TEST(SymmetricHalf, GivesTheWholeDomainsLoadOnTrescaSoil) {
  const Curve full = run(tresca(false), 1.0, 0.1), half = run(tresca(true), 1.0, 0.1);
  EXPECT_EQ(half.particles, full.particles / 2);
  ASSERT_GE(half.q.size(), full.q.size() - 1);
  EXPECT_LT(worst_difference(full, half), 0.01);
  EXPECT_EQ(half.H_max, 0.0) << "the mirror half cancels H";
  EXPECT_EQ(half.M_max, 0.0) << "and the moment";
  EXPECT_NEAR(half.kinetic, full.kinetic, 0.01 * full.kinetic) << "kinetic energy of the whole";
}

TEST(SymmetricHalf, GivesTheWholeDomainsLoadOnAnisotropicSand) {
  const Curve full = run(sand(false), 0.3, 0.06), half = run(sand(true), 0.3, 0.06);
  EXPECT_EQ(half.particles, full.particles / 2);
  ASSERT_GT(full.q.size(), 10u);
  EXPECT_LT(worst_difference(full, half), 0.01);
}

TEST(SymmetricHalf, RefusesScenesThatAreNotTheirOwnMirrorImage) {
  const auto message = mpm_test::parse_error;
  const std::string oblique = message(sand(true, 30));
  EXPECT_NE(oblique.find("/footing/symmetric_half"), std::string::npos) << oblique;
  EXPECT_NE(oblique.find("bedding"), std::string::npos) << oblique;
  const std::string off_centre = message(sand(true, 0, 0.9));
  EXPECT_NE(off_centre.find("/footing/symmetric_half"), std::string::npos) << off_centre;
  EXPECT_NE(off_centre.find("not symmetric"), std::string::npos) << off_centre;
  const std::string off_grid = message(sand(true, 0, 1.2 + 0.05));
  EXPECT_NE(off_grid.find("grid line"), std::string::npos) << off_grid;
  const std::string inclined = message(sand(true, 0, 1.2, 10));
  EXPECT_NE(inclined.find("/footing/symmetric_half"), std::string::npos) << inclined;
  EXPECT_NE(inclined.find("vertical"), std::string::npos) << inclined;
  EXPECT_EQ(message(sand(true, 90)), "accepted");
  EXPECT_EQ(message(sand(true, -90)), "accepted");
}
