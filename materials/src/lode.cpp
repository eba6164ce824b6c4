#include "acst/lode.hpp"

namespace acst {

LodeInterpolation willam_warnke_interpolation(double c, double sin3theta) {
  const double a = 1.0 - c * c, b = 2.0 * c - 1.0;
  const double x = std::cos(std::acos(std::clamp(sin3theta, -1.0, 1.0)) / 3.0);
  const double root = std::sqrt(std::max(4.0 * a * x * x + 5.0 * c * c - 4.0 * c, 0.0));
  const double num = 2.0 * a * x + b * root, den = 4.0 * a * x * x + b * b;
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

}  // namespace acst
