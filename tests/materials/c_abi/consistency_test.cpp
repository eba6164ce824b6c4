// The C ABI (acst_update, acst_update_batch) and the Abaqus entry umat_ give the same numbers as
// the C++ API (acst::Material) on the same path. The convention change is written out here,
// independently of materials/c_abi/src/abi_convention.hpp:
//   ABI stress  = -(model stress)                       (tension positive)
//   ABI strain  = -(model strain), shear slots doubled  (engineering gamma_ij = 2 eps_ij)
//   ABI tangent[6 i + j] = d sigma_i / d gamma_j = D_model(i, j) * (j is shear ? 1/2 : 1)
// The sign flips and factors of 2 are exact in floating point, so the two routes should agree to
// round-off; 1e-12 relative leaves room for nothing but that.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "abi_model.hpp"
#include "acst.h"
#include "acst/material.hpp"
#include "test_materials.hpp"

namespace c_abi_consistency_test {

namespace {

using acst::Mat6;
using acst::test::AbiModel;
using acst::State;
using acst::Sym;

constexpr double tight = 1e-12;  // relative: exact conversions, identical arithmetic behind them

const std::string guide_path = "data/parameters/toyoura_acst_guide.json";

// Model strain (compression positive, tensor shear) -> ABI strain (tension positive, engineering shear).
std::vector<double> to_abi_strain(const Sym& eps) {
  std::vector<double> g(6);
  for (int i = 0; i < 6; ++i) g[i] = -(i < 3 ? 1.0 : 2.0) * eps[i];
  return g;
}

int state_index(const acst_model* model, const char* name) {
  for (int i = 0; i < acst_state_size(model); ++i)
    if (std::string(acst_state_name(model, i)) == name) return i;
  ADD_FAILURE() << "no state variable named " << name;
  return 0;
}

double max_abs(const Sym& s) { return s.cwiseAbs().maxCoeff(); }

// Checks ABI stress and state against the C++ state.
void expect_same_point(const acst_model* model, const double* abi_stress, const double* statev, const State& ref,
                       const std::string& where) {
  const double scale = max_abs(ref.stress);
  for (int i = 0; i < 6; ++i)
    EXPECT_NEAR(abi_stress[i], -ref.stress[i], tight * scale) << where << ", stress component " << i;
  const char* fabric_names[6] = {"F11", "F22", "F33", "F12", "F13", "F23"};
  for (int i = 0; i < 6; ++i)
    EXPECT_NEAR(statev[state_index(model, fabric_names[i])], ref.fabric[i], tight) << where << ", " << fabric_names[i];
  EXPECT_NEAR(statev[state_index(model, "void_ratio")], ref.void_ratio, tight * ref.void_ratio) << where;
  EXPECT_NEAR(statev[state_index(model, "H")], ref.H, tight * std::max(ref.H, 1.0)) << where;
}

// C++ tangent (tensor shear, compression positive) -> expected ABI tangent entry.
double expected_abi_tangent(const Mat6& D, int i, int j) { return D(i, j) * (j < 3 ? 1.0 : 0.5); }

// A general 3-D path: axial compression with lateral expansion and all three shears, so that the
// shear factor and the sign flip are exercised on every slot. Deposition direction tilted so
// that the fabric has shear components too.
const Sym path_increment = (Sym() << 1e-4, -2.5e-5, -3.5e-5, 2e-5, -1e-5, 1.5e-5).finished();
const Eigen::Vector3d tilted_deposition(1.0, 0.4, -0.3);
constexpr double e0 = 0.67;
constexpr double p0 = 100.0;
constexpr int path_steps = 120;

TEST(CAbiConsistency, UpdateMatchesCppApiStressStateAndTangent) {
  const acst::Material mat = acst::test::guide_material();
  AbiModel h(acst::test::read_text(guide_path));
  State ref = mat.initial_state(acst::test::isotropic_stress(p0), e0, tilted_deposition);

  double stress[6], statev[ACST_NSTATV], tangent[36];
  const double s0[6] = {-p0, -p0, -p0, 0, 0, 0}, b[3] = {1.0, 0.4, -0.3};
  ASSERT_EQ(acst_initial_state(statev, stress, h.get(), s0, e0, b).code, ACST_OK);
  expect_same_point(h.get(), stress, statev, ref, "initial state");

  const std::vector<double> d = to_abi_strain(path_increment);
  for (int step = 0; step < path_steps; ++step) {
    Mat6 D;
    const acst::integration::Report rep = mat.update(ref, path_increment, &D);
    ASSERT_EQ(rep.status, acst::integration::Status::ok);
    const acst_status st = acst_update(stress, statev, tangent, nullptr, h.get(), d.data());
    ASSERT_EQ(st.code, ACST_OK) << st.message;
    const std::string where = "step " + std::to_string(step);
    expect_same_point(h.get(), stress, statev, ref, where);
    const double tscale = D.cwiseAbs().maxCoeff();
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)
        ASSERT_NEAR(tangent[6 * i + j], expected_abi_tangent(D, i, j), tight * tscale)
            << where << ", tangent (" << i << "," << j << ")";
  }
  // The path is plastic and sheared: the shear stresses are far from zero, so their sign is tested.
  EXPECT_GT(std::abs(stress[3]), 1.0);
  EXPECT_GT(std::abs(stress[4]), 0.5);
}

// Batch form with strides larger than a point: each point follows its own path and must match
// its own C++ run; the padding between points must not be written.
TEST(CAbiConsistency, BatchWithWideStridesMatchesCppApi) {
  const acst::Material mat = acst::test::guide_material();
  AbiModel h(acst::test::read_text(guide_path));
  constexpr size_t n = 3, ss = 9, sv = ACST_NSTATV + 3, ds = 8;
  constexpr double pad = 12345.678;
  std::vector<double> stress(n * ss, pad), statev(n * sv, pad), dstrain(n * ds, pad);
  std::vector<State> ref(n);
  const double s0[6] = {-p0, -p0, -p0, 0, 0, 0}, b[3] = {1.0, 0.4, -0.3};
  const double scale[n] = {1.0, 0.5, 1.7};  // different paths per point
  for (size_t k = 0; k < n; ++k) {
    ref[k] = mat.initial_state(acst::test::isotropic_stress(p0), e0, tilted_deposition);
    ASSERT_EQ(acst_initial_state(&statev[k * sv], &stress[k * ss], h.get(), s0, e0, b).code, ACST_OK);
    const std::vector<double> d = to_abi_strain(scale[k] * path_increment);
    std::copy(d.begin(), d.end(), dstrain.begin() + k * ds);
  }
  for (int step = 0; step < path_steps; ++step) {
    int point_status[n] = {-1, -1, -1};
    acst_counters counters;
    const acst_status st = acst_update_batch(stress.data(), ss, statev.data(), sv, point_status, &counters, h.get(),
                                             n, dstrain.data(), ds);
    ASSERT_EQ(st.code, ACST_OK) << st.message;
    int plastic = 0;
    for (size_t k = 0; k < n; ++k) {
      EXPECT_EQ(point_status[k], ACST_OK);
      const acst::integration::Report rep = mat.update(ref[k], scale[k] * path_increment);
      ASSERT_EQ(rep.status, acst::integration::Status::ok);
      plastic += rep.plastic;
      expect_same_point(h.get(), &stress[k * ss], &statev[k * sv], ref[k],
                        "point " + std::to_string(k) + " step " + std::to_string(step));
    }
    EXPECT_EQ(counters.plastic, plastic) << "the batch counts its plastic points";
  }
  for (size_t k = 0; k < n; ++k) {
    for (size_t i = 6; i < ss; ++i) EXPECT_EQ(stress[k * ss + i], pad) << "stress padding written, point " << k;
    for (size_t i = ACST_NSTATV; i < sv; ++i) EXPECT_EQ(statev[k * sv + i], pad) << "state padding written, point " << k;
  }
}

// The ABI tangent is the derivative of the ABI update itself. Inside the yield surface (after
// unloading) the response to a small increment is elastic; central differences of acst_update
// in each ABI strain component (engineering shear) must reproduce the returned tangent.
TEST(CAbiConsistency, ElasticTangentMatchesFiniteDifferenceOfUpdate) {
  AbiModel h(acst::test::read_text(guide_path));
  double stress[6], statev[ACST_NSTATV];
  const double s0[6] = {-p0, -p0, -p0, 0, 0, 0}, b[3] = {1.0, 0.4, -0.3};
  ASSERT_EQ(acst_initial_state(statev, stress, h.get(), s0, e0, b).code, ACST_OK);
  const std::vector<double> d = to_abi_strain(path_increment);
  for (int step = 0; step < 60; ++step) ASSERT_EQ(acst_update(stress, statev, nullptr, nullptr, h.get(), d.data()).code, ACST_OK);
  // Unload by a fifth of the loading path: the stress ratio drops, the point is inside the cone.
  std::vector<double> back(6);
  for (int i = 0; i < 6; ++i) back[i] = -12.0 * d[i];
  acst_counters c;
  ASSERT_EQ(acst_update(stress, statev, nullptr, &c, h.get(), back.data()).code, ACST_OK);
  ASSERT_EQ(c.plastic, 0) << "the unloading increment must be elastic";

  // The tangent returned with a zero increment is the one at this very state (elastic).
  double T[36];
  {
    double s[6], q[ACST_NSTATV];
    std::copy(stress, stress + 6, s);
    std::copy(statev, statev + ACST_NSTATV, q);
    const double zero[6] = {0, 0, 0, 0, 0, 0};
    ASSERT_EQ(acst_update(s, q, T, &c, h.get(), zero).code, ACST_OK);
    ASSERT_EQ(c.plastic, 0);
    for (int i = 0; i < 6; ++i) ASSERT_EQ(s[i], stress[i]) << "a zero increment leaves the stress";
  }
  // Central differences with h = 1e-7: truncation O((h K/p)^2) ~ 1e-9 relative (K/p ~ 400);
  // round-off ~ 1e-16 |sigma| / h ~ 1e-7 kPa against entries of 1e4-1e5 kPa. Hence 1e-7 relative
  // to the largest entry, a factor 100 above the truncation estimate.
  const double hstep = 1e-7;
  double maxT = 0.0;
  for (double t : T) maxT = std::max(maxT, std::abs(t));
  for (int j = 0; j < 6; ++j) {
    double sp[6], sm[6], qp[ACST_NSTATV], qm[ACST_NSTATV];
    std::copy(stress, stress + 6, sp);
    std::copy(stress, stress + 6, sm);
    std::copy(statev, statev + ACST_NSTATV, qp);
    std::copy(statev, statev + ACST_NSTATV, qm);
    double dp[6] = {0, 0, 0, 0, 0, 0}, dm[6] = {0, 0, 0, 0, 0, 0};
    dp[j] = hstep;
    dm[j] = -hstep;
    acst_counters cp, cm;
    ASSERT_EQ(acst_update(sp, qp, nullptr, &cp, h.get(), dp).code, ACST_OK);
    ASSERT_EQ(acst_update(sm, qm, nullptr, &cm, h.get(), dm).code, ACST_OK);
    ASSERT_EQ(cp.plastic + cm.plastic, 0) << "probe " << j << " must stay elastic";
    for (int i = 0; i < 6; ++i)
      EXPECT_NEAR(T[6 * i + j], (sp[i] - sm[i]) / (2.0 * hstep), 1e-7 * maxT) << "tangent (" << i << "," << j << ")";
  }
  // Independent closed form of the isotropic elastic stiffness in engineering shear: the shear
  // diagonal is G (tau = G gamma), the normal block lambda + 2G / lambda. 1e-12: exact formulas.
  double dq[ACST_NDIAGNOSTICS];
  ASSERT_EQ(acst_diagnostics(dq, h.get(), stress, statev).code, ACST_OK);
  ASSERT_STREQ(acst_diagnostic_name(11), "G");
  ASSERT_STREQ(acst_diagnostic_name(12), "K");
  const double G = dq[11], K = dq[12], lam = K - 2.0 * G / 3.0;
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) {
      const double expected = i < 3 && j < 3 ? lam + (i == j ? 2.0 * G : 0.0) : (i == j ? G : 0.0);
      EXPECT_NEAR(T[6 * i + j], expected, tight * maxT) << "elastic tangent (" << i << "," << j << ")";
    }
}

