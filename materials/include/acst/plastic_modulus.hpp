#pragma once
// Plastic modulus (docs/model.md section 6).
#include <algorithm>
#include <cmath>

namespace acst {

// h = h1 - h2 e (the caller floors it at h_min and counts when it does).
inline double hardening_coefficient(double h1, double h2, double e) { return h1 - h2 * e; }

// The peak-state coefficient n (p/pa)^beta: n itself when beta = 0 (the published model), else a
// power of the pressure, floored at p_min like the moduli (docs/model.md section 6).
inline double peak_state_coefficient(double n, double beta, double p, double p_min, double pa) {
  if (beta == 0.0) return n;
  return n * std::pow(std::max(p, p_min) / pa, beta);
}

// Kp = G h (Mc g exp(-n zeta) / R - 1): peak where R = Mc g exp(-n zeta), softening beyond.
inline double plastic_modulus(double G, double h, double Mc, double g, double n, double zeta, double R) {
  return G * h * (Mc * g * std::exp(-n * zeta) / R - 1.0);
}

}  // namespace acst
