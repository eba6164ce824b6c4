#pragma once
// Fabric tensor and the anisotropic state variables (docs/model.md sections 3 and 4).
#include <Eigen/Core>
#include <cmath>

#include "acst/inline.hpp"
#include "acst/tensor.hpp"

namespace acst {

// Whether a deposition direction is one: finite and not zero (1e-320 in one component is one).
inline bool usable_direction(const Eigen::Vector3d& direction) {
  return direction.allFinite() && direction.cwiseAbs().maxCoeff() > 0.0;
}

// The unit vector of a usable direction, scaled by its largest component first: the norm of a
// direction like (1e200, 1e200, 0) overflows and that of (1e-320, 0, 0) underflows, and
// normalising by either gave b = 0 (a fabric that was not deviatoric, a direction [0, 0, 0]).
inline Eigen::Vector3d unit_direction(const Eigen::Vector3d& direction) {
  return (direction / direction.cwiseAbs().maxCoeff()).normalized();
}

// F_0 = F0 (3 b b^T - I) / sqrt(6) for the unit deposition direction b (normal to the bedding planes).
inline Sym initial_fabric(double F0, const Eigen::Vector3d& deposition_direction) {
  const Eigen::Vector3d b = unit_direction(deposition_direction);
  Sym bb;
  bb << b[0] * b[0], b[1] * b[1], b[2] * b[2], b[0] * b[1], b[0] * b[2], b[1] * b[2];
  return F0 * (3.0 * bb - identity_tensor()) / std::sqrt(6.0);
}

// Deposition direction b for a bedding angle alpha (degrees): the angle between b and the major
// loading axis, b rotated from that axis towards the minor one about the third (intermediate)
// axis: b = cos(alpha) e_major + sin(alpha) e_minor (axes 0, 1, 2 = x1, x2, x3).
// Element tests: major = 0 (axial), minor = 2. Plane-strain footings (x horizontal, y vertical):
// major = 1 (y), minor = 0 with alpha measured towards -x, i.e. b = (-sin alpha, cos alpha, 0).
inline Eigen::Vector3d bedding_direction(double alpha_degrees, int major_axis, int minor_axis, double minor_sign = 1.0) {
  // Whole turns off first (exact): alpha * pi overflows to infinity for |alpha| near 1e308, and
  // cos and sin of it are NaN. Angles within a turn keep their numbers to the bit.
  if (std::abs(alpha_degrees) >= 360.0) alpha_degrees = std::fmod(alpha_degrees, 360.0);
  const double a = alpha_degrees * M_PI / 180.0;
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  b[major_axis] = std::cos(a);
  b[minor_axis] = minor_sign * std::sin(a);
  return b;
}

// A = F:n, the fabric anisotropy variable.
ACST_INLINE double fabric_anisotropy_variable(const double* F, const double* n) { return contract(F, n); }

inline double fabric_anisotropy_variable(const Sym& F, const Sym& n) { return fabric_anisotropy_variable(F.data(), n.data()); }

// zeta = psi - e_A (A - 1), the dilatancy state parameter.
ACST_INLINE double dilatancy_state_parameter(double psi, double e_A, double A) { return psi - e_A * (A - 1.0); }

// dF = L k_f (n - F) per unit loading index L (> 0), into dF.
ACST_INLINE void fabric_rate(double k_f, const double* n, const double* F, double* dF) {
#pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) dF[i] = k_f * (n[i] - F[i]);
}

inline Sym fabric_rate(double k_f, const Sym& n, const Sym& F) {
  Sym dF;
  fabric_rate(k_f, n.data(), F.data(), dF.data());
  return dF;
}

}  // namespace acst
