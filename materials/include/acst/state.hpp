#pragma once
// The state a material point carries between calls.
#include <Eigen/Core>

#include "acst/tensor.hpp"

namespace acst {

struct State {
  Sym stress = Sym::Zero();  // Cauchy stress, kPa, compression positive
  Sym fabric = Sym::Zero();  // fabric tensor F (symmetric, deviatoric)
  double void_ratio = 0.7;
  double H = 0.0;             // yield-cone size, R/g at the last plastic state
  double substep_hint = 1.0;  // last accepted substep size (pseudo-time)
  int pressure_floor_resets = 0;  // cumulative count of resets to the p_min state
};

}  // namespace acst
