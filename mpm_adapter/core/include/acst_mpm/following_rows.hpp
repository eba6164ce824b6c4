#pragma once
// The grid's rows follow the footing (the scene's /grid/follow_footing; docs/mpm.md, "The grid
// follows the footing"): the rows between the base wall (or the grid's first row) and the
// footing's base keep their count and share the height between them, so the base stays on its
// node row at every settlement. Laid out once from the grid as built; off, it leaves the grid be.
#include <string>

#include "acst_mpm/footing.hpp"
#include "acst_mpm/grid.hpp"
#include "acst_mpm/walls.hpp"

namespace acst::mpm {

class FollowingRows {
 public:
  FollowingRows() = default;
  // Throws SimulationError where the rows cannot follow (a graded grid; a footing base on or
  // below the fixed row). Off unless `on` and the footing is active.
  FollowingRows(bool on, const Grid& grid, const Walls& walls, const Footing& footing);

  // The grid's row spacing and origin for the footing where it is now; throws SimulationError
  // (naming the step) once its base reaches the fixed row.
  void follow(Grid& grid, const Footing& footing, long long step) const;

 private:
  bool on_ = false;
  int fixed_row_ = 0, base_row_ = 0;
  double fixed_y_ = 0.0;
};

}  // namespace acst::mpm