// PROPS in the order documented in materials/c_abi/src/umat.cpp, filled by name from the JSON file.
std::vector<double> props_from_json(const std::string& text) {
  const nlohmann::json j = nlohmann::json::parse(text);
  const nlohmann::json& p = j.at("parameters");
  const char* order[] = {"G0", "nu", "Mc", "c", "e_Gamma", "lambda_c", "xi", "d1", "m",
                         "h1", "h2", "n",  "e_A", "F0", "k_f", "e_max", "e_min", "p_min"};
  std::vector<double> props;
  for (const char* name : order) props.push_back(p.at(name).get<double>());
  props.push_back(1.0);   // PROPS(19): scheme 1 = ME, as the JSON's integrator
  props.push_back(j.at("integrator").at("stol").get<double>());  // PROPS(20): STOL
  return props;
}

struct UmatCall {
  double ddsdde[36] = {};
  double sse = 0, spd = 0, scd = 0, rpl = 0, ddsddt[6] = {}, drplde[6] = {}, drpldt = 0;
  double stran[6] = {}, time[2] = {0, 0}, dtime = 1, temp = 0, dtemp = 0, predef = 0, dpred = 0;
  double coords[3] = {}, drot[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, celent = 1, dfgrd0[9] = {}, dfgrd1[9] = {};
  int ndi = 3, nshr = 3, noel = 1, npt = 1, layer = 1, kspt = 1, kstep = 1, kinc = 1;
  double pnewdt = 1.0;

  void operator()(double* stress, double* statev, const double* dstran, int ntens, int nstatv, const double* props,
                  int nprops) {
    nshr = ntens - 3;
    pnewdt = 1.0;
    const char cmname[8] = {'A', 'C', 'S', 'T', ' ', ' ', ' ', ' '};
    umat_(stress, statev, ddsdde, &sse, &spd, &scd, &rpl, ddsddt, drplde, &drpldt, stran, dstran, time, &dtime, &temp,
          &dtemp, &predef, &dpred, cmname, &ndi, &nshr, &ntens, &nstatv, props, &nprops, coords, drot, &pnewdt,
          &celent, dfgrd0, dfgrd1, &noel, &npt, &layer, &kspt, &kstep, &kinc, sizeof cmname);
  }
};

TEST(CAbiConsistency, Umat3DMatchesCppApiWithColumnMajorDdsdde) {
  const std::string text = acst::test::read_text(guide_path);
  const acst::Material mat = acst::test::guide_material();
  const std::vector<double> props = props_from_json(text);
  AbiModel h(text);
  State ref = mat.initial_state(acst::test::isotropic_stress(p0), e0, tilted_deposition);
  double stress[6], statev[ACST_NSTATV + 2];  // a host may give more state variables than needed
  const double s0[6] = {-p0, -p0, -p0, 0, 0, 0}, b[3] = {1.0, 0.4, -0.3};
  ASSERT_EQ(acst_initial_state(statev, stress, h.get(), s0, e0, b).code, ACST_OK);
  statev[ACST_NSTATV] = statev[ACST_NSTATV + 1] = -7.0;
  const std::vector<double> d = to_abi_strain(path_increment);
  UmatCall umat;
  for (int step = 0; step < path_steps; ++step) {
    Mat6 D;
    ASSERT_EQ(mat.update(ref, path_increment, &D).status, acst::integration::Status::ok);
    umat(stress, statev, d.data(), 6, ACST_NSTATV + 2, props.data(), static_cast<int>(props.size()));
    ASSERT_EQ(umat.pnewdt, 1.0) << "step " << step;
    const std::string where = "umat step " + std::to_string(step);
    expect_same_point(h.get(), stress, statev, ref, where);
    const double tscale = D.cwiseAbs().maxCoeff();
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j)  // DDSDDE(I, J) = d STRESS(I) / d STRAN(J), stored column-major
        ASSERT_NEAR(umat.ddsdde[i + 6 * j], expected_abi_tangent(D, i, j), tight * tscale) << where << " (" << i << "," << j << ")";
  }
  EXPECT_EQ(statev[ACST_NSTATV], -7.0) << "extra state variables are the host's";
}

