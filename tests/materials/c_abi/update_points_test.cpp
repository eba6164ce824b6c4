// acst_update_points, the one update of the C ABI (acst.h), against the functions it stands
// behind: with each mix of its optional inputs (rotation, nonlocal offsets) and outputs (tangent,
// codes, per-point and summed counters, the first failure) every point gets the numbers, code and
// counters of acst_update_nonlocal or acst_update_rotated_nonlocal called on it alone, to the bit,
// and the old batch functions (wrappers of it) answer as before; points on strides other than
// the packed ones; the sand and the closed-form kinds; bad input refused with a message and
// nothing written.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "abi_model.hpp"
#include "acst.h"
#include "test_materials.hpp"

namespace c_abi_update_points_test {

using acst::test::AbiModel;

bool same_bits(const double* a, const double* b, size_t n) { return n == 0 || std::memcmp(a, b, sizeof(double) * n) == 0; }

bool same_counters(const acst_counters& a, const acst_counters& b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::string sand_json() { return acst::test::read_text("data/parameters/toyoura_acst_calibrated.json"); }

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// n points in arrays with room between them (strides above the packed widths, as a host's
// particle records), their rotations, increments and offsets.
struct Points {
  size_t n, ss, qs, es, rs, os;  // strides: stress, state, strain, rotation, offset
  std::vector<double> stress, statev, dstrain, rotation, offset;
  Points(size_t count, size_t stress_stride, size_t state_stride, size_t strain_stride, size_t rotation_stride,
         size_t offset_stride)
      : n(count), ss(stress_stride), qs(state_stride), es(strain_stride), rs(rotation_stride), os(offset_stride),
        stress(count * ss, -7.0), statev(count * qs, -7.0), dstrain(count * es, -7.0),
        rotation(count * rs, -7.0), offset(count * os, -7.0) {}
  double* s(size_t i) { return &stress[i * ss]; }
  double* q(size_t i) { return statev.empty() ? nullptr : &statev[i * qs]; }
  double* e(size_t i) { return &dstrain[i * es]; }
  double* r(size_t i) { return &rotation[i * rs]; }
  double* o(size_t i) { return &offset[i * os]; }
};

// Sand points at geostatic stresses with shear (tension positive), a step's rotations (about
// axis 3, every fifth about a tilted axis) and plane-strain increments, mostly compressing
// vertically so that most points load plastically, offsets of either sign (every fourth none).
// With `bad`, points the update refuses or fails: a rotation that is none, a NaN void ratio, a
// blow-up of an increment, an offset beyond 2.97.
Points sand_points(const acst_model* m, size_t n, size_t ss, size_t qs, size_t es, size_t rs, size_t os,
                   std::mt19937_64& rng, bool bad) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Points P(n, ss, qs, es, rs, os);
  for (size_t i = 0; i < n; ++i) {
    const double p = 10.0 + 300.0 * u(rng), K0 = 0.4 + 0.4 * u(rng);
    const double s0[6] = {-K0 * p, -p, -0.5 * (1.0 + K0) * p, (u(rng) - 0.5) * 0.3 * p, 0.0, 0.0};
    double b[3];
    EXPECT_EQ(acst_bedding_direction(b, 90.0 * u(rng), 1, 0, -1.0).code, ACST_OK);
    const acst_status st = acst_initial_state(P.q(i), P.s(i), m, s0, 0.6 + 0.2 * u(rng), b);
    EXPECT_EQ(st.code, ACST_OK) << st.message;
    const double a = 1e-5 * (2.0 * u(rng) - 1.0), c = std::cos(a), s = std::sin(a);
    if (i % 5 == 2) {  // Rodrigues' formula about the unit axis k
      const double k[3] = {0.48, 0.6, 0.64}, t = 1.0 - c;
      const double Q[9] = {c + t * k[0] * k[0],        t * k[0] * k[1] - s * k[2], t * k[0] * k[2] + s * k[1],
                           t * k[1] * k[0] + s * k[2], c + t * k[1] * k[1],        t * k[1] * k[2] - s * k[0],
                           t * k[2] * k[0] - s * k[1], t * k[2] * k[1] + s * k[0], c + t * k[2] * k[2]};
      std::memcpy(P.r(i), Q, sizeof Q);
    } else {
      const double Q[9] = {c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0};
      std::memcpy(P.r(i), Q, sizeof Q);
    }
    const double size = std::pow(10.0, -6.0 + 2.0 * u(rng)), w = 2.0 * u(rng) - 1.0;
    const double e[6] = {size * (0.4 + 0.5 * w), -size * (1.0 + 0.5 * u(rng)), 0.0, size * w, 0.0, 0.0};
    std::memcpy(P.e(i), e, sizeof e);
    P.o(i)[0] = i % 4 == 3 ? 0.0 : 0.06 * (2.0 * u(rng) - 1.0);
  }
  if (bad && n > 13) {
    P.r(3)[0] = 2.0;
    P.q(6)[6] = nan;
    P.e(9)[1] = 0.5;
    P.o(12)[0] = 3.5;
    P.e(13)[0] = nan;
  }
  return P;
}

// The optional fields of a view: which are given.
struct Fields {
  bool rotation, offset, tangent, status, point_counters, counters, first_failure;
};

struct Outputs {
  std::vector<double> tangent;
  std::vector<int> status;
  std::vector<acst_counters> point_counters;
  acst_counters counters;
  size_t first_failure = static_cast<size_t>(-1);
  acst_status st;
};

// acst_update_points on P with the fields f; the tangent 40 doubles apart.
Outputs update_points(const acst_model* m, Points& P, const Fields& f) {
  Outputs out;
  out.tangent.assign(P.n * 40, -7.0);
  out.status.assign(P.n, -1);
  out.point_counters.assign(P.n, acst_counters{});
  std::memset(&out.counters, 0x5a, sizeof out.counters);
  acst_batch b = {};
  b.n = P.n;
  b.stress = P.stress.data();
  b.stress_stride = P.ss;
  b.statev = P.statev.empty() ? nullptr : P.statev.data();
  b.statev_stride = P.qs;
  b.dstrain = P.dstrain.data();
  b.dstrain_stride = P.es;
  if (f.rotation) b.rotation = P.rotation.data();
  b.rotation_stride = P.rs;
  if (f.offset) b.offset = P.offset.data();
  b.offset_stride = P.os;
  if (f.tangent) b.tangent = out.tangent.data();
  b.tangent_stride = 40;
  if (f.status) b.point_status = out.status.data();
  if (f.point_counters) b.point_counters = out.point_counters.data();
  if (f.counters) b.counters = &out.counters;
  if (f.first_failure) b.first_failure = &out.first_failure;
  out.st = acst_update_points(&b, m);
  return out;
}

// Every point of `given` updated by acst_update_points with the fields f is the one-point
// function's point: stress, state, tangent (where OK), code and counters to the bit; the returned
// status is the first failure's, named; the summed counters are the points' sum.
struct Tally {
  int points = 0, plastic_one_substep = 0, failed = 0;
};

void expect_one_point_numbers(const acst_model* m, const Points& given, const Fields& f, const std::string& where,
                              Tally* tally = nullptr) {
  Points batch = given;
  const Outputs out = update_points(m, batch, f);
  Points one = given;
  acst_counters sum{};
  size_t first = given.n;
  std::string first_message;
  for (size_t i = 0; i < given.n; ++i) {
    const std::string at = where + ", point " + std::to_string(i);
    double D[36];
    std::fill(D, D + 36, -7.0);
    acst_counters c{};
    const double* offset = f.offset ? one.o(i) : nullptr;
    double* tangent = f.tangent ? D : nullptr;
    const acst_status s =
        f.rotation ? acst_update_rotated_nonlocal(one.s(i), one.q(i), tangent, &c, m, one.r(i), one.e(i), offset)
                   : acst_update_nonlocal(one.s(i), one.q(i), tangent, &c, m, one.e(i), offset);
    // A point refused on its own input writes no counters in the one-point call, zeros in a batch.
    if (tally) {
      ++tally->points;
      tally->plastic_one_substep += s.code == ACST_OK && c.plastic && c.substeps_accepted == 1;
      tally->failed += s.code != ACST_OK;
    }
    ASSERT_TRUE(same_bits(batch.s(i), one.s(i), 6)) << at;
    ASSERT_TRUE(same_bits(batch.q(i), one.q(i), acst_state_size(m))) << at;
    if (s.code != ACST_OK) {
      EXPECT_TRUE(same_bits(batch.s(i), given.stress.data() + i * given.ss, 6)) << at << ": left as it came";
      if (first == given.n) {
        first = i;
        first_message = s.message;
      }
    }
    if (f.tangent) {
      const double* t = &out.tangent[40 * i];
      if (s.code == ACST_OK) {
        EXPECT_TRUE(same_bits(t, D, 36)) << at;
      }
      for (int k = s.code == ACST_OK ? 36 : 0; k < 40; ++k) EXPECT_EQ(t[k], -7.0) << at << ": written past its 36";
    }
    if (f.status) {
      EXPECT_EQ(out.status[i], s.code) << at;
    }
    if (f.point_counters) {
      EXPECT_TRUE(same_counters(out.point_counters[i], c)) << at;
    }
    sum.substeps_accepted += c.substeps_accepted;
    sum.substeps_rejected += c.substeps_rejected;
    sum.rate_evaluations += c.rate_evaluations;
    sum.crossing_iterations += c.crossing_iterations;
    sum.unload_reload += c.unload_reload;
    sum.guard_pressure_floor += c.guard_pressure_floor;
    sum.guard_small_R += c.guard_small_R;
    sum.guard_lode_clamp += c.guard_lode_clamp;
    sum.guard_h_floor += c.guard_h_floor;
    sum.guard_uniqueness += c.guard_uniqueness;
    sum.pressure_floor_resets += c.pressure_floor_resets;
    sum.plastic += c.plastic;
  }
  if (f.counters) {
    EXPECT_TRUE(same_counters(out.counters, sum)) << where;
  }
  if (f.first_failure) {
    EXPECT_EQ(out.first_failure, first) << where;
  }
  if (first == given.n) {
    EXPECT_EQ(out.st.code, ACST_OK) << where << ": " << out.st.message;
    EXPECT_STREQ(out.st.message, "");
  } else {
    const std::string prefix = "point " + std::to_string(first) + ": ";
    EXPECT_EQ(std::string(out.st.message).rfind(prefix, 0), 0u) << where << ": " << out.st.message;
    // The one-point functions' refusals of a point's rotation or offsets name the function.
    std::string expected = first_message;
    const bool own_input = expected.find("rotation must") != std::string::npos ||
                           expected.find("nonlocal offset") != std::string::npos;
    for (const char* name : {"acst_update_rotated_nonlocal", "acst_update_nonlocal", "acst_update_rotated"}) {
      if (own_input && expected.rfind(name, 0) == 0) {
        expected = "acst_update_points" + expected.substr(std::strlen(name));
        break;
      }
    }
    EXPECT_EQ(std::string(out.st.message).substr(prefix.size()), expected) << where;
  }
}

const Fields all_mixes[] = {
    {false, false, false, false, false, false, false}, {false, false, true, true, true, true, true},
    {false, true, true, false, true, false, true},     {false, true, false, true, false, true, false},
    {true, false, false, true, true, true, true},      {true, true, false, true, true, false, true},
    {true, true, true, true, true, true, true},        {true, false, true, false, false, true, false},
};

std::string describe(const Fields& f) {
  std::string s;
  const std::pair<bool, const char*> named[] = {{f.rotation, "rotation"},     {f.offset, "offset"},
                                                {f.tangent, "tangent"},       {f.status, "point_status"},
                                                {f.point_counters, "point_counters"}, {f.counters, "counters"},
                                                {f.first_failure, "first_failure"}};
  for (const auto& [given, name] : named)
    if (given) s += (s.empty() ? "" : "+") + std::string(name);
  return s.empty() ? "no optional field" : s;
}

TEST(UpdatePoints, SandPointsGetTheOnePointFunctionsNumbersWithEveryMixOfFields) {
  const AbiModel model(sand_json());
  std::mt19937_64 rng(75);
  Tally tally;
  for (const Fields& f : all_mixes) {
    for (const bool bad : {false, true}) {
      const std::string where = describe(f) + (bad ? ", bad points" : "");
      // 37 points (not a multiple of the blocks of 16 or of the lanes), packed and spread.
      const Points packed = sand_points(model.get(), 37, 6, ACST_NSTATV, 6, 9, 1, rng, bad);
      ASSERT_NO_FATAL_FAILURE(expect_one_point_numbers(model.get(), packed, f, where + ", packed", &tally));
      const Points spread = sand_points(model.get(), 37, 8, 13, 7, 11, 3, rng, bad);
      ASSERT_NO_FATAL_FAILURE(expect_one_point_numbers(model.get(), spread, f, where + ", spread", &tally));
    }
  }
  // Most points load plastically in one substep (the lanes' kind, where a rotation is given and
  // no tangent asked for); the bad points fail.
  EXPECT_GT(tally.plastic_one_substep, tally.points / 3) << tally.plastic_one_substep << " of " << tally.points;
  EXPECT_GE(tally.failed, 3 * 2 * 8) << tally.failed;  // the state, the strains; rotation, offset where given
}

// The closed-form kinds: no state (statev NULL) or one variable, the offsets ignored.
TEST(UpdatePoints, ClosedFormKindsGetTheOnePointFunctionsNumbers) {
  const char* kinds[] = {R"({"model": "linear_elastic", "parameters": {"E": 20000, "nu": 0.25}})",
                         R"({"model": "von_mises", "parameters": {"E": 20000, "nu": 0.25, "yield_stress": 60}})",
                         R"({"model": "drucker_prager", "parameters": {"E": 20000, "nu": 0.25,
                             "friction_angle_deg": 30, "cohesion": 5}})"};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (const char* json : kinds) {
    const AbiModel model(json);
    const int nstatv = acst_state_size(model.get());
    for (const Fields& f : all_mixes) {
      Points P(21, 6, 2, 6, 9, 1);
      for (size_t i = 0; i < P.n; ++i) {
        const double s0[6] = {-100.0, -80.0 + 10.0 * u(rng), -90.0, 5.0 * u(rng), 0.0, 0.0};
        ASSERT_EQ(acst_initial_state(P.q(i), P.s(i), model.get(), s0, 0.7, nullptr).code, ACST_OK);
        const double size = 1e-3 * (1.0 + u(rng));
        const double e[6] = {0.5 * size * u(rng), -size, 0.0, 2.0 * size * u(rng), 0.0, 0.0};
        std::memcpy(P.e(i), e, sizeof e);
        const double Q[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
        std::memcpy(P.r(i), Q, sizeof Q);
        P.o(i)[0] = 10.0;  // ignored: nothing softens
      }
      P.e(4)[2] = nan;
      P.r(7)[8] = -1.0;
      if (nstatv == 0) {  // no state: statev may be NULL
        Points none = P;
        none.statev.clear();
        none.qs = 0;
        ASSERT_NO_FATAL_FAILURE(expect_one_point_numbers(model.get(), none, f, std::string(json) + ", " + describe(f)));
      } else {
        ASSERT_NO_FATAL_FAILURE(expect_one_point_numbers(model.get(), P, f, std::string(json) + ", " + describe(f)));
      }
    }
  }
}

