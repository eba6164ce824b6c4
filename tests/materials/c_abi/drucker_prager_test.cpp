// The drucker_prager verification material behind the C ABI (tension positive, engineering
// shear, kPa): a perfectly plastic cone matched to Mohr-Coulomb in plane strain. Reference values
// are closed forms: Mohr-Coulomb's plane-strain limit (sigma_1 - sigma_3) / 2 = c cos phi +
// (sigma_1 + sigma_3) / 2 sin phi under associated flow, the potential's dilatancy
// d eps_v / |d e| = 3 sqrt2 beta at the limit, the apex at an isotropic tension c cot phi, the
// von Mises kind (s_u = c) at phi = 0. The consistent tangent and the initial state are checked as
// the von_mises kind's are, in plastic_kinds_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "abi_model.hpp"
#include "abi_plastic_point.hpp"
#include "acst.h"

namespace acst::test::c_abi_drucker_prager_test {

namespace {

constexpr double c = 10.0;
const double deg = M_PI / 180.0;

std::string dp_json(double phi, double cohesion, double psi = -1) {
  return R"({"model": "drucker_prager", "parameters": {"E": 20000, "nu": 0.3, "friction_angle_deg": )" +
         std::to_string(phi) + R"(, "cohesion": )" + std::to_string(cohesion) +
         (psi >= 0 ? R"(, "dilation_angle_deg": )" + std::to_string(psi) : std::string()) + "}}";
}

// Plane-strain biaxial compression (eps_33 = 0): axial strain d1 along 22 each step, sigma_11
// held at -sigma3 by Newton on eps_11 with the update's own tangent. Returns the final point
// and, in `last`, the last step's strain increment.
PlasticPoint biaxial(const acst_model* m, double sigma3, double d1, int steps, Voigt* last = nullptr) {
  PlasticPoint p = plastic_start(m, {-sigma3, -sigma3, -sigma3, 0, 0, 0});
  Voigt d{0, d1, 0, 0, 0, 0};
  for (int k = 0; k < steps; ++k) {
    for (int it = 0; it < 20; ++it) {
      PlasticPoint trial = p;
      Tangent D;
      plastic_step(m, trial, d, &D);
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

// Associated flow: at the plane-strain limit the stresses satisfy Mohr-Coulomb with phi and c,
// for frictional and purely frictional soil, to the Newton tolerance.
TEST(CAbiDruckerPragerUpdate, PlaneStrainLimitIsMohrCoulombsWithAssociatedFlow) {
  for (const double phi : {20.0, 30.0, 40.0}) {
    for (const double cohesion : {0.0, c}) {
      AbiModel m(dp_json(phi, cohesion));
      const double sigma3 = 100.0;
      const PlasticPoint p = biaxial(m.get(), sigma3, -2e-4, 400);
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
  PlasticPoint p = plastic_start(m.get(), {0, 0, 0, 0, 0, 0});
  ASSERT_TRUE(plastic_step(m.get(), p, {1e-2, 1e-2, 1e-2, 1e-3, 0, 0}));
  const double apex = c / std::tan(phi * deg);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(p.stress[i], apex, 1e-12 * apex);
  for (int i = 3; i < 6; ++i) EXPECT_NEAR(p.stress[i], 0.0, 1e-12 * apex);
  EXPECT_GT(p.eps_p, 0.0);
}

TEST(CAbiDruckerPragerUpdate, NoFrictionIsTheVonMisesKindWithTheCohesionAsUndrainedStrength) {
  AbiModel dp(dp_json(0, c));
  AbiModel vm(R"({"model": "von_mises", "parameters": {"E": 20000, "nu": 0.3, "undrained_shear_strength": 10}})");
  PlasticPoint a = plastic_start(dp.get(), {-50, -45, -40, 2, 0, 0});
  PlasticPoint b = plastic_start(vm.get(), {-50, -45, -40, 2, 0, 0});
  for (int k = 0; k < 300; ++k) {
    const Voigt d{-3e-5 * std::cos(0.05 * k), 2e-5, 1e-5, 4e-5 * std::sin(0.03 * k), 1e-5, -2e-5};
    EXPECT_EQ(plastic_step(dp.get(), a, d), plastic_step(vm.get(), b, d)) << "step " << k;
  }
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(a.stress[i], b.stress[i], 1e-9 * 50.0);
  EXPECT_NEAR(a.eps_p, b.eps_p, 1e-9 * b.eps_p);
  EXPECT_GT(b.eps_p, 0.0);
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

}  // namespace acst::test::c_abi_drucker_prager_test