// Plane strain, NTENS = 4 (11 22 33 12): eps_33 = eps_13 = eps_23 = 0 and a deposition direction
// in the 1-2 plane, so the C++ run keeps sigma_13 = sigma_23 = 0 and the 4 components must agree.
struct PlaneStrainPoint {
  double stress[4];
  double statev[ACST_NSTATV];
};

// umat_ with PROPS `props` (NTENS 4) on a plane-strain path (vertical compression and simple
// shear, bedding tilted by 30 degrees in the footing frame) gives the stress, void ratio and
// tangent of the material of the JSON `text` through the C++ API; returns the point's last state.
PlaneStrainPoint expect_umat_plane_strain_matches(const std::string& text, const std::vector<double>& props) {
  const acst::Material mat = acst::Material::from_json(text);
  AbiModel h(text);
  PlaneStrainPoint pt{};
  const Eigen::Vector3d b3(-0.5, 0.866, 0.0);
  State ref = mat.initial_state(acst::test::isotropic_stress(p0), e0, b3);
  double stress6[6];
  const double s0[6] = {-p0, -p0, -p0, 0, 0, 0}, b[3] = {-0.5, 0.866, 0.0};
  EXPECT_EQ(acst_initial_state(pt.statev, stress6, h.get(), s0, e0, b).code, ACST_OK);
  std::copy(stress6, stress6 + 4, pt.stress);
  const Sym inc = (Sym() << -3e-5, 1e-4, 0.0, 3e-5, 0.0, 0.0).finished();
  const std::vector<double> d6 = to_abi_strain(inc);
  const double d[4] = {d6[0], d6[1], d6[2], d6[3]};
  UmatCall umat;
  for (int step = 0; step < path_steps; ++step) {
    Mat6 D;
    EXPECT_EQ(mat.update(ref, inc, &D).status, acst::integration::Status::ok);
    EXPECT_EQ(ref.stress[4], 0.0);
    EXPECT_EQ(ref.stress[5], 0.0);
    umat(pt.stress, pt.statev, d, 4, ACST_NSTATV, props.data(), static_cast<int>(props.size()));
    EXPECT_EQ(umat.pnewdt, 1.0) << "step " << step;
    const std::string where = "plane strain step " + std::to_string(step);
    const double scale = max_abs(ref.stress), tscale = D.cwiseAbs().maxCoeff();
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(pt.stress[i], -ref.stress[i], tight * scale) << where << ", " << i;
    EXPECT_NEAR(pt.statev[state_index(h.get(), "void_ratio")], ref.void_ratio, tight) << where;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j)  // 4 x 4, column-major with leading dimension NTENS
        EXPECT_NEAR(umat.ddsdde[i + 4 * j], expected_abi_tangent(D, i, j), tight * tscale) << where << " (" << i << "," << j << ")";
    if (::testing::Test::HasFailure()) break;
  }
  return pt;
}

