#include "acst_mpm/following_rows.hpp"

#include <cmath>

#include "acst_mpm/simulation_error.hpp"

namespace acst::mpm {

FollowingRows::FollowingRows(bool on, const Grid& grid, const Walls& walls, const Footing& footing) {
  if (on && grid.graded()) throw SimulationError("the rows cannot follow the footing on a graded grid");
  if (!on || !footing.active()) return;
  // From the grid as built (spacing h): the base wall's row stays put, the row of the footing's
  // starting base follows it.
  on_ = true;
  fixed_row_ = walls.base_wall != WallKind::none ? static_cast<int>(std::lround((walls.base - grid.y0) / grid.h)) : 0;
  fixed_y_ = grid.y0 + fixed_row_ * grid.h;
  base_row_ = static_cast<int>(std::lround((footing.base_y() - grid.y0) / grid.h));
  if (base_row_ <= fixed_row_)
    throw SimulationError("the rows cannot follow a footing whose base lies on or below the grid's fixed row");
}

void FollowingRows::follow(Grid& grid, const Footing& footing, long long step) const {
  if (!on_) return;
  const double height = footing.base_y() - fixed_y_;
  if (!(height > 0.0))
    throw SimulationError("step " + std::to_string(step) + ": the footing's base reached the grid's fixed row");
  grid.hy = height / (base_row_ - fixed_row_);
  grid.y0 = fixed_y_ - fixed_row_ * grid.hy;
}

}  // namespace acst::mpm
