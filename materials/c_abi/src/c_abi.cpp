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
  // The kind's sizes, read once at creation: every update asks for them, and each is a virtual
  // call (with the one update's view, a one-point update asked four times).
  int state_size;
  int nonlocal_size;
};

using namespace acst::abi;

namespace {

int state_size_of(const acst_model& model) { return model.state_size; }

// |Q Q^T - I| < 1e-8 as its square, so no square root on the MPM hosts' hot path; Q Q^T is
// symmetric, so its six distinct entries are the rows' dot products, and det Q is the rows'
// triple product (written out on the row-major array: Eigen's general product and determinant
// took 2.7 % of an MPM step).
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
  for (int k = 0; k < model.nonlocal_size; ++k)
    if (!(std::abs(offset[k]) < acst::void_ratio_limit))
      return "the nonlocal offset " + std::to_string(offset[k]) + " (value " + std::to_string(k) +
             ") is not finite or not smaller than " + std::to_string(acst::void_ratio_limit) + " in size";
  return "";
}

// Whether n points `stride` doubles apart, each `width` doubles wide, fit in an array a host can
// hold (its size in bytes within ptrdiff_t). A stride checked only from below let one that wraps
// size_t through (a negative stride passed as size_t): the batch wrote before the caller's array.
// With 64-bit sizes, counts, strides and widths below 2^20, 2^32 and 2^32 (every host's) reach
// less than 2^53 doubles and need no division: an update checks several spans per call, and an MPM
// host calls it for every 16 particles.
bool span_fits(size_t n, size_t stride, size_t width) {
  if (n == 0) return true;
  constexpr uint64_t one = 1;
  if (sizeof(size_t) >= 8 && uint64_t{n} < (one << 20) && uint64_t{stride} < (one << 32) &&
      uint64_t{width} < (one << 32))
    return true;
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
    std::unique_ptr<const ModelKind> kind = make_model_kind(json_text);
    const int state_size = kind->state().size, nonlocal_size = kind->nonlocal_size();
    *model = new acst_model{std::move(kind), state_size, nonlocal_size};
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

}  // extern "C"

