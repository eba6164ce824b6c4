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
#include <array>
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

  // The step's hooks, in the order Simulation::step calls them. The rotations' terms of the maps,
  // the internal force and the particle update ride on the step's own passes over the particles
  // (one walk of each particle's stencil, every nodal sum added in the order it had on its own):
  // the pass takes the unit's fields and per-particle terms, and the unit finishes its part after.

  // The map: the nodes' rotational inertia and angular momentum, a particle's {J, J spin}.
  struct MapTerms {
    double* inertia;
    double* momentum;
    const double* mass;
    const double* spin;
    double inertia_per_mass;
    std::array<double, 2> operator()(std::size_t p) const {
      const double J = mass[p] * inertia_per_mass;
      return {J, J * spin[p]};
    }
  };
  MapTerms map_terms(const Particles& P, const Grid& grid);
  // After the map: the walls' mirror images folded in, the angular momentum over the inertia.
  void finish_map(const Walls& walls, const Grid& grid);
  // After the constraints: the skew and couple stresses over dt from the nodal velocities; the
  // first particle whose stresses are not finite, or -1. On a walk of the stencils of its own:
  // riding on the material's walk was measured slower (bench/RESULTS.md 1aj).
  long long update_stress(const Particles& P, const StepScratch& w, const double* vx, const double* vy, double dt);
  // The internal force: the skew stress's nodal forces (x, y) and the nodal couples, the three
  // fields `fields`; particle(p, V) the stresses times the particle's volume V (N/m, N), whose
  // add(f, S, dS/dx, dS/dy) adds a node's share into f[0..3).
  struct ParticleCouples {
    double A, mx, my;
    void add(double* const* f, std::size_t i, double S, double dx, double dy) const {
      f[0][i] += 0.5 * A * dy;
      f[1][i] -= 0.5 * A * dx;
      f[2][i] += A * S - (mx * dx + my * dy);
    }
  };
  struct ForceTerms {
    double* fields[3];
    const double *skew_stress, *couple_x, *couple_y;
    ParticleCouples operator()(std::size_t p, double V) const {
      return {V * skew_stress[p], V * couple_x[p], V * couple_y[p]};
    }
  };
  ForceTerms force_terms();
  // After the internal force's scatter, before the walls fold the force: the skew forces added to
  // w.fx, w.fy; the couples folded and, over the inertia, the spin's rate, damped as the velocities
  // are; the nodes' spin at the step's end, spin_i + rate_i dt (once per node, for spin_at).
  void finish_forces(StepScratch& w, const Walls& walls, const Grid& grid, double grid_damping, double dt);
  // The particle update: a particle's spin is PIC, sum S (spin_i + spin rate_i dt) (spin_at), less
  // its damping (set_spin); the grains' spin holds no history of its own.
  double spin_at(std::size_t node) const { return couple_[node]; }
  void set_spin(std::size_t p, double mapped, double dt, double particle_damping) {
    state_.spin[p] = mapped - particle_damping * state_.spin[p] * dt;
  }
  // The time step the rotations allow (infinite while off), c_max the stiffest (scaled) wave speed.
  double stable_time_step(double c_max, const Grid& grid, double cfl) const;

 private:
  double modulus(const Particles& P, std::size_t p) const;
  double inertia_per_mass(const Grid& grid) const;

  Micropolar settings_;
  ParticleState state_;
  // The nodes' rotational inertia, spin (angular momentum, then the micro-rotation rate), couple
  // (then the spin at the step's end) and the skew stress's nodal forces.
  std::vector<double> inertia_, spin_, couple_, skew_fx_, skew_fy_;
};

}  // namespace acst::mpm
