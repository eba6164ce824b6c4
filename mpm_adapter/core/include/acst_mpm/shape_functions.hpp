#pragma once
// B2GIMP shape functions: quadratic B-spline grid functions averaged over a uniform, undeformed
// particle domain of half-width l cells (l = 1/(2 n) for n particles per cell and direction).
// xi = (x_p - x_i)/h is the particle-node distance in cells; S is the weight, dS its derivative
// with respect to xi (divide by h for the spatial gradient).
#include <cmath>

#include "acst_common/double_pair.hpp"

namespace acst::mpm {

// The weights are bound by the divider (24 scalar divisions per particle and step): the terms
// that depend on l alone are worked out once, and the rest are divided in pairs (the same
// numbers).
using common::DoublePair;

// The terms of the ranges that depend on l alone, worked out once per loop rather than per
// weight; each is the expression the ranges were written with, so the weights are the same.
struct B2gimpDomain {
  explicit B2gimpDomain(double half_width)
      : l(half_width),
        inv_l(1.0 / l),
        l2_third(l * l / 3.0),
        l2_sixth(l * l / 6.0),
        half_inv_l(0.5 * inv_l),
        quarter_inv_l(0.25 * inv_l),
        inv_l_twelfth(inv_l / 12.0) {}
  double l, inv_l, l2_third, l2_sixth, half_inv_l, quarter_inv_l, inv_l_twelfth;
};

// 1-D weight S(xi) and slope dS/dxi together, in one pass over the ranges (docs/mpm.md, "One
// step", phase 1; mpm-core design note table). One function for both keeps the ranges
// written once; the particle loops call it 8 times per particle and step.
struct B2gimpValue {
  double w, dw;
};

inline B2gimpValue b2gimp(double xi, const B2gimpDomain& D) {
  const double a = std::fabs(xi), l = D.l;
  double w = 0.0, d = 0.0;
  if (a < 0.5 - l) {
    w = 0.75 - a * a - D.l2_third;
    d = -2.0 * a;
  } else if (a < 0.5 + l) {
    const double b = a - l, c = 1.5 - a - l;
    const DoublePair cubes = DoublePair{b * b * b, c * c * c} / DoublePair{3.0, 6.0};  // b^3/3, c^3/6
    w = (0.5 - 0.75 * b + cubes[0] - cubes[1]) * D.half_inv_l;
    d = (0.5 * c * c - (0.75 - b * b)) * D.half_inv_l;
  } else if (a <= 1.5 - l) {
    w = 0.5 * (1.5 - a) * (1.5 - a) + D.l2_sixth;
    d = a - 1.5;
  } else if (a < 1.5 + l) {
    const double c = 1.5 + l - a;
    w = c * c * c * D.inv_l_twelfth;
    d = -c * c * D.quarter_inv_l;
  }
  return {w, xi < 0.0 ? -d : d};
}

inline double b2gimp_weight(double xi, double l) { return b2gimp(xi, B2gimpDomain(l)).w; }

// dS/dxi.
inline double b2gimp_slope(double xi, double l) { return b2gimp(xi, B2gimpDomain(l)).dw; }

// The 4 nodes along one axis that can carry weight for a particle at X = (x - x_origin)/h
// (support half-width 1.5 + l <= 2 cells): nodes first .. first + 3.
struct AxisWeights {
  int first;
  double w[4];
  double dw[4];  // dS/dxi: divide by h for d/dx
};

inline AxisWeights axis_weights(double X, const B2gimpDomain& D) {
  AxisWeights a;
  a.first = static_cast<int>(std::floor(X)) - 1;
  for (int k = 0; k < 4; ++k) {
    const B2gimpValue v = b2gimp(X - (a.first + k), D);
    a.w[k] = v.w;
    a.dw[k] = v.dw;
  }
  return a;
}

inline AxisWeights axis_weights(double X, double l) { return axis_weights(X, B2gimpDomain(l)); }

}  // namespace acst::mpm
