// Columns under gravity: the elastic K0 column at rest (nu = 2/7 gives K0 = nu/(1 - nu) = 0.4)
// and the confined column loaded by its own weight from zero stress (sigma_yy = -rho g depth).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "mpm_scenes.hpp"

using namespace acst::mpm;

namespace {
constexpr double rho = 2000.0, g = 9.8, depth = 5.0, width = 1.0;
}

TEST(MpmColumn, ElasticK0ColumnStaysAtRestAndTheBaseCarriesItsWeight) {
  Simulation sim = mpm_test::build(mpm_test::elastic_block(
      width, depth, 0.25, 2e4, 2.0 / 7.0, rho,
      R"("gravity": 9.8, "initial_stress": {"type": "geostatic", "K0": 0.4}, "stop": {"steps": 1})",
      R"({"grid_damping": 0})"));
  const std::vector<double> s0 = sim.particles().stress;
  const double c = std::sqrt(2e7 * (1 - 2.0 / 7) / ((1 + 2.0 / 7) * (1 - 4.0 / 7)) / rho);
  while (sim.time() < 4.0 * depth / c * 2) sim.step();  // two periods of the column's first mode
  double vmax = 0.0, sdev = 0.0;
  for (std::size_t p = 0; p < sim.particles().n; ++p) {
    vmax = std::max(vmax, std::hypot(sim.particles().vx[p], sim.particles().vy[p]));
    for (int k : {0, 1, 2}) sdev = std::max(sdev, std::fabs(sim.particles().stress[6 * p + k] - s0[6 * p + k]));
  }
  // Scale: a column released from zero stress would swing at g * depth / c; at rest is far below.
  EXPECT_LT(vmax, 0.01 * g * depth / c) << "max particle speed " << vmax << " m/s";
  EXPECT_LT(sdev, 0.01 * rho * g * depth / 1000.0) << "max stress change " << sdev << " kPa";
  const double weight = rho * g * depth * width;  // N/m
  EXPECT_NEAR(sim.reaction(reaction_base).fy, weight, 0.005 * weight);
  EXPECT_NEAR(sim.reaction(reaction_base).fx, 0.0, 1e-6 * weight);
}

TEST(MpmColumn, SelfWeightFromZeroStressSettlesToRhoGDepth) {
  for (const char* when : {"average", "first", "last"}) {  // docs/mpm.md, "One step"
    SCOPED_TRACE(when);
    Simulation sim = mpm_test::build(mpm_test::elastic_block(
        width, depth, 0.25, 2e4, 0.3, rho, R"("gravity": 9.8, "stop": {"steps": 1})",
        std::string(R"({"grid_damping": 20, "particle_update": "FLIP", "stress_update": ")") + when + "\"}"));
    while (sim.time() < 3.0) sim.step();
    double worst = 0.0;
    for (std::size_t p = 0; p < sim.particles().n; ++p) {
      const double d = depth - sim.particles().y[p];
      const double expected = -rho * g * d / 1000.0;  // kPa
      worst = std::max(worst, std::fabs(sim.particles().stress[6 * p + 1] - expected));
    }
    EXPECT_LT(worst, 0.02 * rho * g * depth / 1000.0) << "largest error in sigma_yy, kPa";
    EXPECT_NEAR(sim.reaction(reaction_base).fy, rho * g * depth * width, 0.01 * rho * g * depth * width);
  }
}

TEST(MpmColumn, SurchargeReadoutEqualsTheAppliedLoad) {
  // A weightless layer under a 10 kPa surcharge: the base reaction is q * width once at rest.
  Simulation sim = mpm_test::build(mpm_test::elastic_block(
      width, depth, 0.25, 2e4, 0.3, rho, R"("surcharge_kPa": 10, "stop": {"steps": 1})",
      R"({"grid_damping": 20, "particle_update": "FLIP"})"));
  while (sim.time() < 3.0) sim.step();
  EXPECT_NEAR(sim.reaction(reaction_base).fy, 10e3 * width, 0.005 * 10e3 * width);
}
