#pragma once
// The rigid strip footing as one boundary unit: a rigid body of width B driven at a constant
// speed at `inclination` (rad) from the downward vertical, toward +x for positive angles:
// velocity = speed (sin b, -cos b), reversed once the settlement reaches `unload_at` (if set).
//
// Two formulations (docs/mpm.md, "The footing"):
// - penalty contact (the default): the footing is the half-plane body {|x - c| <= B/2, y >= base};
//   every particle whose domain overlaps it is pushed out through the face its centre lies
//   beyond (the base for a centre under the base; for a centre inside the outline or at a
//   corner, the face the domain penetrates least) by a force k_n * depth * (contact
//   length), k_n = factor * M / h with M = rho c_max^2 from the particle's density and the
//   stiffest particle's wave speed (a contact layer as stiff as h / factor of the stiffest
//   soil), and a dashpot (half critical) on the approach speed
//   (never pulling), with friction on the base (rough: no slip while pressed;
//   smooth; or Coulomb with a coefficient) through a tangential spring, and nothing once
//   separated. The load is a sum over particles, continuous in the footing's position.
// - node rows (the old formulation, kept to show its artefact): grid nodes inside the footprint
//   and at or above the base (nearest node row) move with the footing.
#include <algorithm>

#include "acst_mpm/grid.hpp"

namespace acst::mpm {

enum class FootingContact { penalty, node_rows };
enum class FootingInterface { rough, smooth, coulomb };

// The part of a particle the contact sees: its centre, velocity, the half-extents of its
// (deformed) domain, its (inertial) mass and its penalty stiffness k_n (N/m^3: force per metre
// out of plane, per metre of contact length, per metre of penetration).
struct ContactParticle {
  double x, y, vx, vy, half_x, half_y, mass, stiffness;
};

// The footing's force on one particle (N/m) and where it acts.
struct ContactForce {
  double fx = 0.0, fy = 0.0;
  double at_x = 0.0, at_y = 0.0;  // point of action (for the moment about the footing's centre)
  double penetration = 0.0;       // depth of overlap, m (0 when apart)
};

class Footing {
 public:
  struct Spec {
    double centre_x = 0.0, width = 0.0, base_y = 0.0;  // base_y: the soil surface under it
    double speed = 0.0, inclination = 0.0;
    double unload_at = 0.0;  // settlement (m) at which the footing reverses; 0: never
    FootingContact contact = FootingContact::penalty;
    FootingInterface interface = FootingInterface::rough;
    double friction = 0.0;        // Coulomb coefficient (interface coulomb)
    double penalty_factor = 4.0;  // k_n = factor * M / h (above)
    double ramp_time = 0.0;       // s over which the speed rises from zero (0: none)
  };
  // How far it has moved and the work it has done on the soil (checkpointed).
  struct Motion {
    double dx = 0.0, dy = 0.0, work = 0.0;  // m, m, J/m
    bool unloading = false;
  };

  Footing() = default;
  explicit Footing(const Spec& spec) : spec_(spec), active_(true) {}

  bool active() const { return active_; }
  const Spec& spec() const { return spec_; }
  Motion& motion() { return motion_; }
  const Motion& motion() const { return motion_; }
  double centre_x() const { return spec_.centre_x + motion_.dx; }
  double base_y() const { return spec_.base_y + motion_.dy; }
  double settlement() const { return -motion_.dy; }
  bool uses_contact() const { return active_ && spec_.contact == FootingContact::penalty; }

  // Node rows: prescribes its velocity on the nodes it covers (reaction set reaction_footing).
  void constrain(const Grid& grid, NodeConstraints& c) const;

  // Whether a particle's domain (centre x, y; half-extents half_x, half_y) overlaps the footing:
  // the contact's own test, asked before the particle's stiffness is worked out.
  bool overlaps(double x, double y, double half_x, double half_y) const {
    const double half = 0.5 * spec_.width;
    return !(x + half_x <= centre_x() - half || x - half_x >= centre_x() + half || y + half_y <= base_y());
  }

  // Penalty contact on one particle (all zero where it does not overlap). `friction` is the
  // tangential force the base holds on it (N/m along x), carried from step to step; dt the step.
  ContactForce contact(const ContactParticle& p, double& friction, double dt) const;

  // Moves on by its velocity over dt; `on_soil` is the force it exerts on the soil (N/m).
  void advance(const Reaction& on_soil, double dt);
  // The clock's time at the start of a step: sets the speed on the ramp.
  void at_time(double t);
  double vx() const;
  double vy() const;

 private:
  Spec spec_;
  Motion motion_;
  bool active_ = false;
  double ramp_ = 1.0;  // fraction of the speed reached on the ramp
};

}  // namespace acst::mpm
