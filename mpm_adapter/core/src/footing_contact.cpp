// Penalty contact between the rigid footing and one particle's domain (docs/mpm.md, "The
// footing"): normal force from the overlap, friction on the base through a tangential spring.
#include <algorithm>
#include <cmath>

#include "acst_mpm/footing.hpp"

namespace acst::mpm {

ContactForce Footing::contact(const ContactParticle& p, double& friction, double dt) const {
  ContactForce out;
  const double half = 0.5 * spec_.width, left = centre_x() - half, right = centre_x() + half, base = base_y();
  const double x0 = p.x - p.half_x, x1 = p.x + p.half_x, y0 = p.y - p.half_y, y1 = p.y + p.half_y;
  if (!overlaps(p.x, p.y, p.half_x, p.half_y)) {  // apart: no force, the spring relaxes
    friction = 0.0;
    return out;
  }
  // The face that pushes: the base for a centre under the base; otherwise the face the domain
  // penetrates least, as a signed distance to the outline gives (where that choice changes, both
  // faces' penetrations are equal, so the overlap does not jump). Inside the outline this is the
  // base under the middle and a side near it (heaved soil a side let in goes back out, instead of
  // down with its height above the base counted as penetration); beside the footing it is the
  // side, except for a domain flattened at the corner, which the base overlaps less. Rules that
  // let the overlap jump threw particles off the grid (docs/footing-study.md, "Which face pushes").
  const double d_base = y1 - base, d_left = x1 - left, d_right = right - x0;
  const bool under = p.x >= left && p.x <= right;
  const bool base_face = (under && p.y < base) || d_base <= std::min(d_left, d_right);
  double nx = 0.0, ny = -1.0, depth = d_base, length = 0.0;
  if (base_face) {
    const double a = std::max(x0, left), b = std::min(x1, right);
    length = b - a;
    out.at_x = 0.5 * (a + b);
    out.at_y = base;
  } else {
    nx = d_left <= d_right ? -1.0 : 1.0;  // beside: the near side; inside: the nearer side
    ny = 0.0;
    depth = nx < 0.0 ? d_left : d_right;
    const double a = std::max(y0, base);
    length = y1 - a;
    out.at_x = nx < 0.0 ? left : right;
    out.at_y = 0.5 * (a + y1);
  }
  const double k = p.stiffness * length;  // N/m per m of penetration or stretch
  // The dashpot removes the contact's own vibration (a spring against a body driven at a set
  // speed chatters); it acts on the approach speed only, so a steady push carries no viscous load.
  // Half the critical damping: explicit in time, c dt / m = omega dt <= 1 stays stable where the
  // time step keeps omega dt <= 1 (Simulation::stable_time_step).
  const double rvx = p.vx - vx(), rvy = p.vy - vy();
  const double approach = -(rvx * nx + rvy * ny);  // > 0 while the particle moves into the footing
  const double fn = std::max(0.0, k * depth + std::sqrt(k * p.mass) * approach);
  // Friction on the base only: the footing's sides meet heaved soil alone and are taken as
  // smooth. Incremental (as in DEM): the stored tangential force grows by the spring's stiffness
  // times the slip of this step, so a change of contact length does not rescale what is stored.
  const double tx = 1.0, ty = 0.0;
  double ft = 0.0;
  if (ny < 0.0 && fn > 0.0 && spec_.interface != FootingInterface::smooth) {
    ft = friction - k * rvx * dt;
    if (spec_.interface == FootingInterface::coulomb) ft = std::clamp(ft, -spec_.friction_coefficient * fn, spec_.friction_coefficient * fn);
  }
  friction = ft;
  out.fx = fn * nx + ft * tx;
  out.fy = fn * ny + ft * ty;
  out.penetration = depth;
  return out;
}

}  // namespace acst::mpm
