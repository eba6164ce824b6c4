#pragma once
// The rigid strip footing as one boundary unit: a rigid body of width B driven at a constant
// speed at `inclination_deg` from the downward vertical, toward +x for positive angles:
// velocity = speed (sin b, -cos b), reversed once the settlement reaches `unload_at_S_over_B` B
// (if set). It owns what its contact with the soil needs from step to step (the base's friction
// per particle, the touching particles of a step) and the one function that builds it from the
// scene's /footing.
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
#include <cstddef>
#include <vector>

#include "acst_mpm/grid.hpp"
#include "acst_mpm/particles.hpp"

namespace acst::mpm {

enum class FootingContact { penalty, node_rows };
enum class FootingInterface { rough, smooth, coulomb };

// The footing as the scene's /footing describes it: m, m/s, degrees (docs/mpm.md, "Scenes").
struct FootingSpec {
  double width = 0, centre_x = 0, speed = 0, inclination_deg = 0;
  FootingContact contact = FootingContact::penalty;
  FootingInterface interface = FootingInterface::rough;
  double friction_coefficient = 0;  // interface "coulomb"
  double penalty_factor = 4;        // contact "penalty": k_n = factor * M / h
  double unload_at_S_over_B = 0;    // reverse the footing there (0: never)
  bool symmetric_half = false;      // model x >= centre_x only, its mirror image standing for the rest
  double ramp_S_over_B = 0;         // the speed rises from zero (half a cosine) while the footing settles this
};

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

// The footing contact over the last step: moment about the base centre of the footing's force
// on the soil (N m/m, counter-clockwise positive), deepest penetration (m), particles touching.
struct ContactSummary {
  double moment = 0.0, max_penetration = 0.0;
  std::size_t touching = 0;
};

class Footing {
 public:
  // How far it has moved and the work it has done on the soil (checkpointed).
  struct Motion {
    double dx = 0.0, dy = 0.0, work = 0.0;  // m, m, J/m
    bool unloading = false;
  };

  Footing() = default;
  // From the scene's /footing, its base on the soil surface at base_y.
  Footing(const FootingSpec& spec, double base_y);

  bool active() const { return active_; }
  const FootingSpec& spec() const { return spec_; }
  Motion& motion() { return motion_; }
  const Motion& motion() const { return motion_; }
  double centre_x() const { return spec_.centre_x + motion_.dx; }
  double base_y() const { return base_y_ + motion_.dy; }
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

  // The contact's phase of a step: the force on every particle whose domain (l h, shrunk by its
  // stretch) touches the footing, with k_n from the stiffest wave speed c_max; their sum is
  // reaction() (the footing's force on the soil, N/m; V doubled and H, M zero on a symmetric
  // half), summed in particle order, the same for any thread count.
  void touch(const Particles& P, const Grid& grid, double particle_half_width, double c_max, double dt, int threads);
  const Reaction& reaction() const { return reaction_; }
  const ContactSummary& summary() const { return summary_; }
  // Each contact force of the last touch() as a point load where it acts on the footing's face,
  // shared by the four nodes around that point in proportion to hat weight x nodal mass.
  void spread(const Grid& grid, const double* mass, double* fx, double* fy) const;

  // The contact's penalty stiffness for particle p: k_n = factor * rho c^2 / h (rho its current
  // density, c the stiffest soil's wave speed).
  double stiffness(const Particles& P, std::size_t p, double h, double c_max) const {
    const double rho = P.density[p] * P.volume_initial[p] / P.volume(p);
    return spec_.penalty_factor * rho * c_max * c_max / h;
  }
  // The stiffest contact spring's omega^2 = k_n w / m for a particle pressed along its whole
  // width w = 2 l h: the time step keeps dt <= 2 cfl / omega (Simulation::stable_time_step).
  // `may_exceed` is a bound with a margin far above the terms' rounding: where it says no, the
  // exact term cannot pass `omega2_so_far` and need not be worked out (the same maxima).
  struct SpringRate {
    const Footing& footing;
    double h, width, c_max, bound;
    bool may_exceed(const Particles& P, std::size_t p, double omega2_so_far) const {
      const double V = P.volume(p);
      return !(V > 0.0 && bound * P.density[p] * P.volume_initial[p] <= omega2_so_far * V * P.mass[p]);
    }
    double omega2(const Particles& P, std::size_t p) const { return footing.stiffness(P, p, h, c_max) * width / P.mass[p]; }
  };
  SpringRate spring_rate(double h, double particle_half_width, double c_max, double margin) const;

  // The tangential force the base holds on each particle (N/m along x; checkpointed).
  std::vector<double>& friction() { return friction_; }
  const std::vector<double>& friction() const { return friction_; }

  // Moves on by its velocity over dt; `on_soil` is the force it exerts on the soil (N/m).
  void advance(const Reaction& on_soil, double dt);
  // The clock's time at the start of a step: sets the speed on the ramp.
  void at_time(double t);
  double vx() const;
  double vy() const;

 private:
  FootingSpec spec_;
  double base_y_ = 0.0;     // the soil surface under it at the start
  double inclination_ = 0.0, unload_at_ = 0.0, ramp_time_ = 0.0;  // rad, m, s
  Motion motion_;
  bool active_ = false;
  double ramp_ = 1.0;  // fraction of the speed reached on the ramp
  std::vector<double> friction_;
  // A step's touching particles and the force on each. Each thread lists its own on its own
  // cache line, and only the few touching particles are written: a force stored for every
  // particle, then read by the serial sum, moved the cache lines of one thread's half to the
  // other core and back every step.
  struct Touch {
    std::size_t particle;
    ContactForce force;
  };
  struct alignas(64) TouchList {
    std::vector<Touch> touches;
  };
  std::vector<TouchList> touching_of_thread_;
  std::vector<Touch> touching_;
  Reaction reaction_;
  ContactSummary summary_;

 public:
  // Bytes the contact holds per touching particle (scene_size.hpp's memory estimate).
  static constexpr double bytes_per_touch = sizeof(Touch);
};

}  // namespace acst::mpm
