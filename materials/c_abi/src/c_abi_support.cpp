#include "c_abi_support.hpp"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "abi_convention.hpp"
#include "acst/reference/von_mises.hpp"
#include "state_layout.hpp"

namespace acst::abi {

acst_status make_status(int code, const std::string& message, double factor) {
  acst_status s;
  s.code = code;
  s.suggested_step_factor = factor;
  std::snprintf(s.message, sizeof s.message, "%s", message.c_str());
  return s;
}

acst_status ok_status() {
  acst_status s;
  s.code = ACST_OK;
  s.suggested_step_factor = 1.0;
  s.message[0] = '\0';
  return s;
}

void copy_counters(const integration::Report& r, acst_counters* out) {
  const integration::Counters& c = r.counters;
  *out = acst_counters{c.substeps_accepted, c.substeps_rejected, c.rate_evaluations,  c.crossing_iterations,
                       c.unload_reload,     c.guard_pressure_floor, c.guard_small_R,   c.guard_lode_clamp,
                       c.guard_h_floor,     c.guard_uniqueness,  c.pressure_floor_resets, r.plastic ? 1 : 0};
}

acst_status status_from_report(const integration::Report& r) {
  switch (r.status) {
    case integration::Status::ok: return ok_status();
    case integration::Status::step_reduction_requested:
      return make_status(ACST_STEP_REDUCTION,
                         std::string("integration failed: ") + integration::reason_text(r.reason) +
                             "; retry with a smaller strain increment",
                         r.suggested_step_factor);
    case integration::Status::invalid_input:
      return make_status(ACST_INVALID_INPUT, "strain increment is not finite", 1.0);
    case integration::Status::nonphysical_state:
      return make_status(ACST_NONPHYSICAL_STATE, "stress or state variables are non-finite or non-physical", 1.0);
  }
  return make_status(ACST_INTERNAL_ERROR, "unknown integrator status", 1.0);
}

// Before any is converted (the reset count to an integer, where a NaN would be undefined
// behaviour); the substep hint alone may be anything (no number: no hint).
bool state_variables_finite(const double* statev) {
  bool finite = true;
  for (int i = 0; i < state_size; ++i) finite = finite && (i == slot_substep_hint || std::isfinite(statev[i]));
  return finite;
}

acst_status update_point(double* stress, double* statev, double* tangent, const Material& mat, const double* dstrain,
                         integration::Report& rep, double void_ratio_offset) {
  if (!state_variables_finite(statev)) {
    rep = integration::Report{};
    rep.status = integration::Status::nonphysical_state;
    return status_from_report(rep);
  }
  State s;
  s.stress = stress_to_model(stress);
  fill_state(s, statev);
  Mat6 D;
  rep = mat.update(s, strain_to_model(dstrain), tangent ? &D : nullptr, void_ratio_offset);
  if (rep.status != integration::Status::ok) return status_from_report(rep);
  stress_from_model(s.stress, stress);
  store_state(s, statev);
  if (tangent) tangent_from_model(D, tangent);
  return ok_status();
}

bool entry_ok(const Sym& stress, bool state_ok, const Sym& strain_increment, integration::Report& rep) {
  rep = integration::Report{};
  if (!strain_increment.allFinite())
    rep.status = integration::Status::invalid_input;
  else if (!stress.allFinite() || !state_ok)
    rep.status = integration::Status::nonphysical_state;
  return rep.status == integration::Status::ok;
}

bool all_finite(const double* values, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(values[i])) return false;
  return true;
}

acst_status nonfinite_result(const std::string& what) {
  return make_status(ACST_STEP_REDUCTION, what + " came out non-finite; retry with a smaller strain increment", 0.5);
}

acst_status text_to_buffer(const std::string& text, char* buffer, size_t* length, const char* function) {
  const size_t needed = text.size() + 1;
  const size_t room = *length;
  *length = needed;
  if (!buffer) return ok_status();
  if (room < needed)
    return make_status(ACST_INVALID_INPUT,
                       std::string(function) + ": the buffer of " + std::to_string(room) + " bytes is too small; the text needs " +
                           std::to_string(needed) + " (nothing was written)",
                       1.0);
  std::memcpy(buffer, text.c_str(), needed);
  return ok_status();
}

bool reference_diagnostic(int i) { return i == 0 || i == 1 || i == ACST_NDIAGNOSTICS - 2 || i == ACST_NDIAGNOSTICS - 1; }

void reference_diagnostics(double* out, const Sym& stress, const ElasticModuli& m) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double v[ACST_NDIAGNOSTICS] = {trace(stress) / 3.0, reference::equivalent_stress(stress), nan, nan, nan, nan,
                                       nan, nan, nan, nan, nan, m.G, m.K};
  std::memcpy(out, v, sizeof v);
}

}  // namespace acst::abi
