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
#include "acst.h"

namespace c_abi_von_mises_test {

namespace {

using acst::test::AbiModel;
using acst::test::failed_creation;
using acst::test::Tangent;
using acst::test::Voigt;

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

// One update; returns whether it yielded.
bool step(const acst_model* m, Point& p, const Voigt& dstrain, Tangent* tangent = nullptr) {
  acst_counters c;
  const acst_status st =
      acst_update(p.stress.data(), &p.eps_p, tangent ? tangent->data() : nullptr, &c, m, dstrain.data());
  EXPECT_EQ(st.code, ACST_OK) << st.message;
  return c.plastic == 1;
}

TEST(CAbiVonMises, KindStateAndBothStrengthSpellings) {
  AbiModel by_su(json), by_sy(von_mises_json(R"("yield_stress": )" + std::to_string(sigma_y)));
  EXPECT_STREQ(acst_model_kind(by_su.get()), "von_mises");
  ASSERT_EQ(acst_state_size(by_su.get()), 1);
  EXPECT_STREQ(acst_state_name(by_su.get(), 0), "equivalent_plastic_strain");
  EXPECT_EQ(acst_state_name(by_su.get(), 1), nullptr);
  // Same yield stress either way: uniaxial loading saturates at the same q.
  for (const AbiModel* m : {&by_su, &by_sy}) {
    Point p = start(m->get(), {0, 0, 0, 0, 0, 0});
    for (int k = 0; k < 100; ++k) step(m->get(), p, {-1e-3, 0.5e-3, 0.5e-3, 0, 0, 0});
    EXPECT_NEAR(q_of(p.stress), sigma_y, 1e-6 * sigma_y);
  }
}

TEST(CAbiVonMisesUpdate, PlaneStrainSimpleShearTendsToUndrainedStrength) {
  AbiModel m(json);
  Point p = start(m.get(), {-60, -100, -60, 0, 0, 0});  // K0-like start: s_11, s_22, s_33 must decay
  const double dgamma = 1e-4;
  double tau_early = 0.0;
  for (int k = 0; k < 5000; ++k) {
    step(m.get(), p, {0, 0, 0, dgamma, 0, 0});  // eps_11 = eps_22 = eps_33 = 0
    if (k == 300) tau_early = p.stress[3];
    EXPECT_LE(q_of(p.stress), sigma_y * (1.0 + round_off)) << "step " << k;
  }
  EXPECT_LT(tau_early, s_u * (1.0 - 1e-3)) << "the limit is approached, not reached at first yield";
  EXPECT_NEAR(p.stress[3], s_u, 1e-6 * s_u);
  EXPECT_NEAR(p.stress[0] - p.stress[1], 0.0, 1e-3 * s_u);
}

TEST(CAbiVonMisesUpdate, UniaxialStressPathIsElasticThenSaturatesAtYieldStress) {
  AbiModel m(json);
  Point p = start(m.get(), {0, 0, 0, 0, 0, 0});
  const double de = -1e-4;  // lateral strain nu de keeps the lateral stresses at zero while elastic
  const Voigt d{de, -nu * de, -nu * de, 0, 0, 0};
  int first_plastic = -1;
  for (int k = 1; k <= 400; ++k) {
    const bool plastic = step(m.get(), p, d);
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
  Point p = start(vm.get(), {-100, -90, -80, 5, -5, 3});
  Voigt elastic = p.stress;
  Tangent D_vm, D_le;
  for (int k = 0; k < 20; ++k) {
    const Voigt d{-2e-5, 1e-5, 0.5e-5, 1e-5 * std::sin(k), -0.5e-5, 0.3e-5};
    EXPECT_FALSE(step(vm.get(), p, d, &D_vm));
    ASSERT_EQ(acst_update(elastic.data(), nullptr, D_le.data(), nullptr, le.get(), d.data()).code, ACST_OK);
  }
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(p.stress[i], elastic[i], round_off * 100.0);
  for (int i = 0; i < 36; ++i) EXPECT_NEAR(D_vm[i], D_le[i], round_off * E);
  EXPECT_EQ(p.eps_p, 0.0);
}

// Central differences of the update with respect to each strain component, from a state on the
// yield surface and an increment that yields for every perturbation. h = 1e-7: truncation
// (~ h^2 G^3 / sigma_y^2) and cancellation (~ 1e-16 sigma / h) both stay below 1e-9 of G.
TEST(CAbiVonMisesUpdate, ConsistentTangentEqualsFiniteDifferences) {
  AbiModel m(json);
  Point on_surface = start(m.get(), {-100, -100, -100, 0, 0, 0});
  for (int k = 0; k < 50; ++k) step(m.get(), on_surface, {-4e-4, 1e-4, 1.5e-4, 2e-4, 0, -1e-4});
  const Voigt d{-1e-4, 2e-5, 3e-5, 1e-4, -6e-5, 4e-5};  // turns the deviatoric direction
  Point p = on_surface;
  Tangent D;
  ASSERT_TRUE(step(m.get(), p, d, &D));
  double scale = 0.0;
  for (double v : D) scale = std::max(scale, std::abs(v));
  const double h = 1e-7;
  for (int j = 0; j < 6; ++j) {
    Voigt up = d, down = d;
    up[j] += h;
    down[j] -= h;
    Point pu = on_surface, pd = on_surface;
    ASSERT_TRUE(step(m.get(), pu, up));
    ASSERT_TRUE(step(m.get(), pd, down));
    for (int i = 0; i < 6; ++i)
      EXPECT_NEAR(D[6 * i + j], (pu.stress[i] - pd.stress[i]) / (2.0 * h), 1e-5 * scale) << "i " << i << " j " << j;
  }
  // Perfect plasticity: no deviatoric stiffness along the return direction, the bulk one intact.
  const double dp = (D[0] + D[1] + D[2] + D[6] + D[7] + D[8] + D[12] + D[13] + D[14]) / 9.0;
  EXPECT_NEAR(dp, K, round_off * 1e3 * K) << "1 : C : 1 / 9 = K, the bulk response stays elastic";
}

TEST(CAbiVonMisesUpdate, RadialPlasticStepGivesClosedFormPlasticStrain) {
  AbiModel m(json);
  // Uniaxial compression on the yield surface; a strain increment c n along its deviatoric
  // direction n (|n| = 1) plus a volumetric part: all of c n is plastic, so the stress
  // deviator stays, p changes by K times the volumetric strain, eps_p grows by sqrt(2/3) c.
  Point p = start(m.get(), {-sigma_y, 0, 0, 0, 0, 0});
  const double c = 2e-3, volumetric = -3e-4;
  const double n[3] = {-2.0 / std::sqrt(6.0), 1.0 / std::sqrt(6.0), 1.0 / std::sqrt(6.0)};
  Voigt d{0, 0, 0, 0, 0, 0};
  for (int i = 0; i < 3; ++i) d[i] = c * n[i] + volumetric / 3.0;
  const Voigt before = p.stress;
  ASSERT_TRUE(step(m.get(), p, d));
  EXPECT_NEAR(p.eps_p, std::sqrt(2.0 / 3.0) * c, round_off * c);
  for (int i = 0; i < 3; ++i) EXPECT_NEAR(p.stress[i], before[i] + K * volumetric, round_off * sigma_y);
  for (int i = 3; i < 6; ++i) EXPECT_EQ(p.stress[i], 0.0);
}

TEST(CAbiVonMisesInitialState, StressOutsideTheYieldSurfaceIsRejected) {
  AbiModel m(json);
  double eps_p = 7.0;
  Voigt out{1, 2, 3, 4, 5, 6};
  const Voigt untouched = out;
  const Voigt beyond{-sigma_y * 1.01, 0, 0, 0, 0, 0};
  const acst_status st = acst_initial_state(&eps_p, out.data(), m.get(), beyond.data(), 0.0, nullptr);
  EXPECT_EQ(st.code, ACST_NONPHYSICAL_STATE);
  EXPECT_NE(std::string(st.message).find("yield surface"), std::string::npos) << st.message;
  EXPECT_EQ(out, untouched);
  EXPECT_EQ(eps_p, 7.0);
  const Voigt on{-sigma_y * (1.0 + 1e-10), 0, 0, 0, 0, 0};  // within the 1e-9 tolerance
  EXPECT_EQ(acst_initial_state(&eps_p, out.data(), m.get(), on.data(), 0.0, nullptr).code, ACST_OK);
  EXPECT_EQ(eps_p, 0.0);
  EXPECT_EQ(acst_initial_state(nullptr, out.data(), m.get(), on.data(), 0.0, nullptr).code, ACST_INVALID_INPUT)
      << "von_mises has one state variable, so statev is required";
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
  const Point p = start(m.get(), {-80, -50, -50, 0, 0, 0});
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
    Point p = start(m.get(), {-100, -100, -100, 0, 0, 0});
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
        step(m.get(), p, d, &D);
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

}  // namespace c_abi_von_mises_test
