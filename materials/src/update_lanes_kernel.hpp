#pragma once
// The lane kernel of update_lanes (include/acst/update_lanes.hpp), compiled once per instruction
// set (materials/CMakeLists.txt): the same source, so the same operations in every build of it.
#include "acst/update_lanes.hpp"

namespace acst::lanes {

// The material's numbers the kernel reads: its parameter set (the struct of the parameter table,
// acst/parameters.hpp) and its integrator options, whole and by name, so that no list of them
// kept in step by position stands between the table and the kernel; and the Lode form they give.
struct Constants {
  Parameters p;
  integration::Options o;
  bool willam_warnke;  // the Lode form: Willam & Warnke (true) or Li 2002
};

namespace generic {
void update(const Constants& k, UpdateLanes& lanes);
}
namespace x86_64_v3 {
void update(const Constants& k, UpdateLanes& lanes);
}

}  // namespace acst::lanes
