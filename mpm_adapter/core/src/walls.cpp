#include "acst_mpm/walls.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace acst::mpm {

void Walls::fold(double* q, FieldKind c, const Grid& grid) const {
  const int nx = grid.nx, ny = grid.ny;
  auto at = [&](int i, int j) -> double& { return q[static_cast<std::size_t>(j) * nx + i]; };
  // node(k): the node k steps inward from the wall (k < 0: beyond it); `reach` exterior nodes.
  auto fold_line = [](double s, int reach, auto&& node) {
    for (int k = 1; k <= reach; ++k) node(k) += s * node(-k);
    node(0) *= 1.0 + s;
    for (int k = 1; k <= reach; ++k) node(-k) = s * node(k);
  };
  // The mirror image's sign: a scalar keeps it; the component normal to the wall changes it, and
  // the tangential one too where the wall holds it (no slip), not where it slides. A rotation is
  // reversed by a mirror, and a wall that holds the soil holds its grains' rotation too.
  const auto sign = [c](WallKind wall, FieldKind normal) {
    if (c == FieldKind::rotation) return -1.0;
    return c == FieldKind::scalar ? 1.0 : (c == normal || wall == WallKind::fixed ? -1.0 : 1.0);
  };
  if (left_side != WallKind::none) {
    const double s = sign(left_side, FieldKind::x);
    const int il = grid.column_near(left);
    for (int j = 0; j < ny; ++j) fold_line(s, std::min(il, nx - 1 - il), [&](int k) -> double& { return at(il + k, j); });
  }
  if (right_side != WallKind::none) {
    const double s = sign(right_side, FieldKind::x);
    const int ir = grid.column_near(right);
    for (int j = 0; j < ny; ++j) fold_line(s, std::min(nx - 1 - ir, ir), [&](int k) -> double& { return at(ir - k, j); });
  }
  if (base_wall != WallKind::none) {
    const double s = sign(base_wall, FieldKind::y);
    const int jb = grid.row_near(base);
    for (int i = 0; i < nx; ++i) fold_line(s, std::min(jb, ny - 1 - jb), [&](int k) -> double& { return at(i, jb + k); });
  }
}

Walls::Lines Walls::lines(const Grid& grid) const {
  return {grid.column_near(left), grid.column_near(right), grid.row_near(base)};
}

int Walls::wall_of(int i, int j, const Lines& at) const {
  if (base_wall != WallKind::none && j <= at.base + 2) return reaction_base;
  if (left_side != WallKind::none && i <= at.left + 2) return reaction_left;
  if (right_side != WallKind::none && i >= at.right - 2) return reaction_right;
  return free_node;
}

}  // namespace acst::mpm