// The old batch functions are wrappers: acst_update_batch (summed counters) and
// acst_update_rotated_batch_nonlocal (per-point counters) answer as acst_update_points with the
// same view, message included.
TEST(UpdatePoints, TheBatchFunctionsAreItsWrappers) {
  const AbiModel model(sand_json());
  std::mt19937_64 rng(3);
  const Points given = sand_points(model.get(), 37, 6, ACST_NSTATV, 6, 9, 1, rng, true);
  {
    Points a = given, b = given;
    std::vector<int> codes(given.n, -1);
    acst_counters c{};
    const acst_status old = acst_update_batch(a.stress.data(), 6, a.statev.data(), ACST_NSTATV, codes.data(), &c,
                                              model.get(), a.n, a.dstrain.data(), 6);
    const Outputs out = update_points(model.get(), b, Fields{false, false, false, true, false, true, false});
    EXPECT_TRUE(same_bits(a.stress.data(), b.stress.data(), a.stress.size()));
    EXPECT_TRUE(same_bits(a.statev.data(), b.statev.data(), a.statev.size()));
    EXPECT_EQ(codes, out.status);
    EXPECT_TRUE(same_counters(c, out.counters));
    EXPECT_EQ(old.code, out.st.code);
    EXPECT_STREQ(old.message, out.st.message);
  }
  {
    Points a = given, b = given;
    std::vector<int> codes(given.n, -1);
    std::vector<acst_counters> c(given.n);
    const acst_status old =
        acst_update_rotated_batch_nonlocal(a.stress.data(), 6, a.statev.data(), ACST_NSTATV, codes.data(), c.data(),
                                           model.get(), a.n, a.rotation.data(), a.dstrain.data(), a.offset.data());
    const Outputs out = update_points(model.get(), b, Fields{true, true, false, true, true, false, false});
    EXPECT_TRUE(same_bits(a.stress.data(), b.stress.data(), a.stress.size()));
    EXPECT_TRUE(same_bits(a.statev.data(), b.statev.data(), a.statev.size()));
    EXPECT_EQ(codes, out.status);
    for (size_t i = 0; i < given.n; ++i) EXPECT_TRUE(same_counters(c[i], out.point_counters[i])) << i;
    EXPECT_EQ(old.code, out.st.code);
    // The first failure is point 3's rotation; the batch names itself.
    EXPECT_STREQ(old.message,
                 "point 3: acst_update_rotated_batch: rotation must be a finite proper orthogonal 3x3 matrix, "
                 "row-major (|Q Q^T - I| < 1e-8, det Q > 0)");
    EXPECT_STREQ(out.st.message,
                 "point 3: acst_update_points: rotation must be a finite proper orthogonal 3x3 matrix, "
                 "row-major (|Q Q^T - I| < 1e-8, det Q > 0)");
  }
  // A one-point function refuses a bad rotation or offset as the whole call: no point named,
  // the counters untouched.
  Points p = given;
  acst_counters c;
  std::memset(&c, 0x5a, sizeof c);
  const acst_counters before = c;
  const acst_status st = acst_update_rotated(p.s(3), p.q(3), nullptr, &c, model.get(), p.r(3), p.e(3));
  EXPECT_EQ(st.code, ACST_INVALID_INPUT);
  EXPECT_EQ(std::string(st.message).rfind("acst_update_rotated: rotation must", 0), 0u) << st.message;
  EXPECT_TRUE(same_counters(c, before));
  const acst_status off = acst_update_nonlocal(p.s(12), p.q(12), nullptr, &c, model.get(), p.e(12), p.o(12));
  EXPECT_EQ(off.code, ACST_INVALID_INPUT);
  EXPECT_EQ(std::string(off.message).rfind("acst_update_nonlocal: the nonlocal offset", 0), 0u) << off.message;
  EXPECT_TRUE(same_counters(c, before));
  EXPECT_EQ(p.stress, given.stress);
}

