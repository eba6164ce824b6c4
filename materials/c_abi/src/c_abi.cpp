// The C ABI: thin wrappers that never let an exception escape. What differs between model
// kinds lives behind ModelKind (one file per kind, registered in model_kinds.cpp).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <memory>
#include <new>
#include <string>

#include "acst.h"
#include "acst/fabric.hpp"
#include "c_abi_support.hpp"
#include "model_kind.hpp"

struct acst_model {
  std::unique_ptr<const acst::abi::ModelKind> kind;
};

using namespace acst::abi;

namespace {

int state_size_of(const acst_model& model) { return model.kind->state().size; }

// |Q Q^T - I| < 1e-8 as its square, so no square root on the MPM hosts' hot path; Q Q^T is
// symmetric, so its six distinct entries are the rows' dot products, and det Q is the rows'
// triple product (written out on the row-major array: Eigen's general product and determinant
// took 2.7 % of an MPM step, bench/RESULTS.md 1s).
bool proper_rotation(const double* r) {
  // A turn about axis 3, [[c, s, 0], [-s, c, 0], [0, 0, 1]] (every rotation of a plane-strain
  // host), first: for it the rule below is exactly 2 a^2 < 1e-16 with a = c c + s s - 1 and
  // det = c c + s s, the same decision in each rounding (its other terms are exact zeros, and
  // s s + c c is c c + s s), at a fraction of the cost: an MPM step rotates every particle. A NaN
  // fails the equalities, an infinity the bound.
  if (r[2] == 0.0 && r[5] == 0.0 && r[6] == 0.0 && r[7] == 0.0 && r[8] == 1.0 && r[3] == -r[1] && r[4] == r[0]) {
    const double c = r[0], s = r[1];
    const double cs = c * c + s * s, a = cs - 1.0;
    return a * a + a * a < 1e-16 && cs > 0.0;
  }
  bool finite = true;
  for (int i = 0; i < 9; ++i) finite = finite && std::isfinite(r[i]);
  if (!finite) return false;
  const double* a = r;
  const double* b = r + 3;
  const double* c = r + 6;
  const auto dot = [](const double* x, const double* y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  const double aa = dot(a, a) - 1.0, bb = dot(b, b) - 1.0, cc = dot(c, c) - 1.0, ab = dot(a, b), ac = dot(a, c),
               bc = dot(b, c);
  const double det = a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) +
                     a[2] * (b[0] * c[1] - b[1] * c[0]);
  return aa * aa + bb * bb + cc * cc + 2.0 * (ab * ab + ac * ac + bc * bc) < 1e-16 && det > 0.0;
}

#define ACST_ROTATION_RULE "rotation must be a finite proper orthogonal 3x3 matrix, row-major (|Q Q^T - I| < 1e-8, det Q > 0)"

// The offsets' rule (acst.h, "Nonlocal regularisation"), "" where they may be taken.
std::string offset_problem(const acst_model& model, const double* offset) {
  if (!offset) return "";
  for (int k = 0; k < model.kind->nonlocal_size(); ++k)
    if (!(std::abs(offset[k]) < acst::void_ratio_limit))
      return "the nonlocal offset " + std::to_string(offset[k]) + " (value " + std::to_string(k) +
             ") is not finite or not smaller than " + std::to_string(acst::void_ratio_limit) + " in size";
  return "";
}

// Whether n points `stride` doubles apart, each `width` doubles wide, fit in an array a host can
// hold (its size in bytes within ptrdiff_t). A stride checked only from below let one that wraps
// size_t through (a negative stride passed as size_t): the batch wrote before the caller's array.
bool span_fits(size_t n, size_t stride, size_t width) {
  if (n == 0) return true;
  const size_t most = static_cast<size_t>(PTRDIFF_MAX) / sizeof(double);
  return width <= most && n - 1 <= (most - width) / std::max<size_t>(stride, 1);
}

#define ACST_SPAN_RULE                                                                                        \
  "n points at these strides reach past the largest array a host can hold (a stride that wraps size_t: a " \
  "negative stride passed as size_t?)"

}  // namespace

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

// The entry check of the functions that read a stress and state without updating them.
#define ACST_REQUIRE_PHYSICAL(function)                                                               \
  if (const std::string problem = model->kind->state_problem(stress, statev); !problem.empty()) \
  return make_status(ACST_NONPHYSICAL_STATE, std::string(function) + ": " + problem, 1.0)

