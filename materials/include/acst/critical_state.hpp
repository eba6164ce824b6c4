#pragma once
// Critical state line and state parameter (docs/model.md section 3).
#include <cmath>

#include "acst/inline.hpp"
#include "acst/parameters.hpp"

namespace acst {

// e_c = e_Gamma - lambda_c (p/pa)^xi (Li & Wang 1998) at the normalised pressure p/pa (the lanes'
// kernel computes that in its vector loops, the pow outside them).
ACST_INLINE double critical_void_ratio(double e_Gamma, double lambda_c, double xi, double pressure_ratio) {
  return e_Gamma - lambda_c * std::pow(pressure_ratio, xi);
}

inline double critical_void_ratio(const Parameters& prm, double p) {
  return critical_void_ratio(prm.e_Gamma, prm.lambda_c, prm.xi, normalised_pressure(p, 0.0));
}

// psi = e - e_c (Been & Jefferies).
ACST_INLINE double state_parameter(double e, double e_c) { return e - e_c; }

inline double state_parameter(const Parameters& prm, double e, double p) {
  return state_parameter(e, critical_void_ratio(prm, p));
}

}  // namespace acst
