#pragma once
// What one integrator call reports: status, reason, and the counters of its work and guards.

namespace acst::integration {

enum class Status {
  ok = 0,
  step_reduction_requested = 1,  // failed; retry with a smaller strain increment (suggested factor)
  invalid_input = 2,             // non-finite strain increment or options
  nonphysical_state = 3,         // non-finite or non-physical stress/state on entry
};

enum class Reason {
  none = 0,
  pressure_floor,        // a stage fell below p_min
  loss_of_uniqueness,    // non-positive loading-index denominator
  substep_too_small,     // dT fell below dT_min
  too_many_substeps,
  non_finite,            // NaN or inf appeared in a rate or a result
  void_ratio_range,      // the void ratio left (0, void_ratio_limit)
};

const char* status_name(Status s);
const char* reason_text(Reason r);

struct Counters {
  int substeps_accepted = 0;
  int substeps_rejected = 0;
  int rate_evaluations = 0;      // plastic and elastic rate evaluations
  int crossing_iterations = 0;   // Pegasus iterations for the elastic-plastic crossing
  int unload_reload = 0;         // calls that unloaded then reloaded within the increment
  // Guards (docs/model.md section 10): each counts the times it fired.
  int guard_pressure_floor = 0;  // a stage or trial fell below p_min
  int guard_small_R = 0;         // loading direction taken from the strain increment
  int guard_lode_clamp = 0;      // sin3theta clamped to [-1, 1]
  int guard_h_floor = 0;         // h = h1 - h2 e floored at h_min
  int guard_uniqueness = 0;      // non-positive loading-index denominator
  int pressure_floor_resets = 0; // point set to an isotropic p_min state

  Counters& operator+=(const Counters& o);
};

struct Report {
  Status status = Status::ok;
  Reason reason = Reason::none;
  double suggested_step_factor = 1.0;  // < 1 when a smaller increment is requested
  bool plastic = false;                // the call ended on a plastic substep
  Counters counters;
};

}  // namespace acst::integration
