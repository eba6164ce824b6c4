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

// The state parameter of a host's nonlocal regularisation (docs/model.md section 11): psi + offset,
// the offset being the host's averaged void ratio minus the point's own, but no looser than
// critical unless the point is looser itself. The averaging carries a band's softening (its
// approach to the critical state) into the soil around it; a point that dense soil surrounds,
// told that it is looser than critical, would contract at a rate exp(m zeta) that its own
// stiffness cannot carry (a non-positive loading-index denominator: measured in the MPM's
// biaxial test, docs/footing-study.md, "The regularised biaxial test"). With no offset, psi.
ACST_INLINE double nonlocal_state_parameter(double psi, double offset) { return min_of(psi + offset, max_of(psi, 0.0)); }

}  // namespace acst
