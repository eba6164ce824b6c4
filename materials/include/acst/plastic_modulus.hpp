#pragma once
// Plastic modulus (docs/model.md section 6).
#include <cmath>

#include "acst/inline.hpp"

namespace acst {

// h = h1 - h2 e.
ACST_INLINE double hardening_coefficient(double h1, double h2, double e) { return h1 - h2 * e; }

// h floored at h_min, and whether the floor acted (a guard the integrator counts).
struct FlooredHardening {
  double h;
  int floored;  // 0 or 1 (an int: acst/inline.hpp)
};

ACST_INLINE FlooredHardening floored_hardening_coefficient(double h1, double h2, double h_min, double e) {
  const double h = hardening_coefficient(h1, h2, e);
  const bool floored = h < h_min;
  return {floored ? h_min : h, floored};
}

// The peak-state coefficient n (p/pa)^beta at the normalised pressure p/pa (floored at p_min
// like the moduli): n itself when beta = 0 (the published model), else a power of the pressure
// (docs/model.md section 6).
ACST_INLINE double peak_state_coefficient(double n, double beta, double pressure_ratio) {
  return beta == 0.0 ? n : n * std::pow(pressure_ratio, beta);
}

// exp(-n zeta), the plastic modulus's exponential: the lanes' kernel calls it outside its vector
// loops.
ACST_INLINE double peak_exponential(double n, double zeta) { return std::exp(-n * zeta); }

// Kp's R: R floored at R_tolerance, below which R may be 0 (n is then the strain increment's).
ACST_INLINE double plastic_modulus_stress_ratio(double R, double R_tolerance) { return max_of(R, R_tolerance); }

// Kp = G h (Mc g exp(-n zeta) / R - 1) with exp(-n zeta) given.
ACST_INLINE double plastic_modulus_of_exponential(double G, double h, double Mc, double g, double exp_n_zeta, double R) {
  return G * h * (Mc * g * exp_n_zeta / R - 1.0);
}

// Kp = G h (Mc g exp(-n zeta) / R - 1): peak where R = Mc g exp(-n zeta), softening beyond.
inline double plastic_modulus(double G, double h, double Mc, double g, double n, double zeta, double R) {
  return plastic_modulus_of_exponential(G, h, Mc, g, peak_exponential(n, zeta), R);
}

}  // namespace acst
