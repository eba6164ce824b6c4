// What the perfectly plastic verification kinds behind the C ABI (von_mises, drucker_prager;
// tension positive, engineering shear, kPa) have in common, checked for each kind alike: one state
// variable, the equivalent plastic strain; a consistent tangent equal to central differences of the
// update, for each flow rule; an initial stress outside the yield surface refused with the outputs
// untouched. What is particular to a kind (its closed forms, its parameters) is tested in
// von_mises_test.cpp and drucker_prager_test.cpp.
#include <gtest/gtest.h>

#include <cmath>
#include <ostream>
#include <string>
#include <vector>

#include "abi_model.hpp"
#include "abi_plastic_point.hpp"
#include "acst.h"

namespace acst::test::c_abi_plastic_kinds_test {

namespace {

struct PlasticKind {
  std::string name;                     // what acst_model_kind answers
  std::string material;                 // a material of the kind
  std::vector<std::string> flow_rules;  // materials whose tangent is checked, one per flow rule
  std::string initial_material;         // the material whose initial states are checked
  Voigt outside, on;                    // initial stresses beyond its yield surface and on it
  std::string refusal;                  // what the refusal of `outside` says
};

void PrintTo(const PlasticKind& kind, std::ostream* os) { *os << kind.name; }

PlasticKind von_mises() {
  const std::string json = R"({"model": "von_mises", "parameters": {"E": 10000, "nu": 0.3, "undrained_shear_strength": 50}})";
  const double sigma_y = std::sqrt(3.0) * 50.0;
  return {"von_mises", json, {json}, json,
          {-sigma_y * 1.01, 0, 0, 0, 0, 0},
          {-sigma_y * (1.0 + 1e-10), 0, 0, 0, 0, 0},  // within the 1e-9 tolerance
          "yield surface"};
}

PlasticKind drucker_prager() {
  const std::string dp = R"({"model": "drucker_prager", "parameters": {"E": 20000, "nu": 0.3, "friction_angle_deg": 30, )";
  return {"drucker_prager", dp + R"("cohesion": 10}})",
          {dp + R"("cohesion": 10, "dilation_angle_deg": 30}})",    // associated flow
           dp + R"("cohesion": 10, "dilation_angle_deg": 5}})"},    // non-associated flow
          dp + R"("cohesion": 0}})",
          {1, 1, 1, 0, 0, 0},  // beyond the apex of cohesionless soil
          {0, 0, 0, 0, 0, 0},  // at the apex
          "Drucker-Prager cone"};
}

class CAbiPlasticKind : public ::testing::TestWithParam<PlasticKind> {};

TEST_P(CAbiPlasticKind, KindAndState) {
  AbiModel m(GetParam().material);
  EXPECT_STREQ(acst_model_kind(m.get()), GetParam().name.c_str());
  ASSERT_EQ(acst_state_size(m.get()), 1);
  EXPECT_STREQ(acst_state_name(m.get(), 0), "equivalent_plastic_strain");
  EXPECT_EQ(acst_state_name(m.get(), 1), nullptr);
}

// From a state on the yield surface, for associated and non-associated flow.
TEST_P(CAbiPlasticKind, ConsistentTangentEqualsFiniteDifferences) {
  for (const std::string& json : GetParam().flow_rules) {
    SCOPED_TRACE(json);
    AbiModel m(json);
    Tangent D;
    ASSERT_NO_FATAL_FAILURE(check_yielding_tangent(m.get(), D));
  }
}

TEST_P(CAbiPlasticKind, InitialStressOutsideTheYieldSurfaceIsRejected) {
  const PlasticKind& kind = GetParam();
  AbiModel m(kind.initial_material);
  double eps_p = 7.0;
  Voigt out{1, 2, 3, 4, 5, 6};
  const Voigt untouched = out;
  const acst_status st = acst_initial_state(&eps_p, out.data(), m.get(), kind.outside.data(), 0.0, nullptr);
  EXPECT_EQ(st.code, ACST_NONPHYSICAL_STATE);
  EXPECT_NE(std::string(st.message).find(kind.refusal), std::string::npos) << st.message;
  EXPECT_EQ(out, untouched);
  EXPECT_EQ(eps_p, 7.0);
  EXPECT_EQ(acst_initial_state(&eps_p, out.data(), m.get(), kind.on.data(), 0.0, nullptr).code, ACST_OK);
  EXPECT_EQ(eps_p, 0.0);
  EXPECT_EQ(acst_initial_state(nullptr, out.data(), m.get(), kind.on.data(), 0.0, nullptr).code, ACST_INVALID_INPUT)
      << kind.name << " has one state variable, so statev is required";
}

INSTANTIATE_TEST_SUITE_P(Kinds, CAbiPlasticKind, ::testing::Values(von_mises(), drucker_prager()),
                         [](const ::testing::TestParamInfo<PlasticKind>& i) { return i.param.name; });

}  // namespace

}  // namespace acst::test::c_abi_plastic_kinds_test
