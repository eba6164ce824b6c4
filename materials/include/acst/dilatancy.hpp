#pragma once
// Dilatancy (docs/model.md section 6).
#include <cmath>

#include "acst/inline.hpp"

namespace acst {

// exp(m zeta), dilatancy's exponential: the lanes' kernel calls it outside its vector loops.
ACST_INLINE double dilatancy_exponential(double m, double zeta) { return std::exp(m * zeta); }

// D = d1 (exp(m zeta) - R / (Mc g)) with exp(m zeta) given.
ACST_INLINE double dilatancy_of_exponential(double d1, double exp_m_zeta, double R, double Mc, double g) {
  return d1 * (exp_m_zeta - R / (Mc * g));
}

// D = d1 (exp(m zeta) - R / (Mc g)); D = d eps_v^p / d eps_q^p, positive for contraction.
inline double dilatancy(double d1, double m, double zeta, double R, double Mc, double g) {
  return dilatancy_of_exponential(d1, dilatancy_exponential(m, zeta), R, Mc, g);
}

}  // namespace acst