namespace {

// Who called the one update, acst_update_points or one of its wrappers: the names its messages
// start with (each wrapper's messages are what they were) and how its points' own inputs are
// judged. A one-point function (acst_update, acst_update_rotated and their _nonlocal forms)
// refuses a point's bad rotation or offsets as the whole call, writing nothing, with a message
// that names no point; a batch fails that point alone.
struct Caller {
  const char* name;           // of the call's own messages (NULL pointers, strides, rotations)
  const char* nonlocal_name;  // of the offsets' messages
  bool one_point;
  bool rotation_required;     // acst_update_rotated*: a NULL rotation is a NULL pointer, not "no turn"
};

// Point i's array, `stride` doubles after point i - 1's; null where the array is absent.
template <class T>
T* point_at(T* base, size_t stride, size_t i) {
  return base ? base + i * stride : nullptr;
}

// Whether n objects of `bytes` each fit in an array a host can hold (span_fits for the int and
// counter arrays, which are not strided).
bool count_fits(size_t n, size_t bytes) { return n <= static_cast<size_t>(PTRDIFF_MAX) / bytes; }

// The sizes of a model's points (acst_model keeps them).
struct Sizes {
  size_t state, offsets;
};

// The arrays of a view with their strides and widths, in the order their checks name them.
struct Array {
  const char* what;
  bool present;
  size_t stride, width;
};

// Written out rather than as a table of Arrays: an MPM host checks a view for every 16 particles.
bool strides_usable(const acst_batch& b, const Sizes& z, const double* offsets) {
  return b.stress_stride >= 6 && b.statev_stride >= z.state && b.dstrain_stride >= 6 &&
         (!b.rotation || b.rotation_stride >= 9) && (!offsets || b.offset_stride >= z.offsets) &&
         (!b.tangent || b.tangent_stride >= 36);
}

bool spans_fit(const acst_batch& b, const Sizes& z, const double* offsets) {
  const size_t n = b.n;
  return span_fits(n, b.stress_stride, 6) && span_fits(n, b.statev_stride, z.state) &&
         span_fits(n, b.dstrain_stride, 6) && (!b.rotation || span_fits(n, b.rotation_stride, 9)) &&
         (!offsets || span_fits(n, b.offset_stride, z.offsets)) && (!b.tangent || span_fits(n, b.tangent_stride, 36)) &&
         (!b.point_status || count_fits(n, sizeof(int))) && (!b.point_counters || count_fits(n, sizeof(acst_counters)));
}

// Which stride is short (strides_usable false).
std::string short_stride(const acst_batch& b, const Sizes& z, const double* offsets) {
  const Array arrays[] = {{"stress", true, b.stress_stride, 6},
                          {"statev", true, b.statev_stride, z.state},
                          {"dstrain", true, b.dstrain_stride, 6},
                          {"rotation", b.rotation != nullptr, b.rotation_stride, 9},
                          {"offset", offsets != nullptr, b.offset_stride, z.offsets},
                          {"tangent", b.tangent != nullptr, b.tangent_stride, 36}};
  for (const Array& a : arrays)
    if (a.present && a.stride < a.width)
      return std::string("the ") + a.what + " stride " + std::to_string(a.stride) + " is below a point's " +
             std::to_string(a.width) + " doubles (strides must be at least 6 (stress, strain), acst_state_size "
             "(state), 9 (rotation), acst_nonlocal_size (offset) and 36 (tangent))";
  return "a stride is too short";
}

// The checks of the whole call, before any point is touched: whether the points may be attempted
// (view_usable) and, where not, why (view_problem). `offsets`: the view's offsets where the kind
// takes any, else null (not read).
bool pointers_given(const acst_batch& b, const Sizes& z, const Caller& c) {
  return !(c.one_point || b.n > 0) ||
         (b.stress && b.dstrain && (b.statev || z.state == 0) && (b.rotation || !c.rotation_required));
}

// The view of the old batch functions' common arguments.
acst_batch batch_view(size_t n, double* stress, size_t stress_stride, double* statev, size_t statev_stride,
                      int* point_status, const double* dstrain, size_t dstrain_stride) {
  acst_batch b{};
  b.n = n;
  b.stress = stress;
  b.stress_stride = stress_stride;
  b.statev = statev;
  b.statev_stride = statev_stride;
  b.dstrain = dstrain;
  b.dstrain_stride = dstrain_stride;
  b.point_status = point_status;
  return b;
}


// A one-point function's view is its own (one_point_view): one point, at strides that hold it.
bool view_usable(const acst_batch& b, const Sizes& z, const double* offsets, const Caller& c) {
  return pointers_given(b, z, c) &&
         (b.n == 0 || c.one_point || (strides_usable(b, z, offsets) && spans_fit(b, z, offsets)));
}

std::string view_problem(const acst_batch& b, const Sizes& z, const double* offsets, const Caller& c) {
  if (!pointers_given(b, z, c)) return c.one_point ? "a required pointer argument is NULL" : "a required pointer is NULL";
  if (!strides_usable(b, z, offsets)) return short_stride(b, z, offsets);
  return ACST_SPAN_RULE;
}

// Whether a point's offsets may be taken (offset_problem's rule, without its message).
bool offsets_usable(const double* offset, size_t count) {
  bool usable = true;
  for (size_t k = 0; k < count; ++k) usable = usable && std::abs(offset[k]) < acst::void_ratio_limit;
  return usable;
}

// What is wrong with a point's own inputs, its rotation and then its offsets; "" where they may
// be taken (offsets are checked only where given: the local model's points pay nothing here).
std::string point_input_problem(const acst_model& model, const double* rotation, const double* offset,
                                const Caller& c) {
  if (rotation && !proper_rotation(rotation)) return std::string(c.name) + ": " ACST_ROTATION_RULE;
  if (offset)
    if (std::string p = offset_problem(model, offset); !p.empty()) return std::string(c.nonlocal_name) + ": " + p;
  return "";
}

// Whether a point's own inputs may be taken: point_input_problem's "", without building strings.
bool point_inputs_usable(const double* rotation, const double* offset, const Sizes& z) {
  return (!rotation || proper_rotation(rotation)) && (!offset || offsets_usable(offset, z.offsets));
}

// One point's update, turned first where it has a rotation: acst_update_rotated_nonlocal's or
// acst_update_nonlocal's numbers.
acst_status update_one_point(const ModelKind& kind, double* stress, double* statev, double* tangent,
                             const double* rotation, const double* dstrain, const double* offset,
                             acst::integration::Report& rep) {
  return rotation ? kind.update_rotated(stress, statev, tangent, rotation, dstrain, offset, rep)
                  : kind.update(stress, statev, tangent, dstrain, offset, rep);
}

// A one-point function's update (the view holds one point).
acst_status update_single(const acst_batch& b, const acst_model& model, const Sizes& z, const double* offset,
                          const Caller& c) {
  if (!point_inputs_usable(b.rotation, offset, z))
    return make_status(ACST_INVALID_INPUT, point_input_problem(model, b.rotation, offset, c), 1.0);
  acst::integration::Report rep;
  const acst_status st = update_one_point(*model.kind, b.stress, b.statev, b.tangent, b.rotation, b.dstrain, offset, rep);
  if (b.point_counters) copy_counters(rep, b.point_counters);
  if (b.counters) copy_counters(rep, b.counters);
  // A kind's OK is ok_status(); made here, it is built in the caller's status rather than
  // copied there (272 bytes per call, mostly the empty message).
  if (st.code == ACST_OK) return ok_status();
  return st;
}

// A batch's update: in blocks of points whose own inputs may be taken, updated in place together
// (with a rotation and no tangent, by the kind's update_rotated_points: the sand's SIMD lanes),
// a failed point left as it came. Not inlined into update_points: its blocks' arrays would make
// every one-point call clear a frame of 3 kB (a third more time per call of the elastic kind).
__attribute__((noinline)) acst_status update_many(const acst_batch& b, const acst_model& model, const Sizes& z,
                                                   const double* offsets, const Caller& c) {
  const size_t n = b.n;
  const bool together = b.rotation && !b.tangent;
  constexpr int block = 16;
  acst_status first = ok_status();
  size_t first_point = n;
  const auto note_failure = [&](size_t i, int code, const char* message, double factor) {
    if (i >= first_point) return;
    first_point = i;
    first = make_status(code, "point " + std::to_string(i) + ": " + message, factor);
  };
  acst::integration::Counters total;
  int plastic = 0;
  for (size_t start = 0; start < n; start += block) {
    const int m = static_cast<int>(std::min<size_t>(block, n - start));
    double *s_ptr[block], *q_ptr[block], *t_ptr[block];
    const double *r_ptr[block], *e_ptr[block], *o_ptr[block];
    int index[block], codes[block];
    acst::integration::Report reports[block];
    int used = 0;
    for (int k = 0; k < m; ++k) {
      const size_t i = start + static_cast<size_t>(k);
      const double* rotation = point_at(b.rotation, b.rotation_stride, i);
      const double* offset = point_at(offsets, b.offset_stride, i);
      if (!point_inputs_usable(rotation, offset, z)) {
        if (b.point_status) b.point_status[i] = ACST_INVALID_INPUT;
        if (b.point_counters) b.point_counters[i] = acst_counters{};
        note_failure(i, ACST_INVALID_INPUT, point_input_problem(model, rotation, offset, c).c_str(), 1.0);
        continue;
      }
      s_ptr[used] = b.stress + i * b.stress_stride;
      q_ptr[used] = point_at(b.statev, b.statev_stride, i);
      t_ptr[used] = point_at(b.tangent, b.tangent_stride, i);
      r_ptr[used] = rotation;
      e_ptr[used] = b.dstrain + i * b.dstrain_stride;
      o_ptr[used] = offset;
      index[used++] = k;
    }
    acst_status failure = ok_status();  // the block's first failed point's status
    if (together) {
      model.kind->update_rotated_points(used, s_ptr, q_ptr, r_ptr, e_ptr, offsets ? o_ptr : nullptr, codes, reports,
                                        failure);
    } else {
      for (int u = 0; u < used; ++u) {
        const acst_status st =
            update_one_point(*model.kind, s_ptr[u], q_ptr[u], t_ptr[u], r_ptr[u], e_ptr[u], o_ptr[u], reports[u]);
        codes[u] = st.code;
        if (st.code != ACST_OK && failure.code == ACST_OK) failure = st;
      }
    }
    bool failure_named = false;
    for (int u = 0; u < used; ++u) {
      const size_t i = start + static_cast<size_t>(index[u]);
      if (b.point_status) b.point_status[i] = codes[u];
      if (b.point_counters) copy_counters(reports[u], &b.point_counters[i]);
      if (b.counters) {
        total += reports[u].counters;
        plastic += reports[u].plastic;
      }
      if (codes[u] != ACST_OK && !failure_named) {
        failure_named = true;
        note_failure(i, failure.code, failure.message, failure.suggested_step_factor);
      }
    }
  }
  if (b.counters) {
    acst::integration::Report sum;
    sum.counters = total;
    copy_counters(sum, b.counters);
    b.counters->plastic = plastic;
  }
  if (b.first_failure) *b.first_failure = first_point;
  return first;
}

// acst_update_points and its wrappers: the whole call's checks, then the points.
acst_status update_points(const acst_batch* view, const acst_model* model, const Caller& c) {
  if (!view || !model)
    return make_status(ACST_INVALID_INPUT,
                       std::string(c.name) + (c.one_point ? ": a required pointer argument is NULL"
                                                          : ": a required pointer is NULL"),
                       1.0);
  ACST_GUARD({
    const Sizes z{static_cast<size_t>(model->state_size), static_cast<size_t>(model->nonlocal_size)};
    const double* offsets = z.offsets > 0 ? view->offset : nullptr;  // a kind without any ignores them
    if (!view_usable(*view, z, offsets, c))
      return make_status(ACST_INVALID_INPUT, std::string(c.name) + ": " + view_problem(*view, z, offsets, c), 1.0);
    return c.one_point ? update_single(*view, *model, z, offsets, c) : update_many(*view, *model, z, offsets, c);
  })
}

// A one-point function's view (acst_update, acst_update_rotated and their _nonlocal forms).
acst_batch one_point_view(double* stress, double* statev, double* tangent, acst_counters* counters,
                          const acst_model* model, const double* rotation, const double* dstrain,
                          const double* offset) {
  acst_batch b = batch_view(1, stress, 6, statev, model ? static_cast<size_t>(model->state_size) : 0, nullptr,
                            dstrain, 6);
  b.rotation = rotation;
  b.rotation_stride = 9;
  b.offset = offset;
  b.offset_stride = model ? static_cast<size_t>(model->nonlocal_size) : 0;
  b.tangent = tangent;
  b.tangent_stride = 36;
  b.point_counters = counters;
  return b;
}

constexpr Caller update_caller{"acst_update", "acst_update_nonlocal", true, false};
constexpr Caller update_rotated_caller{"acst_update_rotated", "acst_update_rotated_nonlocal", true, true};
constexpr Caller update_batch_caller{"acst_update_batch", "acst_update_batch", false, false};
constexpr Caller update_rotated_batch_caller{"acst_update_rotated_batch", "acst_update_rotated_batch_nonlocal", false,
                                             true};
constexpr Caller update_points_caller{"acst_update_points", "acst_update_points", false, false};

}  // namespace

