#pragma once
#include <cstddef>
#include <vector>

namespace acst::mpm {

// The regular background grid: nodes (i, j) at (x0 + i h, y0 + j hy), node index j * nx + i.
// The row spacing hy is h unless the rows follow a footing's base (docs/mpm.md, "The grid
// follows the footing"), where it changes every step.
struct Grid {
  double x0 = 0.0, y0 = 0.0, h = 1.0, hy = 1.0;
  int nx = 0, ny = 0;
  std::size_t nodes() const { return static_cast<std::size_t>(nx) * ny; }
};

// How a nodal field behaves under a mirror image: a scalar (mass) keeps its sign, the velocity
// or force component normal to a wall changes it.
enum class FieldKind { scalar, x, y };

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