TEST(CAbiConsistency, UmatPlaneStrainMatchesCppApi) {
  const std::string text = acst::test::read_text(guide_path);
  const PlaneStrainPoint pt = expect_umat_plane_strain_matches(text, props_from_json(text));
  EXPECT_LT(pt.stress[3], -1.0) << "the simple shear builds a shear stress of the strain's sign (tension positive)";
}

// PROPS(23) carries the Lode form: with 1 umat_ is the material whose JSON says "lode_form": 1
// (a plane-strain path, off the compression meridian, where the forms differ), and 0.5 is refused.
TEST(CAbiConsistency, UmatLodeFormFromProps23MatchesTheJsonMaterial) {
  nlohmann::json j = nlohmann::json::parse(acst::test::read_text(guide_path));
  const std::vector<double> li_props = props_from_json(j.dump());
  j["parameters"]["lode_form"] = 1;
  const acst::Material mat = acst::Material::from_json(j.dump());
  std::vector<double> props = li_props;
  props.insert(props.end(), {0.0, 0.0, 1.0});  // PROPS(21) reset, PROPS(22) rotate with DROT, PROPS(23) Willam & Warnke
  AbiModel h(j.dump());
  State ref = mat.initial_state(acst::test::isotropic_stress(p0), e0, Eigen::Vector3d(0.0, 1.0, 0.0));
  double stress6[6], statev[ACST_NSTATV], li_statev[ACST_NSTATV];
  const double s0[6] = {-p0, -p0, -p0, 0, 0, 0}, b[3] = {0.0, 1.0, 0.0};
  ASSERT_EQ(acst_initial_state(statev, stress6, h.get(), s0, e0, b).code, ACST_OK);
  std::copy(statev, statev + ACST_NSTATV, li_statev);
  double stress[4] = {-p0, -p0, -p0, 0.0}, li_stress[4] = {-p0, -p0, -p0, 0.0};
  const Sym inc = (Sym() << -4e-5, 1e-4, 0.0, 0.0, 0.0, 0.0).finished();  // plane strain: eps_33 = 0
  const std::vector<double> d6 = to_abi_strain(inc);
  const double d[4] = {d6[0], d6[1], d6[2], d6[3]};
  UmatCall umat;
  for (int step = 0; step < path_steps; ++step) {
    ASSERT_EQ(mat.update(ref, inc).status, acst::integration::Status::ok);
    umat(stress, statev, d, 4, ACST_NSTATV, props.data(), static_cast<int>(props.size()));
    umat(li_stress, li_statev, d, 4, ACST_NSTATV, li_props.data(), static_cast<int>(li_props.size()));
    ASSERT_EQ(umat.pnewdt, 1.0) << "step " << step;
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(stress[i], -ref.stress[i], tight * max_abs(ref.stress)) << "step " << step << ", " << i;
  }
  // The two forms part: sigma_22 (the loaded axis) differs by more than a kPa after 1.2 % strain.
  EXPECT_GT(std::abs(stress[1] - li_stress[1]), 1.0);
  props.back() = 0.5;
  umat(stress, statev, d, 4, ACST_NSTATV, props.data(), static_cast<int>(props.size()));
  EXPECT_LT(umat.pnewdt, 1.0) << "PROPS(23) = 0.5 is neither form";
}

