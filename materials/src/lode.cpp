#include "acst/lode.hpp"

namespace acst {

namespace {

// g's numerator and denominator at x = cos(theta_w) (include/acst/lode.hpp).
struct Quotient {
  double a, b, root, num, den;
};

Quotient willam_warnke_quotient(double c, double x) {
  const double a = 1.0 - c * c, b = 2.0 * c - 1.0;
  const double root = std::sqrt(std::max(4.0 * a * x * x + 5.0 * c * c - 4.0 * c, 0.0));
  return {a, b, root, 2.0 * a * x + b * root, 4.0 * a * x * x + b * b};
}

// g and dg/ds at x.
LodeInterpolation willam_warnke_at(double c, double x) {
  const auto [a, b, root, num, den] = willam_warnke_quotient(c, x);
  const double g = num / den;
  const double delta = x - 0.5;
  if (delta < 1e-6) {
    const double b2 = b * b;
    return {g, -a / (3.0 * b2) + delta * a * (2.0 - c) * (2.0 - c) / (3.0 * b2 * b2)};
  }
  const double dnum = 2.0 * a + (root > 0.0 ? b * 4.0 * a * x / root : 0.0), dden = 8.0 * a * x;
  const double dg_dx = (dnum * den - num * dden) / (den * den);
  return {g, dg_dx / (12.0 * delta * (x + 0.5))};
}

double cosine_from_sin3theta(double sin3theta) { return std::cos(std::acos(std::clamp(sin3theta, -1.0, 1.0)) / 3.0); }

// x = -sqrt(3/2) min eig(scale a) for a with a_13 = a_23 = 0: a_33 and the in-plane pair
// m -+ sqrt(d^2 + a_12^2) are a's principal values.
double cosine_from_principal_values(const Sym& a, double scale) {
  const double m = 0.5 * (a[0] + a[1]), d = 0.5 * (a[0] - a[1]);
  const double radius = std::sqrt(d * d + a[3] * a[3]);
  const double lowest = scale > 0.0 ? std::min(a[2], m - radius) : std::max(a[2], m + radius);
  return std::clamp(-std::sqrt(1.5) * scale * lowest, 0.5, 1.0);
}

// x from the principal values where there is shear in the plane only (include/acst/lode.hpp).
double willam_warnke_cosine(double sin3theta, const Sym& a, double scale) {
  const bool plane_shear = a[3] != 0.0 && a[4] == 0.0 && a[5] == 0.0;
  return plane_shear ? cosine_from_principal_values(a, scale) : cosine_from_sin3theta(sin3theta);
}

}  // namespace

LodeInterpolation willam_warnke_interpolation(double c, double sin3theta) {
  return willam_warnke_at(c, cosine_from_sin3theta(sin3theta));
}

LodeInterpolation willam_warnke_interpolation(double c, double sin3theta, const Sym& a, double scale) {
  return willam_warnke_at(c, willam_warnke_cosine(sin3theta, a, scale));
}

double willam_warnke_g(double c, double sin3theta, const Sym& a, double scale) {
  const Quotient q = willam_warnke_quotient(c, willam_warnke_cosine(sin3theta, a, scale));
  return q.num / q.den;
}

}  // namespace acst
