// Material::update on bad input (C++ API): a non-finite strain increment is invalid input, a
// non-finite or non-physical state is reported as such, and in both cases the state is left
// exactly as it was (docs/integration.md: never a silently wrong stress).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "test_materials.hpp"

namespace {

using acst::Sym;
using acst::integration::Status;

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();

// Bitwise equality of two states (NaN slots compare equal to themselves).
bool identical(const acst::State& a, const acst::State& b) {
  return std::memcmp(a.stress.data(), b.stress.data(), sizeof(double) * 6) == 0 &&
         std::memcmp(a.fabric.data(), b.fabric.data(), sizeof(double) * 6) == 0 &&
         std::memcmp(&a.void_ratio, &b.void_ratio, sizeof(double)) == 0 &&
         std::memcmp(&a.H, &b.H, sizeof(double)) == 0 &&
         std::memcmp(&a.substep_hint, &b.substep_hint, sizeof(double)) == 0 &&
         a.pressure_floor_resets == b.pressure_floor_resets;
}

acst::State sheared_state(const acst::Material& mat) {
  acst::State s = mat.initial_state((Sym() << 180, 100, 90, 12, 0, -4).finished(), 0.75, Eigen::Vector3d(0, 0, 1));
  s.substep_hint = 0.37;  // a carried value that must survive a rejected call
  return s;
}

const Sym good_increment = (Sym() << 1e-4, -3e-5, -3e-5, 1e-5, 0, 0).finished();

TEST(UpdateBadInput, NonFiniteStrainIncrementIsInvalidInputAndLeavesTheStateAlone) {
  const acst::Material mat = acst::test::guide_material();
  for (int slot = 0; slot < 6; ++slot) {
    for (double bad : {nan, inf, -inf}) {
      acst::State s = sheared_state(mat);
      const acst::State before = s;
      Sym deps = good_increment;
      deps[slot] = bad;
      const acst::integration::Report rep = mat.update(s, deps);
      EXPECT_EQ(rep.status, Status::invalid_input) << "slot " << slot << " value " << bad;
      EXPECT_TRUE(identical(s, before)) << "slot " << slot;
    }
  }
}

TEST(UpdateBadInput, NonFiniteStressIsNonphysicalStateAndLeavesTheStateAlone) {
  const acst::Material mat = acst::test::guide_material();
  for (int slot = 0; slot < 6; ++slot) {
    acst::State s = sheared_state(mat);
    s.stress[slot] = nan;
    const acst::State before = s;
    EXPECT_EQ(mat.update(s, good_increment).status, Status::nonphysical_state) << "slot " << slot;
    EXPECT_TRUE(identical(s, before)) << "slot " << slot;
  }
  acst::State s = sheared_state(mat);
  s.stress[0] = inf;
  EXPECT_EQ(mat.update(s, good_increment).status, Status::nonphysical_state);
}

TEST(UpdateBadInput, NonPositiveVoidRatioIsNonphysicalState) {
  const acst::Material mat = acst::test::guide_material();
  for (double e : {0.0, -0.1, nan}) {
    acst::State s = sheared_state(mat);
    s.void_ratio = e;
    const acst::State before = s;
    EXPECT_EQ(mat.update(s, good_increment).status, Status::nonphysical_state) << "e = " << e;
    EXPECT_TRUE(identical(s, before)) << "e = " << e;
  }
}

TEST(UpdateBadInput, NonFiniteFabricOrMemoryIsNonphysicalState) {
  const acst::Material mat = acst::test::guide_material();
  acst::State s = sheared_state(mat);
  s.fabric[3] = nan;
  EXPECT_EQ(mat.update(s, good_increment).status, Status::nonphysical_state);
  s = sheared_state(mat);
  s.H = nan;
  EXPECT_EQ(mat.update(s, good_increment).status, Status::nonphysical_state);
  s = sheared_state(mat);
  s.H = -0.1;  // the cone size R/g cannot be negative
  EXPECT_EQ(mat.update(s, good_increment).status, Status::nonphysical_state);
}

TEST(UpdateBadInput, TheSameStateAndIncrementAreFineWhenValid) {
  // Guards the tests above: their failures come from the one bad value, not from the base case.
  const acst::Material mat = acst::test::guide_material();
  acst::State s = sheared_state(mat);
  EXPECT_EQ(mat.update(s, good_increment).status, Status::ok);
}

}  // namespace
