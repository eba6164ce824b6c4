#include "acst/integration/options.hpp"

#include <string>

#include "acst/integration/report.hpp"
#include "acst/parameters.hpp"

namespace acst::integration {

std::string options_problem(const Options& o) {
  const auto fraction = [](const char* name, double v, bool one_allowed) {
    if (v > 0.0 && (v < 1.0 || (one_allowed && v == 1.0))) return std::string();
    return std::string(name) + " = " + std::to_string(v) + ": allowed range (0, 1" + (one_allowed ? "]" : ")");
  };
  const auto count = [](const char* name, int v) {
    return v >= 1 && v <= 100000000 ? std::string()
                                     : std::string(name) + " = " + std::to_string(v) + ": allowed range [1, 100000000]";
  };
  for (const std::string& m : {fraction("stol", o.stol, true), fraction("ftol", o.ftol, true), fraction("ltol", o.ltol, true),
                               fraction("min_substep", o.min_substep, false), count("max_substeps", o.max_substeps),
                               count("fe_substeps", o.fe_substeps), count("unload_scan_intervals", o.unload_scan_intervals),
                               count("crossing_max_iterations", o.crossing_max_iterations)})
    if (!m.empty()) return m;
  return "";
}

const char* scheme_name(Scheme s) {
  switch (s) {
    case Scheme::forward_euler: return "FE";
    case Scheme::modified_euler: return "ME";
    case Scheme::rk23: return "RK23";
    case Scheme::rk45: return "RK45";
  }
  return "?";
}

Scheme scheme_from_name(const std::string& name) {
  for (Scheme s : {Scheme::forward_euler, Scheme::modified_euler, Scheme::rk23, Scheme::rk45})
    if (name == scheme_name(s)) return s;
  throw InputError("unknown integration scheme '" + name + "' (allowed: FE, ME, RK23, RK45)");
}

const char* status_name(Status s) {
  switch (s) {
    case Status::ok: return "ok";
    case Status::step_reduction_requested: return "step reduction requested";
    case Status::invalid_input: return "invalid input";
    case Status::nonphysical_state: return "non-physical state";
  }
  return "?";
}

const char* reason_text(Reason r) {
  switch (r) {
    case Reason::none: return "none";
    case Reason::pressure_floor: return "mean stress fell below p_min";
    case Reason::loss_of_uniqueness: return "non-positive loading-index denominator (loss of uniqueness)";
    case Reason::substep_too_small: return "substep fell below the minimum size";
    case Reason::too_many_substeps: return "more substeps than allowed";
    case Reason::non_finite: return "non-finite value (NaN or inf)";
    case Reason::void_ratio_range: return "void ratio left its range (0, 2.97)";
  }
  return "?";
}

Counters& Counters::operator+=(const Counters& o) {
  substeps_accepted += o.substeps_accepted;
  substeps_rejected += o.substeps_rejected;
  rate_evaluations += o.rate_evaluations;
  crossing_iterations += o.crossing_iterations;
  unload_reload += o.unload_reload;
  guard_pressure_floor += o.guard_pressure_floor;
  guard_small_R += o.guard_small_R;
  guard_lode_clamp += o.guard_lode_clamp;
  guard_h_floor += o.guard_h_floor;
  guard_uniqueness += o.guard_uniqueness;
  pressure_floor_resets += o.pressure_floor_resets;
  return *this;
}

}  // namespace acst::integration
