#pragma once
// Dilatancy (docs/model.md section 6).
#include <cmath>

namespace acst {

// D = d1 (exp(m zeta) - R / (Mc g)); D = d eps_v^p / d eps_q^p, positive for contraction.
inline double dilatancy(double d1, double m, double zeta, double R, double Mc, double g) {
  return d1 * (std::exp(m * zeta) - R / (Mc * g));
}

}  // namespace acst
