#pragma once
// Critical state line and state parameter (docs/model.md section 3).
#include <algorithm>
#include <cmath>

#include "acst/parameters.hpp"

namespace acst {

// e_c = e_Gamma - lambda_c (p/pa)^xi  (Li & Wang 1998).
inline double critical_void_ratio(const Parameters& prm, double p) {
  return prm.e_Gamma - prm.lambda_c * std::pow(std::max(p, 0.0) / atmospheric_pressure, prm.xi);
}

// psi = e - e_c (Been & Jefferies).
inline double state_parameter(const Parameters& prm, double e, double p) { return e - critical_void_ratio(prm, p); }

}  // namespace acst
