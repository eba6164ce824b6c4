// XPIC(m) invariants: XPIC(1) is PIC, a uniform velocity field is a fixed point, and the
// k >= 2 terms keep the total momentum (no walls, no forces).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "mpm_scenes.hpp"

using namespace acst::mpm;

namespace {

// A free-floating, stress-free elastic block (no walls, no gravity) with random velocities.
Simulation floating_block(const std::string& solver) {
  Simulation sim = mpm_test::build(mpm_test::elastic_block(
      2.0, 1.0, 0.1, 1e4, 0.3, 2000.0, R"("walls": {"base": "none", "sides": "none"}, "stop": {"steps": 1})", solver));
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 0.01);
  for (std::size_t p = 0; p < sim.particles().n; ++p) sim.particles().vx[p] = n(rng), sim.particles().vy[p] = n(rng);
  return sim;
}

double momentum(const Simulation& s, const std::vector<double>& v) {
  double m = 0;
  for (std::size_t p = 0; p < s.particles().n; ++p) m += s.particles().mass[p] * v[p];
  return m;
}

}  // namespace

TEST(Xpic, OrderOneIsPic) {
  Simulation pic = floating_block(R"({"particle_update": "PIC", "grid_damping": 0})");
  Simulation x1 = floating_block(R"({"particle_update": "XPIC", "xpic_order": 1, "xpic_every": 1, "grid_damping": 0})");
  for (int k = 0; k < 5; ++k) pic.step(), x1.step();
  for (std::size_t p = 0; p < pic.particles().n; ++p) {
    ASSERT_EQ(pic.particles().vx[p], x1.particles().vx[p]);
    ASSERT_EQ(pic.particles().vy[p], x1.particles().vy[p]);
  }
}

TEST(Xpic, UniformVelocityIsAFixedPoint) {
  for (int m : {2, 4, 8}) {
    Simulation sim = floating_block(R"({"particle_update": "XPIC", "xpic_order": )" + std::to_string(m) +
                                    R"(, "xpic_every": 1, "grid_damping": 0})");
    for (std::size_t p = 0; p < sim.particles().n; ++p) sim.particles().vx[p] = 0.3, sim.particles().vy[p] = -0.2;
    sim.step();
    for (std::size_t p = 0; p < sim.particles().n; ++p) {
      ASSERT_NEAR(sim.particles().vx[p], 0.3, 1e-13) << "XPIC(" << m << ")";
      ASSERT_NEAR(sim.particles().vy[p], -0.2, 1e-13) << "XPIC(" << m << ")";
    }
  }
}

TEST(Xpic, KeepsTotalMomentumAndFiltersTheNoise) {
  for (const char* update : {"PIC", "XPIC"}) {
    Simulation sim = floating_block(std::string(R"({"particle_update": ")") + update +
                                    R"(", "xpic_order": 4, "xpic_every": 1, "grid_damping": 0})");
    const double px = momentum(sim, sim.particles().vx), py = momentum(sim, sim.particles().vy);
    double ke0 = sim.kinetic_energy();
    sim.step();
    // Stress-free body with tiny strains: forces are O(1e-6) of the momentum over one step.
    EXPECT_NEAR(momentum(sim, sim.particles().vx), px, 1e-9 * std::fabs(px) + 1e-9) << update;
    EXPECT_NEAR(momentum(sim, sim.particles().vy), py, 1e-9 * std::fabs(py) + 1e-9) << update;
    EXPECT_LT(sim.kinetic_energy(), 0.9 * ke0) << update << " removes particle-scale noise";
  }
}

TEST(Xpic, HigherOrderKeepsMoreOfASmoothField) {
  // A smooth (resolved) velocity field loses less kinetic energy under XPIC(4) than under PIC.
  auto ke_after = [](const std::string& solver) {
    Simulation s = floating_block(solver);
    for (std::size_t p = 0; p < s.particles().n; ++p) {
      s.particles().vx[p] = 0.01 * std::sin(3.14159265358979 * s.particles().x[p] / 2.0);
      s.particles().vy[p] = 0.0;
    }
    const double ke0 = s.kinetic_energy();
    s.step();
    return s.kinetic_energy() / ke0;
  };
  const double pic = ke_after(R"({"particle_update": "PIC", "grid_damping": 0})");
  const double xpic = ke_after(R"({"particle_update": "XPIC", "xpic_order": 4, "xpic_every": 1, "grid_damping": 0})");
  EXPECT_GT(xpic, pic);
  EXPECT_GT(xpic, 0.99);
}
