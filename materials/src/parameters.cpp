#include "acst/parameters.hpp"

#include <cmath>
#include <limits>
#include <sstream>

namespace acst {

namespace {

struct Range {
  const char* name;
  double lo;
  bool lo_open;
  double hi;
  bool hi_open;
};

std::string describe(const Range& r) {
  std::ostringstream os;
  os << (r.lo_open ? "(" : "[") << r.lo << ", ";
  if (std::isinf(r.hi))
    os << "inf)";
  else
    os << r.hi << (r.hi_open ? ")" : "]");
  return os.str();
}

void check(const Range& r, double v) {
  const bool ok = std::isfinite(v) && (r.lo_open ? v > r.lo : v >= r.lo) && (r.hi_open ? v < r.hi : v <= r.hi);
  if (!ok) {
    std::ostringstream os;
    os << "parameter '" << r.name << "' = " << v << " is outside its allowed range " << describe(r);
    throw ParameterRangeError(os.str(), r.name);
  }
}

constexpr double inf = std::numeric_limits<double>::infinity();

}  // namespace

void validate(const Parameters& p) {
  check({"G0", 0, true, inf, true}, p.G0);
  check({"nu", 0, false, 0.5, true}, p.nu);
  check({"Mc", 0, true, 3, false}, p.Mc);
  // Below about 0.7 the deviatoric section of g(theta) is no longer convex (below sqrt(2) - 1
  // g(compression) is not even 1): such c would give non-unique loading directions.
  check({"c", 0.7, false, 1, false}, p.c);
  check({"e_Gamma", 0, true, 2.97, true}, p.e_Gamma);
  check({"lambda_c", 0, true, inf, true}, p.lambda_c);
  check({"xi", 0, true, 2, false}, p.xi);
  check({"d1", 0, true, inf, true}, p.d1);
  check({"m", 0, false, inf, true}, p.m);
  check({"h1", 0, true, inf, true}, p.h1);
  check({"h2", 0, false, inf, true}, p.h2);
  check({"n", 0, false, inf, true}, p.n);
  check({"e_A", 0, false, inf, true}, p.e_A);
  check({"F0", 0, false, inf, true}, p.F0);
  check({"k_f", 0, false, inf, true}, p.k_f);
  check({"e_min", 0, true, inf, true}, p.e_min);
  check({"e_max", p.e_min, true, 2.97, true}, p.e_max);
  check({"p_min", 0, true, inf, true}, p.p_min);
  check({"h_min", 0, true, inf, true}, p.h_min);
  check({"R_tolerance", 0, true, 1e-3, false}, p.R_tolerance);
  if (p.variant == Variant::isotropic && (p.F0 != 0.0 || p.e_A != 0.0 || p.k_f != 0.0))
    throw InputError("the isotropic model has no fabric: parameters 'F0', 'e_A' and 'k_f' must be 0 or absent");
}

double& parameter_by_index(Parameters& p, int i) {
  double* slots[] = {&p.G0, &p.nu, &p.Mc, &p.c,   &p.e_Gamma, &p.lambda_c, &p.xi,    &p.d1,    &p.m,
                     &p.h1, &p.h2, &p.n,  &p.e_A, &p.F0,      &p.k_f,      &p.e_max, &p.e_min, &p.p_min};
  if (i < 0 || i >= parameter_count) throw InputError("parameter index out of range");
  return *slots[i];
}

double parameter_by_index(const Parameters& p, int i) { return parameter_by_index(const_cast<Parameters&>(p), i); }

}  // namespace acst
