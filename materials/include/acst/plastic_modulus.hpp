#pragma once
// Plastic modulus (docs/model.md section 6).
#include <algorithm>
#include <cmath>

namespace acst {

// h = h1 - h2 e (the caller floors it at h_min and counts when it does).
inline double hardening_coefficient(double h1, double h2, double e) { return h1 - h2 * e; }

// Kp = G h (Mc g exp(-n zeta) / R - 1): peak where R = Mc g exp(-n zeta), softening beyond.
inline double plastic_modulus(double G, double h, double Mc, double g, double n, double zeta, double R) {
  return G * h * (Mc * g * std::exp(-n * zeta) / R - 1.0);
}

}  // namespace acst
