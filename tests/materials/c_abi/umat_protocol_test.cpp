// umat_'s failure protocol, called exactly as the two host families call it (acst.h, acst_umat;
// docs/c-abi.md "umat_ and its hosts"): CalculiX passes PNEWDT = -1 and an uninitialised DDSDDE
// (here: NaN), Abaqus/Standard a large PNEWDT. A good update leaves PNEWDT alone; a step reduction
// returns a factor in (0, 1); an unrecoverable call returns ACST_UMAT_UNRECOVERABLE_PNEWDT; every
// failure leaves STRESS and STATEV as they came and DDSDDE finite and positive definite.
#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "abi_model.hpp"
#include "acst.h"
#include "test_materials.hpp"

namespace c_abi_umat_protocol_test {

namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double calculix_entry = -1.0;  // CalculiX: "no request yet"
constexpr double abaqus_entry = 1e36;    // Abaqus/Standard: a large value

const std::string guide = "data/parameters/toyoura_acst_guide.json";

std::vector<double> guide_props() {
  const nlohmann::json p = nlohmann::json::parse(acst::test::read_text(guide)).at("parameters");
  std::vector<double> props;
  for (const char* name : {"G0", "nu", "Mc", "c", "e_Gamma", "lambda_c", "xi", "d1", "m", "h1", "h2", "n", "e_A", "F0",
                           "k_f", "e_max", "e_min", "p_min"})
    props.push_back(p.at(name).get<double>());
  return props;
}

// A point at 100 kPa, e 0.7, with everything umat_ receives; `call` runs umat_ as a host would.
struct Point {
  std::vector<double> props = guide_props();
  double stress[6], statev[ACST_NSTATV], ddsdde[36];
  double pnewdt = 0.0;
  int ntens = 6, nstatv = ACST_NSTATV;

  Point() {
    acst::test::AbiModel model(acst::test::read_text(guide));
    const double s0[6] = {-100, -100, -100, 0, 0, 0}, b[3] = {1, 0, 0};
    EXPECT_EQ(acst_initial_state(statev, stress, model.get(), s0, 0.7, b).code, ACST_OK);
  }

  acst_status call(const double* dstran, double pnewdt_on_entry) {
    std::fill(ddsdde, ddsdde + 36, nan);
    pnewdt = pnewdt_on_entry;
    const int nprops = static_cast<int>(props.size());
    // The same call through the Fortran entry point, on copies, must do exactly what acst_umat does.
    double s2[6], q2[ACST_NSTATV], d2[36], p2 = pnewdt_on_entry, sse = 0, spd = 0, scd = 0, rpl = 0, ddsddt[6],
                                            drplde[6], drpldt = 0, stran[6] = {}, time[2] = {}, dtime = 1, temp = 0,
                                            dtemp = 0, predef = 0, dpred = 0, coords[3] = {}, celent = 1, f0[9] = {},
                                            f1[9] = {};
    std::copy(stress, stress + 6, s2);
    std::copy(statev, statev + ACST_NSTATV, q2);
    std::fill(d2, d2 + 36, nan);
    const int ndi = 3, nshr = ntens - 3, noel = 1, npt = 1, layer = 1, kspt = 1, kstep = 1, kinc = 1;
    umat_(s2, q2, d2, &sse, &spd, &scd, &rpl, ddsddt, drplde, &drpldt, stran, dstran, time, &dtime, &temp, &dtemp,
          &predef, &dpred, "ACST", &ndi, &nshr, &ntens, &nstatv, props.data(), &nprops, coords, nullptr, &p2, &celent,
          f0, f1, &noel, &npt, &layer, &kspt, &kstep, &kinc, 4);
    const acst_status st = acst_umat(stress, statev, ddsdde, dstran, ntens, nstatv, props.data(), nprops, nullptr, &pnewdt);
    EXPECT_EQ(p2, pnewdt) << "umat_ and acst_umat disagree on PNEWDT";
    for (int i = 0; i < ntens; ++i)
      EXPECT_TRUE(s2[i] == stress[i] || (std::isnan(s2[i]) && std::isnan(stress[i])))
          << "umat_ and acst_umat disagree on STRESS";
    return st;
  }
};

// Finite, and (after a failure) positive definite in its symmetric part, which is what CalculiX
// assembles; a good update's tangent may be indefinite where the sand softens.
void expect_usable_tangent(const double* ddsdde, int n, bool definite = true) {
  Eigen::MatrixXd D(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      ASSERT_TRUE(std::isfinite(ddsdde[i + j * n])) << "DDSDDE(" << i + 1 << "," << j + 1 << ")";
      D(i, j) = ddsdde[i + j * n];
    }
  if (!definite) return;
  const Eigen::MatrixXd sym = 0.5 * (D + D.transpose());
  EXPECT_EQ(Eigen::LLT<Eigen::MatrixXd>(sym).info(), Eigen::Success) << "DDSDDE is not positive definite";
}

// The elastic tangent of the start state in closed form (engineering shear: the shear diagonal
// is G), from G and K of acst_diagnostics: what a failed call must leave in DDSDDE.
void expect_start_elastic_tangent(const Point& before, const double* ddsdde) {
  acst::test::AbiModel model(acst::test::read_text(guide));
  double d[ACST_NDIAGNOSTICS];
  ASSERT_EQ(acst_diagnostics(d, model.get(), before.stress, before.statev).code, ACST_OK);
  const double G = d[11], K = d[12], lam = K - 2.0 * G / 3.0;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      const double expected = i < 3 && j < 3 ? lam + (i == j ? 2.0 * G : 0.0) : (i == j ? G : 0.0);
      EXPECT_NEAR(ddsdde[i + 6 * j], expected, 1e-12 * (K + 2 * G)) << "(" << i << "," << j << ")";
    }
}