// An optional option entry at PROPS(position) (1-based; the entries before it at their defaults,
// 0): with `value` umat_ is the material whose JSON sets `name` so (stress and tangent on the
// plane-strain path above), and `bad` is refused.
void expect_umat_option_from_props(const char* name, int position, double value, double bad) {
  SCOPED_TRACE(std::string(name) + " at PROPS(" + std::to_string(position) + ")");
  nlohmann::json j = nlohmann::json::parse(acst::test::read_text(guide_path));
  std::vector<double> props = props_from_json(j.dump());
  props.resize(position, 0.0);
  props.back() = value;
  j["parameters"][name] = value;
  PlaneStrainPoint pt = expect_umat_plane_strain_matches(j.dump(), props);
  props.back() = bad;
  const double d[4] = {1e-5, -1e-5, 0.0, 0.0};
  UmatCall umat;
  umat(pt.stress, pt.statev, d, 4, ACST_NSTATV, props.data(), static_cast<int>(props.size()));
  EXPECT_LT(umat.pnewdt, 1.0) << bad << " is out of range";
}

TEST(CAbiConsistency, UmatElasticAnisotropyFromProps24MatchesTheJsonMaterial) {
  expect_umat_option_from_props("elastic_anisotropy", 24, 1.5, 6.0);
}

