// The vibrating bar: a confined elastic column (fixed base, smooth sides, no gravity) released
// in its first mode v_y = v0 sin(pi y / 2L). Period T = 4 L / c with c = sqrt(M / rho), M the
// constrained modulus. FLIP keeps the energy, PIC dissipates it, XPIC(4) lies between. One
// stress update per step (first or last) instead of two halves keeps the period and the energy.
#include <gtest/gtest.h>

#include <cmath>

#include "mpm_scenes.hpp"

namespace mpm_vibrating_bar_test {

using namespace acst::mpm;

namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double L = 4.0, rho = 1000.0, E = 1e4, nu = 0.25;

struct BarRun {
  double period = 0.0, energy_ratio = 0.0;
};

double strain_energy(const Simulation& s) {  // J/m: sum V/2 sigma : eps, kPa -> Pa
  double u = 0;
  for (std::size_t p = 0; p < s.particles().n; ++p) {
    const double* sg = &s.particles().stress[6 * p];
    const double* e = &s.particles().strain[3 * p];
    u += 0.5 * s.particles().volume(p) * 1000.0 * (sg[0] * e[0] + sg[1] * e[1] + 2 * sg[3] * e[2]);
  }
  return u;
}

BarRun vibrate(const std::string& solver, double periods) {
  Simulation s = mpm_test::build(mpm_test::elastic_block(0.4, L, 0.1, E, nu, rho, R"("stop": {"steps": 1})", solver));
  for (std::size_t p = 0; p < s.particles().n; ++p) s.particles().vy[p] = 0.01 * std::sin(pi * s.particles().y[p] / (2 * L));
  const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) * 1000.0;
  const double T = 4 * L / std::sqrt(M / rho);
  const double e0 = s.kinetic_energy();
  auto momentum = [&] {
    double m = 0;
    for (std::size_t p = 0; p < s.particles().n; ++p) m += s.particles().mass[p] * s.particles().vy[p];
    return m;
  };
  // Zero crossings of the vertical momentum (~ cos(2 pi t / T)) are half a period apart.
  std::vector<double> crossings;
  double last = momentum(), last_t = 0.0;
  while (s.time() < periods * T) {
    s.step();
    const double m = momentum();
    if ((m > 0) != (last > 0)) crossings.push_back(last_t + (s.time() - last_t) * last / (last - m));
    last = m, last_t = s.time();
  }
  BarRun r;
  if (crossings.size() >= 3) r.period = crossings[2] - crossings[0];
  r.energy_ratio = (s.kinetic_energy() + strain_energy(s)) / e0;
  r.period /= T;
  return r;
}

}  // namespace

TEST(VibratingBar, FlipPeriodAndEnergyMatchTheClosedForm) {
  const BarRun flip = vibrate(R"({"particle_update": "FLIP", "grid_damping": 0})", 2.25);
  EXPECT_NEAR(flip.period, 1.0, 0.02) << "period / (4 L / c)";
  EXPECT_NEAR(flip.energy_ratio, 1.0, 0.02) << "FLIP keeps the energy";
}

TEST(VibratingBar, PicDissipatesAndXpicSitsBetween) {
  const std::string base = R"(, "grid_damping": 0})";
  const BarRun pic = vibrate(R"({"particle_update": "PIC")" + base, 2.25);
  const BarRun xpic = vibrate(R"({"particle_update": "XPIC", "xpic_order": 4, "xpic_every": 1)" + base, 2.25);
  const BarRun flip = vibrate(R"({"particle_update": "FLIP")" + base, 2.25);
  EXPECT_LT(pic.energy_ratio, 0.9) << "PIC loses energy";
  EXPECT_GT(xpic.energy_ratio, pic.energy_ratio);
  EXPECT_LT(xpic.energy_ratio, flip.energy_ratio + 1e-3);
  EXPECT_NEAR(pic.period, 1.0, 0.05);
}

TEST(VibratingBar, GridDampingRemovesEnergyAtTheExpectedRate) {
  // Grid damping alpha decays the velocity like exp(-alpha t), hence the energy about
  // exp(-alpha t) on average over a period (kinetic half of the time).
  const double alpha = 0.5;
  const BarRun d = vibrate(R"({"particle_update": "FLIP", "grid_damping": 0.5})", 2.0);
  const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) * 1000.0;
  const double t = 2.0 * 4 * L / std::sqrt(M / rho);
  EXPECT_NEAR(d.energy_ratio, std::exp(-alpha * t), 0.02);
}

TEST(VibratingBar, OneStressUpdatePerStepKeepsPeriodAndEnergy) {
  for (const char* when : {"first", "last"}) {
    SCOPED_TRACE(when);
    const BarRun r = vibrate(std::string(R"({"particle_update": "FLIP", "grid_damping": 0, "stress_update": ")") + when + "\"}", 2.25);
    EXPECT_NEAR(r.period, 1.0, 0.02) << "period / (4 L / c)";
    EXPECT_NEAR(r.energy_ratio, 1.0, 0.03);
  }
}

}  // namespace mpm_vibrating_bar_test
