#pragma once
// Lode angle and the Lode interpolation function g(theta): Li (2002), the default, or, as an
// option, Willam & Warnke (1975) (docs/model.md section 1).
#include <cmath>

#include "acst/inline.hpp"
#include "acst/tensor.hpp"

namespace acst {

// sin(3 theta) = -sqrt(6) tr(r_hat^3) for a unit deviatoric r_hat; -1 in triaxial compression,
// +1 in extension. For a traceless tensor tr(a^3) = 3 det(a). Unclamped: callers clamp and count.
ACST_INLINE double lode_sin3theta_unclamped(const double* unit_deviator) {
  return -std::sqrt(6.0) * 3.0 * determinant(unit_deviator);
}

inline double lode_sin3theta_unclamped(const Sym& unit_deviator) { return lode_sin3theta_unclamped(unit_deviator.data()); }

struct LodeInterpolation {
  double g;       // g(theta), 1 in compression, c in extension
  double dg_ds;   // dg/d(sin 3theta)
};

// g = [sqrt((1+c^2)^2 + 4c(1-c^2)s) - (1+c^2)] / [2(1-c)s], written in the rationalised form
// g = 2c(1+c) / [(1+c^2) + sqrt((1+c^2)^2 + 4c(1-c^2)s)] that has no 0/0 at s = 0 nor at c = 1.
ACST_INLINE LodeInterpolation lode_interpolation(double c, double sin3theta) {
  const double a = 1.0 + c * c;
  const double b = 4.0 * c * (1.0 - c * c);
  // The radicand is >= (1 - 2c - c^2)^2 >= 0 for s in [-1, 1]; the floor only guards round-off.
  const double root = std::sqrt(max_of(a * a + b * sin3theta, 1e-300));
  const double g = 2.0 * c * (1.0 + c) / (a + root);
  const double dg_ds = -g * b / (2.0 * root * (a + root));
  return {g, dg_ds};
}

// Willam & Warnke (1975)'s elliptic interpolation with r_c = 1, r_t = c; in terms of
// x = cos(theta_w), theta_w = acos(s)/3 the angle from the extension meridian (s = 4x^3 - 3x):
//   g = [2(1-c^2) x + (2c-1) sqrt(4(1-c^2) x^2 + 5c^2 - 4c)] / [4(1-c^2) x^2 + (2c-1)^2].
// Convex for 1/2 < c <= 1, so it reaches lower c than Li's form (convex from 0.7),
// and at a given c it is lower between the meridians. dg/ds = (dg/dx)/(12x^2 - 3); at triaxial
// compression (x = 1/2) both vanish, and within delta = x - 1/2 < 1e-6 of it the quotient loses
// digits, so there dg/ds takes its expansion -a/(3b^2) + delta a (2-c)^2/(3b^4), a = 1-c^2,
// b = 2c-1 (derived symbolically; tests/materials/lode_willam_warnke_test.cpp checks the joint). The arc is
// continued by reflection across the meridians, so g is C2 there, not analytic: dg/ds has a
// sqrt(1 + s) term at compression.
// Out of line (src/lode.cpp): inlined, its acos and cos slowed every update with Li's form by
// 4-11 %.
LodeInterpolation willam_warnke_interpolation(double c, double sin3theta);

// The same for the unit deviator u = scale a whose sin 3theta is sin3theta, with x taken from
// u's principal values where that is cheaper: 4x^3 - 3x = s has the principal values of
// -sqrt(3/2) u as its roots, and acos(s)/3 in [0, pi/3] picks the largest, so x = -sqrt(3/2)
// min eig(u). With shear in the 1-2 plane only (a_12 != 0, a_13 = a_23 = 0: an MPM host's
// states) that eigenvalue costs one square root instead of acos and cos, a tenth of a footing's
// time, and is the more accurate near the meridians, where acos(s) of an s
// rounded near -1 puts theta 1e-8 off. Other states take x from s as before: among them are the
// element tests' diagonal states, which the delivered sets were fitted with, and the fit follows
// even round-off changes of their results to another set (0.4 standard errors away, measured;
// data/calibration/README.md). tests/materials/lode_willam_warnke_test.cpp checks both paths.
LodeInterpolation willam_warnke_interpolation(double c, double sin3theta, const double* a, double scale);

// Its g alone, the same number, for the yield value (which has no use for dg/ds and its divisions).
double willam_warnke_g(double c, double sin3theta, const double* a, double scale);

// Their arithmetic, shared with the lanes' kernel (acst/inline.hpp).

// g's numerator and denominator at x = cos(theta_w), with the a, b and root they are made of.
struct WillamWarnkeQuotient {
  double a, b, root, num, den;
};

ACST_INLINE WillamWarnkeQuotient willam_warnke_quotient(double c, double x) {
  const double a = 1.0 - c * c, b = 2.0 * c - 1.0;
  const double root = std::sqrt(max_of(4.0 * a * x * x + 5.0 * c * c - 4.0 * c, 0.0));
  return {a, b, root, 2.0 * a * x + b * root, 4.0 * a * x * x + b * b};
}

// dg/ds = (dg/dx)/(12 delta (x + 1/2)) at x = 1/2 + delta, away from compression.
ACST_INLINE double willam_warnke_slope(const WillamWarnkeQuotient& q, double x, double delta) {
  const double dnum = 2.0 * q.a + (q.root > 0.0 ? q.b * 4.0 * q.a * x / q.root : 0.0), dden = 8.0 * q.a * x;
  const double dg_dx = (dnum * q.den - q.num * dden) / (q.den * q.den);
  return dg_dx / (12.0 * delta * (x + 0.5));
}

// dg/ds's expansion within delta < 1e-6 of compression (above).
ACST_INLINE double willam_warnke_slope_near_compression(const WillamWarnkeQuotient& q, double c, double delta) {
  const double b2 = q.b * q.b;
  return -q.a / (3.0 * b2) + delta * q.a * (2.0 - c) * (2.0 - c) / (3.0 * b2 * b2);
}

// g and dg/ds at x = cos(theta_w). Both slopes are cheap: the lanes' kernel computes the two and
// selects, the scalar code branches (the same numbers).
ACST_INLINE LodeInterpolation willam_warnke_at(double c, double x) {
  const WillamWarnkeQuotient q = willam_warnke_quotient(c, x);
  const double delta = x - 0.5;
  return {q.num / q.den,
          delta < 1e-6 ? willam_warnke_slope_near_compression(q, c, delta) : willam_warnke_slope(q, x, delta)};
}

// Whether a has shear in the 1-2 plane only, where x comes from its principal values (& rather
// than &&: no branch in the lanes' vector loops).
ACST_INLINE bool plane_shear(const double* a) { return (a[3] != 0.0) & (a[4] == 0.0) & (a[5] == 0.0); }

// x = -sqrt(3/2) min eig(scale a) for a with a_13 = a_23 = 0: a_33 and the in-plane pair
// m -+ sqrt(d^2 + a_12^2) are a's principal values.
ACST_INLINE double cosine_from_principal_values(const double* a, double scale) {
  const double m = 0.5 * (a[0] + a[1]), d = 0.5 * (a[0] - a[1]);
  const double radius = std::sqrt(d * d + a[3] * a[3]);
  const double lowest = scale > 0.0 ? min_of(a[2], m - radius) : max_of(a[2], m + radius);
  return clamp_of(-std::sqrt(1.5) * scale * lowest, 0.5, 1.0);
}

enum class LodeForm { li2002, willam_warnke };

// The Lode interpolation a material uses: its c and its form (Li 2002 unless chosen otherwise).
// Implicit from c alone, for the default form.
struct LodeShape {
  LodeShape(double c_, LodeForm form_ = LodeForm::li2002) : c(c_), form(form_) {}  // NOLINT(google-explicit-constructor)
  double c;
  LodeForm form;
};

inline LodeInterpolation lode_interpolation(const LodeShape& shape, double sin3theta) {
  return shape.form == LodeForm::willam_warnke ? willam_warnke_interpolation(shape.c, sin3theta)
                                               : lode_interpolation(shape.c, sin3theta);
}

// The same for sin3theta of the unit deviator scale a (scale != 0), which Willam & Warnke's form
// uses for a cheaper angle.
inline LodeInterpolation lode_interpolation(const LodeShape& shape, double sin3theta, const double* a, double scale) {
  return shape.form == LodeForm::willam_warnke ? willam_warnke_interpolation(shape.c, sin3theta, a, scale)
                                               : lode_interpolation(shape.c, sin3theta);
}

inline LodeInterpolation lode_interpolation(const LodeShape& shape, double sin3theta, const Sym& a, double scale) {
  return lode_interpolation(shape, sin3theta, a.data(), scale);
}

// g alone, for the same arguments.
inline double lode_g(const LodeShape& shape, double sin3theta, const double* a, double scale) {
  return shape.form == LodeForm::willam_warnke ? willam_warnke_g(shape.c, sin3theta, a, scale)
                                               : lode_interpolation(shape.c, sin3theta).g;
}

inline double lode_g(const LodeShape& shape, double sin3theta, const Sym& a, double scale) {
  return lode_g(shape, sin3theta, a.data(), scale);
}

}  // namespace acst
