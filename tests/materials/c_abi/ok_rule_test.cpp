// The OK rule of the C ABI and umat_ (acst.h, docs/reliability.md): ACST_OK promises that every
// output is finite and physical (void ratio in (0, 2.97), p >= p_min, H >= 0, tangent finite);
// anything else is a step reduction or an error with a message, and leaves the caller's stress
// and state as they came. One test per defect issue 14 reported, and a randomized sweep of
// states and increments of every size over every model kind and umat_.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "abi_model.hpp"
#include "test_materials.hpp"

namespace c_abi_ok_rule_test {

namespace {

using acst::test::AbiModel;

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
constexpr int nstatv = ACST_NSTATV;
constexpr int void_ratio_slot = 6, H_slot = 7, hint_slot = 8;

const std::string guide = acst::test::read_text("data/parameters/toyoura_acst_guide.json");
const std::string linear_elastic = R"({"model": "linear_elastic", "parameters": {"E": 1e5, "nu": 0.3}})";
const std::string von_mises = R"({"model": "von_mises", "parameters": {"E": 1e5, "nu": 0.3, "yield_stress": 200}})";
double p_min() { return nlohmann::json::parse(guide)["parameters"]["p_min"].get<double>(); }

struct Point {
  double stress[6];
  double statev[nstatv];
};

// An isotropic sand point at p (kPa) and void ratio e through acst_initial_state.
Point sand_point(const acst_model* m, double p, double e) {
  Point pt{};
  const double s0[6] = {-p, -p, -p, 0, 0, 0}, b[3] = {0, 0, 1};
  const acst_status st = acst_initial_state(pt.statev, pt.stress, m, s0, e, b);
  EXPECT_EQ(st.code, ACST_OK) << st.message;
  return pt;
}

bool finite(const double* v, int n) {
  for (int i = 0; i < n; ++i)
    if (!std::isfinite(v[i])) return false;
  return true;
}

// What an OK update must hold for a sand point (ABI convention: tension positive).
void expect_physical_sand(const double* stress, const double* statev, const double* tangent, const std::string& where) {
  EXPECT_TRUE(finite(stress, 6)) << where;
  EXPECT_TRUE(finite(statev, nstatv)) << where;
  if (tangent) {
    EXPECT_TRUE(finite(tangent, 36)) << where;
  }
  EXPECT_GT(statev[void_ratio_slot], 0.0) << where;
  EXPECT_LT(statev[void_ratio_slot], 2.97) << where;
  EXPECT_GE(statev[H_slot], 0.0) << where;
  EXPECT_GE(-(stress[0] + stress[1] + stress[2]) / 3.0, p_min() * (1.0 - 1e-12)) << where;
}

// Updates a copy; returns the status and checks the rule: OK -> physical, else untouched.
acst_status checked_update(const acst_model* m, Point& pt, const double* de, bool sand, const std::string& where) {
  Point before = pt;
  double tangent[36];
  const acst_status st = acst_update(pt.stress, pt.statev, tangent, nullptr, m, de);
  if (st.code == ACST_OK) {
    if (sand) {
      expect_physical_sand(pt.stress, pt.statev, tangent, where);
    } else {
      EXPECT_TRUE(finite(pt.stress, 6) && finite(tangent, 36) && finite(pt.statev, acst_state_size(m))) << where;
    }
  } else {
    EXPECT_EQ(std::memcmp(&before, &pt, sizeof pt), 0) << where << ": a failed update changed its inputs";
    EXPECT_NE(st.message[0], '\0') << where;
    if (st.code == ACST_STEP_REDUCTION) {
      EXPECT_TRUE(st.suggested_step_factor > 0.0 && st.suggested_step_factor < 1.0) << where;
    }
  }
  return st;
}

}  // namespace

// From 100 kPa a volumetric compression of 60 % would take e below zero: it came back OK, with
// e < 0 and the point reset to p_min. Now a smaller increment is asked for, naming the void ratio.
TEST(AbiOkRule, ACompressionBeyondZeroVoidRatioIsNotOk) {
  const AbiModel m(guide);
  Point pt = sand_point(m.get(), 100.0, 0.67);
  const double de[6] = {-0.2, -0.2, -0.2, 0, 0, 0};
  const acst_status st = checked_update(m.get(), pt, de, true, "60 % compression");
  EXPECT_EQ(st.code, ACST_STEP_REDUCTION);
  EXPECT_NE(std::string(st.message).find("void ratio"), std::string::npos) << st.message;
  // The same compression in 1 % steps is possible until the void ratio nears zero: every OK step
  // is physical, and the first refusal comes before e <= 0 (e = (1 + e0) exp(-eps_v) - 1 > 0 for
  // eps_v < ln 1.67 = 0.51).
  Point path = sand_point(m.get(), 100.0, 0.67);
  const double step[6] = {-0.01 / 3, -0.01 / 3, -0.01 / 3, 0, 0, 0};
  int ok = 0;
  while (ok < 60 && checked_update(m.get(), path, step, true, "1 % steps").code == ACST_OK) ++ok;
  EXPECT_GE(ok, 30) << "the first half of the compression is an ordinary path";
  EXPECT_LT(ok, 60);
}

// A state far outside the model's void ratios is a non-physical state, not a request for a
// smaller increment (no increment could help); the other entry points say the same.
TEST(AbiOkRule, AVoidRatioOutOfRangeIsANonPhysicalState) {
  const AbiModel m(guide);
  for (double e : {-0.1, 0.0, 3.5, 1e9, not_a_number}) {
    Point pt = sand_point(m.get(), 100.0, 0.7);
    pt.statev[void_ratio_slot] = e;
    const double de[6] = {-1e-4, 0, 0, 0, 0, 0};
    EXPECT_EQ(checked_update(m.get(), pt, de, true, "e = " + std::to_string(e)).code, ACST_NONPHYSICAL_STATE);
    double out[ACST_NDIAGNOSTICS], c = -1.0;
    const acst_status d = acst_diagnostics(out, m.get(), pt.stress, pt.statev);
    EXPECT_EQ(d.code, ACST_NONPHYSICAL_STATE) << e;
    EXPECT_EQ(acst_wave_speed(&c, m.get(), pt.stress, pt.statev, 1600.0).code, ACST_NONPHYSICAL_STATE) << e;
    EXPECT_EQ(c, -1.0) << "no output on failure";
    const double Q[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1};
    const Point before = pt;
    EXPECT_EQ(acst_rotate_state(pt.stress, pt.statev, m.get(), Q).code, ACST_NONPHYSICAL_STATE) << e;
    EXPECT_EQ(std::memcmp(&before, &pt, sizeof pt), 0);
  }
}

// NaN in the stress: diagnostics, wave speed and rotation said OK and returned NaN.
TEST(AbiOkRule, DiagnosticsWaveSpeedAndRotationRefuseANonFiniteStress) {
  for (const std::string& json : {guide, linear_elastic, von_mises}) {
    const AbiModel m(json);
    double stress[6] = {-100, -100, not_a_number, 0, 0, 0}, statev[nstatv] = {}, out[ACST_NDIAGNOSTICS], c = 0;
    if (acst_state_size(m.get()) == nstatv) statev[void_ratio_slot] = 0.7;
    const std::string kind = acst_model_kind(m.get());
    EXPECT_EQ(acst_diagnostics(out, m.get(), stress, statev).code, ACST_NONPHYSICAL_STATE) << kind;
    EXPECT_EQ(acst_wave_speed(&c, m.get(), stress, statev, 1600.0).code, ACST_NONPHYSICAL_STATE) << kind;
    const double Q[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    EXPECT_EQ(acst_rotate_state(stress, statev, m.get(), Q).code, ACST_NONPHYSICAL_STATE) << kind;
    // and the diagnostics of a good state are finite where they apply (the verification kinds
    // give p, q, G and K; the sand entries are NaN by contract)
    stress[2] = -100;
    ASSERT_EQ(acst_diagnostics(out, m.get(), stress, statev).code, ACST_OK) << kind;
    for (int i : {0, 1, 11, 12}) EXPECT_TRUE(std::isfinite(out[i])) << kind << " " << acst_diagnostic_name(i);
  }
}

// Huge increments on the verification kinds gave infinities with OK.
TEST(AbiOkRule, OverflowingVerificationUpdatesAreNotOk) {
  for (const std::string& json : {linear_elastic, von_mises}) {
    const AbiModel m(json);
    Point pt{};
    for (double& s : pt.stress) s = -50.0;
    const double de[6] = {1e306, -1e306, 1e306, 1e306, 0, 0};
    const acst_status st = checked_update(m.get(), pt, de, false, acst_model_kind(m.get()));
    EXPECT_NE(st.code, ACST_OK) << acst_model_kind(m.get());
  }
}

// A deposition direction whose norm overflows gave b = 0 and a fabric that was not deviatoric.
TEST(AbiOkRule, AHugeDepositionDirectionGivesTheSameFabricAsItsUnitVector) {
  const AbiModel m(guide);
  const double s0[6] = {-100, -100, -100, 0, 0, 0};
  double big[nstatv], unit[nstatv], s[6];
  const double b_big[3] = {1e200, 1e200, 0}, b_unit[3] = {std::sqrt(0.5), std::sqrt(0.5), 0};
  ASSERT_EQ(acst_initial_state(big, s, m.get(), s0, 0.7, b_big).code, ACST_OK);
  ASSERT_EQ(acst_initial_state(unit, s, m.get(), s0, 0.7, b_unit).code, ACST_OK);
  for (int i = 0; i < 6; ++i) EXPECT_NEAR(big[i], unit[i], 1e-14) << "F slot " << i;
  EXPECT_NEAR(big[0] + big[1] + big[2], 0.0, 1e-14) << "deviatoric";
  const double tiny[3] = {1e-300, 0, 1e-300};  // its norm underflows; it is still a direction
  EXPECT_EQ(acst_initial_state(big, s, m.get(), s0, 0.7, tiny).code, ACST_OK);
  const double huge_p[6] = {-1e308, -1e308, -1e308, 1e308, 0, 0};
  EXPECT_NE(acst_initial_state(big, s, m.get(), huge_p, 0.7, b_unit).code, ACST_OK) << "a state that overflows";
}

// A substep hint below the smallest substep made every call fail before its first substep, so a
// host cutting its step could never advance.
TEST(AbiOkRule, ASubstepHintBelowTheMinimumStillAdvances) {
  const AbiModel m(guide);
  Point pt = sand_point(m.get(), 100.0, 0.7);
  const double shear[6] = {-2e-3, 1e-3, 1e-3, 0, 0, 0};  // triaxial compression: plastic at once
  for (double hint : {1e-12, 0.0, -1.0, not_a_number}) {
    Point p = pt;
    p.statev[hint_slot] = hint;
    EXPECT_EQ(checked_update(m.get(), p, shear, true, "hint " + std::to_string(hint)).code, ACST_OK) << hint;
  }
}

// The fuzz target's finding: a NaN hint on an update that ends at the pressure floor (no substep
// rewrites the hint) came back OK and NaN; now it counts as no hint and comes back finite. Any
// other state variable that is not a number is refused before it is read (the reset count would
// be converted to an integer).
TEST(AbiOkRule, OnlyTheHintMayBeNotANumberOnEntry) {
  const AbiModel m(guide);
  Point p = sand_point(m.get(), 100.0, 0.7);
  p.statev[hint_slot + 1] = not_a_number;
  const double shear[6] = {-2e-3, 1e-3, 1e-3, 0, 0, 0};
  EXPECT_EQ(checked_update(m.get(), p, shear, true, "reset count NaN").code, ACST_NONPHYSICAL_STATE);
}

// umat_ took an error tolerance the JSON input refuses (STOL 5): the same range everywhere now.
TEST(AbiOkRule, UmatRefusesAToleranceTheJsonRefuses) {
  const nlohmann::json j = nlohmann::json::parse(guide);
  std::vector<double> props;
  for (const char* name : {"G0", "nu", "Mc", "c", "e_Gamma", "lambda_c", "xi", "d1", "m", "h1", "h2", "n", "e_A", "F0",
                           "k_f", "e_max", "e_min", "p_min"})
    props.push_back(j["parameters"][name].get<double>());
  props.push_back(1.0);
  props.push_back(5.0);  // PROPS(20): STOL
  const AbiModel m(guide);
  Point pt = sand_point(m.get(), 100.0, 0.7);
  double ddsdde[36], sse = 0, spd = 0, scd = 0, rpl = 0, ddsddt[6], drplde[6], drpldt = 0, stran[6] = {}, time[2] = {};
  double dtime = 1, temp = 0, dtemp = 0, predef = 0, dpred = 0, coords[3] = {}, celent = 1, dfgrd[9] = {};
  double drot[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, dstran[6] = {-1e-4, 0, 0, 0, 0, 0};
  int ndi = 3, nshr = 3, ntens = 6, nsv = nstatv, nprops = static_cast<int>(props.size()), one = 1;
  const char cmname[8] = {'A', 'C', 'S', 'T', ' ', ' ', ' ', ' '};
  const Point before = pt;
  for (double stol : {5.0, 0.0, not_a_number}) {
    props[19] = stol;
    double pnewdt = 1.0;
    umat_(pt.stress, pt.statev, ddsdde, &sse, &spd, &scd, &rpl, ddsddt, drplde, &drpldt, stran, dstran, time, &dtime,
          &temp, &dtemp, &predef, &dpred, cmname, &ndi, &nshr, &ntens, &nsv, props.data(), &nprops, coords, drot, &pnewdt,
          &celent, dfgrd, dfgrd, &one, &one, &one, &one, &one, &one, sizeof cmname);
    EXPECT_LT(pnewdt, 1.0) << "STOL " << stol << " accepted";
    EXPECT_EQ(std::memcmp(&before, &pt, sizeof pt), 0) << "STOL " << stol;
  }
  nlohmann::json bad = j;
  bad["integrator"]["stol"] = 5.0;
  acst_model* model = nullptr;
  const acst_status st = acst_model_create(&model, bad.dump().c_str());
  EXPECT_EQ(st.code, ACST_INVALID_INPUT);
  EXPECT_NE(std::string(st.message).find("stol"), std::string::npos) << st.message;
  acst_model_destroy(model);
}

// The sweep: random states (p from 0.1 kPa to 100 MPa, void ratios across the range, sheared and
// anisotropic) and increments from 1e-9 to 10 in random directions, for every kind. Whatever
// the status, the rule holds (checked_update); a good share of the calls is OK, so the check
// is not vacuous.
TEST(AbiOkRule, RandomStatesAndIncrementsOfEverySizeKeepTheRule) {
  std::mt19937 rng(20261124);
  std::uniform_real_distribution<double> u(-1.0, 1.0), unit(0.0, 1.0);
  for (const std::string& json : {guide, linear_elastic, von_mises}) {
    const AbiModel m(json);
    const bool sand = acst_state_size(m.get()) == nstatv;
    int ok = 0, calls = 0;
    for (int k = 0; k < 1500; ++k) {
      Point pt{};
      const double p = std::pow(10.0, -1.0 + 6.0 * unit(rng));
      if (sand) {
        pt = sand_point(m.get(), 100.0, 0.6 + 0.35 * unit(rng));
        for (int i = 0; i < 3; ++i) pt.stress[i] = -p * (1.0 + 0.5 * u(rng));
        for (int i = 3; i < 6; ++i) pt.stress[i] = 0.3 * p * u(rng);
        pt.statev[H_slot] = 0.5 * unit(rng);
      } else {
        for (int i = 0; i < 3; ++i) pt.stress[i] = -std::min(p, 100.0);
      }
      const double size = std::pow(10.0, -9.0 + 10.0 * unit(rng));
      double de[6];
      for (double& d : de) d = size * u(rng);
      ++calls;
      ok += checked_update(m.get(), pt, de, sand, std::string(acst_model_kind(m.get())) + " call " + std::to_string(k)).code ==
            ACST_OK;
    }
    EXPECT_GT(ok, calls / 4) << acst_model_kind(m.get());
  }
}

}  // namespace c_abi_ok_rule_test
