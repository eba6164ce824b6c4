// Turns a scene into a ready simulation: grid around the bodies, walls at their extent,
// particles with their geostatic stress and initial state (through the material ABI).
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "acst_footing_tool/build_simulation.hpp"
#include "acst_footing_tool/scene_size.hpp"
#include "acst_mpm/material_frame.hpp"

namespace acst::mpm {
namespace {

// Vertical total stress (kPa, compression positive) at (x, y): surcharge plus the weight of the
// bodies above in the same column.
double overburden(const Scene& s, double x, double y) {
  double sv = s.surcharge;
  for (const BodySpec& b : s.bodies)
    if (x >= b.x_min && x <= b.x_max && b.y_max > y)
      sv += b.density * s.gravity * (b.y_max - std::max(y, b.y_min)) / 1000.0;  // Pa -> kPa
  return sv;
}

double column_top(const Scene& s, double x) {
  double top = -INFINITY;
  for (const BodySpec& b : s.bodies)
    if (x >= b.x_min && x <= b.x_max) top = std::max(top, b.y_max);
  return top;
}

// The particle nearest each output/particle_histories position: it must be a sand's and lie
// within a cell (a graded grid's largest) of the position (a position outside the soil, or in
// the half a symmetric run leaves out, is an error, not the nearest particle far away).
void follow_particles(const Scene& s, const std::vector<std::shared_ptr<const AbiMaterial>>& materials, Particles& P) {
  const auto& tracks = s.output.particle_histories;
  P.tracked.clear();
  P.track_frame.assign(material_frame_size * tracks.size(), 0.0);
  for (std::size_t k = 0; k < tracks.size(); ++k) {
    const std::string at = "/output/particle_histories/" + std::to_string(k) + "/at";
    std::size_t best = 0;
    double best_d2 = INFINITY;
    for (std::size_t p = 0; p < P.n; ++p) {
      const double d2 = std::pow(P.x[p] - tracks[k].x, 2) + std::pow(P.y[p] - tracks[k].y, 2);
      if (d2 < best_d2) best = p, best_d2 = d2;
    }
    const double cell = s.graded ? s.graded->largest_cell : s.cell_size;  // a graded grid's largest cell
    if (!(best_d2 <= cell * cell))
      throw common::InputError(at + ": no particle within a cell (" + std::to_string(cell) + " m) of (" +
                               std::to_string(tracks[k].x) + ", " + std::to_string(tracks[k].y) +
                               ") m in the modelled soil");
    if (!materials[static_cast<std::size_t>(P.material[best])]->is_sand())
      throw common::InputError(at + ": the particle there is not of a sand material (its history needs fabric, void ratio and H)");
    P.tracked.push_back(static_cast<int>(best));
    P.track_frame[material_frame_size * k] = 1.0;  // cos of no rotation yet
  }
}

// One axis of the graded grid (docs/mpm.md, "The graded grid"): fine cells on the regular grid's
// lattice (through lo.at) over the window, graded toward the ends outside it.
GradedAxis graded_axis(const AxisEnd& lo, const AxisEnd& hi, double window_lo, double window_hi, const Scene& s,
                       const char* axis) {
  const GradedGridSpec& g = *s.graded;
  try {
    return GradedAxis(graded_knots(lo, hi, lo.at, window_lo, window_hi, {s.cell_size, g.growth, g.largest_cell}));
  } catch (const std::invalid_argument& e) {
    throw common::InputError(std::string("/grid/graded: along ") + axis + ", " + e.what());
  }
}

Grid graded_grid(const Scene& s, const GridExtent& extent, double base_y) {
  const FootingSpec& f = *s.footing;
  const double h = s.cell_size, reach = f.width * s.graded->half_width_B;
  constexpr int margin = GridExtent::margin;
  const double top = extent.y_max + s.cells_above * h;  // the regular grid's top row
  Grid grid;
  grid.h = grid.hy = h;
  grid.graded_x = graded_axis({extent.x_min, extent.cells_left}, {extent.x_max, extent.cells_left},
                              f.centre_x - reach, f.centre_x + reach, s, "x");
  grid.graded_y = graded_axis({extent.y_min, margin}, {top, 0}, base_y - f.width * s.graded->depth_B, top, s, "y");
  grid.nx = grid.graded_x.nodes();
  grid.ny = grid.graded_y.nodes();
  grid.x0 = grid.graded_x.node(0);
  grid.y0 = grid.graded_y.node(0);
  return grid;
}

// The particles' centres and widths along one axis of a body from lo to hi: n per cell of the
// regular grid (spacing h), or per node cell of the graded one, whose nodes the body's edges must
// lie on.
struct Row {
  std::vector<double> at, width;
};
Row particle_row(double lo, double hi, double h, int n, const GradedAxis* graded, const std::string& path) {
  Row r;
  if (!graded) {
    const double d = h / n;
    const long long count = std::llround((hi - lo) / d);
    for (long long k = 0; k < count; ++k) r.at.push_back(lo + (k + 0.5) * d), r.width.push_back(d);
    return r;
  }
  const int first = graded->node_at(lo, 1e-9 * h), last = graded->node_at(hi, 1e-9 * h);
  if (first < 0 || last < 0)
    throw common::InputError(path + ": with /grid/graded the body's edges must lie on the graded grid's nodes (the "
                             "soil's outer edges, or fine cells inside the refined window)");
  for (int i = first; i < last; ++i) {
    const double d = (graded->node(i + 1) - graded->node(i)) / n;
    for (int k = 0; k < n; ++k) r.at.push_back(graded->node(i) + (k + 0.5) * d), r.width.push_back(d);
  }
  return r;
}

}  // namespace

Simulation build_simulation(const Scene& scene) {
  const bool half = scene.footing && scene.footing->symmetric_half;
  const Scene s = modelled_part(scene);
  const double h = s.cell_size;
  // The reader checked the node and particle counts against their caps (scene_size.hpp).
  const GridExtent extent = grid_extent(s);
  const double x_min = extent.x_min, x_max = extent.x_max, y_min = extent.y_min;
  constexpr int margin = GridExtent::margin;
  const double base_y = s.footing ? column_top(s, s.footing->centre_x) : 0.0;
  if (!std::isfinite(base_y)) throw common::InputError("/footing/centre_x: no body lies under the footing");
  Grid grid;
  if (s.graded) {
    grid = graded_grid(s, extent, base_y);
  } else {
    grid.h = grid.hy = h;
    grid.x0 = x_min - extent.cells_left * h;
    grid.y0 = y_min - margin * h;
    grid.nx = static_cast<int>(extent.nodes_x);
    grid.ny = static_cast<int>(extent.nodes_y);
  }

  Boundaries boundaries;
  Walls& walls = boundaries.walls;
  walls.left = x_min, walls.right = x_max, walls.base = y_min;
  walls.base_wall = s.base;
  walls.left_side = half ? WallKind::smooth : s.sides;  // the centre line is a symmetry plane
  walls.right_side = s.sides;
  boundaries.surcharge = s.surcharge;
  boundaries.confining_pressure = s.confining_pressure;
  boundaries.symmetric_half = half;

  std::vector<std::shared_ptr<const AbiMaterial>> materials;
  std::map<std::string, int> index;
  for (std::size_t i = 0; i < s.materials.size(); ++i) {
    materials.push_back(std::make_shared<const AbiMaterial>(s.materials[i].name, s.materials[i].json_text));
    index[s.materials[i].name] = static_cast<int>(i);
  }
  int ppc = s.bodies.front().particles_per_cell;
  std::size_t count = 0, state_size = 0;
  std::vector<Row> columns, rows;  // per body
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const BodySpec& b = s.bodies[i];
    const std::string path = "/bodies/" + std::to_string(i);
    if (b.particles_per_cell != ppc)
      throw common::InputError(path + "/particles_per_cell: all bodies must use the same number (B2GIMP's uniform particle domains)");
    columns.push_back(particle_row(b.x_min, b.x_max, h, ppc, s.graded ? &grid.graded_x : nullptr, path));
    rows.push_back(particle_row(b.y_min, b.y_max, h, ppc, s.graded ? &grid.graded_y : nullptr, path));
    count += columns.back().at.size() * rows.back().at.size();
    state_size = std::max<std::size_t>(state_size, materials[index[b.material]]->state_size());
  }
  if (s.footing) boundaries.footing = Footing(*s.footing, base_y);

