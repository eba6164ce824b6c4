#pragma once
// B2GIMP shape functions: quadratic B-spline grid functions averaged over a uniform, undeformed
// particle domain of half-width l cells (l = 1/(2 n) for n particles per cell and direction).
// xi = (x_p - x_i)/h is the particle-node distance in cells; S is the weight, dS its derivative
// with respect to xi (divide by h for the spatial gradient).
#include <cmath>

namespace acst::mpm {

// 1-D weight S(xi) (docs/mpm.md, section "Shape functions"; mpm-core design note table).
inline double b2gimp_weight(double xi, double l) {
  const double a = std::fabs(xi);
  if (a < 0.5 - l) return 0.75 - a * a - l * l / 3.0;
  if (a < 0.5 + l) {
    const double b = a - l, c = 1.5 - a - l;
    return (0.5 - 0.75 * b + b * b * b / 3.0 - c * c * c / 6.0) / (2.0 * l);
  }
  if (a <= 1.5 - l) return 0.5 * (1.5 - a) * (1.5 - a) + l * l / 6.0;
  if (a < 1.5 + l) {
    const double c = 1.5 + l - a;
    return c * c * c / (12.0 * l);
  }
  return 0.0;
}

// dS/dxi.
inline double b2gimp_slope(double xi, double l) {
  const double a = std::fabs(xi), sign = xi < 0.0 ? -1.0 : 1.0;
  double d = 0.0;
  if (a < 0.5 - l) {
    d = -2.0 * a;
  } else if (a < 0.5 + l) {
    const double b = a - l, c = 1.5 - a - l;
    d = (0.5 * c * c - (0.75 - b * b)) / (2.0 * l);
  } else if (a <= 1.5 - l) {
    d = a - 1.5;
  } else if (a < 1.5 + l) {
    const double c = 1.5 + l - a;
    d = -c * c / (4.0 * l);
  }
  return sign * d;
}

// The 4 nodes along one axis that can carry weight for a particle at X = (x - x_origin)/h
// (support half-width 1.5 + l <= 2 cells): nodes first .. first + 3.
struct AxisWeights {
  int first;
  double w[4];
  double dw[4];  // dS/dxi: divide by h for d/dx
};

inline AxisWeights axis_weights(double X, double l) {
  AxisWeights a;
  a.first = static_cast<int>(std::floor(X)) - 1;
  for (int k = 0; k < 4; ++k) {
    const double xi = X - (a.first + k);
    a.w[k] = b2gimp_weight(xi, l);
    a.dw[k] = b2gimp_slope(xi, l);
  }
  return a;
}

}  // namespace acst::mpm
