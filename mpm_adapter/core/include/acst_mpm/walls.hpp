#pragma once
// Rigid walls at the edges of the soil's box, on grid lines, treated as symmetry planes: the
// grid field of the body's mirror image beyond a wall is folded onto the interior nodes. With
// B-splines this gives the nodes next to a wall the force of the missing particles, which
// plain node fixity leaves unbalanced (docs/mpm.md, "Walls are symmetry planes").
#include "acst_mpm/grid.hpp"

namespace acst::mpm {

enum class WallKind { none, smooth, fixed };

struct Walls {
  double left = 0.0, right = 0.0, base = 0.0;
  WallKind base_wall = WallKind::fixed;  // none, smooth (it slides) or fixed (no slip)
  WallKind left_side = WallKind::smooth, right_side = WallKind::smooth;

  // Folds the mirror image onto the interior nodes (odd components change sign), then mirrors
  // back to the exterior nodes. An odd velocity component is zero on the wall; a smooth wall
  // keeps the tangential component even.
  void fold(double* field, FieldKind kind, const Grid& grid) const;
  // The walls' grid lines as node indices, looked up once per sweep over the nodes.
  struct Lines {
    int left, right, base;
  };
  Lines lines(const Grid& grid) const;
  // The wall whose mirror image acts on node (i, j) (those within the stencil's reach), or free_node.
  int wall_of(int i, int j, const Lines& at) const;
};

}  // namespace acst::mpm
