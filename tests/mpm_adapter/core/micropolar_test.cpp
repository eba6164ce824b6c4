// Micropolar rotations of the soil (docs/mpm.md, "Micropolar rotations"): a length of 0 is the
// classical continuum to the bit; a homogeneously compressed block, which neither rotates nor
// bends, gives the classical result; a uniform micro-rotation in a body at rest swings at the
// closed-form frequency of the grains' rotation against the continuum, sqrt(k / (rho l^2)).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "mpm_scenes.hpp"

namespace mpm_micropolar_test {

using namespace acst::mpm;

// A dense-sand footing run 300 steps with "length_m": 0 against the same scene without the key.
TEST(Micropolar, ALengthOfZeroIsTheClassicalContinuum) {
  const auto scene = mpm_test::small_sand_footing;
  mpm_test::expect_identical_runs(scene(""), scene(R"(, "micropolar": {"length_m": 0})"), 300);
  // With a length the footing's edges bend the soil: the same scene's particles carry couples.
  EXPECT_GT(mpm_test::spread_after(scene(R"(, "micropolar": {"length_m": 0.1})"), 300,
                                   [](const Simulation& s) -> const auto& { return s.micropolar().state().couple_x; }),
            1e-6);
}

// A row of dense sand between smooth walls under a smooth platen over its whole width, compressed
// in 600 steps: nothing rotates, so the micropolar run is the classical one within 1e-12 and its
// skew and couple stresses stay zero.
TEST(Micropolar, AHomogeneouslyCompressedBlockGivesTheClassicalResult) {
  const auto scene = mpm_test::compressed_sand_row;
  Simulation classical = mpm_test::build(scene("")),
             micropolar = mpm_test::build(scene(R"(, "micropolar": {"length_m": 0.2})"));
  for (int k = 0; k < 600; ++k) classical.step(), micropolar.step();
  const Particles &a = classical.particles(), &b = micropolar.particles();
  const MicropolarRotations::ParticleState& rotations = micropolar.micropolar().state();
  ASSERT_EQ(a.n, 12u);
  const mpm_test::ParticleGap gap = mpm_test::particle_gap(a, b);
  EXPECT_LT(gap.stress, 1e-12);
  EXPECT_LT(gap.state, 1e-12);
  for (std::size_t p = 0; p < b.n; ++p) {
    EXPECT_LT(std::fabs(rotations.skew_stress[p]), 1e-12 * gap.scale) << "particle " << p;
    EXPECT_LT(std::hypot(rotations.couple_x[p], rotations.couple_y[p]), 1e-12 * gap.scale) << "particle " << p;
  }
  EXPECT_LT(a.F[3], 0.98) << "the block was compressed";
}

// An elastic block at rest whose grains all spin at Omega0: inside it the micro-rotation theta
// obeys rho l^2 theta'' = -k theta (no gradient, no continuum rotation), so the spin is
// Omega0 cos(omega t) with omega = sqrt(k / (rho l^2)) = c sqrt(ratio) / l. The walls' and the free
// surface's disturbance travels in at c and does not reach the centre in the time measured. The
// zero crossings of the centre's spin give the period within 1 % (the explicit step's own error
// at this time step is (omega dt)^2 / 24, under 0.1 %), and the amplitude stays within 1 % (the
// damping is off; PIC of a uniform field is exact).
TEST(Micropolar, AUniformMicroRotationSwingsAtItsClosedFormFrequency) {
  const double l = 0.05, ratio = 0.5, E = 1e5, nu = 0.25, rho = 2000.0, omega0 = 2.0;
  Simulation sim = mpm_test::build(mpm_test::elastic_block(
      2.0, 2.0, 0.05, E, nu, rho,
      R"("micropolar": {"length_m": 0.05, "modulus_ratio": 0.5}, "walls": {"base": "fixed", "sides": "smooth"}, "stop": {"steps": 1})",
      R"({"cfl": 0.1, "grid_damping": 0})"));
  const Particles& P = sim.particles();
  std::vector<double>& spin = sim.micropolar().state().spin;
  for (double& s : spin) s = omega0;
  std::size_t centre = 0;
  for (std::size_t p = 0; p < P.n; ++p)
    if (std::hypot(P.x[p] - 1.0, P.y[p] - 1.0) < std::hypot(P.x[centre] - 1.0, P.y[centre] - 1.0)) centre = p;
  const double M = E * (1.0 - nu) / ((1.0 + nu) * (1.0 - 2.0 * nu)) * 1000.0;  // constrained modulus, Pa
  const double omega = std::sqrt(ratio * M / rho) / l;
  std::vector<double> crossings;
  double before = spin[centre], t_before = 0.0, largest = 0.0;
  while (crossings.size() < 3) {
    sim.step();
    const double now = spin[centre], t = sim.time();
    if (crossings.size() >= 1) largest = std::max(largest, std::fabs(now));
    if ((before > 0.0) != (now > 0.0)) crossings.push_back(t_before + (t - t_before) * before / (before - now));
    before = now, t_before = t;
    ASSERT_LT(t, 10.0 / omega * 2.0 * M_PI) << "no swing";
  }
  const double pi = std::acos(-1.0);
  // The step updates the stress from the spin and then the spin from the stress (a leapfrog), so
  // the recorded spin leads the continuous one by half a step: the first crossing comes within a
  // step of a quarter period, the period itself within 1 %.
  EXPECT_NEAR(crossings[0], 0.5 * pi / omega, sim.clock().dt);
  EXPECT_NEAR(crossings[2] - crossings[0], 2.0 * pi / omega, 0.01 * 2.0 * pi / omega);
  EXPECT_NEAR(largest, omega0, 0.01 * omega0);
  // The continuum itself stayed nearly at rest there (the explicit step's precursor of the
  // boundaries' disturbance only): its speed is a thousandth of the grains' turning speed.
  EXPECT_LT(std::hypot(P.vx[centre], P.vy[centre]), 1e-3 * omega0 * l);
}

TEST(Micropolar, BadSettingsNameTheirJsonPath) {
  const auto scene = [](const std::string& micropolar) {
    return mpm_test::elastic_block(1.0, 1.0, 0.1, 1e4, 0.3, 1800.0,
                                   R"("micropolar": )" + micropolar + R"(, "stop": {"steps": 1})");
  };
  EXPECT_EQ(mpm_test::parse_error(scene(R"({"length_m": 0.05})")), "accepted");
  // Without a length, the grains' diameter at the acceleration level (0.17 mm for Toyoura sand).
  EXPECT_NEAR(acst::mpm::parse_scene(scene(R"({"acceleration_level": 30})")).solver.micropolar.length, 0.0051, 1e-12);
  EXPECT_NEAR(acst::mpm::parse_scene(scene(R"({"d50_mm": 0.2})")).solver.micropolar.length, 0.0002, 1e-12);
  EXPECT_NE(mpm_test::parse_error(scene(R"({"length_m": 0.1, "d50_mm": 0.2})")).find("/micropolar/d50_mm"), std::string::npos);
  EXPECT_NE(mpm_test::parse_error(scene(R"({"acceleration_level": 0.5})")).find("/micropolar/acceleration_level"),
            std::string::npos);
  EXPECT_NE(mpm_test::parse_error(scene(R"({"length_m": -0.1})")).find("/micropolar/length_m"), std::string::npos);
  EXPECT_NE(mpm_test::parse_error(scene(R"({"length_m": 0.1, "modulus_ratio": 0})")).find("/micropolar/modulus_ratio"),
            std::string::npos);
  EXPECT_NE(mpm_test::parse_error(scene(R"({"length_m": 0.1, "modulus_ratio": 1.5})")).find("/micropolar/modulus_ratio"),
            std::string::npos);
  EXPECT_NE(mpm_test::parse_error(scene(R"({"length_m": 0.1, "ratio": 0.5})")).find("/micropolar"), std::string::npos);
  EXPECT_NE(mpm_test::parse_error(scene(R"({"length_m": "0.1"})")).find("/micropolar/length_m"), std::string::npos);
}

}  // namespace mpm_micropolar_test
