#include "acst_mpm/footing.hpp"

#include <algorithm>
#include <cmath>

#include "acst_common/parallel_for.hpp"

namespace acst::mpm {

Footing::Footing(const FootingSpec& spec, double base_y) : spec_(spec), base_y_(base_y), active_(true) {
  constexpr double pi = 3.14159265358979323846;
  inclination_ = spec.inclination_deg * pi / 180.0;
  unload_at_ = spec.unload_at_S_over_B * spec.width;
  ramp_time_ = spec.ramp_S_over_B > 0.0 ? 2.0 * spec.ramp_S_over_B * spec.width / spec.speed : 0.0;  // S(t_r) = v t_r / 2
}

double Footing::vx() const {
  const double v = ramp_ * spec_.speed * std::sin(inclination_);
  return motion_.unloading ? -v : v;
}

double Footing::vy() const {
  const double v = -ramp_ * spec_.speed * std::cos(inclination_);
  return motion_.unloading ? -v : v;
}

// Half a cosine: the speed and the acceleration start and end without a jump, so the ramp sends
// no wave into the soil at either end; it covers S = speed t_r / 2.
void Footing::at_time(double t) {
  constexpr double pi = 3.14159265358979323846;
  ramp_ = ramp_time_ > 0.0 && t < ramp_time_ ? 0.5 * (1.0 - std::cos(pi * t / ramp_time_)) : 1.0;
}

void Footing::constrain(const Grid& grid, NodeConstraints& c) const {
  if (!active_ || spec_.contact != FootingContact::node_rows) return;
  const double h = grid.h, tol = 1e-9 * h;
  const double vfx = vx(), vfy = vy();
  const double centre = centre_x(), half = 0.5 * spec_.width;
  const int j_base = grid.row_near(base_y());
  for (int j = std::max(0, j_base); j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const double x = grid.node_x(i);
      if (std::fabs(x - centre) > half + tol) continue;
      const std::size_t k = static_cast<std::size_t>(j) * grid.nx + i;
      c.set_y[k] = reaction_footing;
      c.vy[k] = vfy;
      if (spec_.interface != FootingInterface::smooth) {
        c.set_x[k] = reaction_footing;
        c.vx[k] = vfx;
      }
    }
}

void Footing::touch(const Particles& P, const Grid& grid, double particle_half_width, double c_max, double dt,
                    int threads) {
  const double lh = particle_half_width * grid.h;
  friction_.resize(P.n, 0.0);
  touching_of_thread_.resize(static_cast<std::size_t>(threads));
  for (TouchList& l : touching_of_thread_) l.touches.clear();
  common::parallel_for(threads, P.n, [&](int t, std::size_t p) {
    const double* F = &P.F[4 * p];
    // The domain's stretch along the axes: the shear terms would tilt its faces, which the flat
    // footing keeps flat, and under the footing's edge would inflate the box into false overlap.
    // Shrunk, never grown past l h, the undeformed domain the B2GIMP weights use (and the longest
    // contact the time step allows for): a box grown with the stretch reaches under the base where
    // the particle does not, and the push then grows the overlap faster than it moves the particle
    // (docs/footing-study.md, "The contact's stiffness and box").
    const double sx = std::min(std::fabs(F[0]), 1.0), sy = std::min(std::fabs(F[3]), 1.0);
    const double half_x = lh * sx, half_y = lh * sy;
    if (!overlaps(P.x[p], P.y[p], half_x, half_y)) {  // apart: the spring relaxes (written only if held)
      if (friction_[p] != 0.0) friction_[p] = 0.0;
      return;
    }
    const ContactParticle cp{P.x[p], P.y[p], P.vx[p], P.vy[p], half_x, half_y, P.mass[p], stiffness(P, p, grid.h, c_max)};
    touching_of_thread_[t].touches.push_back({p, contact(cp, friction_[p], dt)});
  });
  // Summed in particle order: the same result for any thread count.
  touching_.clear();
  for (const TouchList& l : touching_of_thread_) touching_.insert(touching_.end(), l.touches.begin(), l.touches.end());
  std::sort(touching_.begin(), touching_.end(), [](const Touch& a, const Touch& b) { return a.particle < b.particle; });
  Reaction sum;
  ContactSummary c;
  const double xc = centre_x(), yc = base_y();
  for (const Touch& touch : touching_) {
    const ContactForce& t = touch.force;
    sum.fx += t.fx;
    sum.fy += t.fy;
    c.moment += (t.at_x - xc) * t.fy - (t.at_y - yc) * t.fx;
    c.max_penetration = std::max(c.max_penetration, t.penetration);
    ++c.touching;
  }
  if (spec_.symmetric_half) {  // the mirror half pushes alike: V doubles, H and M cancel
    sum.fy *= 2.0;
    sum.fx = 0.0;
    c.moment = 0.0;
  }
  reaction_ = sum;
  summary_ = c;
}

// The load stays within a cell of the footing's width (a particle's own weights would spread it
// over B + 4 l h + 3 h), and the nodes it moves accelerate together, so a node with little mass
// (above the soil surface) never takes a stiff share of a contact spring.
void Footing::spread(const Grid& grid, const double* mass, double* fx, double* fy) const {
  for (const Touch& touch : touching_) {
    const ContactForce& t = touch.force;
    const Grid::Place px = grid.place_x(t.at_x), py = grid.place_y(t.at_y);
    const int i = px.cell, j = py.cell;
    const double a = px.fraction, b = py.fraction;
    const std::size_t k0 = static_cast<std::size_t>(j) * grid.nx + i;
    const std::size_t k[4] = {k0, k0 + 1, k0 + grid.nx, k0 + grid.nx + 1};
    double wt[4] = {(1 - a) * (1 - b) * mass[k[0]], a * (1 - b) * mass[k[1]], (1 - a) * b * mass[k[2]],
                    a * b * mass[k[3]]};
    const double sum = wt[0] + wt[1] + wt[2] + wt[3];
    if (!(sum > 0.0)) continue;  // cannot happen where a particle touches: its nodes carry its mass
    for (int c = 0; c < 4; ++c) {
      fx[k[c]] += wt[c] / sum * t.fx;
      fy[k[c]] += wt[c] / sum * t.fy;
    }
  }
}

// k_n w / m = factor c^2 w / h * rho0 V0 / (V m), with V > 0 the current volume.
Footing::SpringRate Footing::spring_rate(double h, double particle_half_width, double c_max, double margin) const {
  const double width = 2.0 * particle_half_width * h;  // the longest contact of one particle
  return {*this, h, width, c_max, spec_.penalty_factor * c_max * c_max * width / h * margin};
}

void Footing::advance(const Reaction& on_soil, double dt) {
  if (!active_) return;
  const double vfx = vx(), vfy = vy();
  motion_.work += (on_soil.fx * vfx + on_soil.fy * vfy) * dt;
  motion_.dx += vfx * dt;
  motion_.dy += vfy * dt;
  if (unload_at_ > 0.0 && !motion_.unloading && settlement() >= unload_at_) motion_.unloading = true;
}

}  // namespace acst::mpm
