// The drucker_prager verification material behind the C ABI (tension positive, engineering
// shear, kPa): a perfectly plastic cone matched to Mohr-Coulomb in plane strain. Reference values
// are closed forms: Mohr-Coulomb's plane-strain limit (sigma_1 - sigma_3) / 2 = c cos phi +
// (sigma_1 + sigma_3) / 2 sin phi under associated flow, the potential's dilatancy
// d eps_v / |d e| = 3 sqrt2 beta at the limit, the apex at an isotropic tension c cot phi, the
// von Mises kind (s_u = c) at phi = 0, and central differences for the consistent tangent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "abi_model.hpp"
#include "acst.h"

namespace c_abi_drucker_prager_test {

namespace {

using acst::test::AbiModel;
using acst::test::failed_creation;
using acst::test::Tangent;
using acst::test::Voigt;

constexpr double E = 20000.0, nu = 0.3, c = 10.0;
const double G = E / (2.0 * (1.0 + nu)), K = E / (3.0 * (1.0 - 2.0 * nu));
const double deg = M_PI / 180.0;

std::string dp_json(double phi, double cohesion, double psi = -1) {
  return R"({"model": "drucker_prager", "parameters": {"E": 20000, "nu": 0.3, "friction_angle_deg": )" +
         std::to_string(phi) + R"(, "cohesion": )" + std::to_string(cohesion) +
         (psi >= 0 ? R"(, "dilation_angle_deg": )" + std::to_string(psi) : std::string()) + "}}";
}

struct Point {
  Voigt stress;
  double eps_p = 0.0;
};

Point start(const acst_model* m, const Voigt& stress0) {
  Point p;
  const acst_status st = acst_initial_state(&p.eps_p, p.stress.data(), m, stress0.data(), 0.0, nullptr);
  EXPECT_EQ(st.code, ACST_OK) << st.message;
  return p;
}

bool step(const acst_model* m, Point& p, const Voigt& dstrain, Tangent* tangent = nullptr) {
  acst_counters counters;
  const acst_status st =
      acst_update(p.stress.data(), &p.eps_p, tangent ? tangent->data() : nullptr, &counters, m, dstrain.data());
  EXPECT_EQ(st.code, ACST_OK) << st.message;
  return counters.plastic == 1;
}

// Plane-strain biaxial compression (eps_33 = 0): axial strain d1 along 22 each step, sigma_11
// held at -sigma3 by Newton on eps_11 with the update's own tangent. Returns the final point
// and, in `last`, the last step's strain increment.
Point biaxial(const acst_model* m, double sigma3, double d1, int steps, Voigt* last = nullptr) {
  Point p = start(m, {-sigma3, -sigma3, -sigma3, 0, 0, 0});
  Voigt d{0, d1, 0, 0, 0, 0};
  for (int k = 0; k < steps; ++k) {
    for (int it = 0; it < 20; ++it) {
      Point trial = p;
      Tangent D;
      step(m, trial, d, &D);
      const double r = trial.stress[0] + sigma3;
      if (std::abs(r) < 1e-10 * sigma3) {
        p = trial;
        break;
      }
      d[0] -= r / D[0];
      if (it == 19) ADD_FAILURE() << "lateral stress did not converge at step " << k;
    }
  }
  if (last) *last = d;
  return p;
}

TEST(CAbiDruckerPrager, KindAndState) {
  AbiModel m(dp_json(30, c));
  EXPECT_STREQ(acst_model_kind(m.get()), "drucker_prager");
  ASSERT_EQ(acst_state_size(m.get()), 1);
  EXPECT_STREQ(acst_state_name(m.get(), 0), "equivalent_plastic_strain");
}

// Associated flow: at the plane-strain limit the stresses satisfy Mohr-Coulomb with phi and c,
// for frictional and purely frictional soil, to the Newton tolerance.
TEST(CAbiDruckerPragerUpdate, PlaneStrainLimitIsMohrCoulombsWithAssociatedFlow) {
  for (const double phi : {20.0, 30.0, 40.0}) {
    for (const double cohesion : {0.0, c}) {
      AbiModel m(dp_json(phi, cohesion));
      const double sigma3 = 100.0;
      const Point p = biaxial(m.get(), sigma3, -2e-4, 400);
      const double s1 = -p.stress[1], s3 = -p.stress[0];
      const double mc = (s1 + s3) / 2.0 * std::sin(phi * deg) + cohesion * std::cos(phi * deg);
      EXPECT_NEAR((s1 - s3) / 2.0, mc, 1e-6 * mc) << "phi " << phi << " c " << cohesion;
      EXPECT_NEAR(s3, sigma3, 1e-8 * sigma3);
      const double N = (1.0 + std::sin(phi * deg)) / (1.0 - std::sin(phi * deg));
      EXPECT_NEAR(s1, N * s3 + 2.0 * cohesion * std::sqrt(N), 1e-6 * s1) << "phi " << phi;
    }
  }
}

// At the limit every strain increment is plastic: d eps_v / |d e| = 3 sqrt2 beta (dilation),
// beta from psi, whatever phi.
TEST(CAbiDruckerPragerUpdate, DilatancyAtTheLimitFollowsThePotential) {
  for (const double psi : {0.0, 10.0, 30.0}) {
    AbiModel m(dp_json(30, c, psi));
    Voigt d;
    biaxial(m.get(), 100.0, -2e-4, 2000, &d);  // non-associated flow nears its limit more slowly
    const double v = d[0] + d[1] + d[2];
    const double dev[3] = {d[0] - v / 3.0, d[1] - v / 3.0, d[2] - v / 3.0};
    const double norm_e = std::sqrt(dev[0] * dev[0] + dev[1] * dev[1] + dev[2] * dev[2]);
    const double t = std::tan(psi * deg), beta = t / std::sqrt(9.0 + 12.0 * t * t);
    EXPECT_NEAR(v / norm_e, 3.0 * std::sqrt(2.0) * beta, 1e-6) << "psi " << psi;
  }
}

TEST(CAbiDruckerPragerUpdate, IsotropicTensionReturnsToTheApex) {
  const double phi = 30.0;
  AbiModel m(dp_json(phi, c));
  Point p = start(m.get(), {0, 0, 0, 0, 0, 0});
  ASSERT_TRUE(step(m.get(), p, {1e-2, 1e-2, 1e-2, 1e-3, 0, 0}));
  const double apex = c / std::tan(phi * deg);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(p.stress[i], apex, 1e-12 * apex);
  for (int i = 3; i < 6; ++i) EXPECT_NEAR(p.stress[i], 0.0, 1e-12 * apex);
  EXPECT_GT(p.eps_p, 0.0);
}

TEST(CAbiDruckerPragerUpdate, NoFrictionIsTheVonMisesKindWithTheCohesionAsUndrainedStrength) {
  AbiModel dp(dp_json(0, c));
  AbiModel vm(R"({"model": "von_mises", "parameters": {"E": 20000, "nu": 0.3, "undrained_shear_strength": 10}})");
  Point a = start(dp.get(), {-50, -45, -40, 2, 0, 0}), b = start(vm.get(), {-50, -45, -40, 2, 0, 0});
  for (int k = 0; k < 300; ++k) {
    const Voigt d{-3e-5 * std::cos(0.05 * k), 2e-5, 1e-5, 4e-5 * std::sin(0.03 * k), 1e-5, -2e-5};
    EXPECT_EQ(step(dp.get(), a, d), step(vm.get(), b, d)) << "step " << k;
  }
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(a.stress[i], b.stress[i], 1e-9 * 50.0);
  EXPECT_NEAR(a.eps_p, b.eps_p, 1e-9 * b.eps_p);
  EXPECT_GT(b.eps_p, 0.0);
}

// Central differences from a state on the cone, for associated and non-associated flow.
TEST(CAbiDruckerPragerUpdate, ConsistentTangentEqualsFiniteDifferences) {
  for (const double psi : {30.0, 5.0}) {
    AbiModel m(dp_json(30, c, psi));
    Point on_cone = start(m.get(), {-100, -100, -100, 0, 0, 0});
    for (int k = 0; k < 50; ++k) step(m.get(), on_cone, {-4e-4, 1e-4, 1.5e-4, 2e-4, 0, -1e-4});
    const Voigt d{-1e-4, 2e-5, 3e-5, 1e-4, -6e-5, 4e-5};
    Point p = on_cone;
    Tangent D;
    ASSERT_TRUE(step(m.get(), p, d, &D));
    double scale = 0.0;
    for (double v : D) scale = std::max(scale, std::abs(v));
    const double h = 1e-7;
    for (int j = 0; j < 6; ++j) {
      Voigt up = d, down = d;
      up[j] += h;
      down[j] -= h;
      Point pu = on_cone, pd = on_cone;
      ASSERT_TRUE(step(m.get(), pu, up));
      ASSERT_TRUE(step(m.get(), pd, down));
      for (int i = 0; i < 6; ++i)
        EXPECT_NEAR(D[6 * i + j], (pu.stress[i] - pd.stress[i]) / (2.0 * h), 1e-5 * scale)
            << "psi " << psi << " i " << i << " j " << j;
    }
  }
}

TEST(CAbiDruckerPragerInitialState, StressOutsideTheConeIsRejected) {
  AbiModel m(dp_json(30, 0));
  double eps_p = 7.0;
  Voigt out{1, 2, 3, 4, 5, 6};
  const Voigt untouched = out;
  const Voigt tension{1, 1, 1, 0, 0, 0};  // beyond the apex of cohesionless soil
  const acst_status st = acst_initial_state(&eps_p, out.data(), m.get(), tension.data(), 0.0, nullptr);
  EXPECT_EQ(st.code, ACST_NONPHYSICAL_STATE);
  EXPECT_NE(std::string(st.message).find("Drucker-Prager cone"), std::string::npos) << st.message;
  EXPECT_EQ(out, untouched);
  EXPECT_EQ(eps_p, 7.0);
  const Voigt at_apex{0, 0, 0, 0, 0, 0};
  EXPECT_EQ(acst_initial_state(&eps_p, out.data(), m.get(), at_apex.data(), 0.0, nullptr).code, ACST_OK);
}

TEST(CAbiDruckerPragerBadInput, AnglesAndCohesionOutsideTheirRangesAreNamed) {
  const struct {
    std::string json, names;
  } cases[] = {
      {dp_json(60, c), "/parameters/friction_angle_deg"},
      {dp_json(-1, c), "/parameters/friction_angle_deg"},
      {dp_json(30, -1), "/parameters/cohesion"},
      {dp_json(30, c, 31), "/parameters/dilation_angle_deg"},
      {dp_json(0, 0), "both zero"},
      {R"({"model": "drucker_prager", "parameters": {"E": 1, "nu": 0, "cohesion": 1}})", "friction_angle_deg: required"},
      {R"({"model": "drucker_prager", "parameters": {"E": 1, "nu": 0, "friction_angle_deg": 30, "cohesion": 1, "phi": 3}})",
       "phi"},
      {R"({"model": "drucker_prager", "parameters": {"E": 1, "nu": 0, "friction_angle_deg": 30, "cohesion": 1}, "integrator": {}})",
       "/integrator"},
  };
  for (const auto& k : cases) {
    const acst_status st = failed_creation(k.json);
    EXPECT_EQ(st.code, ACST_INVALID_INPUT) << k.json;
    EXPECT_NE(std::string(st.message).find(k.names), std::string::npos) << st.message;
  }
}

}  // namespace

}  // namespace c_abi_drucker_prager_test
