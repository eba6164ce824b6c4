// The size of an MPM scene and the checks against the caps (see scene_size.hpp).
#include "acst_footing_tool/scene_size.hpp"

#include <algorithm>
#include <cmath>

#include "acst_common/json_fields.hpp"
#include "acst_common/memory.hpp"
#include "acst_common/parallel_for.hpp"
#include "acst_footing_tool/records.hpp"
#include "acst_mpm/footing.hpp"
#include "acst_mpm/nonlocal_average.hpp"

namespace acst::mpm {
namespace f = acst::common::fields;

namespace {

// Bytes a particle costs: its arrays (Particles: 32 doubles, the state variables, the material
// index; the footing base's friction: 1 double), their copy in a checkpoint's buffer, the step's
// shape-function cache and mapped velocities (2 ints, 18 doubles), the footing contact (a list
// entry, at most one per particle), the fields of a frame or contour figure (8 doubles), the
// peak snapshot (4 doubles) and a frame's text (about 400 characters).
double bytes_per_particle(int state_size, bool footing) {
  const double arrays = 8.0 * (33 + state_size) + 4.0;
  return 2.0 * arrays + 8.0 + 8.0 * 18 + (footing ? Footing::bytes_per_touch : 0.0) + 8.0 * 8 + 8.0 * 4 + 400.0;
}

// Bytes a grid node costs: 19 nodal fields (5 of them the micropolar rotations', allocated only
// with them, counted always), its constraints (2 ints, 2 doubles) and each thread's scatter buffer
// (up to 3 fields).
double bytes_per_node(int threads) { return 8.0 * 19 + 24.0 + 8.0 * 3 * threads; }

// A load-record row: the record and its CSV line (12 numbers of up to 17 characters).
constexpr double bytes_per_record_row = sizeof(LoadRecord) + 12 * 18.0;

// The soil's time in the run: the stop time, or the footing's travel to the stop's S/B (half
// the ramp time longer: the speed rises as half a cosine over the ramp).
double run_time(const Scene& s, double first_time_step) {
  if (s.stop.time) return *s.stop.time;
  if (s.stop.S_over_B) return (*s.stop.S_over_B + s.footing->ramp_S_over_B) * s.footing->width / s.footing->speed;
  return static_cast<double>(*s.stop.steps) * first_time_step;
}

double expected_steps(const Scene& s, double dt) {
  return s.stop.steps ? static_cast<double>(*s.stop.steps) : std::ceil(run_time(s, dt) / dt);
}

std::string stop_path(const Scene& s) {
  if (s.stop.time) return "/stop/time";
  if (s.stop.S_over_B) return "/stop/S_over_B";
  return "/stop/steps";
}

void check_memory(const Scene& s, const SceneSize& size, const std::string& steps_from) {
  const double cap = common::memory_limit_bytes(max_memory_bytes);
  if (size.bytes() <= cap) return;
  const double record_share = size.record_rows * size.bytes_per_row / size.bytes();
  std::string what = f::shown(size.nodes) + " grid nodes (/grid/cell_size " + f::shown(s.cell_size) + " m) and " +
                     f::shown(size.particles) + " particles (/bodies/*/particles_per_cell)";
  if (record_share > 0.1)  // named where it matters
    what += " and " + f::shown(size.record_rows) + " load-record rows (" + steps_from +
            (s.output.every_step_csv ? ", /output/every_step_csv" : ", /solver/xpic_every") + ")";
  const bool records = record_share > 0.5;
  f::fail(records ? steps_from : "/grid/cell_size",
          "the scene needs about " + common::gib_text(size.bytes()) + " of memory for " + what + ", more than the " +
              common::gib_text(cap) + " allowed (the smaller of " + common::gib_text(max_memory_bytes) +
              " and this machine's physical memory); " +
              (records ? "run fewer steps or record fewer rows" : "use larger cells or less soil"));
}

}  // namespace

Scene modelled_part(const Scene& scene) {
  if (!scene.footing || !scene.footing->symmetric_half) return scene;
  Scene half = scene;
  for (BodySpec& b : half.bodies) b.x_min = scene.footing->centre_x;
  return half;
}

double deepest_settlement(const Scene& s) {
  if (!s.footing) return 0.0;
  const FootingSpec& f = *s.footing;
  if (f.unload_at_S_over_B > 0.0) return f.unload_at_S_over_B * f.width;
  if (s.stop.S_over_B) return *s.stop.S_over_B * f.width;
  if (s.stop.time) return *s.stop.time * f.speed;
  return 0.0;
}

GridExtent grid_extent(const Scene& s) {
  GridExtent g;
  g.x_min = g.y_min = INFINITY;
  g.x_max = g.y_max = -INFINITY;
  for (const BodySpec& b : s.bodies) {
    g.x_min = std::min(g.x_min, b.x_min), g.x_max = std::max(g.x_max, b.x_max);
    g.y_min = std::min(g.y_min, b.y_min), g.y_max = std::max(g.y_max, b.y_max);
  }
  const double h = s.cell_size;
  g.cells_left = GridExtent::margin + s.cells_beside;
  g.nodes_x = std::round((g.x_max - g.x_min) / h) + 2.0 * g.cells_left + 1;
  const double cells_y = std::round((g.y_max - g.y_min) / h);
  g.nodes_y = cells_y + GridExtent::margin + s.cells_above + 1;
  // Rows that follow a footing get closer as it settles: rows are added above so that the
  // grid's top stays where it was at the deepest settlement of the run.
  if (s.solver.grid_follows_footing && s.footing) {
    const double settled = deepest_settlement(s), hy = (cells_y * h - settled) / cells_y;
    if (hy > 0.0) g.nodes_y += std::max(0.0, std::ceil((s.cells_above * h + settled) / hy - 1e-9) - s.cells_above);
  }
  return g;
}

SceneSize scene_size(const Scene& scene, double steps) {
  const Scene s = modelled_part(scene);
  const GridExtent g = grid_extent(s);
  SceneSize size;
  size.nodes_x = g.nodes_x;
  size.nodes_y = g.nodes_y;
  size.nodes = g.nodes_x * g.nodes_y;
  int state_size = 0;
  for (const BodySpec& b : s.bodies) {
    const double n = b.particles_per_cell;
    size.particles += std::round((b.x_max - b.x_min) / s.cell_size) * std::round((b.y_max - b.y_min) / s.cell_size) * n * n;
    for (const MaterialSpec& m : s.materials)
      if (m.name == b.material) state_size = std::max(state_size, m.state_size);
  }
  size.bytes_per_node = bytes_per_node(common::thread_count(s.solver.threads));
  size.bytes_per_particle = bytes_per_particle(state_size, s.footing.has_value());
  // The regularisation's neighbour lists: a 4-byte entry for each particle within its reach
  // (2.5 l and a skin of l/4; twice that near a half domain's mirror), at most every particle,
  // and 5 doubles of each particle's own (the positions found, the value, the volume, the row).
  if (const double l = s.solver.regularisation.internal_length; l > 0.0) {
    double spacing = s.cell_size;
    for (const BodySpec& b : s.bodies) spacing = std::min(spacing, s.cell_size / b.particles_per_cell);
    const double reach = (nonlocal_reach + 0.25) * l;
    const double within = std::min(size.particles, 2.0 * 3.14159265358979 * reach * reach / (spacing * spacing) + 1.0);
    size.bytes_per_particle += 4.0 * within + 8.0 * 5;
  }
  size.record_rows = steps / s.solver.xpic_every + (s.output.every_step_csv ? steps : 0.0);
  // Each followed particle adds a history row (kept, and its CSV line of 27 numbers) per record row.
  size.bytes_per_row = bytes_per_record_row +
                       static_cast<double>(s.output.particle_histories.size()) * (sizeof(TrackRecord) + 27.0 * 17);
  return size;
}

void check_scene_size(const Scene& s) {
  double extent = 0.0;
  for (const BodySpec& b : s.bodies) extent = std::max({extent, b.x_max - b.x_min, b.y_max - b.y_min});
  if (s.cell_size < min_cell_fraction * extent)
    f::fail("/grid/cell_size", f::shown(s.cell_size) + " m is below " + f::shown(min_cell_fraction) +
                                   " of the soil's extent (" + f::shown(extent) + " m); allowed: at least " +
                                   f::shown(min_cell_fraction * extent) + " m");
  const double steps = s.stop.steps ? static_cast<double>(*s.stop.steps) : 0.0;
  const SceneSize size = scene_size(s, steps);
  const std::string cap = "at most " + f::shown(max_int_count);
  if (size.nodes_x > max_int_count || size.nodes_y > max_int_count || size.nodes > max_int_count)
    f::fail("/grid/cell_size", "the grid would have " + f::shown(size.nodes_x) + " x " + f::shown(size.nodes_y) + " = " +
                                   f::shown(size.nodes) + " nodes for the soil's extent; allowed: " + cap);
  if (size.particles > max_int_count)
    f::fail("/bodies", "the bodies would hold " + f::shown(size.particles) +
                           " particles (their cells at /grid/cell_size times particles_per_cell squared); allowed: " + cap);
  if (s.output.contours_at_S_over_B.size() > max_contours)
    f::fail("/output/contours_at_S_over_B", std::to_string(s.output.contours_at_S_over_B.size()) +
                                                " values; allowed: at most " + f::shown(max_contours));
  check_memory(s, size, "/stop/steps");
}

double expected_particle_steps(const Scene& s, double dt) { return scene_size(s, 0.0).particles * expected_steps(s, dt); }

void check_run_length(const Scene& s, double dt) {
  const double time = run_time(s, dt), steps = expected_steps(s, dt);
  const std::string why = " (" + f::shown(time) + " s of soil time at a first time step of " + f::shown(dt) +
                          " s, set by /grid/cell_size, /solver/cfl and the soil's wave speed)";
  if (!(steps <= max_steps))
    f::fail(stop_path(s), "the run would take about " + f::shown(steps) + " steps" + why + ", more than the " +
                              f::shown(max_steps) + " allowed");
  double frames = 1.0;
  std::string frames_from;
  if (s.output.vtk_every_time) {
    frames += time / *s.output.vtk_every_time;
    frames_from = "/output/vtk_every_time";
  } else if (s.footing && s.output.vtk_every_S_over_B > 0.0) {
    const double travel = s.stop.S_over_B ? *s.stop.S_over_B : s.footing->speed * time / s.footing->width;
    frames += travel / s.output.vtk_every_S_over_B;
    frames_from = "/output/vtk_every_S_over_B";
  }
  frames = std::min(frames, steps + 1.0);  // at most one frame a step
  if (frames > max_frames)
    f::fail(frames_from, "the run would write up to " + f::shown(std::floor(frames)) + " VTK frames over " +
                             f::shown(time) + " s of soil time, more than the " + f::shown(max_frames) + " allowed");
  check_memory(s, scene_size(s, steps), stop_path(s));
}

}  // namespace acst::mpm
