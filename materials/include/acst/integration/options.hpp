#pragma once
// Options of the stress-point integrators (docs/integration.md).
#include <string>

namespace acst::integration {

enum class Scheme {
  forward_euler,    // FE-N: N equal substeps, no error control
  modified_euler,   // ME: Heun-Euler 2(1) with Sloan's error control (the default)
  rk23,             // Bogacki-Shampine 3(2), error controlled
  rk45,             // Dormand-Prince 5(4), error controlled
};

// What to do with a point whose mean stress cannot be kept above p_min (free surface, tension).
enum class PressureFloorPolicy {
  reset,  // set it to an isotropic p_min state, count it, report ok
  fail,   // report a failure with a step-reduction request
};

struct Options {
  Scheme scheme = Scheme::modified_euler;
  double stol = 1e-4;          // relative local error tolerance of a substep
  double ftol = 1e-8;          // yield-surface tolerance
  double ltol = 1e-6;          // cosine threshold of the unload-then-reload test
  double min_substep = 1e-6;   // dT_min, pseudo-time
  int max_substeps = 100000;   // accepted + rejected, per call
  int fe_substeps = 1;         // N of FE-N
  int unload_scan_intervals = 10;  // NSUB of the unload-reload bracket scan
  int crossing_max_iterations = 60;
  bool reuse_last_substep = true;  // start from the substep size this point used last
  PressureFloorPolicy pressure_floor = PressureFloorPolicy::reset;
};

// The one check of the options' values, for every way in (the JSON reader adds its path,
// umat_'s PROPS go through acst::Material): "" when they are valid, else what is wrong and the
// allowed range, e.g. "stol = 5: allowed range (0, 1)".
std::string options_problem(const Options& o);

const char* scheme_name(Scheme s);
// Parses "FE", "ME", "RK23", "RK45" (case-sensitive); throws acst::InputError otherwise.
Scheme scheme_from_name(const std::string& name);

}  // namespace acst::integration
