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

#include "acst_mpm/footing.hpp"
#include "acst_mpm/grid.hpp"
#include "acst_mpm/material_adapter.hpp"
#include "acst_mpm/nonlocal_average.hpp"
#include "acst_mpm/particles.hpp"
#include "acst_mpm/settings.hpp"
#include "acst_mpm/step_scratch.hpp"
#include "acst_mpm/walls.hpp"

namespace acst::mpm {

// kPa -> Pa (kPa m -> N/m): the one unit conversion of the core (simulation.cpp and
// simulation_micropolar.cpp).
inline constexpr double kilo = 1000.0;

struct SimulationError : std::runtime_error {
  using std::runtime_error::runtime_error;
  SimulationError(const std::string& what, std::string replay) : std::runtime_error(what), reproducer(std::move(replay)) {}
  std::string reproducer;  // for a material failure: the scene acst_element replays ("" otherwise)
};

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

// The simulation owns its state; hosts read it through const accessors. The one mutable door
// is particles(), for initial conditions before the first step (tests set velocities there);
// a checkpoint comes back through restore().
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
  // particle, of the same scene.
  void restore(Particles particles, const Clock& clock, const Footing::Motion& motion, std::vector<double> friction);

  const Grid& grid() const { return grid_; }
  const Walls& walls() const { return boundaries_.walls; }
  const Footing& footing() const { return boundaries_.footing; }
  const Settings& settings() const { return settings_; }
  const std::vector<std::shared_ptr<const AbiMaterial>>& materials() const { return materials_; }
  const Particles& particles() const { return particles_; }
  Particles& particles() { return particles_; }
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

 private:
  // The steps of step(), in the order docs/mpm.md gives.
  void regularise();
  void refresh_time_step();
  void compute_shape_functions();
  void compute_shape_functions_graded();
  void graded_domains();
  void map_mass_and_momentum();
  void apply_constraints();
  void update_stress(const double* vx, const double* vy, double dt);
  void footing_contact();
  void internal_force_and_reactions();
  void update_particles();
  void remap_momentum();
  void advance_boundaries();

  // Micropolar rotations (simulation_micropolar.cpp; nothing while they are off).
  void map_micro_rotation();
  void update_micropolar_stress(const double* vx, const double* vy, double dt);
  void micropolar_force();
  void update_micro_spin();
  double micropolar_modulus(std::size_t p) const;
  double micro_inertia() const;

  void prepare();
  void local_void_ratios(std::vector<double>& out) const;
  void follow_footing();
  void velocity_gradients_averaged(const double* vx, const double* vy);
  void refresh_wave_speeds();
  double stiffest_wave_speed() const;
  // Velocity = momentum / mass with the constraints applied (0 on nodes without mass).
  void nodal_velocity(const double* px, const double* py, double* vx, double* vy);
  void xpic_velocity(int order);
  void fold(double* field, FieldKind kind) const { boundaries_.walls.fold(field, kind, grid_); }
  [[noreturn]] void fail(std::size_t particle, const std::string& what, const std::string& reproducer = "") const;

  Grid grid_;
  Boundaries boundaries_;
  Settings settings_;
  std::vector<std::shared_ptr<const AbiMaterial>> materials_;
  Particles particles_;
  double particle_half_width_ = 0.5;
  std::vector<double> domain_x_, domain_y_;  // on a graded grid: each particle's domain half-widths, m
  struct FollowingRows {  // laid out once from the grid as built (docs/mpm.md)
    bool on = false;
    int fixed_row = 0, base_row = 0;
    double fixed_y = 0.0;
  } rows_;
  Clock clock_;
  std::array<Reaction, reaction_sets> reaction_{};
  NonlocalAverage nonlocal_;  // inactive unless the regularisation has an internal length
  std::vector<double> nonlocal_value_, nonlocal_mean_;
  StepScratch work_;  // owned: a copy of a Simulation has its own
};

}  // namespace acst::mpm
