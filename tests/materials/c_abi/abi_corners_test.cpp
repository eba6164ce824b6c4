// The last corners of the C ABI's rules (issue 57, item 10; acst.h, docs/c-abi.md "The OK rule"):
// a bedding angle near the largest double gives a unit direction, not NaN with ACST_OK; a stress
// beyond what the model's arithmetic takes (an isotropic -1e308 kPa) is a non-physical state in
// every function, not a step reduction at every increment size; and for a tensile mean stress
// (or a substep hint that is no number) acst_update_rotated answers as its documented
// equivalent, acst_rotate_state then acst_update.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "abi_model.hpp"
#include "acst.h"
#include "test_materials.hpp"

namespace c_abi_corners_test {

namespace {

using acst::test::AbiModel;

std::string calibrated_acst() { return acst::test::read_text("data/parameters/toyoura_acst_calibrated.json"); }

// A consistent state at 100 kPa (fabric, H on the cone), e 0.8.
struct Point {
  double stress[6], statev[ACST_NSTATV];
  explicit Point(const AbiModel& m) {
    const double s0[6] = {-100, -100, -100, 0, 0, 0}, b[3] = {1, 0, 0};
    EXPECT_EQ(acst_initial_state(statev, stress, m.get(), s0, 0.8, b).code, ACST_OK);
  }
};

// A turn of 30 degrees about axis 3 (a plane-strain host's, the SIMD lanes' case) and a general one.
const double turn_axis3[9] = {std::cos(0.5236), std::sin(0.5236), 0, -std::sin(0.5236), std::cos(0.5236), 0, 0, 0, 1};
const double turn_general[9] = {1, 0, 0, 0, std::cos(0.3), std::sin(0.3), 0, -std::sin(0.3), std::cos(0.3)};

// Bit for bit (a NaN equals itself here).
void expect_untouched(const Point& now, const Point& before, const std::string& what) {
  EXPECT_EQ(std::memcmp(now.stress, before.stress, sizeof now.stress), 0) << what;
  EXPECT_EQ(std::memcmp(now.statev, before.statev, sizeof now.statev), 0) << what;
}

}  // namespace

// alpha * pi overflowed for |alpha| near 1e308: cos and sin of infinity are NaN, returned with
// ACST_OK. Whole turns are taken off first, exactly: 1e308 degrees is the same direction as its
// remainder modulo 360, and 390 degrees as 30 (to round-off: 1e-15 on unit components).
TEST(AbiCorners, ABeddingAngleNearTheLargestDoubleGivesAUnitDirection) {
  for (const double alpha : {1e308, -1e308, 1.7976931348623157e308, 1e300, 123456789.0}) {
    double b[3];
    const acst_status st = acst_bedding_direction(b, alpha, 0, 2, 1.0);
    ASSERT_EQ(st.code, ACST_OK) << alpha;
    EXPECT_TRUE(std::isfinite(b[0]) && std::isfinite(b[1]) && std::isfinite(b[2])) << alpha;
    EXPECT_NEAR(b[0] * b[0] + b[1] * b[1] + b[2] * b[2], 1.0, 1e-15) << alpha;
    double r[3];
    ASSERT_EQ(acst_bedding_direction(r, std::fmod(alpha, 360.0), 0, 2, 1.0).code, ACST_OK);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(b[i], r[i]) << alpha;
  }
  double b390[3], b30[3];
  ASSERT_EQ(acst_bedding_direction(b390, 390.0, 1, 0, -1.0).code, ACST_OK);
  ASSERT_EQ(acst_bedding_direction(b30, 30.0, 1, 0, -1.0).code, ACST_OK);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(b390[i], b30[i], 1e-15);
}

// From an isotropic -1e308 kPa every update failed with a step reduction, at every increment size
// down to zero, so a host that follows the rule (retry smaller) never ends. Beyond 1e100 kPa in a
// component (acst::stress_limit) the state is non-physical, in every function that reads one.
TEST(AbiCorners, AStressBeyondTheModelsArithmeticIsNonphysicalEverywhere) {
  AbiModel m(calibrated_acst());
  const Point good(m);
  for (const double s : {-1e308, -3e307, -1e101, 1e101}) {
    Point p = good;
    for (int i = 0; i < 3; ++i) p.stress[i] = s;
    const Point before = p;
    for (const double inc : {0.0, 1e-12, 1e-6, 1e-3}) {
      const double de[6] = {-inc, 0, 0, 0, 0, 0};
      EXPECT_EQ(acst_update(p.stress, p.statev, nullptr, nullptr, m.get(), de).code, ACST_NONPHYSICAL_STATE) << s << " " << inc;
      EXPECT_EQ(acst_update_rotated(p.stress, p.statev, nullptr, nullptr, m.get(), turn_axis3, de).code, ACST_NONPHYSICAL_STATE)
          << s << " " << inc;
    }
    double out[ACST_NDIAGNOSTICS], speed = 0;
    EXPECT_EQ(acst_diagnostics(out, m.get(), p.stress, p.statev).code, ACST_NONPHYSICAL_STATE) << s;
    EXPECT_EQ(acst_wave_speed(&speed, m.get(), p.stress, p.statev, 1600.0).code, ACST_NONPHYSICAL_STATE) << s;
    EXPECT_EQ(acst_rotate_state(p.stress, p.statev, m.get(), turn_general).code, ACST_NONPHYSICAL_STATE) << s;
    expect_untouched(p, before, "stress " + std::to_string(s));
    double statev[ACST_NSTATV], stress_out[6];
    const double b[3] = {1, 0, 0};
    EXPECT_EQ(acst_initial_state(statev, stress_out, m.get(), p.stress, 0.8, b).code, ACST_INVALID_INPUT) << s;
  }
  // At the limit itself a state is one: an update of zero strain keeps it.
  Point edge = good;
  for (int i = 0; i < 3; ++i) edge.stress[i] = -1e100;
  const double zero[6] = {0, 0, 0, 0, 0, 0};
  const acst_status st = acst_update(edge.stress, edge.statev, nullptr, nullptr, m.get(), zero);
  EXPECT_EQ(st.code, ACST_OK) << st.message;
}

// acst_update takes a tensile state (the integrator's pressure floor deals with it) and a substep
// hint that is no number (no hint); the functions that only read a state, acst_rotate_state among
// them, refuse both. acst_update_rotated is documented as acst_rotate_state then acst_update, and
// the retry after its failure starts with acst_rotate_state: it answered OK or a step reduction
// where its two calls answer a non-physical state, so that retry could not start. Now both answer
// the same, point by point in the batch too (where the SIMD lanes take turns about axis 3).
TEST(AbiCorners, ATensileStateGetsTheAnswerOfTheTwoCallsFromUpdateRotated) {
  AbiModel m(calibrated_acst());
  const Point good(m);
  std::vector<Point> refused;
  for (const std::array<double, 6>& s : {std::array<double, 6>{20, 20, 20, 0, 0, 0}, std::array<double, 6>{5, -1, -1, 2, 0, 0},
                                         std::array<double, 6>{1e-300, 0, 0, 0, 0, 0}}) {
    refused.push_back(good);
    std::copy(s.begin(), s.end(), refused.back().stress);
  }
  for (const double hint : {std::nan(""), std::numeric_limits<double>::infinity()}) {
    refused.push_back(good);
    refused.back().statev[8] = hint;  // the substep hint (acst_state_name 8)
  }
  const double de[6] = {-1e-4, 5e-5, 5e-5, 0, 0, 0};
  for (const Point& start : refused)
    for (const double* rotation : {turn_axis3, turn_general}) {
      Point p = start;
      const Point before = p;
      const acst_status one = acst_update_rotated(p.stress, p.statev, nullptr, nullptr, m.get(), rotation, de);
      expect_untouched(p, before, "acst_update_rotated");
      Point two = before;
      acst_status first = acst_rotate_state(two.stress, two.statev, m.get(), rotation);
      if (first.code == ACST_OK) first = acst_update(two.stress, two.statev, nullptr, nullptr, m.get(), de);
      EXPECT_EQ(first.code, ACST_NONPHYSICAL_STATE) << first.message;
      EXPECT_EQ(one.code, first.code) << "acst_update_rotated: " << one.message << "; the two calls: " << first.message;
      // The batch (SIMD lanes for turns about axis 3) answers as the single call.
      Point b = before;
      int code = -1;
      acst_update_rotated_batch(b.stress, 6, b.statev, ACST_NSTATV, &code, nullptr, m.get(), 1, rotation, de);
      EXPECT_EQ(code, one.code);
      expect_untouched(b, before, "acst_update_rotated_batch");
    }
  // A compressive state turns and updates as before: the two routes agree to the bit.
  Point one = good, two = good;
  ASSERT_EQ(acst_update_rotated(one.stress, one.statev, nullptr, nullptr, m.get(), turn_axis3, de).code, ACST_OK);
  ASSERT_EQ(acst_rotate_state(two.stress, two.statev, m.get(), turn_axis3).code, ACST_OK);
  ASSERT_EQ(acst_update(two.stress, two.statev, nullptr, nullptr, m.get(), de).code, ACST_OK);
  for (int i = 0; i < 6; ++i) EXPECT_EQ(one.stress[i], two.stress[i]);
}

}  // namespace c_abi_corners_test

