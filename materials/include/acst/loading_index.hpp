#pragma once
// Loading index in strain-driven form (docs/model.md section 6).
#include <cmath>

#include "acst/tensor.hpp"

namespace acst {

struct LoadingIndexTerms {
  double numerator;    // 2G n:de - K (n:r) d eps_v
  double denominator;  // Kp + 2G - sqrt(2/3) K D (n:r); must be > 0 (uniqueness)
};

// L = [2G n:de_dev - K (n:r) d eps_v] / [Kp + 2G - sqrt(2/3) K D (n:r)].
inline LoadingIndexTerms loading_index_terms(double G, double K, double Kp, double D, const Sym& n, double n_r,
                                             const Sym& deps) {
  return {2.0 * G * contract(n, deps) - K * n_r * trace(deps), Kp + 2.0 * G - std::sqrt(2.0 / 3.0) * K * D * n_r};
}

}  // namespace acst
