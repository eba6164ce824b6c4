// Fabric-dependent cross-anisotropic elasticity, the option elastic_anisotropy a (docs/model.md
// section 2): D_e : eps = P (D_iso : (P eps P)) P, P = exp(a sqrt(6)/12 F). For a fabric about a
// deposition direction b this is Graham & Houlsby's (1983) cross-anisotropy; the expected moduli
// below are their closed forms, written out from the principal stretches of P, not from the library.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <cmath>
#include <nlohmann/json.hpp>
#include <random>
#include <string>

#include "acst.h"
#include "acst/elasticity.hpp"
#include "acst/fabric.hpp"
#include "acst/material.hpp"
#include "test_materials.hpp"

namespace {

using acst::Mat6;
using acst::Sym;

constexpr double e0 = 0.7, p0 = 80.0, F0 = 0.5;

acst::Parameters with_anisotropy(double a) {
  acst::Parameters prm = acst::test::guide_material().parameters();
  prm.elastic_anisotropy = a;
  return prm;
}

// The principal stretches of P for F = F0 (3 b b^T - I)/sqrt(6): along b and across it.
double stretch_along(double a) { return std::exp(a * std::sqrt(6.0) / 12.0 * 2.0 * F0 / std::sqrt(6.0)); }
double stretch_across(double a) { return std::exp(-a * std::sqrt(6.0) / 12.0 * F0 / std::sqrt(6.0)); }

// The compliance of a Voigt stiffness with tensor shear slots, in engineering terms:
// eps_i = C_ij sigma_j, so E_i = 1/C_ii, nu_ij = -C_ij E_i, and G_ij = 1/(2 C_kk) for a shear slot k.
Mat6 compliance(const Mat6& D) { return D.inverse(); }

TEST(FabricElasticity, IsGrahamAndHoulsbysCrossAnisotropyAboutTheDepositionDirection) {
  for (double a : {1.5, -0.8}) {
    SCOPED_TRACE("a = " + std::to_string(a));
    const acst::Parameters prm = with_anisotropy(a);
    const Sym F = acst::initial_fabric(F0, Eigen::Vector3d(1, 0, 0));  // b along axis 1 (index 0)
    const acst::ElasticModuli mod = acst::elastic_moduli(prm, e0, p0, F);
    ASSERT_TRUE(mod.anisotropic);
    const Mat6 C = compliance(acst::elastic_stiffness(mod));
    const double G = acst::shear_modulus(prm, e0, p0), nu = prm.nu, E = 2.0 * G * (1.0 + nu);
    const double pb = stretch_along(a), ph = stretch_across(a);
    const double tol = 1e-10;
    EXPECT_NEAR(1.0 / C(0, 0), E * std::pow(pb, 4), tol * E) << "E along b";
    EXPECT_NEAR(1.0 / C(1, 1), E * std::pow(ph, 4), tol * E) << "E across b";
    EXPECT_NEAR(1.0 / C(2, 2), E * std::pow(ph, 4), tol * E) << "E across b (isotropic plane)";
    EXPECT_NEAR(C(1, 1) / C(0, 0), std::exp(a * F0), tol) << "E_b / E_h = exp(a |F|), as the parameter table says";
    EXPECT_NEAR(-C(1, 2) / C(1, 1), nu, tol) << "nu in the isotropic plane";
    EXPECT_NEAR(-C(0, 1) / C(0, 0), nu * pb * pb / (ph * ph), tol) << "nu_bh (stress along b)";
    EXPECT_NEAR(1.0 / (2.0 * C(3, 3)), G * pb * pb * ph * ph, tol * G) << "G_bh (slot 12)";
    EXPECT_NEAR(1.0 / (2.0 * C(4, 4)), G * pb * pb * ph * ph, tol * G) << "G_bh (slot 13)";
    EXPECT_NEAR(1.0 / (2.0 * C(5, 5)), G * std::pow(ph, 4), tol * G) << "G_hh (slot 23) = E_h / 2(1 + nu)";
    EXPECT_NEAR(mod.P.determinant(), 1.0, tol) << "P scales no volume";
  }
}

// The stiffness of a turned fabric is the turned stiffness: D(Q F Q^T) : (Q eps Q^T) = Q (D(F) : eps) Q^T.
// To 1e-7: Eigen's closed-form 3 x 3 eigensolver, used for P, loses accuracy to about 1e-8
// where two eigenvalues nearly coincide, as they do for a fabric about one axis (the explicit
// update's own tolerance is 1e-4).
TEST(FabricElasticity, TurnsWithTheFabric) {
  const acst::Parameters prm = with_anisotropy(2.0);
  const Sym F = acst::initial_fabric(F0, Eigen::Vector3d(0.3, 1.0, -0.2));
  const Eigen::Matrix3d Q = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Sym eps = (Sym() << 1e-4, -3e-5, 2e-5, 4e-5, -1e-5, 3e-5).finished();
  const Sym turned_then_loaded =
      acst::elastic_stress_increment(acst::elastic_moduli(prm, e0, p0, acst::rotate(F, Q)), acst::rotate(eps, Q));
  const Sym loaded_then_turned = acst::rotate(acst::elastic_stress_increment(acst::elastic_moduli(prm, e0, p0, F), eps), Q);
  EXPECT_LT((turned_then_loaded - loaded_then_turned).norm(), 1e-7 * loaded_then_turned.norm());
}

// For any fabric and a in [-5, 5]: a:(D:b) = b:(D:a) (an energy), eps:D:eps > 0, and no
// acoustic wave is faster than the P-wave modulus used for time steps, which is reached along
// P's major axis.
TEST(FabricElasticity, SymmetricPositiveDefiniteAndItsWaveSpeedBounded) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto random_sym = [&] { return Sym(Sym::NullaryExpr([&] { return u(rng); })); };
  for (int trial = 0; trial < 200; ++trial) {
    const double a = 5.0 * u(rng);
    const Sym F = 0.9 * acst::deviator(random_sym());
    const acst::ElasticModuli mod = acst::elastic_moduli(with_anisotropy(a), e0, p0, F);
    const Sym x = random_sym(), y = random_sym();
    const double xy = acst::contract(x, acst::elastic_stress_increment(mod, y));
    const double yx = acst::contract(y, acst::elastic_stress_increment(mod, x));
    ASSERT_NEAR(xy, yx, 1e-10 * (std::abs(xy) + std::abs(yx) + mod.K)) << "trial " << trial;
    ASSERT_GT(acst::contract(x, acst::elastic_stress_increment(mod, x)), 0.0) << "trial " << trial;
    const double M = acst::constrained_modulus(mod);
    for (int w = 0; w < 20; ++w) {
      const Eigen::Vector3d n = Eigen::Vector3d::Random().normalized(), v = Eigen::Vector3d::Random().normalized();
      const Sym eps = acst::from_matrix(0.5 * (v * n.transpose() + n * v.transpose()));
      ASSERT_LE(acst::contract(eps, acst::elastic_stress_increment(mod, eps)), M * (1.0 + 1e-12)) << "trial " << trial;
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(mod.P);
    const Eigen::Vector3d major = eig.eigenvectors().col(2);
    const Sym along = acst::from_matrix(major * major.transpose());
    ASSERT_NEAR(acst::contract(along, acst::elastic_stress_increment(mod, along)), M, 1e-10 * M) << "trial " << trial;
  }
}

// Through Material::update, inside the cone: a small increment follows D_e with P written out
// from b directly, P = p_b b b^T + p_h (I - b b^T).
TEST(FabricElasticity, AnElasticUpdateFollowsTheCrossAnisotropicLaw) {
  const double a = 1.5;
  const acst::Material mat(with_anisotropy(a), acst::integration::Options{});
  const Eigen::Vector3d b = Eigen::Vector3d(0.3, 1.0, -0.2).normalized();
  const Sym sigma = (Sym() << 90, 70, 80, 6, -3, 4).finished();
  acst::State s = mat.initial_state(sigma, e0, b);
  s.fabric = acst::initial_fabric(F0, b);
  s.H = 5.0;  // far outside this stress's R/g: every increment is elastic
  const acst::State start = s;
  const Sym deps = 1e-7 * (Sym() << 1.0, -0.4, 0.3, 0.5, -0.2, 0.7).finished();
  const acst::integration::Report rep = mat.update(s, deps);
  ASSERT_EQ(rep.status, acst::integration::Status::ok);
  ASSERT_FALSE(rep.plastic);

  const Eigen::Matrix3d bb = b * b.transpose();
  const Eigen::Matrix3d P = stretch_along(a) * bb + stretch_across(a) * (Eigen::Matrix3d::Identity() - bb);
  const double p = (sigma[0] + sigma[1] + sigma[2]) / 3.0;
  const double G = acst::shear_modulus(mat.parameters(), e0, p), K = acst::bulk_modulus(G, mat.parameters().nu);
  const Eigen::Matrix3d X = P * acst::to_matrix(deps) * P;
  const Eigen::Matrix3d inner = 2.0 * G * (X - X.trace() / 3.0 * Eigen::Matrix3d::Identity()) + K * X.trace() * Eigen::Matrix3d::Identity();
  const Sym expected = acst::from_matrix(P * inner * P);
  // The secant moduli differ from the start's by dG/G ~ dp/(2p) ~ 1e-5: 1e-4 relative.
  EXPECT_LT((s.stress - start.stress - expected).norm(), 1e-4 * expected.norm());
}

// A plastic update from a loading state: the continuum tangent is the derivative of the update
// in the loading direction, (sigma(eps + h d) - sigma(eps)) / h -> D_ep d with an O(h) error.
TEST(FabricElasticity, ThePlasticTangentIsTheDerivativeOfTheUpdate) {
  const acst::Material mat(with_anisotropy(1.5), acst::integration::Options{});
  const Eigen::Vector3d b = Eigen::Vector3d(0.3, 1.0, -0.2).normalized();
  acst::State s = mat.initial_state(acst::test::isotropic_stress(p0), e0, b);
  const Sym d = (Sym() << 1.0, -0.4, -0.3, 0.2, 0.0, 0.1).finished();
  for (int i = 0; i < 30; ++i) ASSERT_EQ(mat.update(s, 1e-4 * d).status, acst::integration::Status::ok);
  const Mat6 D = mat.tangent(s, true, d);
  const Sym predicted = D * d;
  double previous_error = 0.0;
  for (double h : {1e-7, 1e-8}) {
    acst::State t = s;
    const acst::integration::Report rep = mat.update(t, h * d);
    ASSERT_EQ(rep.status, acst::integration::Status::ok);
    ASSERT_TRUE(rep.plastic);
    const double error = ((t.stress - s.stress) / h - predicted).norm() / predicted.norm();
    // Truncation O(h |d sigma''| / |d sigma'|) ~ h K/p ~ 1e-4 at h = 1e-7.
    EXPECT_LT(error, 2e3 * h) << "h = " << h;
    if (previous_error > 0.0) {
      EXPECT_LT(error, 0.2 * previous_error) << "first order in h";
    }
    previous_error = error;
  }
  // Not the isotropic tangent: the stiffness along b enters it.
  const acst::Material iso(with_anisotropy(0.0), acst::integration::Options{});
  EXPECT_GT((iso.tangent(s, true, d) * d - predicted).norm(), 0.02 * predicted.norm());
}

// The general loading index (D_e:g):d eps / [Kp + (D_e:g):m] is the isotropic formula when P = I:
// a path run with a = 1e-9 (the general code) stays within 1e-6 of a = 0 (the isotropic code).
TEST(FabricElasticity, TheGeneralFormReducesToTheIsotropicOne) {
  const acst::Material general(with_anisotropy(1e-9), acst::integration::Options{});
  const acst::Material isotropic(with_anisotropy(0.0), acst::integration::Options{});
  const Eigen::Vector3d b(0.3, 1.0, -0.2);
  acst::State s = general.initial_state(acst::test::isotropic_stress(p0), e0, b), t = s;
  const Sym d = 1e-4 * (Sym() << 1.0, -0.4, -0.3, 0.2, 0.0, 0.1).finished();
  Mat6 Ds, Dt;
  for (int i = 0; i < 100; ++i) {
    ASSERT_EQ(general.update(s, d, &Ds).status, acst::integration::Status::ok);
    ASSERT_EQ(isotropic.update(t, d, &Dt).status, acst::integration::Status::ok);
  }
  EXPECT_LT((s.stress - t.stress).norm(), 1e-6 * t.stress.norm());
  EXPECT_LT((s.fabric - t.fabric).norm(), 1e-6);
  EXPECT_LT((Ds - Dt).norm(), 1e-6 * Dt.norm());
}

// The C ABI's wave speed (time steps, the footing's contact spring) grows with P_max^2.
TEST(FabricElasticity, TheWaveSpeedOfTheCAbiSeesTheStiffestDirection) {
  nlohmann::json j = nlohmann::json::parse(acst::test::read_text("data/parameters/toyoura_acst_guide.json"));
  j["parameters"]["F0"] = F0;
  auto speed = [&](double a) {
    j["parameters"]["elastic_anisotropy"] = a;
    acst_model* model = nullptr;
    EXPECT_EQ(acst_model_create(&model, j.dump().c_str()).code, ACST_OK);
    double stress[6], statev[ACST_NSTATV], c = 0.0;
    const double s0[6] = {-p0, -p0, -p0, 0, 0, 0}, dir[3] = {0.0, 1.0, 0.0};
    EXPECT_EQ(acst_initial_state(statev, stress, model, s0, e0, dir).code, ACST_OK);
    EXPECT_EQ(acst_wave_speed(&c, model, stress, statev, 1600.0).code, ACST_OK);
    acst_model_destroy(model);
    return c;
  };
  const double c0 = speed(0.0);
  EXPECT_NEAR(speed(2.0) / c0, std::pow(stretch_along(2.0), 2), 1e-12);
  EXPECT_NEAR(speed(-2.0) / c0, std::pow(stretch_across(-2.0), 2), 1e-12);
}

// The message of the InputError that reading `material` raises; empty when it is accepted.
std::string input_error_of(const nlohmann::json& material) {
  try {
    acst::Material::from_json(material.dump());
  } catch (const acst::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(FabricElasticity, OutOfRangeAndIsotropicUsesAreRefusedByName) {
  nlohmann::json j = nlohmann::json::parse(acst::test::read_text("data/parameters/toyoura_acst_guide.json"));
  j["parameters"]["elastic_anisotropy"] = 5.5;
  const std::string range = input_error_of(j);
  EXPECT_NE(range.find("/parameters/elastic_anisotropy"), std::string::npos) << range;
  EXPECT_NE(range.find("[-5, 5]"), std::string::npos) << range;
  nlohmann::json iso = nlohmann::json::parse(acst::test::read_text("data/parameters/toyoura_isotropic_literature.json"));
  iso["parameters"]["elastic_anisotropy"] = 1.0;
  const std::string isotropic = input_error_of(iso);
  EXPECT_NE(isotropic.find("elastic_anisotropy"), std::string::npos) << isotropic;
  EXPECT_NE(isotropic.find("no fabric"), std::string::npos) << isotropic;
}

}  // namespace
