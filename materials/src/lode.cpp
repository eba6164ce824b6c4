#include "acst/lode.hpp"

#include <algorithm>

namespace acst {

namespace {

double cosine_from_sin3theta(double sin3theta) { return std::cos(std::acos(std::clamp(sin3theta, -1.0, 1.0)) / 3.0); }

// x from the principal values where there is shear in the plane only (include/acst/lode.hpp).
double willam_warnke_cosine(double sin3theta, const double* a, double scale) {
  return plane_shear(a) ? cosine_from_principal_values(a, scale) : cosine_from_sin3theta(sin3theta);
}

}  // namespace

LodeInterpolation willam_warnke_interpolation(double c, double sin3theta) {
  return willam_warnke_at(c, cosine_from_sin3theta(sin3theta));
}

LodeInterpolation willam_warnke_interpolation(double c, double sin3theta, const double* a, double scale) {
  return willam_warnke_at(c, willam_warnke_cosine(sin3theta, a, scale));
}

// dg/ds is not computed: the compiler drops what only it reads.
double willam_warnke_g(double c, double sin3theta, const double* a, double scale) {
  return willam_warnke_at(c, willam_warnke_cosine(sin3theta, a, scale)).g;
}

}  // namespace acst
