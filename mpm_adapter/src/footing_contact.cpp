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
  if (x1 <= left || x0 >= right || y1 <= base) {  // apart: no force, the spring relaxes
    friction = 0.0;
    return out;
  }
  // The face that pushes is the one the particle's centre lies beyond: the base for a centre
  // under the base, a side for a centre above the base beside the footing; for a centre inside
  // the footing's outline, and below the base beside it (the corners), the face the domain
  // penetrates least, as a signed distance to the outline gives. Under the middle of the base
  // that is the base (soil the base has passed is pushed down); near a side it is the side:
  // heaved soil that a side let in, pushed down instead, counted its height above the base as
  // penetration and the force threw it off the grid (issue 11, the slow Kimura runs).
  const double d_base = y1 - base, d_left = x1 - left, d_right = right - x0;
  const bool under = p.x >= left && p.x <= right;
  const bool above_base = p.y >= base;
  bool base_face = d_base <= std::min(d_left, d_right);  // inside the outline, or a corner below
  if (under && !above_base) base_face = true;             // under the base
  if (!under && above_base) base_face = false;            // beside
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
    if (spec_.interface == FootingInterface::coulomb) ft = std::clamp(ft, -spec_.friction * fn, spec_.friction * fn);
  }
  friction = ft;
  out.fx = fn * nx + ft * tx;
  out.fy = fn * ny + ft * ty;
  out.penetration = depth;
  out.touching = true;
  return out;
}

}  // namespace acst::mpm
