// The von_mises verification material behind the C ABI (tension positive, engineering shear,
// kPa): perfectly plastic, associated, radial return. Reference values are closed forms:
// q <= sigma_y with q = sigma_y while yielding, the plane-strain simple-shear limit tau = s_u
// (sigma_y = sqrt(3) s_u), the equivalent plastic strain sqrt(2/3)|d eps| of a radial step.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <string>
#include <thread>
#include <vector>

#include "abi_model.hpp"
#include "abi_plastic_point.hpp"
#include "acst.h"

namespace acst::test::c_abi_von_mises_test {

namespace {

constexpr double E = 10000.0, nu = 0.3, s_u = 50.0;
const double sigma_y = std::sqrt(3.0) * s_u;
const double G = E / (2.0 * (1.0 + nu)), K = E / (3.0 * (1.0 - 2.0 * nu));
constexpr double round_off = 1e-12;  // relative: closed forms evaluated in a different order

std::string von_mises_json(const std::string& strength) {
  return R"({"model": "von_mises", "parameters": {"E": 10000, "nu": 0.3, )" + strength + "}}";
}
const std::string json = von_mises_json(R"("undrained_shear_strength": 50)");

double q_of(const Voigt& s) {
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

// The kind and its state: plastic_kinds_test.cpp. Same yield stress either way the strength is
// given: uniaxial loading saturates at the same q.
TEST(CAbiVonMises, BothStrengthSpellingsGiveTheSameYieldStress) {
  AbiModel by_su(json), by_sy(von_mises_json(R"("yield_stress": )" + std::to_string(sigma_y)));
  for (const AbiModel* m : {&by_su, &by_sy}) {
    PlasticPoint p = plastic_start(m->get(), {0, 0, 0, 0, 0, 0});
    for (int k = 0; k < 100; ++k) plastic_step(m->get(), p, {-1e-3, 0.5e-3, 0.5e-3, 0, 0, 0});
    EXPECT_NEAR(q_of(p.stress), sigma_y, 1e-6 * sigma_y);
  }
}

TEST(CAbiVonMisesUpdate, PlaneStrainSimpleShearTendsToUndrainedStrength) {
  AbiModel m(json);
  PlasticPoint p = plastic_start(m.get(), {-60, -100, -60, 0, 0, 0});  // K0-like start: s_11, s_22, s_33 must decay
  const double dgamma = 1e-4;
  double tau_early = 0.0;
  for (int k = 0; k < 5000; ++k) {
    plastic_step(m.get(), p, {0, 0, 0, dgamma, 0, 0});  // eps_11 = eps_22 = eps_33 = 0
    if (k == 300) tau_early = p.stress[3];
    EXPECT_LE(q_of(p.stress), sigma_y * (1.0 + round_off)) << "step " << k;
  }
  EXPECT_LT(tau_early, s_u * (1.0 - 1e-3)) << "the limit is approached, not reached at first yield";
  EXPECT_NEAR(p.stress[3], s_u, 1e-6 * s_u);
  EXPECT_NEAR(p.stress[0] - p.stress[1], 0.0, 1e-3 * s_u);
}

TEST(CAbiVonMisesUpdate, UniaxialStressPathIsElasticThenSaturatesAtYieldStress) {
  AbiModel m(json);
  PlasticPoint p = plastic_start(m.get(), {0, 0, 0, 0, 0, 0});
  const double de = -1e-4;  // lateral strain nu de keeps the lateral stresses at zero while elastic
  const Voigt d{de, -nu * de, -nu * de, 0, 0, 0};
  int first_plastic = -1;
  for (int k = 1; k <= 400; ++k) {
    const bool plastic = plastic_step(m.get(), p, d);
    if (plastic && first_plastic < 0) first_plastic = k;
    if (first_plastic < 0) {
      EXPECT_NEAR(p.stress[0], E * de * k, round_off * E * std::abs(de) * k) << "elastic step " << k;
      EXPECT_NEAR(p.stress[1], 0.0, round_off * E * std::abs(de) * k);
    }
  }
  EXPECT_EQ(first_plastic, static_cast<int>(std::ceil(sigma_y / (E * std::abs(de)))));
  EXPECT_NEAR(q_of(p.stress), sigma_y, round_off * sigma_y);
  EXPECT_GT(p.eps_p, 0.0);
}

TEST(CAbiVonMisesUpdate, BelowYieldEqualsLinearElastic) {
  AbiModel vm(json), le(R"({"model": "linear_elastic", "parameters": {"E": 10000, "nu": 0.3}})");
  PlasticPoint p = plastic_start(vm.get(), {-100, -90, -80, 5, -5, 3});
  Voigt elastic = p.stress;
  Tangent D_vm, D_le;
  for (int k = 0; k < 20; ++k) {
    const Voigt d{-2e-5, 1e-5, 0.5e-5, 1e-5 * std::sin(k), -0.5e-5, 0.3e-5};
    EXPECT_FALSE(plastic_step(vm.get(), p, d, &D_vm));
    ASSERT_EQ(acst_update(elastic.data(), nullptr, D_le.data(), nullptr, le.get(), d.data()).code, ACST_OK);
  }
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(p.stress[i], elastic[i], round_off * 100.0);
  for (int i = 0; i < 36; ++i) EXPECT_NEAR(D_vm[i], D_le[i], round_off * E);
  EXPECT_EQ(p.eps_p, 0.0);
}

// Perfect plasticity: no deviatoric stiffness along the return direction, the bulk one intact. The
// tangent (against central differences, as for every plastic kind: plastic_kinds_test.cpp) from a
// state on the yield surface, of an increment that turns the deviatoric direction.
TEST(CAbiVonMisesUpdate, ConsistentTangentKeepsTheElasticBulkModulus) {
  AbiModel m(json);
  Tangent D;
  ASSERT_NO_FATAL_FAILURE(check_yielding_tangent(m.get(), D));
  const double dp = (D[0] + D[1] + D[2] + D[6] + D[7] + D[8] + D[12] + D[13] + D[14]) / 9.0;
  EXPECT_NEAR(dp, K, round_off * 1e3 * K) << "1 : C : 1 / 9 = K, the bulk response stays elastic";
}

TEST(CAbiVonMisesUpdate, RadialPlasticStepGivesClosedFormPlasticStrain) {
  AbiModel m(json);
  // Uniaxial compression on the yield surface; a strain increment c n along its deviatoric
  // direction n (|n| = 1) plus a volumetric part: all of c n is plastic, so the stress
  // deviator stays, p changes by K times the volumetric strain, eps_p grows by sqrt(2/3) c.
  PlasticPoint p = plastic_start(m.get(), {-sigma_y, 0, 0, 0, 0, 0});
  const double c = 2e-3, volumetric = -3e-4;
  const double n[3] = {-2.0 / std::sqrt(6.0), 1.0 / std::sqrt(6.0), 1.0 / std::sqrt(6.0)};
  Voigt d{0, 0, 0, 0, 0, 0};
  for (int i = 0; i < 3; ++i) d[i] = c * n[i] + volumetric / 3.0;
  const Voigt before = p.stress;
  ASSERT_TRUE(plastic_step(m.get(), p, d));
  EXPECT_NEAR(p.eps_p, std::sqrt(2.0 / 3.0) * c, round_off * c);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(p.stress[i], before[i] + K * volumetric, round_off * sigma_y);
  for (int i = 3; i < 6; ++i) EXPECT_EQ(p.stress[i], 0.0);
}

TEST(CAbiVonMisesBadInput, StrengthMustBeGivenExactlyOnce) {
  for (const char* strengths : {R"("yield_stress": 80, "undrained_shear_strength": 50)", R"("nu": 0.3)"}) {
    const std::string text = R"({"model": "von_mises", "parameters": {"E": 10000, )" + std::string(strengths) + "}}";
    const acst_status st = failed_creation(text);
    EXPECT_EQ(st.code, ACST_INVALID_INPUT) << text;
    const std::string message = st.message;
    EXPECT_NE(message.find("exactly one of yield_stress or undrained_shear_strength"), std::string::npos) << message;
  }
  for (const char* bad : {R"("yield_stress": 0)", R"("undrained_shear_strength": -1)", R"("yield_stress": "high")"}) {
    const acst_status st = failed_creation(von_mises_json(bad));
    EXPECT_EQ(st.code, ACST_INVALID_INPUT) << bad;
    EXPECT_NE(std::string(st.message).find("/parameters/"), std::string::npos) << st.message;
  }
  const acst_status st = failed_creation(
      R"({"model": "von_mises", "parameters": {"E": 1, "nu": 0, "yield_stress": 1}, "integrator": {}})");
  EXPECT_EQ(st.code, ACST_INVALID_INPUT);
  EXPECT_NE(std::string(st.message).find("/integrator"), std::string::npos) << st.message;
}

TEST(CAbiVonMises, WaveSpeedAndDiagnosticsFromElasticConstants) {
  AbiModel m(json);
  const PlasticPoint p = plastic_start(m.get(), {-80, -50, -50, 0, 0, 0});
  double c = 0.0;
  ASSERT_EQ(acst_wave_speed(&c, m.get(), p.stress.data(), &p.eps_p, 1800.0).code, ACST_OK);
  EXPECT_NEAR(c, std::sqrt((K + 4.0 * G / 3.0) * 1000.0 / 1800.0), round_off * c);
  double d[ACST_NDIAGNOSTICS];
  ASSERT_EQ(acst_diagnostics(d, m.get(), p.stress.data(), &p.eps_p).code, ACST_OK);
  EXPECT_NEAR(d[0], 60.0, round_off * 60.0);
  EXPECT_NEAR(d[1], 30.0, round_off * 30.0);
  EXPECT_NEAR(d[11], G, round_off * G);
  EXPECT_NEAR(d[12], K, round_off * K);
  EXPECT_TRUE(std::isnan(d[7])) << "fabric norm";
}

// One handle, four threads, each updating (with tangent) and rotating its own point (in two
// calls, or in one with acst_update_rotated): the results must be bit-identical to a serial run.
TEST(CAbiVonMisesThreads, OneHandleManyThreadsBitIdenticalToSerialRun) {
  AbiModel m(json);
  auto run = [&m] {
    std::vector<double> history;
    PlasticPoint p = plastic_start(m.get(), {-100, -100, -100, 0, 0, 0});
    Tangent D;
    const double a = 0.01;  // a small rotation about z at every step
    const double Q[9] = {std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1};
    for (int k = 0; k < 2000; ++k) {
      const double sign = (k / 200) % 2 == 0 ? 1.0 : -1.0;
      const Voigt d{sign * -6e-5, sign * 3e-5, sign * 1.5e-5, sign * 3e-5, 0, -1e-5};
      if (k % 2 == 1) {  // every other step turned and updated in one call
        if (acst_update_rotated(p.stress.data(), &p.eps_p, D.data(), nullptr, m.get(), Q, d.data()).code != ACST_OK)
          history.push_back(NAN);
      } else {
        if (acst_rotate_state(p.stress.data(), &p.eps_p, m.get(), Q).code != ACST_OK) history.push_back(NAN);
        plastic_step(m.get(), p, d, &D);
      }
      history.insert(history.end(), p.stress.begin(), p.stress.end());
      history.push_back(p.eps_p);
    }
    history.insert(history.end(), D.begin(), D.end());
    return history;
  };
  const std::vector<double> serial = run();
  std::vector<std::vector<double>> results(4);
  std::atomic<int> ready{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      ++ready;
      while (ready.load() < 4) std::this_thread::yield();
      results[t] = run();
    });
  for (auto& th : threads) th.join();
  for (int t = 0; t < 4; ++t) EXPECT_TRUE(results[t] == serial) << "thread " << t;
  EXPECT_GT(serial[serial.size() - 37], 0.0) << "the path yields";
}

}  // namespace

}  // namespace acst::test::c_abi_von_mises_test
