// acst_rotate_state: the objective rotation a large-deformation host (MPM) applies before each
// update. At the ABI the stress holds tensor shear components and the strain engineering ones;
// this file rotates them independently of the library, as 3x3 matrices Q A Q^T.
// Objectivity of the ACST update means rotate-then-update equals update-then-rotate: the two
// routes do the same arithmetic in two frames, so they differ by round-off only (1e-9 relative
// leaves room for it to grow over a path through the integrator's error control).
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <string>
#include <vector>

#include "abi_model.hpp"
#include "acst.h"
#include "test_materials.hpp"

namespace c_abi_rotation_test {

namespace {

using acst::test::AbiModel;
using acst::test::Voigt;
using RowMajor3 = Eigen::Matrix<double, 3, 3, Eigen::RowMajor>;

constexpr double frame_round_off = 1e-9;

std::string calibrated_acst() { return acst::test::read_text("data/parameters/toyoura_acst_calibrated.json"); }

// shear_factor 1 for stress-like (tensor shear) vectors, 2 for engineering strain.
Eigen::Matrix3d matrix_of(const double* v, double shear_factor) {
  Eigen::Matrix3d m;
  m << v[0], v[3] / shear_factor, v[4] / shear_factor, v[3] / shear_factor, v[1], v[5] / shear_factor,
      v[4] / shear_factor, v[5] / shear_factor, v[2];
  return m;
}

void rotate_by_hand(double* v, const Eigen::Matrix3d& Q, double shear_factor) {
  const Eigen::Matrix3d r = Q * matrix_of(v, shear_factor) * Q.transpose();
  const double out[6] = {r(0, 0), r(1, 1), r(2, 2), shear_factor * r(0, 1), shear_factor * r(0, 2),
                         shear_factor * r(1, 2)};
  for (int i = 0; i < 6; ++i) v[i] = out[i];
}

const Eigen::Matrix3d general_rotation =
    Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).toRotationMatrix();

acst_status rotate(Voigt& stress, std::vector<double>& statev, const acst_model* m, const Eigen::Matrix3d& Q) {
  const RowMajor3 q = Q;
  return acst_rotate_state(stress.data(), statev.empty() ? nullptr : statev.data(), m, q.data());
}

struct SandPoint {
  Voigt stress;
  std::vector<double> statev = std::vector<double>(ACST_NSTATV);
};

// Anisotropic stress with shear and a tilted deposition direction, so that every stress and
// fabric component is non-zero, then loaded into the plastic range.
SandPoint loaded_sand_point(const acst_model* m) {
  SandPoint p;
  const double s0[6] = {-120, -90, -70, 12, -6, 4}, b[3] = {0.3, 1.0, -0.4};
  EXPECT_EQ(acst_initial_state(p.statev.data(), p.stress.data(), m, s0, 0.75, b).code, ACST_OK);
  const double d[6] = {-2e-4, 5e-5, 6e-5, 8e-5, -3e-5, 2e-5};
  for (int k = 0; k < 10; ++k)
    EXPECT_EQ(acst_update(p.stress.data(), p.statev.data(), nullptr, nullptr, m, d).code, ACST_OK);
  return p;
}

double max_abs(const double* v, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = std::max(m, std::abs(v[i]));
  return m;
}

TEST(CAbiRotation, RotateThenUpdateEqualsUpdateThenRotateForAcst) {
  AbiModel m(calibrated_acst());
  ASSERT_STREQ(acst_model_kind(m.get()), "ACST");
  SandPoint unrotated = loaded_sand_point(m.get());
  SandPoint rotated = unrotated;
  ASSERT_EQ(rotate(rotated.stress, rotated.statev, m.get(), general_rotation).code, ACST_OK);
  int plastic_steps = 0;
  for (int k = 0; k < 40; ++k) {
    double d[6] = {-1e-4, 2e-5 * std::cos(0.3 * k), 3e-5, 6e-5 * std::sin(0.2 * k), -2e-5, 4e-5};
    if (k >= 25) for (double& v : d) v = -0.5 * v;  // unload and reverse
    acst_counters c;
    ASSERT_EQ(acst_update(unrotated.stress.data(), unrotated.statev.data(), nullptr, &c, m.get(), d).code, ACST_OK);
    plastic_steps += c.plastic;
    rotate_by_hand(d, general_rotation, 2.0);
    ASSERT_EQ(acst_update(rotated.stress.data(), rotated.statev.data(), nullptr, nullptr, m.get(), d).code, ACST_OK);

    SandPoint expected = unrotated;
    rotate_by_hand(expected.stress.data(), general_rotation, 1.0);
    rotate_by_hand(expected.statev.data(), general_rotation, 1.0);  // the fabric, slots 0-5
    const double stress_scale = max_abs(expected.stress.data(), 6);
    for (int i = 0; i < 6; ++i)
      ASSERT_NEAR(rotated.stress[i], expected.stress[i], frame_round_off * stress_scale) << "step " << k << " i " << i;
    const double fabric_scale = max_abs(expected.statev.data(), 6);
    for (int i = 0; i < 6; ++i)
      ASSERT_NEAR(rotated.statev[i], expected.statev[i], frame_round_off * fabric_scale) << "step " << k;
    for (int i = 6; i < ACST_NSTATV; ++i)
      ASSERT_NEAR(rotated.statev[i], expected.statev[i], frame_round_off * std::max(1.0, std::abs(expected.statev[i])))
          << "step " << k << ", " << acst_state_name(m.get(), i);
  }
  EXPECT_GT(plastic_steps, 10) << "the path must exercise the plastic update";
}

TEST(CAbiRotation, InvariantsAreUnchanged) {
  AbiModel m(calibrated_acst());
  SandPoint p = loaded_sand_point(m.get());
  double before[ACST_NDIAGNOSTICS], after[ACST_NDIAGNOSTICS];
  ASSERT_EQ(acst_diagnostics(before, m.get(), p.stress.data(), p.statev.data()).code, ACST_OK);
  ASSERT_EQ(rotate(p.stress, p.statev, m.get(), general_rotation).code, ACST_OK);
  ASSERT_EQ(acst_diagnostics(after, m.get(), p.stress.data(), p.statev.data()).code, ACST_OK);
  for (const char* name : {"p", "q", "fabric_norm", "R", "A", "sin3theta"}) {
    int i = 0;
    while (std::string(acst_diagnostic_name(i)) != name) ++i;
    EXPECT_NEAR(after[i], before[i], 1e-12 * std::max(1.0, std::abs(before[i]))) << name;
  }
}

TEST(CAbiRotation, QuarterTurnAboutZSwapsComponentsExactly) {
  AbiModel m(calibrated_acst());
  const SandPoint p = loaded_sand_point(m.get());
  SandPoint r = p;
  const double Q[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
  ASSERT_EQ(acst_rotate_state(r.stress.data(), r.statev.data(), m.get(), Q).code, ACST_OK);
  // sigma' = Q sigma Q^T with e_1 -> e_2, e_2 -> -e_1: 11 <-> 22, 12 and 13 change sign with 23 <-> 13.
  auto expect_swapped = [](const double* a, const double* b, const char* what) {
    EXPECT_EQ(b[0], a[1]) << what;
    EXPECT_EQ(b[1], a[0]) << what;
    EXPECT_EQ(b[2], a[2]) << what;
    EXPECT_EQ(b[3], -a[3]) << what;
    EXPECT_EQ(b[4], -a[5]) << what;
    EXPECT_EQ(b[5], a[4]) << what;
  };
  expect_swapped(p.stress.data(), r.stress.data(), "stress");
  expect_swapped(p.statev.data(), r.statev.data(), "fabric");
  for (int i = 6; i < ACST_NSTATV; ++i) EXPECT_EQ(r.statev[i], p.statev[i]) << "scalar state is not rotated";
}

TEST(CAbiRotation, InvalidRotationsAreRejectedWithStateUnchanged) {
  AbiModel m(calibrated_acst());
  SandPoint p = loaded_sand_point(m.get());
  const SandPoint before = p;
  const RowMajor3 proper = general_rotation;
  RowMajor3 perturbed = proper;
  perturbed(0, 1) += 1e-7;  // orthogonal to 1e-7 only
  const RowMajor3 reflection = Eigen::Vector3d(1, 1, -1).asDiagonal();
  const RowMajor3 improper = proper * reflection;
  RowMajor3 stretched = 1.001 * proper, with_nan = proper;
  with_nan(2, 2) = NAN;
  const RowMajor3* invalid[] = {&perturbed, &reflection, &improper, &stretched, &with_nan};
  for (const RowMajor3* Q : invalid) {
    const acst_status st = acst_rotate_state(p.stress.data(), p.statev.data(), m.get(), Q->data());
    EXPECT_EQ(st.code, ACST_INVALID_INPUT);
    EXPECT_NE(std::string(st.message).find("proper orthogonal"), std::string::npos) << st.message;
    EXPECT_EQ(p.stress, before.stress);
    EXPECT_EQ(p.statev, before.statev);
  }
  EXPECT_EQ(acst_rotate_state(p.stress.data(), nullptr, m.get(), proper.data()).code, ACST_INVALID_INPUT)
      << "ACST has state to rotate";
  EXPECT_EQ(acst_rotate_state(p.stress.data(), p.statev.data(), m.get(), nullptr).code, ACST_INVALID_INPUT);
  EXPECT_EQ(acst_rotate_state(p.stress.data(), p.statev.data(), nullptr, proper.data()).code, ACST_INVALID_INPUT);
  EXPECT_EQ(p.stress, before.stress);
  EXPECT_EQ(p.statev, before.statev);
}

// A turn about axis 3 has its own quick check in the library (a plane-strain host's every
// rotation); the same turn about axis 1 goes through the general one, and the rule's terms are
// the same numbers for both. Scaled turns around the rule's edge (|Q Q^T - I| = sqrt(2) |c^2 +
// s^2 - 1| against 1e-8, so a scale of 1 +- 3.5e-9) must be judged alike, on both sides of it.
TEST(CAbiRotation, PlaneTurnsAreJudgedByTheGeneralRule) {
  AbiModel m(R"({"model": "linear_elastic", "parameters": {"E": 20000, "nu": 0.25}})");
  int accepted = 0, rejected = 0;
  for (int i = 0; i < 4000; ++i) {
    const double theta = 0.001 * (i % 97) - 0.04 + (i % 3 == 0 ? 2.5 : 0.0);
    const double scale = 1.0 + (static_cast<double>(i % 400) - 200.0) * 2e-11 * (i % 2 == 0 ? 1.0 : -1.0) +
                         (i % 400 < 200 ? 3.4e-9 : -3.4e-9);
    const double c = scale * std::cos(theta), s = scale * std::sin(theta);
    const double about_3[9] = {c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0};
    const double about_1[9] = {1.0, 0.0, 0.0, 0.0, c, s, 0.0, -s, c};
    Voigt a{-100, -80, -60, 5, 3, 2}, b = a;
    const int code_3 = acst_rotate_state(a.data(), nullptr, m.get(), about_3).code;
    const int code_1 = acst_rotate_state(b.data(), nullptr, m.get(), about_1).code;
    ASSERT_EQ(code_3, code_1) << "theta " << theta << ", scale - 1 = " << scale - 1.0;
    (code_3 == ACST_OK ? accepted : rejected) += 1;
  }
  EXPECT_GT(accepted, 100);
  EXPECT_GT(rejected, 100);
  const double nan_turn[9] = {NAN, 0.0, 0.0, -0.0, NAN, 0.0, 0.0, 0.0, 1.0};
  const double infinite_turn[9] = {INFINITY, 0.0, 0.0, -0.0, INFINITY, 0.0, 0.0, 0.0, 1.0};
  const double infinite_sine[9] = {0.0, INFINITY, 0.0, -INFINITY, 0.0, 0.0, 0.0, 0.0, 1.0};
  const double half_turn[9] = {-1.0, 0.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 1.0};  // proper
  const double flipped[9] = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, -1.0};     // not a turn about 3
  Voigt v{-100, -80, -60, 5, 3, 2};
  for (const double* bad : {nan_turn, infinite_turn, infinite_sine})
    EXPECT_EQ(acst_rotate_state(v.data(), nullptr, m.get(), bad).code, ACST_INVALID_INPUT);
  EXPECT_EQ(acst_rotate_state(v.data(), nullptr, m.get(), half_turn).code, ACST_OK);
  EXPECT_EQ(acst_rotate_state(v.data(), nullptr, m.get(), flipped).code, ACST_INVALID_INPUT);
}

TEST(CAbiRotation, ReferenceMaterialsRotateTheirStress) {
  AbiModel elastic(R"({"model": "linear_elastic", "parameters": {"E": 20000, "nu": 0.25}})");
  AbiModel plastic(R"({"model": "von_mises", "parameters": {"E": 20000, "nu": 0.25, "yield_stress": 90}})");
  const Voigt s0{-100, -70, -40, 15, -8, 5};

  Voigt s = s0;
  std::vector<double> none;
  ASSERT_EQ(rotate(s, none, elastic.get(), general_rotation).code, ACST_OK) << "no state: statev may be NULL";
  Voigt expected = s0;
  rotate_by_hand(expected.data(), general_rotation, 1.0);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(s[i], expected[i], 1e-13 * 100.0);

  // von Mises: the plastic strain is a scalar, and rotate-then-update = update-then-rotate.
  Voigt a{}, b{};
  std::vector<double> eps_a(1), eps_b(1);
  ASSERT_EQ(acst_initial_state(eps_a.data(), a.data(), plastic.get(), s0.data(), 0.0, nullptr).code, ACST_OK);
  b = a;
  eps_b = eps_a;
  double d[6] = {-3e-3, 1e-3, 0.5e-3, 2e-3, -1e-3, 0.5e-3};
  acst_counters c;
  ASSERT_EQ(acst_update(a.data(), eps_a.data(), nullptr, &c, plastic.get(), d).code, ACST_OK);
  ASSERT_EQ(c.plastic, 1);
  rotate_by_hand(a.data(), general_rotation, 1.0);
  ASSERT_EQ(rotate(b, eps_b, plastic.get(), general_rotation).code, ACST_OK);
  rotate_by_hand(d, general_rotation, 2.0);
  ASSERT_EQ(acst_update(b.data(), eps_b.data(), nullptr, nullptr, plastic.get(), d).code, ACST_OK);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(b[i], a[i], 1e-12 * 100.0);
  EXPECT_NEAR(eps_b[0], eps_a[0], 1e-12 * eps_a[0]);
}

// acst_update_rotated promises the numbers of acst_rotate_state followed by acst_update (the
// same arithmetic in one call), so the two routes are compared bit for bit, with the tangent
// and the counters, along a loading, unloading and reversing path for every kind.
TEST(CAbiRotation, UpdateRotatedGivesTheTwoCallsNumbersBitForBit) {
  const std::string kinds[] = {calibrated_acst(), R"({"model": "linear_elastic", "parameters": {"E": 20000, "nu": 0.25}})",
                               R"({"model": "von_mises", "parameters": {"E": 20000, "nu": 0.25, "yield_stress": 90}})"};
  for (const std::string& kind : kinds) {
    AbiModel m(kind);
    const int n = acst_state_size(m.get());
    SandPoint two, one;
    two.statev.resize(n);
    const bool sand = std::string(acst_model_kind(m.get())) == "ACST";
    const double scale = sand ? 1.0 : 20.0;  // the reference kinds' yield stress is reached by 2e-3
    if (sand) {
      two = loaded_sand_point(m.get());
    } else {
      const double s0[6] = {-100, -70, -40, 15, -8, 5};
      ASSERT_EQ(acst_initial_state(two.statev.data(), two.stress.data(), m.get(), s0, 0.0, nullptr).code, ACST_OK);
    }
    one = two;
    int plastic = 0;
    for (int k = 0; k < 30; ++k) {
      const RowMajor3 Q = Eigen::AngleAxisd(0.002 * (k + 1), Eigen::Vector3d(0.2 * k, 1.0, -0.5).normalized()).toRotationMatrix();
      double d[6] = {-1e-4, 2e-5 * std::cos(0.3 * k), 3e-5, 6e-5 * std::sin(0.2 * k), -2e-5, 4e-5};
      for (double& v : d) v *= k >= 20 ? -0.5 * scale : scale;  // unload and reverse from step 20
      double D_two[36], D_one[36];
      acst_counters c_two, c_one;
      ASSERT_EQ(acst_rotate_state(two.stress.data(), two.statev.data(), m.get(), Q.data()).code, ACST_OK);
      ASSERT_EQ(acst_update(two.stress.data(), two.statev.data(), D_two, &c_two, m.get(), d).code, ACST_OK);
      const acst_status st = acst_update_rotated(one.stress.data(), one.statev.data(), D_one, &c_one, m.get(), Q.data(), d);
      ASSERT_EQ(st.code, ACST_OK) << st.message;
      plastic += c_one.plastic;
      for (int i = 0; i < 6; ++i) ASSERT_EQ(one.stress[i], two.stress[i]) << acst_model_kind(m.get()) << " step " << k;
      for (int i = 0; i < n; ++i) ASSERT_EQ(one.statev[i], two.statev[i]) << acst_model_kind(m.get()) << " step " << k;
      for (int i = 0; i < 36; ++i) ASSERT_EQ(D_one[i], D_two[i]) << acst_model_kind(m.get()) << " step " << k;
      EXPECT_EQ(c_one.substeps_accepted, c_two.substeps_accepted);
      EXPECT_EQ(c_one.rate_evaluations, c_two.rate_evaluations);
      EXPECT_EQ(c_one.plastic, c_two.plastic);
    }
    if (std::string(acst_model_kind(m.get())) != "linear_elastic") {
      EXPECT_GT(plastic, 10) << acst_model_kind(m.get()) << ": the path must exercise the plastic update";
    }
  }
}

// A failed update leaves the state as it came, unrotated; an invalid rotation or a missing
// pointer is refused before anything is computed.
TEST(CAbiRotation, UpdateRotatedChangesNothingWhenItFails) {
  AbiModel m(calibrated_acst());
  SandPoint p = loaded_sand_point(m.get());
  const SandPoint before = p;
  const RowMajor3 proper = general_rotation;
  acst_counters c;

  const double too_large[6] = {-0.2, -0.2, -0.2, 0.0, 0.0, 0.0};  // 60 % compression: e < 0
  const double not_finite[6] = {-1e-4, NAN, 0.0, 0.0, 0.0, 0.0};
  const acst_status big = acst_update_rotated(p.stress.data(), p.statev.data(), nullptr, &c, m.get(), proper.data(), too_large);
  EXPECT_EQ(big.code, ACST_STEP_REDUCTION);
  EXPECT_GT(std::string(big.message).size(), 0u);
  EXPECT_EQ(p.stress, before.stress);
  EXPECT_EQ(p.statev, before.statev);
  EXPECT_EQ(acst_update_rotated(p.stress.data(), p.statev.data(), nullptr, &c, m.get(), proper.data(), not_finite).code,
            ACST_INVALID_INPUT);
  EXPECT_EQ(p.stress, before.stress);

  const double d[6] = {-1e-4, 0, 0, 0, 0, 0};
  SandPoint bad_state = p;
  bad_state.statev[6] = -0.2;  // void ratio out of range: not physical before or after a rotation
  const acst_status bad =
      acst_update_rotated(bad_state.stress.data(), bad_state.statev.data(), nullptr, &c, m.get(), proper.data(), d);
  EXPECT_EQ(bad.code, ACST_NONPHYSICAL_STATE) << bad.message;
  EXPECT_EQ(bad_state.stress, before.stress);

  const RowMajor3 stretched = 1.001 * proper;
  const RowMajor3 reflection = Eigen::Vector3d(1, 1, -1).asDiagonal();
  for (const RowMajor3* Q : {&stretched, &reflection}) {
    const acst_status st = acst_update_rotated(p.stress.data(), p.statev.data(), nullptr, &c, m.get(), Q->data(), d);
    EXPECT_EQ(st.code, ACST_INVALID_INPUT);
    EXPECT_NE(std::string(st.message).find("acst_update_rotated: rotation must be a finite proper orthogonal"),
              std::string::npos)
        << st.message;
  }
  EXPECT_EQ(acst_update_rotated(p.stress.data(), nullptr, nullptr, &c, m.get(), proper.data(), d).code, ACST_INVALID_INPUT);
  EXPECT_EQ(acst_update_rotated(p.stress.data(), p.statev.data(), nullptr, &c, m.get(), nullptr, d).code, ACST_INVALID_INPUT);
  EXPECT_EQ(acst_update_rotated(p.stress.data(), p.statev.data(), nullptr, &c, m.get(), proper.data(), nullptr).code,
            ACST_INVALID_INPUT);
  EXPECT_EQ(acst_update_rotated(p.stress.data(), p.statev.data(), nullptr, &c, nullptr, proper.data(), d).code,
            ACST_INVALID_INPUT);
  EXPECT_EQ(p.stress, before.stress);
  EXPECT_EQ(p.statev, before.statev);
}

}  // namespace

}  // namespace c_abi_rotation_test
