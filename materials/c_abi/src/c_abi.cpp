// The C ABI: thin wrappers over acst::Material and the reference materials that never let an
// exception escape.
#include <Eigen/LU>  // determinant of the rotation
#include <cmath>
#include <cstdio>
#include <cstring>
#include <exception>
#include <limits>
#include <new>
#include <string>
#include <variant>

#include "abi_convention.hpp"
#include "acst.h"
#include "acst/elasticity.hpp"
#include "acst/fabric.hpp"
#include "acst/json_input.hpp"
#include "acst/material.hpp"
#include "acst/reference/linear_elastic.hpp"
#include "acst/reference/von_mises.hpp"
#include "c_abi_support.hpp"
#include "state_layout.hpp"

struct acst_model {
  acst::AnyModel kind;
};

namespace acst::abi {

acst_status make_status(int code, const std::string& message, double factor) {
  acst_status s;
  s.code = code;
  s.suggested_step_factor = factor;
  std::snprintf(s.message, sizeof s.message, "%s", message.c_str());
  return s;
}

acst_status ok_status() {
  acst_status s;  // no formatting on the hot path
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

acst_status update_point(double* stress, double* statev, double* tangent, const Material& mat, const double* dstrain,
                         integration::Report& rep) {
  State s;
  s.stress = stress_to_model(stress);
  fill_state(s, statev);
  Mat6 D;
  rep = mat.update(s, strain_to_model(dstrain), tangent ? &D : nullptr);
  if (rep.status != integration::Status::ok) return status_from_report(rep);
  stress_from_model(s.stress, stress);
  store_state(s, statev);
  if (tangent) tangent_from_model(D, tangent);
  return ok_status();
}

// Entry checks of the closed-form updates, reported like the integrator's.
bool entry_ok(const Sym& stress, bool state_ok, const Sym& strain_increment, integration::Report& rep) {
  rep = integration::Report{};
  if (!strain_increment.allFinite())
    rep.status = integration::Status::invalid_input;
  else if (!stress.allFinite() || !state_ok)
    rep.status = integration::Status::nonphysical_state;
  return rep.status == integration::Status::ok;
}

acst_status update_point(double* stress, double*, double* tangent, const reference::LinearElastic& m,
                         const double* dstrain, integration::Report& rep) {
  const Sym s = stress_to_model(stress), deps = strain_to_model(dstrain);
  if (!entry_ok(s, true, deps, rep)) return status_from_report(rep);
  stress_from_model(reference::updated_stress(m, s, deps), stress);
  if (tangent) tangent_from_model(reference::stiffness(m), tangent);
  return ok_status();
}

acst_status update_point(double* stress, double* statev, double* tangent, const reference::VonMises& m,
                         const double* dstrain, integration::Report& rep) {
  reference::VonMisesPoint point{stress_to_model(stress), statev[0]};
  const Sym deps = strain_to_model(dstrain);
  const bool state_ok = std::isfinite(point.equivalent_plastic_strain) && point.equivalent_plastic_strain >= 0.0;
  if (!entry_ok(point.stress, state_ok, deps, rep)) return status_from_report(rep);
  Mat6 D;
  rep.plastic = reference::radial_return(m, point, deps, tangent ? &D : nullptr);
  stress_from_model(point.stress, stress);
  statev[0] = point.equivalent_plastic_strain;
  if (tangent) tangent_from_model(D, tangent);
  return ok_status();
}

acst_status update_any(double* stress, double* statev, double* tangent, const acst_model& model,
                       const double* dstrain, integration::Report& rep) {
  return std::visit([&](const auto& m) { return update_point(stress, statev, tangent, m, dstrain, rep); },
                    model.kind);
}

const Material* sand_model(const acst_model& model) { return std::get_if<Material>(&model.kind); }

ElasticModuli reference_moduli(const acst_model& model) {
  if (const auto* m = std::get_if<reference::VonMises>(&model.kind)) return reference::moduli(m->elastic);
  return reference::moduli(std::get<reference::LinearElastic>(model.kind));
}

int state_size_of(const acst_model& model) {
  if (sand_model(model)) return state_size;
  return std::holds_alternative<reference::VonMises>(model.kind) ? von_mises_state_size : 0;
}

}  // namespace acst::abi

using namespace acst::abi;

#define ACST_GUARD(...)                                                       \
  try {                                                                        \
    __VA_ARGS__                                                                \
  } catch (const acst::InputError& e) {                                        \
    return make_status(ACST_INVALID_INPUT, e.what(), 1.0);                     \
  } catch (const std::bad_alloc&) {                                            \
    return make_status(ACST_INTERNAL_ERROR, "out of memory", 1.0);             \
  } catch (const std::exception& e) {                                          \
    return make_status(ACST_INTERNAL_ERROR, e.what(), 1.0);                    \
  } catch (...) {                                                              \
    return make_status(ACST_INTERNAL_ERROR, "unknown exception", 1.0);         \
  }

#define ACST_REQUIRE(cond, text) \
  if (!(cond)) return make_status(ACST_INVALID_INPUT, text, 1.0)

extern "C" {

acst_status acst_model_create(acst_model** model, const char* json_text) {
  ACST_REQUIRE(model, "acst_model_create: model pointer is NULL");
  *model = nullptr;
  ACST_REQUIRE(json_text, "acst_model_create: JSON text is NULL");
  ACST_GUARD({
    *model = new acst_model{acst::any_model_from_json(json_text)};
    return ok_status();
  })
}

void acst_model_destroy(acst_model* model) { delete model; }

int acst_state_size(const acst_model* model) { return model ? state_size_of(*model) : 0; }

const char* acst_state_name(const acst_model* model, int i) {
  if (!model || i < 0 || i >= state_size_of(*model)) return nullptr;
  return sand_model(*model) ? state_names[i] : von_mises_state_names[i];
}

const char* acst_model_kind(const acst_model* model) {
  if (!model) return nullptr;
  if (const acst::Material* sand = sand_model(*model))
    return sand->parameters().variant == acst::Variant::isotropic ? "isotropic" : "ACST";
  return std::holds_alternative<acst::reference::VonMises>(model->kind) ? "von_mises" : "linear_elastic";
}

acst_status acst_initial_state(double* statev, double* stress_out, const acst_model* model, const double* stress0,
                               double void_ratio, const double* deposition_direction) {
  ACST_REQUIRE(stress_out && model && stress0 && (statev || state_size_of(*model) == 0),
               "acst_initial_state: a pointer argument is NULL");
  const acst::Material* sand = sand_model(*model);
  ACST_REQUIRE(deposition_direction || !sand, "acst_initial_state: a pointer argument is NULL");
  ACST_GUARD({
    if (sand) {
      const Eigen::Vector3d b(deposition_direction[0], deposition_direction[1], deposition_direction[2]);
      const acst::State s = sand->initial_state(stress_to_model(stress0), void_ratio, b);
      store_state(s, statev);
      stress_from_model(s.stress, stress_out);
      return ok_status();
    }
    const acst::Sym s = stress_to_model(stress0);
    ACST_REQUIRE(s.allFinite(), "acst_initial_state: initial stress is not finite");
    if (const auto* vm = std::get_if<acst::reference::VonMises>(&model->kind)) {
      if (!acst::reference::within_yield_surface(*vm, s))
        return make_status(ACST_NONPHYSICAL_STATE,
                           "acst_initial_state: initial stress lies outside the von Mises yield surface (q = " +
                               std::to_string(acst::reference::equivalent_stress(s)) +
                               " kPa > yield_stress = " + std::to_string(vm->yield_stress) + " kPa)",
                           1.0);
      statev[0] = 0.0;
    }
    stress_from_model(s, stress_out);
    return ok_status();
  })
}

acst_status acst_bedding_direction(double* b, double alpha_degrees, int major_axis, int minor_axis,
                                   double minor_sign) {
  ACST_REQUIRE(b, "acst_bedding_direction: output pointer is NULL");
  ACST_REQUIRE(major_axis >= 0 && major_axis < 3 && minor_axis >= 0 && minor_axis < 3 && major_axis != minor_axis,
               "acst_bedding_direction: axes must be two different indices in 0..2");
  ACST_REQUIRE(std::isfinite(alpha_degrees) && (minor_sign == 1.0 || minor_sign == -1.0),
               "acst_bedding_direction: alpha must be finite and minor_sign +1 or -1");
  const Eigen::Vector3d v = acst::bedding_direction(alpha_degrees, major_axis, minor_axis, minor_sign);
  for (int i = 0; i < 3; ++i) b[i] = v[i];
  return ok_status();
}

acst_status acst_void_ratio_from_relative_density(double* void_ratio, const acst_model* model,
                                                  double relative_density) {
  ACST_REQUIRE(void_ratio && model, "acst_void_ratio_from_relative_density: a pointer argument is NULL");
  const acst::Material* sand = sand_model(*model);
  ACST_REQUIRE(sand, "acst_void_ratio_from_relative_density: only for sand models (ACST, isotropic)");
  ACST_REQUIRE(relative_density >= 0.0 && relative_density <= 1.0,
               "acst_void_ratio_from_relative_density: relative density must lie in [0, 1]");
  *void_ratio = acst::void_ratio_from_relative_density(sand->parameters(), relative_density);
  return ok_status();
}

acst_status acst_update(double* stress, double* statev, double* tangent, acst_counters* counters,
                        const acst_model* model, const double* dstrain) {
  ACST_REQUIRE(stress && model && dstrain && (statev || state_size_of(*model) == 0),
               "acst_update: a required pointer argument is NULL");
  ACST_GUARD({
    acst::integration::Report rep;
    const acst_status st = update_any(stress, statev, tangent, *model, dstrain, rep);
    if (counters) copy_counters(rep, counters);
    return st;
  })
}

acst_status acst_update_batch(double* stress, size_t stress_stride, double* statev, size_t statev_stride,
                              int* point_status, acst_counters* counters, const acst_model* model, size_t n,
                              const double* dstrain, size_t dstrain_stride) {
  ACST_REQUIRE(model, "acst_update_batch: a required pointer is NULL");
  const size_t nstatv = static_cast<size_t>(state_size_of(*model));
  ACST_REQUIRE(n == 0 || (stress && dstrain && (statev || nstatv == 0)),
               "acst_update_batch: a required pointer is NULL");
  ACST_REQUIRE(n == 0 || (stress_stride >= 6 && statev_stride >= nstatv && dstrain_stride >= 6),
               "acst_update_batch: strides must be at least 6 (stress, strain) and acst_state_size (state)");
  ACST_GUARD({
    acst_status first = ok_status();
    acst::integration::Report rep;
    acst::integration::Counters total;
    int plastic = 0;
    for (size_t i = 0; i < n; ++i) {
      double* point_statev = statev ? statev + i * statev_stride : nullptr;
      const acst_status st =
          update_any(stress + i * stress_stride, point_statev, nullptr, *model, dstrain + i * dstrain_stride, rep);
      total += rep.counters;
      plastic += rep.plastic;
      if (point_status) point_status[i] = st.code;
      if (st.code != ACST_OK && first.code == ACST_OK)
        first = make_status(st.code, "point " + std::to_string(i) + ": " + st.message, st.suggested_step_factor);
    }
    if (counters) {
      rep.counters = total;
      copy_counters(rep, counters);
      counters->plastic = plastic;
    }
    return first;
  })
}

acst_status acst_wave_speed(double* speed, const acst_model* model, const double* stress, const double* statev,
                            double density) {
  ACST_REQUIRE(speed && model && stress && (statev || state_size_of(*model) == 0),
               "acst_wave_speed: a pointer argument is NULL");
  ACST_REQUIRE(density > 0.0 && std::isfinite(density), "acst_wave_speed: density must be positive (kg/m^3)");
  ACST_GUARD({
    acst::ElasticModuli moduli;
    if (const acst::Material* sand = sand_model(*model)) {
      acst::State s;
      s.stress = stress_to_model(stress);
      fill_state(s, statev);
      const acst::Diagnostics d = sand->diagnostics(s);
      moduli = {d.G, d.K};
    } else {
      moduli = reference_moduli(*model);
    }
    *speed = std::sqrt(acst::constrained_modulus(moduli) * 1000.0 / density);  // kPa -> Pa
    ACST_REQUIRE(std::isfinite(*speed), "acst_wave_speed: state gives a non-finite stiffness");
    return ok_status();
  })
}

static const char* const diagnostic_names[ACST_NDIAGNOSTICS] = {"p", "q", "R", "sin3theta", "psi", "zeta", "A",
                                                                "fabric_norm", "e_c", "D", "Kp", "G", "K"};

const char* acst_diagnostic_name(int i) { return (i >= 0 && i < ACST_NDIAGNOSTICS) ? diagnostic_names[i] : nullptr; }

acst_status acst_diagnostics(double* out, const acst_model* model, const double* stress, const double* statev) {
  ACST_REQUIRE(out && model && stress && (statev || state_size_of(*model) == 0),
               "acst_diagnostics: a pointer argument is NULL");
  ACST_GUARD({
    const acst::Sym sigma = stress_to_model(stress);
    if (const acst::Material* sand = sand_model(*model)) {
      acst::State s;
      s.stress = sigma;
      fill_state(s, statev);
      const acst::Diagnostics d = sand->diagnostics(s);
      const double v[ACST_NDIAGNOSTICS] = {d.p,           d.q,   d.R, d.sin3theta, d.psi, d.zeta, d.A,
                                           d.fabric_norm, d.critical_void_ratio, d.D, d.Kp, d.G, d.K};
      std::memcpy(out, v, sizeof v);
      return ok_status();
    }
    // The sand-specific entries (R ... Kp) have no meaning for the reference materials.
    const acst::ElasticModuli m = reference_moduli(*model);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const double v[ACST_NDIAGNOSTICS] = {acst::trace(sigma) / 3.0, acst::reference::equivalent_stress(sigma),
                                         nan, nan, nan, nan, nan, nan, nan, nan, nan, m.G, m.K};
    std::memcpy(out, v, sizeof v);
    return ok_status();
  })
}

acst_status acst_rotate_state(double* stress, double* statev, const acst_model* model, const double* rotation) {
  ACST_REQUIRE(stress && model && rotation && (statev || state_size_of(*model) == 0),
               "acst_rotate_state: a required pointer argument is NULL");
  const Eigen::Matrix3d Q = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(rotation);
  ACST_REQUIRE(Q.allFinite() && (Q * Q.transpose() - Eigen::Matrix3d::Identity()).norm() < 1e-8 &&
                   Q.determinant() > 0.0,
               "acst_rotate_state: rotation must be a finite proper orthogonal 3x3 matrix, row-major "
               "(|Q Q^T - I| < 1e-8, det Q > 0)");
  stress_from_model(acst::rotate(stress_to_model(stress), Q), stress);
  if (sand_model(*model)) rotate_tensorial_state(statev, Q);
  return ok_status();
}

}  // extern "C"
