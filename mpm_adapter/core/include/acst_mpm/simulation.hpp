#pragma once
// The compact MPM core: 2-D plane strain, explicit, regular grid, B2GIMP shape functions,
// update-stress-average (USAVG) step, FLIP / PIC / XPIC(m) particle update with grid and
// particle damping, rigid walls, surcharge, a rigid footing driven at constant velocity (penalty
// contact with the particles, or node rows).
// Units: m, s, kg (per metre out of plane), kPa for stress; forces in N per metre internally,
// reported in kN/m. Stress in the material ABI's convention: tension positive, Voigt
// xx yy zz xy xz yz (docs/mpm.md).
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "acst_mpm/following_rows.hpp"
#include "acst_mpm/footing.hpp"
#include "acst_mpm/grid.hpp"
#include "acst_mpm/material_adapter.hpp"
#include "acst_mpm/micropolar_rotations.hpp"
#include "acst_mpm/particle_weights.hpp"
#include "acst_mpm/particles.hpp"
#include "acst_mpm/regulariser.hpp"
#include "acst_mpm/settings.hpp"
#include "acst_mpm/simulation_error.hpp"
#include "acst_mpm/step_phases.hpp"
#include "acst_mpm/step_scratch.hpp"
#include "acst_mpm/walls.hpp"

namespace acst::mpm {

// The boundaries that load the body besides its weight (walls are geometry, kept with them).
struct Boundaries {
  Walls walls;
  Footing footing;         // inactive unless the scene has one
  double surcharge = 0.0;  // kPa on the particles with a surcharge_length
  double confining_pressure = 0.0;  // kPa on the particles with a side_length (a biaxial test's sides)
  // Half domain: the left wall is the footing's centre line and the soil beyond it this soil's
  // mirror image, so the footing's V and the kinetic energy are reported doubled, H and M zero.
  bool symmetric_half = false;
};

// Where a run stands in time (checkpointed).
struct Clock {
  long long step = 0;
  double time = 0.0, dt = 0.0;
};

// The step features' particle state, checkpointed with the particles.
struct FeatureState {
  Regulariser::ParticleState regularisation;
  MicropolarRotations::ParticleState micropolar;
};

// The simulation owns its state and the step's units (docs/mpm.md, "The code: three parts"): the
// shape functions, the rows that follow the footing, the regularisation, the micropolar rotations
// and the boundaries; step() calls their phases in order. Hosts read the state through const
// accessors. The mutable doors are particles() and micropolar(), for initial conditions before the
// first step (tests set velocities and spins there); a checkpoint comes back through restore().
class Simulation {
 public:
  // `particle_half_width` is l in cells: 1/(2 n) for n particles per cell and direction.
  // Checks the particles lie on the grid with room for the stencil; computes wave speeds.
  Simulation(Grid grid, Boundaries boundaries, Settings settings,
             std::vector<std::shared_ptr<const AbiMaterial>> materials, Particles particles,
             double particle_half_width);

  // Advances one step; throws SimulationError naming step and particle on a material failure.
  void step();
  // Continues from a checkpoint: particles, clock, footing motion and the base's friction per
  // particle, of the same scene, and the step features' state.
  void restore(Particles particles, FeatureState features, const Clock& clock, const Footing::Motion& motion,
               std::vector<double> friction);
  FeatureState feature_state() const { return {regulariser_.state(), micropolar_.state()}; }

  const Grid& grid() const { return grid_; }
  const Walls& walls() const { return boundaries_.walls; }
  const Footing& footing() const { return boundaries_.footing; }
  const Settings& settings() const { return settings_; }
  const std::vector<std::shared_ptr<const AbiMaterial>>& materials() const { return materials_; }
  const Particles& particles() const { return particles_; }
  Particles& particles() { return particles_; }
  const Regulariser& regulariser() const { return regulariser_; }
  const MicropolarRotations& micropolar() const { return micropolar_; }
  MicropolarRotations& micropolar() { return micropolar_; }
  const Clock& clock() const { return clock_; }
  long long step_count() const { return clock_.step; }
  double time() const { return clock_.time; }
  // Force the boundary applied to the body over the last step, N/m.
  const Reaction& reaction(ReactionSet set) const { return reaction_[set]; }
  const ContactSummary& contact() const { return boundaries_.footing.summary(); }
  double kinetic_energy() const;
  bool is_xpic_step(long long step) const;
  // The time step the next step would take (CFL on the wave speeds, and the contact springs).
  double stable_time_step() const;
  // Wall seconds each phase of step() has taken in this process (a resumed run counts anew).
  const StepPhaseSeconds& phase_seconds() const { return phase_seconds_; }

 private:
  // The steps of step(), in the order docs/mpm.md gives.
  void refresh_time_step();
  void compute_shape_functions();
  void map_mass_and_momentum();
  void apply_constraints();
  void update_stress(const double* vx, const double* vy, double dt);
  void footing_contact();
  void internal_force_and_reactions();
  void update_particles();
  void remap_momentum();
  void advance_boundaries();

  void prepare();
  void refresh_wave_speeds();
  double stiffest_wave_speed() const;
  // Velocity = momentum / mass with the constraints applied (0 on nodes without mass).
  void nodal_velocity(const double* px, const double* py, double* vx, double* vy);
  void xpic_velocity(int order);
  void fold(double* field, FieldKind kind) const { boundaries_.walls.fold(field, kind, grid_); }
  [[noreturn]] void fail(std::size_t particle, const std::string& what, const std::string& reproducer = "") const;
  // fail() where a unit reports a failed particle (>= 0); nothing for -1.
  void fail_at(long long particle, const char* what) const;

  Grid grid_;
  Boundaries boundaries_;
  Settings settings_;
  std::vector<std::shared_ptr<const AbiMaterial>> materials_;
  Particles particles_;
  // The step's units (each does nothing while its feature is off).
  ParticleWeights weights_;
  FollowingRows rows_;
  Regulariser regulariser_;
  MicropolarRotations micropolar_;
  Clock clock_;
  std::array<Reaction, reaction_sets> reaction_{};
  StepScratch work_;  // owned: a copy of a Simulation has its own
  StepPhaseSeconds phase_seconds_{};
};

}  // namespace acst::mpm
