#pragma once
#include <cmath>
#include <cstddef>
#include <vector>

#include "acst_mpm/graded_axis.hpp"

namespace acst::mpm {

// The background grid, node index j * nx + i. Regular: nodes (i, j) at (x0 + i h, y0 + j hy);
// the row spacing hy is h unless the rows follow a footing's base (docs/mpm.md, "The grid
// follows the footing"), where it changes every step. Graded (docs/mpm.md, "The graded grid"):
// both axes' nodes from their knots, h the finest cell (the time step's and the contact's).
struct Grid {
  double x0 = 0.0, y0 = 0.0, h = 1.0, hy = 1.0;
  int nx = 0, ny = 0;
  GradedAxis graded_x, graded_y;  // empty on a regular grid
  std::size_t nodes() const { return static_cast<std::size_t>(nx) * ny; }
  bool graded() const { return !graded_x.empty(); }
  double node_x(int i) const { return graded() ? graded_x.node(i) : x0 + i * h; }
  double node_y(int j) const { return graded() ? graded_y.node(j) : y0 + j * hy; }
  // The column and the row of the node nearest x or y.
  int column_near(double x) const {
    return graded() ? nearest(graded_x, x) : static_cast<int>(std::lround((x - x0) / h));
  }
  int row_near(double y) const { return graded() ? nearest(graded_y, y) : static_cast<int>(std::lround((y - y0) / hy)); }
  // The node cell holding x (y) and the fraction of its width to x (y): bilinear spreading.
  struct Place {
    int cell;
    double fraction;
  };
  Place place_x(double x) const { return graded() ? place(graded_x, x) : place_regular((x - x0) / h); }
  Place place_y(double y) const { return graded() ? place(graded_y, y) : place_regular((y - y0) / hy); }

 private:
  static int nearest(const GradedAxis& a, double x) {
    const int i = a.cell(x);
    return x - a.node(i) <= a.node(i + 1) - x ? i : i + 1;
  }
  static Place place(const GradedAxis& a, double x) {
    const int i = a.cell(x);
    return {i, (x - a.node(i)) / (a.node(i + 1) - a.node(i))};
  }
  static Place place_regular(double u) {
    const int i = static_cast<int>(std::floor(u));
    return {i, u - i};
  }
};

// How a nodal field behaves under a mirror image: a scalar (mass) keeps its sign, the velocity
// or force component normal to a wall changes it, a rotation (about the out-of-plane axis)
// changes it at every wall.
enum class FieldKind { scalar, x, y, rotation };

// Forces a boundary exerts on the body, N/m (summed over its nodes).
struct Reaction {
  double fx = 0.0, fy = 0.0;
};

// Which boundary's reaction a node's constraint or mirror image adds to.
enum ReactionSet { reaction_base = 0, reaction_left, reaction_right, reaction_footing, reaction_sets };
inline constexpr int free_node = -1;

// Prescribed nodal velocities: per node and component the reaction set that prescribes it (or
// free_node) and the velocity.
struct NodeConstraints {
  std::vector<int> set_x, set_y;
  std::vector<double> vx, vy;
  void resize(std::size_t nodes) {
    set_x.assign(nodes, free_node);
    set_y.assign(nodes, free_node);
    vx.assign(nodes, 0.0);
    vy.assign(nodes, 0.0);
  }
  void clear() {
    std::fill(set_x.begin(), set_x.end(), free_node);
    std::fill(set_y.begin(), set_y.end(), free_node);
  }
};

}  // namespace acst::mpm