// beta = 0.9, so that the path's 100-110 kPa, near pa, still changes n by a few per cent.
TEST(CAbiConsistency, UmatPeakPressureExponentFromProps25MatchesTheJsonMaterial) {
  expect_umat_option_from_props("peak_pressure_exponent", 25, 0.9, 1.2);
}

// A failing increment asks for a smaller step and leaves stress and state as they were.
TEST(CAbiConsistency, FailingIncrementRequestsStepReductionAndLeavesStateUntouched) {
  nlohmann::json j = nlohmann::json::parse(acst::test::read_text(guide_path));
  j["integrator"]["pressure_floor"] = "fail";
  AbiModel h(j.dump());
  double stress[6], statev[ACST_NSTATV];
  const double s0[6] = {-p0, -p0, -p0, 0, 0, 0}, b[3] = {1, 0, 0};
  ASSERT_EQ(acst_initial_state(statev, stress, h.get(), s0, e0, b).code, ACST_OK);
  const std::vector<double> stress_before(stress, stress + 6), statev_before(statev, statev + ACST_NSTATV);
  // 3 % volumetric extension: elastically p would drop by K * 0.03 ~ 1000 kPa, far below p_min.
  const double extension[6] = {0.01, 0.01, 0.01, 0, 0, 0};
  double tangent[36];
  const acst_status st = acst_update(stress, statev, tangent, nullptr, h.get(), extension);
  EXPECT_EQ(st.code, ACST_STEP_REDUCTION);
  EXPECT_GT(st.suggested_step_factor, 0.0);
  EXPECT_LT(st.suggested_step_factor, 1.0);
  EXPECT_STRNE(st.message, "");
  EXPECT_EQ(std::vector<double>(stress, stress + 6), stress_before);
  EXPECT_EQ(std::vector<double>(statev, statev + ACST_NSTATV), statev_before);

  // The batch reports the failing point by index and still advances the good one.
  double bs[12], bq[2 * ACST_NSTATV], bd[12] = {0.01, 0.01, 0.01, 0, 0, 0, -1e-4, 0, 0, 0, 0, 0};
  for (int k = 0; k < 2; ++k) {
    std::copy(stress_before.begin(), stress_before.end(), bs + 6 * k);
    std::copy(statev_before.begin(), statev_before.end(), bq + ACST_NSTATV * k);
  }
  int ps[2] = {-1, -1};
  const acst_status bst = acst_update_batch(bs, 6, bq, ACST_NSTATV, ps, nullptr, h.get(), 2, bd, 6);
  EXPECT_EQ(bst.code, ACST_STEP_REDUCTION);
  EXPECT_NE(std::string(bst.message).find("point 0"), std::string::npos) << bst.message;
  EXPECT_EQ(ps[0], ACST_STEP_REDUCTION);
  EXPECT_EQ(ps[1], ACST_OK);
  EXPECT_EQ(std::vector<double>(bs, bs + 6), stress_before);
  EXPECT_LT(bs[6], stress_before[0]) << "the compressed point moved";
}

TEST(CAbiConsistency, UmatFailingIncrementSetsPnewdtBelowOneAndLeavesStateUntouched) {
  const std::string text = acst::test::read_text(guide_path);
  std::vector<double> props = props_from_json(text);
  // STOL = 1e-20 lies below the error floor of the substepping (1e-16): every plastic substep is
  // rejected until the substep falls below its minimum, an honest step-reduction failure.
  props[19] = 1e-20;
  AbiModel h(text);
  double stress[6], statev[ACST_NSTATV];
  const double s0[6] = {-p0, -p0, -p0, 0, 0, 0}, b[3] = {1, 0, 0};
  ASSERT_EQ(acst_initial_state(statev, stress, h.get(), s0, e0, b).code, ACST_OK);
  const std::vector<double> stress_before(stress, stress + 6), statev_before(statev, statev + ACST_NSTATV);
  const std::vector<double> d = to_abi_strain(path_increment);  // plastic from the isotropic state
  UmatCall umat;
  umat.ddsdde[0] = 42.0;
  umat(stress, statev, d.data(), 6, ACST_NSTATV, props.data(), static_cast<int>(props.size()));
  EXPECT_GT(umat.pnewdt, 0.0);
  EXPECT_LT(umat.pnewdt, 1.0);
  EXPECT_EQ(std::vector<double>(stress, stress + 6), stress_before);
  EXPECT_EQ(std::vector<double>(statev, statev + ACST_NSTATV), statev_before);
}

