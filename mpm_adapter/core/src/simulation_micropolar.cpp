// Micropolar (Cosserat) rotations of the soil (docs/mpm.md, "Micropolar rotations"): each particle
// carries a micro-rotation theta besides its motion. The stored energy per unit volume is
//   1/2 k (theta_M - theta)^2 + 1/2 k l^2 |grad theta|^2,
// theta_M the continuum's rotation (its rate the spin W = (dv_y/dx - dv_x/dy) / 2), k the
// particle's modulus (modulus_ratio rho c^2), l the length. Its stresses are the skew stress
// A = k (theta_M - theta) and the couple stress m = k l^2 grad theta; their power
// A (W - theta') + m . grad theta' gives, on the grid, the nodal forces and couples below. The
// grains' rotational inertia is micro_inertia() per unit mass. The material's (symmetric) stress
// is untouched: a field without rotation gradients and with theta = theta_M has A = 0 and m = 0,
// and the classical continuum's numbers.
#include <algorithm>
#include <cmath>

#include "acst_mpm/simulation.hpp"

namespace acst::mpm {

// k of particle p, kPa: modulus_ratio times the material's constrained modulus rho c^2 at the
// particle's current density (the wave speed as last refreshed).
double Simulation::micropolar_modulus(std::size_t p) const {
  const Particles& P = particles_;
  const double rho = P.density[p] * P.volume_initial[p] / P.volume(p);
  return settings_.micropolar.modulus_ratio * rho * P.wave_speed[p] * P.wave_speed[p] / kilo;
}

// The grains' rotational inertia per unit mass, m^2: l^2, scaled up to a finest cell's h^2 where
// l is shorter (as mass scaling does for the motion: a quasi-static run's answer does not depend
// on it, and the time step then need not resolve the grains' spin against the continuum).
double Simulation::micro_inertia() const {
  const double l = settings_.micropolar.length, h = std::min(grid_.h, grid_.hy);
  return std::max(l * l, h * h);
}

// The nodes' rotational inertia and micro-rotation rate (angular momentum over inertia), the walls'
// mirror images folded in (a rotation changes sign in a mirror).
void Simulation::map_micro_rotation() {
  if (!settings_.micropolar.active()) return;
  StepScratch& w = work_;
  const Particles& P = particles_;
  const double j = micro_inertia();
  w.map_to_grid<2>({w.inertia.data(), w.spin.data()}, P.n, [&](std::size_t p) {
    const double J = P.mass[p] * j;
    return std::array<double, 2>{J, J * P.micro_spin[p]};
  });
  fold(w.inertia.data(), FieldKind::scalar);
  fold(w.spin.data(), FieldKind::rotation);
  for (std::size_t i = 0; i < grid_.nodes(); ++i) w.spin[i] = w.inertia[i] > 0.0 ? w.spin[i] / w.inertia[i] : 0.0;
}

// The skew and couple stresses over dt from the nodal velocities and micro-rotation rates; the
// couple stress, a vector in the plane, turns with the continuum (its Jaumann rate).
void Simulation::update_micropolar_stress(const double* vx, const double* vy, double dt) {
  if (!settings_.micropolar.active()) return;
  StepScratch& w = work_;
  Particles& P = particles_;
  const double l2 = settings_.micropolar.length * settings_.micropolar.length;
  std::vector<long long> failed(w.scatter.threads(), -1);
  parallel_for(w.scatter.threads(), P.n, [&](int t, std::size_t p) {
    double W = 0.0, rate = 0.0, gx = 0.0, gy = 0.0;
    w.stencil(p, [&](std::size_t i, double S, double dx, double dy) {
      W += 0.5 * (vy[i] * dx - vx[i] * dy);
      rate += S * w.spin[i];
      gx += w.spin[i] * dx;
      gy += w.spin[i] * dy;
    });
    const double k = micropolar_modulus(p), turn = W * dt;
    const double mx = P.couple_x[p], my = P.couple_y[p];
    P.skew_stress[p] += k * (W - rate) * dt;
    P.couple_x[p] = mx + k * l2 * gx * dt - turn * my;
    P.couple_y[p] = my + k * l2 * gy * dt + turn * mx;
    if (!std::isfinite(P.skew_stress[p] + P.couple_x[p] + P.couple_y[p]) && failed[t] < 0)
      failed[t] = static_cast<long long>(p);
  });
  for (long long p : failed)
    if (p >= 0) fail(static_cast<std::size_t>(p), "the micropolar stresses are not finite");
}

// The skew stress's nodal forces, added to the internal force (before the walls fold it), and the
// nodal couples of both stresses, folded; over the inertia they become the spin's rate, damped as
// the velocities are.
void Simulation::micropolar_force() {
  if (!settings_.micropolar.active()) return;
  StepScratch& w = work_;
  const Particles& P = particles_;
  double* out[3] = {w.skew_fx.data(), w.skew_fy.data(), w.couple.data()};
  w.scatter.run(3, out, P.n, [&](std::size_t p, double* const* f) {
    const double V = kilo * P.volume(p);
    const double A = V * P.skew_stress[p], mx = V * P.couple_x[p], my = V * P.couple_y[p];
    w.stencil(p, [&](std::size_t i, double S, double dx, double dy) {
      f[0][i] += 0.5 * A * dy;
      f[1][i] -= 0.5 * A * dx;
      f[2][i] += A * S - (mx * dx + my * dy);
    });
  });
  fold(w.couple.data(), FieldKind::rotation);
  const double ag = settings_.grid_damping;
  for (std::size_t i = 0; i < grid_.nodes(); ++i) {
    w.fx[i] += w.skew_fx[i];
    w.fy[i] += w.skew_fy[i];
    w.couple[i] = w.inertia[i] > 0.0 ? w.couple[i] / w.inertia[i] - ag * w.spin[i] : 0.0;
  }
}

// The particles' micro-rotation rates from the grid's (PIC: the grains' spin holds no history of
// its own, and PIC damps the rotations' grid-scale noise), with the particle damping.
void Simulation::update_micro_spin() {
  if (!settings_.micropolar.active()) return;
  StepScratch& w = work_;
  Particles& P = particles_;
  const double dt = clock_.dt, ap = settings_.particle_damping;
  parallel_for(w.scatter.threads(), P.n, [&](int, std::size_t p) {
    double s = 0.0;
    w.stencil(p, [&](std::size_t i, double S, double, double) { s += S * (w.spin[i] + w.couple[i] * dt); });
    P.micro_spin[p] = s - ap * P.micro_spin[p] * dt;
  });
}

}  // namespace acst::mpm
