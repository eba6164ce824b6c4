#pragma once
// Micropolar (Cosserat) rotations of the soil as one step feature (docs/mpm.md, "Micropolar
// rotations"): each particle carries a micro-rotation theta besides its motion, with the stored
// energy per unit volume
//   1/2 k (theta_M - theta)^2 + 1/2 k l^2 |grad theta|^2,
// theta_M the continuum's rotation (its rate the spin W = (dv_y/dx - dv_x/dy) / 2), k the
// particle's modulus (modulus_ratio rho c^2), l the length. Its stresses are the skew stress
// A = k (theta_M - theta) and the couple stress m = k l^2 grad theta; their power
// A (W - theta') + m . grad theta' gives the nodal forces and couples. The material's (symmetric)
// stress is untouched: a field without rotation gradients and with theta = theta_M has A = 0 and
// m = 0, and the classical continuum's numbers.
//
// The unit owns its particle fields (checkpointed as its ParticleState) and its nodal fields; its
// hooks do nothing while it is off (length 0), so the classical step is the one it was, to the bit.
#include <cstddef>
#include <vector>

#include "acst_mpm/grid.hpp"
#include "acst_mpm/particles.hpp"
#include "acst_mpm/settings.hpp"
#include "acst_mpm/step_scratch.hpp"
#include "acst_mpm/walls.hpp"

namespace acst::mpm {

class MicropolarRotations {
 public:
  // The particles' rotational state, zeros at the start: the micro-rotation's rate (rad/s,
  // counter-clockwise), the skew stress (kPa) and the couple stress's x and y components (kPa m).
  struct ParticleState {
    std::vector<double> spin, skew_stress, couple_x, couple_y;
  };

  MicropolarRotations() = default;
  MicropolarRotations(const Micropolar& settings, std::size_t particles);

  bool active() const { return settings_.active(); }
  ParticleState& state() { return state_; }
  const ParticleState& state() const { return state_; }
  // Sizes the nodal fields for a grid of `nodes` nodes (nothing while off).
  void prepare(std::size_t nodes);

  // The step's hooks, in the order Simulation::step calls them.
  // After the mass: the nodes' rotational inertia and micro-rotation rate.
  void map(const Particles& P, StepScratch& w, const Walls& walls, const Grid& grid);
  // After the constraints: the skew and couple stresses over dt from the nodal velocities; the
  // first particle whose stresses are not finite, or -1.
  long long update_stress(const Particles& P, const StepScratch& w, const double* vx, const double* vy, double dt);
  // In the internal force, before the walls fold it: the skew stress's nodal forces added to
  // w.fx, w.fy; the nodal couples over the inertia become the spin's rate.
  void add_forces(const Particles& P, StepScratch& w, const Walls& walls, const Grid& grid, double grid_damping);
  // After the particles' velocities: their micro-rotation rates from the grid's.
  void update_spin(const StepScratch& w, std::size_t particles, double dt, double particle_damping);
  // The time step the rotations allow (infinite while off), c_max the stiffest (scaled) wave speed.
  double stable_time_step(double c_max, const Grid& grid, double cfl) const;

 private:
  double modulus(const Particles& P, std::size_t p) const;
  double inertia_per_mass(const Grid& grid) const;

  Micropolar settings_;
  ParticleState state_;
  // The nodes' rotational inertia, spin (angular momentum, then the micro-rotation rate), couple
  // (then the spin's rate) and the skew stress's nodal forces.
  std::vector<double> inertia_, spin_, couple_, skew_fx_, skew_fy_;
};

}  // namespace acst::mpm