// PROPS(21) = 1 selects pressure_floor = fail: an extension far below p_min asks for a smaller step.
TEST(CAbiConsistency, UmatPressureFloorFailOptionRequestsStepReduction) {
  const std::string text = acst::test::read_text(guide_path);
  std::vector<double> props = props_from_json(text);
  props.push_back(1.0);  // PROPS(21): fail
  AbiModel h(text);
  double stress[6], statev[ACST_NSTATV];
  const double s0[6] = {-p0, -p0, -p0, 0, 0, 0}, b[3] = {1, 0, 0};
  ASSERT_EQ(acst_initial_state(statev, stress, h.get(), s0, e0, b).code, ACST_OK);
  const std::vector<double> stress_before(stress, stress + 6);
  const double extension[6] = {0.01, 0.01, 0.01, 0, 0, 0};
  UmatCall umat;
  umat(stress, statev, extension, 6, ACST_NSTATV, props.data(), static_cast<int>(props.size()));
  EXPECT_GT(umat.pnewdt, 0.0);
  EXPECT_LT(umat.pnewdt, 1.0);
  EXPECT_EQ(std::vector<double>(stress, stress + 6), stress_before);
  props.back() = 0.0;  // reset (the default): the point goes to the isotropic p_min state
  umat(stress, statev, extension, 6, ACST_NSTATV, props.data(), static_cast<int>(props.size()));
  EXPECT_EQ(umat.pnewdt, 1.0);
  const double p_min = nlohmann::json::parse(text).at("parameters").at("p_min").get<double>();
  for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(stress[i], -p_min);
  props.back() = 0.5;  // neither 0 nor 1
  umat(stress, statev, extension, 6, ACST_NSTATV, props.data(), static_cast<int>(props.size()));
  EXPECT_EQ(umat.pnewdt, ACST_UMAT_UNRECOVERABLE_PNEWDT);
}

TEST(CAbiConsistency, UmatRejectsBadNtensAndShortPropsAsUnrecoverable) {
  const std::string text = acst::test::read_text(guide_path);
  const std::vector<double> props = props_from_json(text);
  AbiModel h(text);
  double stress[6], statev[ACST_NSTATV];
  const double s0[6] = {-p0, -p0, -p0, 0, 0, 0}, b[3] = {1, 0, 0};
  ASSERT_EQ(acst_initial_state(statev, stress, h.get(), s0, e0, b).code, ACST_OK);
  const std::vector<double> stress_before(stress, stress + 6), statev_before(statev, statev + ACST_NSTATV);
  const std::vector<double> d = to_abi_strain(path_increment);
  UmatCall umat;
  auto untouched = [&] {
    EXPECT_EQ(std::vector<double>(stress, stress + 6), stress_before);
    EXPECT_EQ(std::vector<double>(statev, statev + ACST_NSTATV), statev_before);
  };
  umat(stress, statev, d.data(), 3, ACST_NSTATV, props.data(), static_cast<int>(props.size()));  // NTENS 3
  EXPECT_EQ(umat.pnewdt, ACST_UMAT_UNRECOVERABLE_PNEWDT);
  untouched();
  umat(stress, statev, d.data(), 6, ACST_NSTATV, props.data(), 17);  // one constant short
  EXPECT_EQ(umat.pnewdt, ACST_UMAT_UNRECOVERABLE_PNEWDT);
  untouched();
  umat(stress, statev, d.data(), 6, ACST_NSTATV - 1, props.data(), static_cast<int>(props.size()));  // NSTATV short
  EXPECT_EQ(umat.pnewdt, ACST_UMAT_UNRECOVERABLE_PNEWDT);
  untouched();
  std::vector<double> bad = props;
  bad[1] = 0.7;  // nu out of range
  umat(stress, statev, d.data(), 6, ACST_NSTATV, bad.data(), static_cast<int>(bad.size()));
  EXPECT_EQ(umat.pnewdt, ACST_UMAT_UNRECOVERABLE_PNEWDT);
  untouched();
  bad = props;
  bad[18] = 7;  // no such scheme
  umat(stress, statev, d.data(), 6, ACST_NSTATV, bad.data(), static_cast<int>(bad.size()));
  EXPECT_EQ(umat.pnewdt, ACST_UMAT_UNRECOVERABLE_PNEWDT);
  untouched();
  // Sanity: the same call with good arguments succeeds, so the rejections above were the arguments'.
  umat(stress, statev, d.data(), 6, ACST_NSTATV, props.data(), static_cast<int>(props.size()));
  EXPECT_EQ(umat.pnewdt, 1.0);
}

}  // namespace

// DROT (Abaqus/Standard convention, the default): the host hands over the stress already turned
// by the increment's rigid rotation R and expects the fabric in STATEV to be turned by umat_.
// A rigidly rotated problem must give the rotated answer. The rotation is written here with
// 3 x 3 matrices (engineering shear halved for strains), independently of the library's.
namespace {

using M3 = Eigen::Matrix3d;

M3 tensor_of(const double* v, double shear_factor) {
  M3 m;
  m << v[0], shear_factor * v[3], shear_factor * v[4], shear_factor * v[3], v[1], shear_factor * v[5],
      shear_factor * v[4], shear_factor * v[5], v[2];
  return m;
}

void voigt_of(const M3& m, double shear_factor, double* v) {
  const double out[6] = {m(0, 0), m(1, 1), m(2, 2), m(0, 1) / shear_factor, m(0, 2) / shear_factor,
                         m(1, 2) / shear_factor};
  std::copy(out, out + 6, v);
}

void rotated(const double* v, const M3& R, double shear_factor, double* out) {
  voigt_of(R * tensor_of(v, shear_factor) * R.transpose(), shear_factor, out);
}

double max_abs(const double* v, int n) {
  double m = 0.0;
  for (int i = 0; i < n; ++i) m = std::max(m, std::abs(v[i]));
  return m;
}

}  // namespace