const double plastic[6] = {-0.002, 0.001, 0.001, 0, 0, 0};  // from the isotropic state: plastic

TEST(UmatProtocol, GoodUpdateLeavesPnewdtAsItCameForBothHosts) {
  for (double entry : {calculix_entry, abaqus_entry, 0.5}) {
    Point pt;
    const acst_status st = pt.call(plastic, entry);
    ASSERT_EQ(st.code, ACST_OK) << st.message;
    EXPECT_EQ(pt.pnewdt, entry);
    expect_usable_tangent(pt.ddsdde, 6, false);
  }
}

// STOL 1e-20 lies below the substepping's error floor: an honest step reduction.
TEST(UmatProtocol, StepReductionReturnsAFactorBelowOneAndTheStartElasticTangent) {
  for (double entry : {calculix_entry, abaqus_entry}) {
    Point pt;
    pt.props.push_back(1.0);    // PROPS(19): ME
    pt.props.push_back(1e-20);  // PROPS(20): STOL
    const Point before = pt;
    const acst_status st = pt.call(plastic, entry);
    ASSERT_EQ(st.code, ACST_STEP_REDUCTION) << st.message;
    EXPECT_GT(pt.pnewdt, 0.0);
    EXPECT_LT(pt.pnewdt, 1.0);
    EXPECT_GT(std::string(st.message).size(), 0u);
    for (int i = 0; i < 6; ++i) EXPECT_EQ(pt.stress[i], before.stress[i]);
    for (int i = 0; i < ACST_NSTATV; ++i) EXPECT_EQ(pt.statev[i], before.statev[i]);
    expect_start_elastic_tangent(before, pt.ddsdde);
  }
  // A smaller request already made at another point of the increment is kept.
  Point pt;
  pt.props.push_back(1.0);
  pt.props.push_back(1e-20);
  pt.call(plastic, 1e-3);
  EXPECT_EQ(pt.pnewdt, 1e-3);
}

