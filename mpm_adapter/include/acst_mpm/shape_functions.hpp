#pragma once
// B2GIMP shape functions: quadratic B-spline grid functions averaged over a uniform, undeformed
// particle domain of half-width l cells (l = 1/(2 n) for n particles per cell and direction).
// xi = (x_p - x_i)/h is the particle-node distance in cells; S is the weight, dS its derivative
// with respect to xi (divide by h for the spatial gradient).
#include <cmath>

namespace acst::mpm {

// 1-D weight S(xi) and slope dS/dxi together, in one pass over the ranges, with inv_l = 1/l
// (docs/mpm.md, section "Shape functions"; mpm-core design note table). One function for both
// keeps the ranges written once; the particle loops call it 8 times per particle and step.
struct B2gimpValue {
  double w, dw;
};

inline B2gimpValue b2gimp(double xi, double l, double inv_l) {
  const double a = std::fabs(xi);
  double w = 0.0, d = 0.0;
  if (a < 0.5 - l) {
    w = 0.75 - a * a - l * l / 3.0;
    d = -2.0 * a;
  } else if (a < 0.5 + l) {
    const double b = a - l, c = 1.5 - a - l;
    w = (0.5 - 0.75 * b + b * b * b / 3.0 - c * c * c / 6.0) * (0.5 * inv_l);
    d = (0.5 * c * c - (0.75 - b * b)) * (0.5 * inv_l);
  } else if (a <= 1.5 - l) {
    w = 0.5 * (1.5 - a) * (1.5 - a) + l * l / 6.0;
    d = a - 1.5;
  } else if (a < 1.5 + l) {
    const double c = 1.5 + l - a;
    w = c * c * c * (inv_l / 12.0);
    d = -c * c * (0.25 * inv_l);
  }
  return {w, xi < 0.0 ? -d : d};
}

inline double b2gimp_weight(double xi, double l) { return b2gimp(xi, l, 1.0 / l).w; }

// dS/dxi.
inline double b2gimp_slope(double xi, double l) { return b2gimp(xi, l, 1.0 / l).dw; }

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
  const double inv_l = 1.0 / l;
  for (int k = 0; k < 4; ++k) {
    const B2gimpValue v = b2gimp(X - (a.first + k), l, inv_l);
    a.w[k] = v.w;
    a.dw[k] = v.dw;
  }
  return a;
}

}  // namespace acst::mpm
