#pragma once
// Helpers shared by the acst_* functions, the model kinds and umat_.
#include <string>

#include "acst.h"
#include "acst/elasticity.hpp"
#include "acst/integration/report.hpp"
#include "acst/material.hpp"

namespace acst::abi {

acst_status make_status(int code, const std::string& message, double factor);
acst_status ok_status();  // no formatting: it is on the hot path
acst_status status_from_report(const integration::Report& r);
void copy_counters(const integration::Report& r, acst_counters* out);

// Whether a sand point's state variables may be converted (all finite but the substep hint).
bool state_variables_finite(const double* statev);

// Converts, updates one sand point, converts back; stress and statev untouched on failure.
// `void_ratio_offset`: the host's nonlocal offset (Material::update).
acst_status update_point(double* stress, double* statev, double* tangent, const Material& mat, const double* dstrain,
                         integration::Report& rep, double void_ratio_offset = 0.0);

// Entry checks of the closed-form updates, reported like the integrator's: false (and `rep`
// says why) for a non-finite increment, stress or state.
bool entry_ok(const Sym& stress, bool state_ok, const Sym& strain_increment, integration::Report& rep);

// The OK rule (acst.h): an output with a NaN or an infinity is never returned with ACST_OK.
bool all_finite(const double* values, int n);
// A result that came out non-finite from finite inputs: ask for a smaller increment.
acst_status nonfinite_result(const std::string& what);

// Copies `text` into a host's buffer with snprintf-like rules (acst.h, acst_reproducer).
acst_status text_to_buffer(const std::string& text, char* buffer, size_t* length, const char* function);

// Diagnostics of a verification kind: p, q, G and K; the sand-specific entries are NaN.
void reference_diagnostics(double* out, const Sym& stress, const ElasticModuli& moduli);
bool reference_diagnostic(int i);  // whether entry i is one of those four

}  // namespace acst::abi
