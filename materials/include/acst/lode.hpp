#pragma once
// Lode angle and the Lode interpolation function g(theta) of Li (2002).
#include <algorithm>
#include <cmath>

#include "acst/tensor.hpp"

namespace acst {

// sin(3 theta) = -sqrt(6) tr(r_hat^3) for a unit deviatoric r_hat; -1 in triaxial compression,
// +1 in extension. For a traceless tensor tr(a^3) = 3 det(a). Unclamped: callers clamp and count.
inline double lode_sin3theta_unclamped(const Sym& unit_deviator) {
  return -std::sqrt(6.0) * 3.0 * determinant(unit_deviator);
}

struct LodeInterpolation {
  double g;       // g(theta), 1 in compression, c in extension
  double dg_ds;   // dg/d(sin 3theta)
};

// g = [sqrt((1+c^2)^2 + 4c(1-c^2)s) - (1+c^2)] / [2(1-c)s], written in the rationalised form
// g = 2c(1+c) / [(1+c^2) + sqrt((1+c^2)^2 + 4c(1-c^2)s)] that has no 0/0 at s = 0 nor at c = 1.
inline LodeInterpolation lode_interpolation(double c, double sin3theta) {
  const double a = 1.0 + c * c;
  const double b = 4.0 * c * (1.0 - c * c);
  // The radicand is >= (1 - 2c - c^2)^2 >= 0 for s in [-1, 1]; the floor only guards round-off.
  const double root = std::sqrt(std::max(a * a + b * sin3theta, 1e-300));
  const double g = 2.0 * c * (1.0 + c) / (a + root);
  const double dg_ds = -g * b / (2.0 * root * (a + root));
  return {g, dg_ds};
}

}  // namespace acst
