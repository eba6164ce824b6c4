#include "acst_mpm/footing.hpp"

#include <algorithm>
#include <cmath>

namespace acst::mpm {

double Footing::vx() const {
  const double v = ramp_ * spec_.speed * std::sin(spec_.inclination);
  return motion_.unloading ? -v : v;
}

double Footing::vy() const {
  const double v = -ramp_ * spec_.speed * std::cos(spec_.inclination);
  return motion_.unloading ? -v : v;
}

// Half a cosine: the speed and the acceleration start and end without a jump, so the ramp sends
// no wave into the soil at either end; it covers S = speed t_r / 2.
void Footing::at_time(double t) {
  constexpr double pi = 3.14159265358979323846;
  ramp_ = spec_.ramp_time > 0.0 && t < spec_.ramp_time ? 0.5 * (1.0 - std::cos(pi * t / spec_.ramp_time)) : 1.0;
}

void Footing::constrain(const Grid& grid, NodeConstraints& c) const {
  if (!active_ || spec_.contact != FootingContact::node_rows) return;
  const double h = grid.h, tol = 1e-9 * h;
  const double vfx = vx(), vfy = vy();
  const double centre = centre_x(), half = 0.5 * spec_.width;
  const long long j_base = std::llround((base_y() - grid.y0) / grid.hy);
  for (int j = static_cast<int>(std::max(0LL, j_base)); j < grid.ny; ++j)
    for (int i = 0; i < grid.nx; ++i) {
      const double x = grid.x0 + i * h;
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

void Footing::advance(const Reaction& on_soil, double dt) {
  if (!active_) return;
  const double vfx = vx(), vfy = vy();
  motion_.work += (on_soil.fx * vfx + on_soil.fy * vfy) * dt;
  motion_.dx += vfx * dt;
  motion_.dy += vfy * dt;
  if (spec_.unload_at > 0.0 && !motion_.unloading && settlement() >= spec_.unload_at) motion_.unloading = true;
}

}  // namespace acst::mpm