extern "C" {

acst_status acst_model_create(acst_model** model, const char* json_text) {
  ACST_REQUIRE(model, "acst_model_create: model pointer is NULL");
  *model = nullptr;
  ACST_REQUIRE(json_text, "acst_model_create: JSON text is NULL");
  ACST_GUARD({
    *model = new acst_model{make_model_kind(json_text)};
    return ok_status();
  })
}

void acst_model_destroy(acst_model* model) { delete model; }

int acst_state_size(const acst_model* model) { return model ? state_size_of(*model) : 0; }

const char* acst_state_name(const acst_model* model, int i) {
  if (!model || i < 0 || i >= state_size_of(*model)) return nullptr;
  return model->kind->state().names[i];
}

const char* acst_model_kind(const acst_model* model) { return model ? model->kind->name() : nullptr; }

acst_status acst_initial_state(double* statev, double* stress_out, const acst_model* model, const double* stress0,
                               double void_ratio, const double* deposition_direction) {
  ACST_REQUIRE(stress_out && model && stress0 && (statev || state_size_of(*model) == 0),
               "acst_initial_state: a pointer argument is NULL");
  ACST_GUARD({ return model->kind->initial_state(statev, stress_out, stress0, void_ratio, deposition_direction); })
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
  ACST_GUARD({ return model->kind->void_ratio_from_relative_density(void_ratio, relative_density); })
}

acst_status acst_update(double* stress, double* statev, double* tangent, acst_counters* counters,
                        const acst_model* model, const double* dstrain) {
  return acst_update_nonlocal(stress, statev, tangent, counters, model, dstrain, nullptr);
}

acst_status acst_update_nonlocal(double* stress, double* statev, double* tangent, acst_counters* counters,
                                 const acst_model* model, const double* dstrain, const double* offset) {
  ACST_REQUIRE(stress && model && dstrain && (statev || state_size_of(*model) == 0),
               "acst_update: a required pointer argument is NULL");
  ACST_GUARD({
    if (const std::string p = offset_problem(*model, offset); !p.empty())
      return make_status(ACST_INVALID_INPUT, "acst_update_nonlocal: " + p, 1.0);
    acst::integration::Report rep;
    const acst_status st = model->kind->update(stress, statev, tangent, dstrain, offset, rep);
    if (counters) copy_counters(rep, counters);
    // A kind's OK is ok_status(); made here, it is built in the caller's status rather than
    // copied there (272 bytes per call, mostly the empty message).
    if (st.code == ACST_OK) return ok_status();
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
  ACST_REQUIRE(span_fits(n, stress_stride, 6) && span_fits(n, statev_stride, nstatv) && span_fits(n, dstrain_stride, 6),
               "acst_update_batch: " ACST_SPAN_RULE);
  ACST_GUARD({
    acst_status first = ok_status();
    acst::integration::Report rep;
    acst::integration::Counters total;
    int plastic = 0;
    for (size_t i = 0; i < n; ++i) {
      double* point_statev = statev ? statev + i * statev_stride : nullptr;
      const acst_status st =
          model->kind->update(stress + i * stress_stride, point_statev, nullptr, dstrain + i * dstrain_stride, nullptr, rep);
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
  ACST_REQUIRE_PHYSICAL("acst_wave_speed");
  ACST_GUARD({
    const acst::ElasticModuli moduli = model->kind->moduli(stress, statev);
    const double c = std::sqrt(acst::constrained_modulus(moduli) * 1000.0 / density);  // kPa -> Pa
    if (!(std::isfinite(c) && c > 0.0))
      return make_status(ACST_NONPHYSICAL_STATE, "acst_wave_speed: the state gives no finite positive stiffness", 1.0);
    *speed = c;
    return ok_status();
  })
}

static const char* const diagnostic_names[ACST_NDIAGNOSTICS] = {"p", "q", "R", "sin3theta", "psi", "zeta", "A",
                                                                "fabric_norm", "e_c", "D", "Kp", "G", "K"};

const char* acst_diagnostic_name(int i) { return (i >= 0 && i < ACST_NDIAGNOSTICS) ? diagnostic_names[i] : nullptr; }

acst_status acst_diagnostics(double* out, const acst_model* model, const double* stress, const double* statev) {
  ACST_REQUIRE(out && model && stress && (statev || state_size_of(*model) == 0),
               "acst_diagnostics: a pointer argument is NULL");
  ACST_REQUIRE_PHYSICAL("acst_diagnostics");
  ACST_GUARD({
    double v[ACST_NDIAGNOSTICS];
    model->kind->diagnostics(v, stress, statev);
    for (int i = 0; i < ACST_NDIAGNOSTICS; ++i)
      if (model->kind->diagnostic_applies(i) && !std::isfinite(v[i]))
        return make_status(ACST_NONPHYSICAL_STATE,
                           std::string("acst_diagnostics: ") + diagnostic_names[i] + " is not finite for this state", 1.0);
    std::copy(v, v + ACST_NDIAGNOSTICS, out);
    return ok_status();
  })
}

acst_status acst_rotate_state(double* stress, double* statev, const acst_model* model, const double* rotation) {
  ACST_REQUIRE(stress && model && rotation && (statev || state_size_of(*model) == 0),
               "acst_rotate_state: a required pointer argument is NULL");
  ACST_REQUIRE(proper_rotation(rotation), "acst_rotate_state: " ACST_ROTATION_RULE);
  // Rotated into copies and the result checked: a state that was not physical is not after the
  // rotation either (the scalars stay, NaN stays, p is invariant), and a rotation keeps p only in
  // exact arithmetic: with a shear 1e300 times p the round-off can leave p of either sign (found
  // by fuzz_c_abi).
  double s[6], q[ACST_NSTATV];
  model->kind->rotated_copy(stress, statev, rotation, s, q);
  if (const std::string problem = model->kind->state_problem(s, q); !problem.empty())
    return make_status(ACST_NONPHYSICAL_STATE, "acst_rotate_state: " + problem, 1.0);
  std::copy(s, s + 6, stress);
  std::copy(q, q + state_size_of(*model), statev);
  return ok_status();
}

acst_status acst_update_rotated(double* stress, double* statev, double* tangent, acst_counters* counters,
                                const acst_model* model, const double* rotation, const double* dstrain) {
  return acst_update_rotated_nonlocal(stress, statev, tangent, counters, model, rotation, dstrain, nullptr);
}

acst_status acst_update_rotated_nonlocal(double* stress, double* statev, double* tangent, acst_counters* counters,
                                         const acst_model* model, const double* rotation, const double* dstrain,
                                         const double* offset) {
  ACST_REQUIRE(stress && model && rotation && dstrain && (statev || state_size_of(*model) == 0),
               "acst_update_rotated: a required pointer argument is NULL");
  ACST_REQUIRE(proper_rotation(rotation), "acst_update_rotated: " ACST_ROTATION_RULE);
  ACST_GUARD({
    if (const std::string p = offset_problem(*model, offset); !p.empty())
      return make_status(ACST_INVALID_INPUT, "acst_update_rotated_nonlocal: " + p, 1.0);
    acst::integration::Report rep;
    const acst_status st = model->kind->update_rotated(stress, statev, tangent, rotation, dstrain, offset, rep);
    if (counters) copy_counters(rep, counters);
    if (st.code == ACST_OK) return ok_status();  // built in the caller's status (acst_update)
    return st;
  })
}

acst_status acst_update_rotated_batch(double* stress, size_t stress_stride, double* statev, size_t statev_stride,
                                      int* point_status, acst_counters* point_counters, const acst_model* model,
                                      size_t n, const double* rotation, const double* dstrain) {
  return acst_update_rotated_batch_nonlocal(stress, stress_stride, statev, statev_stride, point_status, point_counters,
                                            model, n, rotation, dstrain, nullptr);
}

acst_status acst_update_rotated_batch_nonlocal(double* stress, size_t stress_stride, double* statev,
                                               size_t statev_stride, int* point_status, acst_counters* point_counters,
                                               const acst_model* model, size_t n, const double* rotation,
                                               const double* dstrain, const double* offset) {
  ACST_REQUIRE(model, "acst_update_rotated_batch: a required pointer is NULL");
  const size_t nstatv = static_cast<size_t>(state_size_of(*model));
  ACST_REQUIRE(n == 0 || (stress && rotation && dstrain && (statev || nstatv == 0)),
               "acst_update_rotated_batch: a required pointer is NULL");
  ACST_REQUIRE(n == 0 || (stress_stride >= 6 && statev_stride >= nstatv),
               "acst_update_rotated_batch: strides must be at least 6 (stress) and acst_state_size (state)");
  const size_t per_point_offsets = static_cast<size_t>(model->kind->nonlocal_size());
  ACST_REQUIRE(span_fits(n, stress_stride, 6) && span_fits(n, statev_stride, nstatv) && span_fits(n, 9, 9) &&
                   span_fits(n, per_point_offsets, per_point_offsets) && span_fits(n, sizeof(acst_counters), sizeof(acst_counters)),
               "acst_update_rotated_batch: " ACST_SPAN_RULE);
  ACST_GUARD({
    const size_t per_point = static_cast<size_t>(model->kind->nonlocal_size());
    // In blocks of points with a proper rotation and usable offsets, updated in place together
    // (a failed point stays as it came).
    constexpr int block = 16;
    acst_status first = ok_status();
    size_t first_point = n;
    const auto note_failure = [&](size_t i, int code, const char* message, double factor) {
      if (i >= first_point) return;
      first_point = i;
      first = make_status(code, "point " + std::to_string(i) + ": " + message, factor);
    };
    for (size_t start = 0; start < n; start += block) {
      const int m = static_cast<int>(std::min<size_t>(block, n - start));
      double *s_ptr[block], *q_ptr[block];
      const double *r_ptr[block], *e_ptr[block], *o_ptr[block];
      int index[block], codes[block];
      acst::integration::Report reports[block];
      int used = 0;
      for (int k = 0; k < m; ++k) {
        const size_t i = start + static_cast<size_t>(k);
        if (!proper_rotation(rotation + 9 * i)) {
          if (point_status) point_status[i] = ACST_INVALID_INPUT;
          if (point_counters) point_counters[i] = acst_counters{};
          note_failure(i, ACST_INVALID_INPUT, "acst_update_rotated_batch: " ACST_ROTATION_RULE, 1.0);
          continue;
        }
        const double* point_offset = offset && per_point > 0 ? offset + per_point * i : nullptr;
        // Checked only where given: the local model's points (no offsets) pay nothing here.
        if (const std::string p = point_offset ? offset_problem(*model, point_offset) : std::string(); !p.empty()) {
          if (point_status) point_status[i] = ACST_INVALID_INPUT;
          if (point_counters) point_counters[i] = acst_counters{};
          note_failure(i, ACST_INVALID_INPUT, ("acst_update_rotated_batch_nonlocal: " + p).c_str(), 1.0);
          continue;
        }
        o_ptr[used] = point_offset;
        s_ptr[used] = stress + i * stress_stride;
        q_ptr[used] = statev ? statev + i * statev_stride : nullptr;
        r_ptr[used] = rotation + 9 * i;
        e_ptr[used] = dstrain + 6 * i;
        index[used++] = k;
      }
      acst_status failure = ok_status();
      model->kind->update_rotated_points(used, s_ptr, q_ptr, r_ptr, e_ptr, offset ? o_ptr : nullptr, codes, reports,
                                         failure);
      bool failure_named = false;  // `failure` is the block's first failed point's status
      for (int u = 0; u < used; ++u) {
        const size_t i = start + static_cast<size_t>(index[u]);
        if (point_status) point_status[i] = codes[u];
        if (point_counters) copy_counters(reports[u], &point_counters[i]);
        if (codes[u] != ACST_OK && !failure_named) {
          failure_named = true;
          note_failure(i, failure.code, failure.message, failure.suggested_step_factor);
        }
      }
    }
    return first;
  })
}

acst_status acst_reproducer(char* buffer, size_t* length, const acst_model* model, const double* stress,
                            const double* statev, const double* dstrain) {
  return acst_reproducer_nonlocal(buffer, length, model, stress, statev, dstrain, nullptr);
}

acst_status acst_reproducer_nonlocal(char* buffer, size_t* length, const acst_model* model, const double* stress,
                                     const double* statev, const double* dstrain, const double* offset) {
  ACST_REQUIRE(length && model && stress && dstrain && (statev || state_size_of(*model) == 0),
               "acst_reproducer: a required pointer argument is NULL");
  ACST_GUARD({
    if (const std::string p = offset_problem(*model, offset); !p.empty())
      return make_status(ACST_INVALID_INPUT, "acst_reproducer_nonlocal: " + p, 1.0);
    return text_to_buffer(model->kind->reproducer(stress, statev, dstrain, offset).dump(2) + "\n", buffer, length,
                          "acst_reproducer");
  })
}

int acst_nonlocal_size(const acst_model* model) { return model ? model->kind->nonlocal_size() : 0; }

const char* acst_nonlocal_name(const acst_model* model, int i) {
  return model && i >= 0 && i < model->kind->nonlocal_size() ? model->kind->nonlocal_name(i) : nullptr;
}

acst_status acst_nonlocal_local(double* local, const acst_model* model, const double* stress, const double* statev) {
  ACST_REQUIRE(local && model && stress && (statev || state_size_of(*model) == 0),
               "acst_nonlocal_local: a pointer argument is NULL");
  ACST_REQUIRE_PHYSICAL("acst_nonlocal_local");
  ACST_GUARD({
    model->kind->nonlocal_local(local, stress, statev);
    return ok_status();
  })
}

}  // extern "C"