TEST(UmatProtocol, UnrecoverableCallsReturnTheSmallFactorAndAFiniteTangent) {
  struct Case {
    const char* what;
    void (*spoil)(Point&);
    const double* dstran;
  };
  static const double nan_strain[6] = {nan, 0, 0, 0, 0, 0};
  const Case cases[] = {
      {"void ratio 0 (a zero-filled STATEV)", [](Point& p) { std::fill(p.statev, p.statev + ACST_NSTATV, 0.0); }, plastic},
      {"NaN stress", [](Point& p) { p.stress[0] = nan; }, plastic},
      {"NaN strain increment", [](Point&) {}, nan_strain},
      {"17 PROPS", [](Point& p) { p.props.resize(17); }, plastic},
      {"9 STATEV", [](Point& p) { p.nstatv = ACST_NSTATV - 1; }, plastic},
      {"nu out of range", [](Point& p) { p.props[1] = 0.7; }, plastic},
      {"NTENS 4 with void ratio 3.5", [](Point& p) {
         p.ntens = 4;
         p.statev[6] = 3.5;
       }, plastic},
      // PROPS(19) was converted to an int before it was checked: undefined behaviour for these,
      // which the sanitizer build stops at (issue 57).
      {"PROPS(19) NaN", [](Point& p) { p.props.push_back(nan); }, plastic},
      {"PROPS(19) infinity", [](Point& p) { p.props.push_back(std::numeric_limits<double>::infinity()); }, plastic},
      {"PROPS(19) 1e300", [](Point& p) { p.props.push_back(1e300); }, plastic},
      {"PROPS(19) -1e300", [](Point& p) { p.props.push_back(-1e300); }, plastic},
      {"PROPS(19) 2.5", [](Point& p) { p.props.push_back(2.5); }, plastic},
      // Beyond the model's arithmetic (acst::stress_limit): a step reduction here failed at
      // every increment size, so the host cut back for ever.
      {"an isotropic stress of -1e308 kPa", [](Point& p) { std::fill(p.stress, p.stress + 3, -1e308); }, plastic},
  };
  for (const Case& c : cases)
    for (double entry : {calculix_entry, abaqus_entry}) {
      Point pt;
      c.spoil(pt);
      const Point before = pt;
      const acst_status st = pt.call(c.dstran, entry);
      EXPECT_NE(st.code, ACST_OK) << c.what;
      EXPECT_NE(st.code, ACST_STEP_REDUCTION) << c.what;
      EXPECT_EQ(pt.pnewdt, ACST_UMAT_UNRECOVERABLE_PNEWDT) << c.what;
      EXPECT_GT(std::string(st.message).size(), 0u) << c.what;
      for (int i = 0; i < 6; ++i) {
        if (!std::isnan(before.stress[i])) {
          EXPECT_EQ(pt.stress[i], before.stress[i]) << c.what;
        }
      }
      for (int i = 0; i < ACST_NSTATV; ++i) EXPECT_EQ(pt.statev[i], before.statev[i]) << c.what;
      expect_usable_tangent(pt.ddsdde, pt.ntens);
    }
}

// A huge increment is never an OK-looking result: either the integrator manages it (then the
// state is physical) or the host is asked to cut back.
TEST(UmatProtocol, HugeIncrementIsPhysicalOrACutBack) {
  for (double scale : {0.1, 1.0, 10.0, 1e6}) {
    Point pt;
    const double huge[6] = {-scale, 0.3 * scale, 0.2 * scale, 0.5 * scale, 0, 0};
    const Point before = pt;
    const acst_status st = pt.call(huge, calculix_entry);
    expect_usable_tangent(pt.ddsdde, 6, st.code != ACST_OK);
    if (st.code == ACST_OK) {
      EXPECT_EQ(pt.pnewdt, calculix_entry);
      EXPECT_GT(pt.statev[6], 0.0);
      EXPECT_LT(pt.statev[6], 2.97);
    } else {
      EXPECT_GT(pt.pnewdt, 0.0) << st.message;
      EXPECT_LT(pt.pnewdt, 1.0) << st.message;
      for (int i = 0; i < 6; ++i) EXPECT_EQ(pt.stress[i], before.stress[i]);
    }
  }
}

}  // namespace

}  // namespace c_abi_umat_protocol_test