extern "C" {

acst_status acst_update_points(const acst_batch* points, const acst_model* model) {
  return update_points(points, model, update_points_caller);
}

// The functions before acst_update_points, kept as thin wrappers: each fills a view.

acst_status acst_update(double* stress, double* statev, double* tangent, acst_counters* counters,
                        const acst_model* model, const double* dstrain) {
  return acst_update_nonlocal(stress, statev, tangent, counters, model, dstrain, nullptr);
}

acst_status acst_update_nonlocal(double* stress, double* statev, double* tangent, acst_counters* counters,
                                 const acst_model* model, const double* dstrain, const double* offset) {
  const acst_batch b = one_point_view(stress, statev, tangent, counters, model, nullptr, dstrain, offset);
  return update_points(&b, model, update_caller);
}

acst_status acst_update_batch(double* stress, size_t stress_stride, double* statev, size_t statev_stride,
                              int* point_status, acst_counters* counters, const acst_model* model, size_t n,
                              const double* dstrain, size_t dstrain_stride) {
  acst_batch b = batch_view(n, stress, stress_stride, statev, statev_stride, point_status, dstrain, dstrain_stride);
  b.counters = counters;
  return update_points(&b, model, update_batch_caller);
}

acst_status acst_update_rotated(double* stress, double* statev, double* tangent, acst_counters* counters,
                                const acst_model* model, const double* rotation, const double* dstrain) {
  return acst_update_rotated_nonlocal(stress, statev, tangent, counters, model, rotation, dstrain, nullptr);
}

acst_status acst_update_rotated_nonlocal(double* stress, double* statev, double* tangent, acst_counters* counters,
                                         const acst_model* model, const double* rotation, const double* dstrain,
                                         const double* offset) {
  const acst_batch b = one_point_view(stress, statev, tangent, counters, model, rotation, dstrain, offset);
  return update_points(&b, model, update_rotated_caller);
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
  acst_batch b = batch_view(n, stress, stress_stride, statev, statev_stride, point_status, dstrain, 6);
  b.rotation = rotation;
  b.rotation_stride = 9;
  b.offset = offset;
  b.offset_stride = model ? static_cast<size_t>(model->nonlocal_size) : 0;
  b.point_counters = point_counters;
  return update_points(&b, model, update_rotated_batch_caller);
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

int acst_nonlocal_size(const acst_model* model) { return model ? model->nonlocal_size : 0; }

const char* acst_nonlocal_name(const acst_model* model, int i) {
  return model && i >= 0 && i < model->nonlocal_size ? model->kind->nonlocal_name(i) : nullptr;
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