  Particles P;
  P.resize(count, static_cast<int>(state_size));
  std::size_t p = 0;
  for (std::size_t bi = 0; bi < s.bodies.size(); ++bi) {
    const BodySpec& b = s.bodies[bi];
    const std::string path = "/bodies/" + std::to_string(bi);
    const AbiMaterial& mat = *materials[index[b.material]];
    double e = 0.0, deposition[3] = {0.0, 1.0, 0.0};
    if (mat.is_sand()) {
      if (!b.void_ratio && !b.relative_density)
        throw common::InputError(path + ": a sand material needs void_ratio or relative_density_pct");
      e = b.void_ratio ? *b.void_ratio : mat.void_ratio_from_relative_density(*b.relative_density);
      // b = (-sin alpha, cos alpha, 0): alpha from the vertical (loading) axis, as in the reference study.
      const acst_status st = acst_bedding_direction(deposition, b.bedding_angle_deg, 1, 0, -1.0);
      if (st.code != ACST_OK) throw common::InputError(path + "/bedding_angle_deg: " + st.message);
    }
    const Row &across = columns[bi], &up = rows[bi];
    for (std::size_t jy = 0; jy < up.at.size(); ++jy)
      for (std::size_t ix = 0; ix < across.at.size(); ++ix, ++p) {
        const double x = across.at[ix], y = up.at[jy], dx = across.width[ix], dy = up.width[jy];
        P.x[p] = P.x_initial[p] = x;
        P.y[p] = P.y_initial[p] = y;
        P.volume_initial[p] = dx * dy;
        P.density[p] = b.density;
        P.weight_mass[p] = b.density * dx * dy;
        P.mass[p] = P.weight_mass[p] * s.solver.mass_scaling;
        P.material[p] = index[b.material];
        double* sig = &P.stress[6 * p];
        if (s.initial_stress == InitialStress::isotropic) {
          sig[0] = sig[1] = sig[2] = -s.initial_p;
        } else if (s.initial_stress == InitialStress::geostatic) {
          const double sv = overburden(s, x, y);
          sig[0] = sig[2] = -s.K0 * sv;
          sig[1] = -sv;
        }
        try {
          mat.initial_state(P.statev.data() + P.state_size * p, sig, e, deposition);
        } catch (const MaterialError& err) {
          throw common::InputError(path + ": particle at (" + std::to_string(x) + ", " + std::to_string(y) + "): " + err.what());
        }
        const bool top_row = y + dy > column_top(s, x) - 1e-9 * h;
        const bool under_footing = s.footing && std::fabs(x - s.footing->centre_x) < 0.5 * s.footing->width;
        if (top_row && !under_footing && s.surcharge > 0.0) P.surcharge_length[p] = dx;
        if (s.confining_pressure > 0.0) {  // the soil's outermost columns, pushed inward
          if (x - dx < x_min + 1e-9 * h) P.side_length[p] = dy;
          if (x + dx > x_max - 1e-9 * h) P.side_length[p] = -dy;
        }
      }
  }
  follow_particles(s, materials, P);
  return Simulation(grid, boundaries, s.solver, std::move(materials), std::move(P), 0.5 / ppc);
}

}  // namespace acst::mpm
