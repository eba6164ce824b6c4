// The time step against its formula (docs/mpm.md, "One step" and "The footing"): dt = cfl min(h, hy) / max_p(c_p /
// sqrt(mass scaling) + |v_p|), and with the contact footing also dt <= 2 cfl / omega, omega^2 =
// max_p k_n,p (2 l h) / m_p. The step skips a particle's exact term where a bound shows it cannot
// set the maximum; the result must be the formula's number bit for bit, including where many
// particles lie within rounding of the largest.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "mpm_scenes.hpp"

using namespace acst::mpm;

namespace mpm_time_step_test {
namespace {

// The formula, particle by particle, as docs/mpm.md states it.
double formula(const Simulation& s, double half_width_cells) {
  const Particles& P = s.particles();
  const double scale = 1.0 / std::sqrt(s.settings().mass_scaling);
  const double c_max = *std::max_element(P.wave_speed.begin(), P.wave_speed.end());
  const double h = s.grid().h, width = 2.0 * half_width_cells * h;
  double fastest = 0.0, omega2 = 0.0;
  for (std::size_t p = 0; p < P.n; ++p) {
    fastest = std::max(fastest, P.wave_speed[p] * scale + std::hypot(P.vx[p], P.vy[p]));
    const double rho = P.density[p] * P.volume_initial[p] / P.volume(p);
    const double k = s.footing().spec().penalty_factor * rho * c_max * c_max / h;
    omega2 = std::max(omega2, k * width / P.mass[p]);
  }
  const double dt = s.settings().cfl * std::min(h, s.grid().hy) / fastest;
  return std::min(dt, 2.0 * s.settings().cfl / std::sqrt(omega2));
}

Simulation footing_block(const std::string& solver) {
  return mpm_test::build(mpm_test::elastic_block(
      2.0, 1.0, 0.1, 1e4, 0.3, 1800.0, R"("footing": {"width": 0.5, "centre_x": 1.0, "speed": 0.01}, "stop": {"steps": 1})",
      solver));
}

}  // namespace

TEST(TimeStep, IsTheFormulasNumberWhereManyParticlesTieWithinRounding) {
  // Trials in turn: (0) velocities near the wave speed, where hypot and |vx| + |vy| differ most;
  // (1) every particle compressed to 0.95 within rounding, so the contact's bound decides among
  // ties; (2) compressions spread over [0.9, 1], the contact's bound deciding; (3) the wave
  // speeds' bound deciding among ties. Compressed soil is denser, so its springs are stiffer
  // than the wave speed's bound (0 and 3 leave the volumes alone).
  std::mt19937 rng(11);
  for (const char* solver : {R"({})", R"({"mass_scaling": 16})"}) {
    Simulation s = footing_block(solver);
    Particles& P = s.particles();
    ASSERT_GT(P.n, 100u);
    for (int trial = 0; trial < 40; ++trial) {
      const int kind = trial % 4;
      std::uniform_real_distribution<double> ulp(-4e-16, 4e-16), v(-1.0, 1.0), squeeze(0.9, 1.0);
      const double v_scale = kind == 0 ? 100.0 : 1e-3;
      for (std::size_t p = 0; p < P.n; ++p) {
        P.wave_speed[p] = 200.0 * (1.0 + ulp(rng));
        P.vx[p] = v_scale * v(rng);
        P.vy[p] = v_scale * v(rng);
        const double fx = kind == 1 ? 0.95 * (1.0 + ulp(rng)) : kind == 2 ? squeeze(rng) : 1.0;
        const double fy = kind == 1 ? 0.95 * (1.0 + ulp(rng)) : kind == 2 ? squeeze(rng) : 1.0;
        P.F[4 * p] = fx;
        P.F[4 * p + 3] = fy;
      }
      const double expected = formula(s, 0.5);  // one particle per cell: l = 1/2
      EXPECT_EQ(s.stable_time_step(), expected) << solver << ", trial " << trial;
    }
  }
}

}  // namespace mpm_time_step_test