TEST(CAbiConsistency, UmatTurnsTheFabricWithDrotAndGivesTheRotatedAnswer) {
  const std::string text = acst::test::read_text(guide_path);
  std::vector<double> props = props_from_json(text);
  props.push_back(1.0);  // PROPS(21): pressure floor policy "fail" (no silent reset here)
  AbiModel h(text);
  double stress[6], statev[ACST_NSTATV];
  const double s0[6] = {-150, -100, -80, 10, -5, 3}, b[3] = {1.0, 0.4, -0.3};
  ASSERT_EQ(acst_initial_state(statev, stress, h.get(), s0, e0, b).code, ACST_OK);
  const double dstran[6] = {-2e-4, 5e-5, 4e-5, 6e-5, -3e-5, 2e-5};
  const M3 R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(0.3, -0.5, 0.8).normalized()).toRotationMatrix();

  // Reference: the unrotated problem.
  UmatCall umat;
  double s_ref[6], q_ref[ACST_NSTATV];
  std::copy(stress, stress + 6, s_ref);
  std::copy(statev, statev + ACST_NSTATV, q_ref);
  umat(s_ref, q_ref, dstran, 6, ACST_NSTATV, props.data(), static_cast<int>(props.size()));
  ASSERT_EQ(umat.pnewdt, 1.0);

  // Abaqus: stress and strain increment turned by R, the fabric still in the old frame, DROT = R.
  double s_rot[6], q_rot[ACST_NSTATV], d_rot[6];
  rotated(stress, R, 1.0, s_rot);
  rotated(dstran, R, 0.5, d_rot);
  std::copy(statev, statev + ACST_NSTATV, q_rot);
  Eigen::Map<M3>(umat.drot) = R;  // DROT(i, j) column-major, as Eigen stores it
  umat(s_rot, q_rot, d_rot, 6, ACST_NSTATV, props.data(), static_cast<int>(props.size()));
  ASSERT_EQ(umat.pnewdt, 1.0);

  double s_expected[6], f_expected[6];
  rotated(s_ref, R, 1.0, s_expected);
  rotated(q_ref, R, 1.0, f_expected);  // the fabric is stored with tensor shear components
  const double stol = 1e-9 * max_abs(s_expected, 6), ftol = 1e-9 * std::max(max_abs(f_expected, 6), 1e-3);
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(s_rot[i], s_expected[i], stol) << "stress " << i;
    EXPECT_NEAR(q_rot[i], f_expected[i], ftol) << "fabric " << i;
  }
  EXPECT_NEAR(q_rot[6], q_ref[6], 1e-12) << "the void ratio is a scalar";

  // PROPS(22) = 1, the material frame: the host has turned everything (fabric included) and
  // umat_ must not turn the fabric again, whatever DROT says.
  std::vector<double> material_frame = props;
  material_frame.push_back(1.0);
  double s_mat[6], q_mat[ACST_NSTATV];
  rotated(stress, R, 1.0, s_mat);
  std::copy(statev, statev + ACST_NSTATV, q_mat);
  rotated(statev, R, 1.0, q_mat);
  umat(s_mat, q_mat, d_rot, 6, ACST_NSTATV, material_frame.data(), static_cast<int>(material_frame.size()));
  ASSERT_EQ(umat.pnewdt, 1.0);
  for (int i = 0; i < 6; ++i) {
    EXPECT_NEAR(s_mat[i], s_expected[i], stol) << "stress " << i;
    EXPECT_NEAR(q_mat[i], f_expected[i], ftol) << "fabric " << i;
  }

  // A DROT that is no rotation is refused: PNEWDT 0 and the state untouched.
  umat.drot[0] = 2.0;
  double s_bad[6], q_bad[ACST_NSTATV];
  std::copy(stress, stress + 6, s_bad);
  std::copy(statev, statev + ACST_NSTATV, q_bad);
  umat(s_bad, q_bad, dstran, 6, ACST_NSTATV, props.data(), static_cast<int>(props.size()));
  EXPECT_EQ(umat.pnewdt, ACST_UMAT_UNRECOVERABLE_PNEWDT);
  for (int i = 0; i < ACST_NSTATV; ++i) EXPECT_EQ(q_bad[i], statev[i]);
}

}  // namespace c_abi_consistency_test