// Whole-call refusals: ACST_INVALID_INPUT with a message naming acst_update_points, and nothing
// written: no stress, state or tangent, no code, counter or first failure.
TEST(UpdatePoints, BadInputIsRefusedWithAMessageAndNothingWritten) {
  const AbiModel model(sand_json());
  std::mt19937_64 rng(9);
  const Points given = sand_points(model.get(), 3, 6, ACST_NSTATV, 6, 9, 1, rng, false);
  Points P = given;
  std::vector<double> tangent(3 * 36, -7.0);
  int codes[3] = {-1, -1, -1};
  acst_counters per_point[3], sum;
  std::memset(per_point, 0x5a, sizeof per_point);
  std::memset(&sum, 0x5a, sizeof sum);
  size_t first = 12345;
  const auto view = [&] {
    acst_batch b = {};
    b.n = 3;
    b.stress = P.stress.data();
    b.stress_stride = 6;
    b.statev = P.statev.data();
    b.statev_stride = ACST_NSTATV;
    b.dstrain = P.dstrain.data();
    b.dstrain_stride = 6;
    b.rotation = P.rotation.data();
    b.rotation_stride = 9;
    b.offset = P.offset.data();
    b.offset_stride = 1;
    b.tangent = tangent.data();
    b.tangent_stride = 36;
    b.point_status = codes;
    b.point_counters = per_point;
    b.counters = &sum;
    b.first_failure = &first;
    return b;
  };
  const auto refused = [&](const acst_batch* b, const acst_model* m, const char* what, const char* says) {
    const acst_status st = acst_update_points(b, m);
    EXPECT_EQ(st.code, ACST_INVALID_INPUT) << what;
    EXPECT_EQ(std::string(st.message).rfind("acst_update_points: ", 0), 0u) << what << ": " << st.message;
    EXPECT_NE(std::string(st.message).find(says), std::string::npos) << what << ": " << st.message;
    EXPECT_EQ(P.stress, given.stress) << what;
    EXPECT_TRUE(same_bits(P.statev.data(), given.statev.data(), P.statev.size())) << what;
    for (double t : tangent) ASSERT_EQ(t, -7.0) << what;
    for (int c : codes) EXPECT_EQ(c, -1) << what;
    for (const acst_counters& c : per_point) EXPECT_EQ(c.plastic, 0x5a5a5a5a) << what;
    EXPECT_EQ(sum.plastic, 0x5a5a5a5a) << what;
    EXPECT_EQ(first, 12345u) << what;
  };
  acst_batch b = view();
  refused(nullptr, model.get(), "NULL view", "NULL");
  refused(&b, nullptr, "NULL model", "NULL");
  const struct {
    const char* what;
    void (*spoil)(acst_batch&);
    const char* says;
  } cases[] = {
      {"NULL stress", [](acst_batch& v) { v.stress = nullptr; }, "NULL"},
      {"NULL statev", [](acst_batch& v) { v.statev = nullptr; }, "NULL"},
      {"NULL dstrain", [](acst_batch& v) { v.dstrain = nullptr; }, "NULL"},
      {"stress stride 5", [](acst_batch& v) { v.stress_stride = 5; }, "stress stride 5"},
      {"state stride 9", [](acst_batch& v) { v.statev_stride = ACST_NSTATV - 1; }, "statev stride 9"},
      {"strain stride 0", [](acst_batch& v) { v.dstrain_stride = 0; }, "dstrain stride 0"},
      {"rotation stride 8", [](acst_batch& v) { v.rotation_stride = 8; }, "rotation stride 8"},
      {"offset stride 0", [](acst_batch& v) { v.offset_stride = 0; }, "offset stride 0"},
      {"tangent stride 35", [](acst_batch& v) { v.tangent_stride = 35; }, "tangent stride 35"},
      {"stress stride wrapping size_t", [](acst_batch& v) { v.stress_stride = SIZE_MAX - 5; }, "wraps size_t"},
      {"state stride wrapping size_t", [](acst_batch& v) { v.statev_stride = SIZE_MAX / 2; }, "wraps size_t"},
      {"strain stride wrapping size_t", [](acst_batch& v) { v.dstrain_stride = SIZE_MAX / 2; }, "wraps size_t"},
      {"rotation stride wrapping size_t", [](acst_batch& v) { v.rotation_stride = SIZE_MAX / 2; }, "wraps size_t"},
      {"offset stride wrapping size_t", [](acst_batch& v) { v.offset_stride = SIZE_MAX / 2; }, "wraps size_t"},
      {"tangent stride wrapping size_t", [](acst_batch& v) { v.tangent_stride = SIZE_MAX / 2; }, "wraps size_t"},
  };
  for (const auto& c : cases) {
    acst_batch spoilt = view();
    c.spoil(spoilt);
    refused(&spoilt, model.get(), c.what, c.says);
  }
  // An absent optional array's stride is not read; no point: nothing required.
  acst_batch absent = view();
  absent.tangent = nullptr;
  absent.tangent_stride = 0;
  absent.rotation = nullptr;
  absent.rotation_stride = SIZE_MAX;
  EXPECT_EQ(acst_update_points(&absent, model.get()).code, ACST_OK);
  EXPECT_EQ(first, 3u);
  acst_batch none = {};
  none.counters = &sum;
  none.first_failure = &first;
  const acst_status st = acst_update_points(&none, model.get());
  EXPECT_EQ(st.code, ACST_OK) << st.message;
  EXPECT_EQ(first, 0u);
  EXPECT_TRUE(same_counters(sum, acst_counters{}));
}

}  // namespace c_abi_update_points_test
