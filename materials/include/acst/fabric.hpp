#pragma once
// Fabric tensor and the anisotropic state variables (docs/acst-model.md sections 3 and 4).
#include <Eigen/Core>
#include <cmath>

#include "acst/tensor.hpp"

namespace acst {

// F_0 = F0 (3 b b^T - I) / sqrt(6) for a unit deposition direction b (normal to the bedding planes).
inline Sym initial_fabric(double F0, const Eigen::Vector3d& deposition_direction) {
  const Eigen::Vector3d b = deposition_direction.normalized();
  Sym bb;
  bb << b[0] * b[0], b[1] * b[1], b[2] * b[2], b[0] * b[1], b[0] * b[2], b[1] * b[2];
  return F0 * (3.0 * bb - identity_tensor()) / std::sqrt(6.0);
}

// A = F:n, the fabric anisotropy variable.
inline double fabric_anisotropy_variable(const Sym& F, const Sym& n) { return contract(F, n); }

// zeta = psi - e_A (A - 1), the dilatancy state parameter.
inline double dilatancy_state_parameter(double psi, double e_A, double A) { return psi - e_A * (A - 1.0); }

// dF = L k_f (n - F) per unit loading index L (> 0).
inline Sym fabric_rate(double k_f, const Sym& n, const Sym& F) { return k_f * (n - F); }

}  // namespace acst