namespace c_abi_corners_test {

// A stride whose product with the point count wraps size_t (a host's negative stride passed as
// size_t) was checked only from below: the batch wrote before the caller's array and answered OK.
// Every batch entry point refuses it with ACST_INVALID_INPUT and a message, writing nothing.
TEST(AbiCorners, AStrideThatWrapsSizeTIsRefusedAndNothingIsWritten) {
  const AbiModel m(calibrated_acst());
  Point p[2] = {Point(m), Point(m)};
  const Point before[2] = {p[0], p[1]};
  const double dstrain[12] = {-1e-4, 0, 0, 0, 0, 0, -1e-4, 0, 0, 0, 0, 0};
  const double turns[18] = {1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const double offsets[2] = {0, 0};
  const size_t backward = static_cast<size_t>(-static_cast<std::ptrdiff_t>(sizeof(Point) / sizeof(double)));
  const size_t state_stride = sizeof(Point) / sizeof(double);
  int codes[2] = {-1, -1};
  const auto refused = [&](const acst_status& st, const char* which) {
    EXPECT_EQ(st.code, ACST_INVALID_INPUT) << which;
    EXPECT_NE(std::string(st.message).find("wraps size_t"), std::string::npos) << which << ": " << st.message;
    expect_untouched(p[0], before[0], which);
    expect_untouched(p[1], before[1], which);
    EXPECT_EQ(codes[0], -1) << which;
  };
  // The second point addressed backwards from the first: before the array.
  refused(acst_update_batch(p[1].stress, backward, p[1].statev, state_stride, codes, nullptr, m.get(), 2, dstrain, 6),
          "acst_update_batch, stress");
  refused(acst_update_batch(p[0].stress, state_stride, p[0].statev, SIZE_MAX, codes, nullptr, m.get(), 2, dstrain, 6),
          "acst_update_batch, state");
  refused(acst_update_batch(p[0].stress, state_stride, p[0].statev, state_stride, codes, nullptr, m.get(), 2, dstrain, SIZE_MAX / 2),
          "acst_update_batch, strain");
  refused(acst_update_rotated_batch(p[1].stress, backward, p[1].statev, state_stride, codes, nullptr, m.get(), 2, turns, dstrain),
          "acst_update_rotated_batch");
  refused(acst_update_rotated_batch_nonlocal(p[0].stress, state_stride, p[0].statev, SIZE_MAX / 3, codes, nullptr, m.get(), 2,
                                             turns, dstrain, offsets),
          "acst_update_rotated_batch_nonlocal");
  // Strides a host uses still work: the two points apart by one Point.
  EXPECT_EQ(acst_update_batch(p[0].stress, state_stride, p[0].statev, state_stride, codes, nullptr, m.get(), 2, dstrain, 6).code,
            ACST_OK);
}

}  // namespace c_abi_corners_test
