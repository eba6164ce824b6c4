#include "acst_mpm/micropolar_rotations.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "acst_mpm/units.hpp"

namespace acst::mpm {

MicropolarRotations::MicropolarRotations(const Micropolar& settings, std::size_t particles) : settings_(settings) {
  for (auto* v : {&state_.spin, &state_.skew_stress, &state_.couple_x, &state_.couple_y}) v->assign(particles, 0.0);
}

void MicropolarRotations::prepare(std::size_t nodes) {
  if (!active()) return;
  for (auto* v : {&inertia_, &spin_, &couple_, &skew_fx_, &skew_fy_}) v->assign(nodes, 0.0);
}

// k of particle p, kPa: modulus_ratio times the material's constrained modulus rho c^2 at the
// particle's current density (the wave speed as last refreshed).
double MicropolarRotations::modulus(const Particles& P, std::size_t p) const {
  const double rho = P.density[p] * P.volume_initial[p] / P.volume(p);
  return settings_.modulus_ratio * rho * P.wave_speed[p] * P.wave_speed[p] / kilo;
}

// The grains' rotational inertia per unit mass, m^2: l^2, scaled up to a finest cell's h^2 where
// l is shorter (as mass scaling does for the motion: a quasi-static run's answer does not depend
// on it, and the time step then need not resolve the grains' spin against the continuum).
double MicropolarRotations::inertia_per_mass(const Grid& grid) const {
  const double l = settings_.length, h = std::min(grid.h, grid.hy);
  return std::max(l * l, h * h);
}

// The nodes' rotational inertia and angular momentum (the step's map adds them).
MicropolarRotations::MapTerms MicropolarRotations::map_terms(const Particles& P, const Grid& grid) {
  return {inertia_.data(), spin_.data(), P.mass.data(), state_.spin.data(), inertia_per_mass(grid)};
}

// The walls' mirror images folded in (a rotation changes sign in a mirror); the micro-rotation rate.
void MicropolarRotations::finish_map(const Walls& walls, const Grid& grid) {
  if (!active()) return;
  walls.fold(inertia_.data(), FieldKind::scalar, grid);
  walls.fold(spin_.data(), FieldKind::rotation, grid);
  for (std::size_t i = 0; i < grid.nodes(); ++i) spin_[i] = inertia_[i] > 0.0 ? spin_[i] / inertia_[i] : 0.0;
}

// The couple stress, a vector in the plane, turns with the continuum (its Jaumann rate).
long long MicropolarRotations::update_stress(const Particles& P, const StepScratch& w, const double* vx,
                                             const double* vy, double dt) {
  if (!active()) return -1;
  const double l2 = settings_.length * settings_.length;
  std::vector<long long> failed(w.scatter.threads(), -1);
  parallel_for(w.scatter.threads(), P.n, [&](int t, std::size_t p) {
    double W = 0.0, rate = 0.0, gx = 0.0, gy = 0.0;
    w.stencil(p, [&](std::size_t i, double S, double dx, double dy) {
      W += 0.5 * (vy[i] * dx - vx[i] * dy);
      rate += S * spin_[i];
      gx += spin_[i] * dx;
      gy += spin_[i] * dy;
    });
    const double k = modulus(P, p), turn = W * dt;
    const double mx = state_.couple_x[p], my = state_.couple_y[p];
    state_.skew_stress[p] += k * (W - rate) * dt;
    state_.couple_x[p] = mx + k * l2 * gx * dt - turn * my;
    state_.couple_y[p] = my + k * l2 * gy * dt + turn * mx;
    if (!std::isfinite(state_.skew_stress[p] + state_.couple_x[p] + state_.couple_y[p]) && failed[t] < 0)
      failed[t] = static_cast<long long>(p);
  });
  for (long long p : failed)
    if (p >= 0) return p;
  return -1;
}

MicropolarRotations::ForceTerms MicropolarRotations::force_terms() {
  return {{skew_fx_.data(), skew_fy_.data(), couple_.data()},
          state_.skew_stress.data(),
          state_.couple_x.data(),
          state_.couple_y.data()};
}

void MicropolarRotations::finish_forces(StepScratch& w, const Walls& walls, const Grid& grid, double grid_damping,
                                        double dt) {
  if (!active()) return;
  walls.fold(couple_.data(), FieldKind::rotation, grid);
  for (std::size_t i = 0; i < grid.nodes(); ++i) {
    w.fx[i] += skew_fx_[i];
    w.fy[i] += skew_fy_[i];
    const double rate = inertia_[i] > 0.0 ? couple_[i] / inertia_[i] - grid_damping * spin_[i] : 0.0;
    couple_[i] = spin_[i] + rate * dt;
  }
}

// The stiffest rotation's frequency, omega^2 = ratio c^2 (1 + 4 l^2/h^2) / j (the relative
// rotation, and the couple stress's shortest wave, over the grains' inertia j): dt <= 2 cfl / omega.
double MicropolarRotations::stable_time_step(double c_max, const Grid& grid, double cfl) const {
  constexpr double unbounded = std::numeric_limits<double>::infinity();
  if (!active()) return unbounded;
  const double l = settings_.length, h = std::min(grid.h, grid.hy);
  const double rotation = c_max * std::sqrt(settings_.modulus_ratio * (1.0 + 4.0 * l * l / (h * h)) / inertia_per_mass(grid));
  return rotation > 0.0 ? 2.0 * cfl / rotation : unbounded;
}

}  // namespace acst::mpm
