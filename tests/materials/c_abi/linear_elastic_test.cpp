// The linear_elastic verification material behind the C ABI (tension positive, engineering
// shear, kPa) against closed forms: K = E / 3(1 - 2nu), G = E / 2(1 + nu), lambda = K - 2G/3.
// The update is one linear map, so stresses agree with the closed forms to round-off (1e-12
// relative); finite differences of a linear map are exact up to cancellation (1e-7 relative).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <string>

#include "abi_model.hpp"
#include "acst.h"

namespace acst::test::c_abi_linear_elastic_test {

namespace {

constexpr double E = 20000.0, nu = 0.3;
const double G = E / (2.0 * (1.0 + nu)), K = E / (3.0 * (1.0 - 2.0 * nu));
const double constrained = K + 4.0 * G / 3.0, lame = K - 2.0 * G / 3.0;
constexpr double exact = 1e-12;

const std::string json = R"({"model": "linear_elastic", "parameters": {"E": 20000, "nu": 0.3}})";

Voigt updated(const acst_model* m, Voigt stress, const Voigt& dstrain, Tangent* tangent = nullptr) {
  const acst_status st = acst_update(stress.data(), nullptr, tangent ? tangent->data() : nullptr, nullptr, m,
                                     dstrain.data());
  EXPECT_EQ(st.code, ACST_OK) << st.message;
  return stress;
}

TEST(CAbiLinearElastic, KindAndEmptyState) {
  AbiModel m(json);
  EXPECT_STREQ(acst_model_kind(m.get()), "linear_elastic");
  EXPECT_EQ(acst_state_size(m.get()), 0);
  EXPECT_EQ(acst_state_name(m.get(), 0), nullptr);
  EXPECT_EQ(acst_model_kind(nullptr), nullptr);
}

TEST(CAbiLinearElasticUpdate, UniaxialStrainGivesConstrainedAndLameModuli) {
  AbiModel m(json);
  const double eps = -1e-3;  // compression
  const Voigt s = updated(m.get(), {0, 0, 0, 0, 0, 0}, {eps, 0, 0, 0, 0, 0});
  EXPECT_NEAR(s[0], constrained * eps, exact * constrained * std::abs(eps));
  EXPECT_NEAR(s[1], lame * eps, exact * constrained * std::abs(eps));
  EXPECT_NEAR(s[2], lame * eps, exact * constrained * std::abs(eps));
  for (int i = 3; i < 6; ++i) EXPECT_EQ(s[i], 0.0);
}

TEST(CAbiLinearElasticUpdate, EngineeringShearStrainGivesShearModulus) {
  AbiModel m(json);
  const double gamma = 2e-3;
  for (int slot = 3; slot < 6; ++slot) {
    Voigt d{0, 0, 0, 0, 0, 0};
    d[slot] = gamma;
    const Voigt s = updated(m.get(), {-100, -80, -60, 5, -3, 2}, d);
    const Voigt start{-100, -80, -60, 5, -3, 2};
    for (int i = 0; i < 6; ++i)
      EXPECT_NEAR(s[i] - start[i], i == slot ? G * gamma : 0.0, exact * G * gamma) << "slot " << slot << " i " << i;
  }
}

TEST(CAbiLinearElasticUpdate, TangentEqualsFiniteDifferencesAndCountersAreZero) {
  AbiModel m(json);
  const Voigt s0{-120, -90, -70, 10, -4, 6}, d0{-1e-4, 3e-5, 2e-5, 4e-5, -1e-5, 2e-5};
  Tangent D;
  acst_counters c;
  Voigt s = s0;
  ASSERT_EQ(acst_update(s.data(), nullptr, D.data(), &c, m.get(), d0.data()).code, ACST_OK);
  acst_counters zero;
  std::memset(&zero, 0, sizeof zero);
  EXPECT_EQ(std::memcmp(&c, &zero, sizeof c), 0) << "every counter, plastic included, is zero";
  const double h = 1e-6;
  for (int j = 0; j < 6; ++j) {
    Voigt up = d0, down = d0;
    up[j] += h;
    down[j] -= h;
    const Voigt su = updated(m.get(), s0, up), sd = updated(m.get(), s0, down);
    for (int i = 0; i < 6; ++i)
      EXPECT_NEAR(D[6 * i + j], (su[i] - sd[i]) / (2.0 * h), 1e-7 * constrained) << "i " << i << " j " << j;
  }
  EXPECT_NEAR(D[6 * 3 + 3], G, exact * G) << "d tau / d gamma = G (engineering shear column)";
}

TEST(CAbiLinearElastic, WaveSpeedDiagnosticsAndStatelessCalls) {
  AbiModel m(json);
  const Voigt s0{-150, -100, -50, 20, 0, 0};
  Voigt s{};
  ASSERT_EQ(acst_initial_state(nullptr, s.data(), m.get(), s0.data(), 0.0, nullptr).code, ACST_OK);
  EXPECT_EQ(s, s0) << "the initial stress is copied";

  const double rho = 2000.0;
  double c = 0.0;
  ASSERT_EQ(acst_wave_speed(&c, m.get(), s.data(), nullptr, rho).code, ACST_OK);
  EXPECT_NEAR(c, std::sqrt(constrained * 1000.0 / rho), exact * c);

  double d[ACST_NDIAGNOSTICS];
  ASSERT_EQ(acst_diagnostics(d, m.get(), s.data(), nullptr).code, ACST_OK);
  const double q = std::sqrt(0.5 * (50.0 * 50.0 + 50.0 * 50.0 + 100.0 * 100.0) + 3.0 * 20.0 * 20.0);
  EXPECT_NEAR(d[0], 100.0, exact * 100.0) << "p, compression positive";
  EXPECT_NEAR(d[1], q, exact * q);
  EXPECT_NEAR(d[11], G, exact * G);
  EXPECT_NEAR(d[12], K, exact * K);
  for (int i = 2; i < 11; ++i) EXPECT_TRUE(std::isnan(d[i])) << acst_diagnostic_name(i);

  const Voigt strain{-1e-4, 0, 0, 0, 0, 0};
  Voigt batch_stress = s0;
  int code = -1;
  ASSERT_EQ(acst_update_batch(batch_stress.data(), 6, nullptr, 0, &code, nullptr, m.get(), 1, strain.data(), 6).code,
            ACST_OK);
  EXPECT_EQ(code, ACST_OK);
  EXPECT_EQ(batch_stress, updated(m.get(), s0, strain));

  double e = 0.0;
  const acst_status st = acst_void_ratio_from_relative_density(&e, m.get(), 0.5);
  EXPECT_EQ(st.code, ACST_INVALID_INPUT);
  EXPECT_NE(std::string(st.message).find("only for sand models"), std::string::npos) << st.message;
}

TEST(CAbiLinearElasticUpdate, NonFiniteInputLeavesStressUnchanged) {
  AbiModel m(json);
  Voigt s{-100, -100, -100, 0, 0, 0};
  const Voigt before = s, bad_strain{NAN, 0, 0, 0, 0, 0};
  EXPECT_EQ(acst_update(s.data(), nullptr, nullptr, nullptr, m.get(), bad_strain.data()).code, ACST_INVALID_INPUT);
  EXPECT_EQ(s, before);
  Voigt nan_stress{NAN, 0, 0, 0, 0, 0};
  const Voigt strain{-1e-4, 0, 0, 0, 0, 0};
  EXPECT_EQ(acst_update(nan_stress.data(), nullptr, nullptr, nullptr, m.get(), strain.data()).code,
            ACST_NONPHYSICAL_STATE);
}

struct BadInput {
  const char* parameters;
  const char* named;  // what the message must mention
};

class CAbiLinearElasticBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(CAbiLinearElasticBadInput, IsRejectedNamingTheParameter) {
  const std::string text = std::string(R"({"model": "linear_elastic", "parameters": )") + GetParam().parameters + "}";
  const acst_status st = failed_creation(text);
  EXPECT_EQ(st.code, ACST_INVALID_INPUT) << text;
  EXPECT_NE(std::string(st.message).find(GetParam().named), std::string::npos) << st.message;
}

INSTANTIATE_TEST_SUITE_P(
    Parameters, CAbiLinearElasticBadInput,
    ::testing::Values(BadInput{R"({"E": 20000, "nu": 0.5})", "/parameters/nu"},
                      BadInput{R"({"E": 20000, "nu": -1})", "(-1, 0.5)"},
                      BadInput{R"({"E": -5, "nu": 0.3})", "/parameters/E"},
                      BadInput{R"({"E": 0, "nu": 0.3})", "(0, inf)"},
                      BadInput{R"({"E": 20000, "nu": 0.3, "G0": 125})", "/parameters/G0: unknown key"},
                      BadInput{R"({"E": "stiff", "nu": 0.3})", "/parameters/E: expected a number"},
                      BadInput{R"({"E": 20000})", "/parameters/nu: required"},
                      BadInput{R"([20000, 0.3])", "/parameters: expected a JSON object"}));

TEST(CAbiLinearElasticBadInput, IntegratorIsRejected) {
  const acst_status st = failed_creation(
      R"({"model": "linear_elastic", "parameters": {"E": 1, "nu": 0}, "integrator": {"scheme": "ME"}})");
  EXPECT_EQ(st.code, ACST_INVALID_INPUT);
  EXPECT_NE(std::string(st.message).find("/integrator"), std::string::npos) << st.message;
}

TEST(CAbiLinearElasticBadInput, UnknownModelListsEveryKind) {
  const acst_status st = failed_creation(R"({"model": "elastic", "parameters": {"E": 1, "nu": 0}})");
  EXPECT_EQ(st.code, ACST_INVALID_INPUT);
  for (const char* kind : {"ACST", "isotropic", "linear_elastic", "von_mises"})
    EXPECT_NE(std::string(st.message).find(kind), std::string::npos) << st.message;
}

}  // namespace

}  // namespace acst::test::c_abi_linear_elastic_test
