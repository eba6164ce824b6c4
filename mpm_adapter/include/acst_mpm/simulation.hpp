#pragma once
// The compact MPM core: 2-D plane strain, explicit, regular grid, B2GIMP shape functions,
// update-stress-average (USAVG) step, FLIP / PIC / XPIC(m) particle update with grid and
// particle damping, rigid walls, surcharge, a rigid footing driven at constant velocity.
// Units: m, s, kg (per metre out of plane), kPa for stress; forces in N per metre internally,
// reported in kN/m. Stress in the material ABI's convention: tension positive, Voigt
// xx yy zz xy xz yz (docs/mpm.md).
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "acst_mpm/material_adapter.hpp"

namespace acst::mpm {

struct SimulationError : std::runtime_error {
  using std::runtime_error::runtime_error;
  SimulationError(const std::string& what, std::string replay) : std::runtime_error(what), reproducer(std::move(replay)) {}
  std::string reproducer;  // for a material failure: the scene acst_element replays ("" otherwise)
};

enum class ParticleUpdate { FLIP, PIC, XPIC };

struct Settings {
  double cfl = 0.5;
  ParticleUpdate update = ParticleUpdate::XPIC;
  int xpic_order = 4;   // m of XPIC(m)
  int xpic_every = 20;  // XPIC on every k-th step, FLIP between
  double grid_damping = 0.5;      // alpha_g, 1/s
  double particle_damping = 0.0;  // alpha_p, 1/s
  int wave_speed_every = 100;     // steps between refreshes of the particles' wave speeds
  double mass_scaling = 1.0;      // inertial mass x this factor (weight unchanged)
  double gravity = 0.0;           // m/s^2, acting in -y
  int threads = 0;                // 0: OpenMP default
};

// The regular background grid: nodes (i, j) at (x0 + i h, y0 + j h), node index j * nx + i.
struct Grid {
  double x0 = 0.0, y0 = 0.0, h = 1.0;
  int nx = 0, ny = 0;
  std::size_t nodes() const { return static_cast<std::size_t>(nx) * ny; }
};

enum class SideWall { none, smooth, fixed };

// Rigid walls at the edges of a box (the soil's extent), on grid lines, treated as symmetry
// planes (see Simulation::fold); B2GIMP reaches two cells past the soil, so the grid does too.
struct Walls {
  double left = 0.0, right = 0.0, base = 0.0;
  bool base_fixed = true;  // false: no base wall
  SideWall sides = SideWall::smooth;
};

// A rough (or smooth) rigid strip footing driven at a constant speed at `inclination` (rad)
// from the downward vertical, toward +x for positive angles: velocity = speed (sin b, -cos b).
// Grid nodes inside its footprint and at or above its base (nearest node row) move with it.
struct Footing {
  bool active = false;
  double centre_x = 0.0, width = 0.0, base_y = 0.0;
  double speed = 0.0, inclination = 0.0;
  bool rough = true;
};

// Particle data in flat arrays (structure of arrays).
struct Particles {
  std::size_t n = 0;
  int state_size = 0;
  std::vector<double> x, y, x_initial, y_initial, vx, vy;
  std::vector<double> mass, weight_mass, volume_initial;  // mass = inertial (scaled) mass
  std::vector<double> density;                             // initial density, kg/m^3
  std::vector<double> F;        // deformation gradient, 4 per particle (xx xy yx yy)
  std::vector<double> stress;   // 6 per particle, kPa, tension positive
  std::vector<double> strain;   // accumulated small strain, 3 per particle (xx yy xy tensor)
  std::vector<double> statev;   // state_size per particle
  std::vector<double> surcharge_length;  // top-edge length loaded by the surcharge (0: none)
  std::vector<double> wave_speed;
  std::vector<int> material;    // index into Simulation::materials

  void resize(std::size_t count, int state_size);
  double volume(std::size_t p) const;
};

// Forces a constrained node set exerts on the body, N/m (summed over the set's nodes).
struct Reaction {
  double fx = 0.0, fy = 0.0;
};

enum ReactionSet { reaction_base = 0, reaction_left, reaction_right, reaction_footing, reaction_sets };

class Simulation {
 public:
  Simulation(Grid grid, Walls walls, Settings settings, std::vector<std::shared_ptr<const Material>> materials);

  Grid grid;
  Walls walls;
  Footing footing;
  Settings settings;
  std::vector<std::shared_ptr<const Material>> materials;
  Particles particles;
  double surcharge = 0.0;  // kPa on the particles with a surcharge_length
  double particle_half_width = 0.5;  // l in cells: 1/(2 n) for n particles per cell and direction

  // Time, step count and the footing's displacement.
  long long step_count = 0;
  double time = 0.0, dt = 0.0;
  double footing_dx = 0.0, footing_dy = 0.0;
  double footing_work = 0.0;  // J/m done by the footing on the soil

  // Reactions of the last step (force the constraint applies to the soil, N/m).
  std::array<Reaction, reaction_sets> reaction{};

  // Checks the particles lie on the grid with room for the stencil; refreshes wave speeds.
  void prepare();
  // Advances one step; throws SimulationError naming step and particle on a material failure.
  void step();
  double kinetic_energy() const;
  double footing_base_y() const { return footing.base_y + footing_dy; }
  bool is_xpic_step(long long step) const;

 private:
  struct Work;
  std::shared_ptr<Work> work_;
  void refresh_wave_speeds();
  double stable_time_step() const;
  void compute_shape_functions();
  void update_constraints();
  // Velocity = momentum / mass with the constraints applied (0 on nodes without mass).
  void nodal_velocity(const double* px, const double* py, double* vx, double* vy);
  void update_stress(const double* vx, const double* vy, double dt);
  void xpic_velocity(int order);
  enum class Component { scalar, x, y };
  int wall_node(double coordinate, double origin) const;
  void fold(double* field, Component c) const;
  int wall_of(int i, int j) const;
  [[noreturn]] void fail(std::size_t particle, const std::string& what, const std::string& reproducer = "") const;
};

}  // namespace acst::mpm
