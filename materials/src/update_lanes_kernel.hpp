#pragma once
// The lane kernel of update_lanes (include/acst/update_lanes.hpp), compiled once per instruction
// set (materials/CMakeLists.txt): the same source, so the same operations in every build of it.
#include "acst/update_lanes.hpp"

namespace acst::lanes {

// The material's numbers the kernel reads, copied out of Parameters and Options.
struct Constants {
  bool willam_warnke;  // the Lode form: Willam & Warnke (true) or Li 2002
  double c, R_tolerance, p_min, G0, nu, e_Gamma, lambda_c, xi, e_A, d1, m, Mc, h1, h2, h_min, n, beta, k_f;
  double ftol, ltol, stol;
  bool reuse_last_substep;
};

namespace generic {
void update(const Constants& k, UpdateLanes& lanes);
}
namespace x86_64_v3 {
void update(const Constants& k, UpdateLanes& lanes);
}

}  // namespace acst::lanes
