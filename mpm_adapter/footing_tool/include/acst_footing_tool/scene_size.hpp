#pragma once
// What an MPM scene asks of the machine, counted in double before anything becomes an integer:
// grid nodes, particles, memory and, once the first time step is known, steps and VTK frames.
// A scene beyond the caps is refused with the JSON paths that set the size and the computed
// value (docs/reliability.md); a cell size of 1e-300 or a grid of 1e9 cells never reaches an
// integer conversion or an allocation.
#include "acst_footing_tool/scene.hpp"

namespace acst::mpm {

// The part of the scene the simulation models: the soil right of the footing's centre line
// for a symmetric half, else the whole scene.
Scene modelled_part(const Scene& scene);

// The grid around the bodies of a modelled part, as build_simulation lays it out.
struct GridExtent {
  double x_min = 0, x_max = 0, y_min = 0, y_max = 0;
  double nodes_x = 0, nodes_y = 0;  // whole numbers, in double
  int cells_left = 0;               // cells left of the bodies (the margin and /grid/cells_beside)
  static constexpr int margin = 3;  // cells beyond the walls: the stencil reaches two
};
GridExtent grid_extent(const Scene& part);
// The footing's settlement at the end of the run (m): its unloading point, or its stop by S/B or
// by time; 0 without a footing or for a run that stops by steps.
double deepest_settlement(const Scene& scene);

struct SceneSize {
  double nodes_x = 0, nodes_y = 0, nodes = 0, particles = 0;
  double bytes_per_node = 0, bytes_per_particle = 0;
  double record_rows = 0, bytes_per_row = 0;  // the load record kept in memory
  double bytes() const { return nodes * bytes_per_node + particles * bytes_per_particle + record_rows * bytes_per_row; }
};
// `steps`: the run's length in steps, 0 when not known yet.
SceneSize scene_size(const Scene& scene, double steps);

// Caps. Counts that become an int (grid nodes per direction and in all, particles) stay below
// 2^31; the memory estimate below the smaller of max_memory_bytes and the machine's physical
// memory; steps below max_steps (at a few thousand steps a second, 1e9 steps are days); VTK
// frames below max_frames (their names have four digits, and the .pvd listing them is
// rewritten with each); requested contour figures below max_contours.
inline constexpr double max_int_count = 2147483647.0;
inline constexpr double max_memory_bytes = 64.0 * 1024 * 1024 * 1024;
inline constexpr double max_steps = 1e9;
inline constexpr double max_frames = 10000;
inline constexpr double max_contours = 100;
inline constexpr std::size_t max_particle_histories = 100;  // each a file and a row per load-record row
// The cell size must be at least this fraction of the soil's extent.
inline constexpr double min_cell_fraction = 1e-6;

// At read time: cell size against the extent, nodes, particles, memory (with the load record
// when the run stops by steps). Throws common::InputError naming the JSON paths.
void check_scene_size(const Scene& scene);

// Once the simulation is built: the run's length in steps from its first time step, the VTK
// frames it writes and the memory with its load record. Throws common::InputError.
void check_run_length(const Scene& scene, double first_time_step);

// The run's expected work in particle-steps at its first time step: how a sweep ranks its cases
// by length (the time step shrinks as the soil under a footing stiffens, much alike in cases of
// one study).
double expected_particle_steps(const Scene& scene, double first_time_step);

}  // namespace acst::mpm
