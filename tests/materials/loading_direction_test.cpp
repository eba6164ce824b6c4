// Loading direction n and yield-surface gradient of f = R/g(theta) - H (docs/model.md
// section 5), checked against finite differences of a function written out here from the notes.
#include <gtest/gtest.h>

#include <Eigen/Core>
#include <cmath>
#include <random>
#include <vector>

#include "acst/yield_function.hpp"

namespace loading_direction_test {
namespace {

using acst::Sym;

constexpr double c = 0.75;  // Me/Mc of Toyoura sand
constexpr double R_tolerance = 1e-9;

// Voigt (11 22 33 12 13 23, tensor shear components) to a 3x3 matrix, written here so that the
// reference does not share the library's helpers.
Eigen::Matrix3d matrix(const Sym& a) {
  Eigen::Matrix3d m;
  m << a[0], a[3], a[4], a[3], a[1], a[5], a[4], a[5], a[2];
  return m;
}

// g of the notes, original (non-rationalised) form; the callers keep |sin3theta| > 0.05.
double g_notes(double s) {
  const double a = 1.0 + c * c;
  return (std::sqrt(a * a + 4.0 * c * (1.0 - c * c) * s) - a) / (2.0 * (1.0 - c) * s);
}

double sin3theta_of(const Eigen::Matrix3d& r) {
  const Eigen::Matrix3d r_hat = r / r.norm();  // Frobenius norm = sqrt(r:r)
  return -std::sqrt(6.0) * (r_hat * r_hat * r_hat).trace();
}

// R/g as a function of the (symmetric) stress-ratio tensor r, from the definitions
// R = sqrt(3/2 r:r), sin3theta = -sqrt(6) tr(r_hat^3).
double R_over_g(const Sym& r_voigt) {
  const Eigen::Matrix3d r = matrix(r_voigt);
  return std::sqrt(1.5) * r.norm() / g_notes(sin3theta_of(r));
}

// f(sigma) = R/g - H with r = dev(sigma)/p.
double yield(const Sym& sigma, double H) {
  const Eigen::Matrix3d s = matrix(sigma);
  const double p = s.trace() / 3.0;
  const Eigen::Matrix3d r = (s - p * Eigen::Matrix3d::Identity()) / p;
  const Sym r_voigt = (Sym() << r(0, 0), r(1, 1), r(2, 2), r(0, 1), r(0, 2), r(1, 2)).finished();
  return R_over_g(r_voigt) - H;
}

// Tensor gradient of a function of a symmetric tensor, by central differences on the Voigt
// slots. Perturbing a normal slot k < 3 by h changes only a_kk: the difference quotient is
// d phi/d a_kk. Perturbing a shear slot (say 12) by h changes BOTH tensor components a_12 and
// a_21 by h (the Voigt vector stores the tensor component once for the symmetric pair), so
//   d phi = (d phi/d a_12 + d phi/d a_21) h = 2 (d phi/d a)_12 h,
// and the tensor component of the gradient is half the difference quotient.
template <class Function>
Sym tensor_gradient(Function phi, const Sym& a, double h) {
  Sym grad;
  for (int k = 0; k < 6; ++k) {
    Sym plus = a, minus = a;
    plus[k] += h;
    minus[k] -= h;
    const double quotient = (phi(plus) - phi(minus)) / (2.0 * h);
    grad[k] = k < 3 ? quotient : 0.5 * quotient;
  }
  return grad;
}

Sym dev(const Sym& a) {
  Sym d = a;
  const double m = (a[0] + a[1] + a[2]) / 3.0;
  for (int i = 0; i < 3; ++i) d[i] -= m;
  return d;
}

// Tensor norm sqrt(a:a): shear slots count twice.
double tensor_norm(const Sym& a) { return matrix(a).norm(); }

// Random stress states p (I + r) with R between 0.2 and 1.6 and |sin3theta| > 0.05 (where the
// reference g of the notes is well conditioned).
std::vector<Sym> random_stresses(int count) {
  std::mt19937 rng(20240611u);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<Sym> out;
  while (int(out.size()) < count) {
    Sym r;
    for (int k = 0; k < 6; ++k) r[k] = u(rng);
    r = dev(r);
    const double R_target = 0.9 + 0.7 * u(rng);
    r *= R_target / (std::sqrt(1.5) * tensor_norm(r));
    if (std::abs(sin3theta_of(matrix(r))) < 0.05) continue;
    const double p = 175.0 + 125.0 * u(rng);
    Sym sigma = p * r;
    for (int i = 0; i < 3; ++i) sigma[i] += p;
    out.push_back(sigma);
  }
  return out;
}

TEST(LoadingDirection, MatchesNormalisedDeviatoricFiniteDifferenceGradient) {
  for (const Sym& sigma : random_stresses(25)) {
    const acst::StressRatioState st = acst::stress_ratio_state(sigma, c, R_tolerance, Sym::Zero());
    ASSERT_FALSE(st.small_R);
    // N = d(R/g)/dr; n = dev(N)/|dev(N)|. h = 1e-6 on r of order 1: truncation ~1e-12, round-off
    // ~1e-10, so 1e-6 leaves a wide margin and still catches any wrong term.
    const Sym devN = dev(tensor_gradient(R_over_g, st.r, 1e-6));
    const Sym n_fd = devN / tensor_norm(devN);
    EXPECT_LT(tensor_norm(st.n - n_fd), 1e-6) << "sigma " << sigma.transpose();
    EXPECT_NEAR(st.dev_N_norm, tensor_norm(devN), 1e-6 * tensor_norm(devN));
  }
}

TEST(LoadingDirection, IsUnitAndDeviatoric) {
  for (const Sym& sigma : random_stresses(25)) {
    const acst::StressRatioState st = acst::stress_ratio_state(sigma, c, R_tolerance, Sym::Zero());
    EXPECT_NEAR(tensor_norm(st.n), 1.0, 1e-13);  // normalised to round-off
    EXPECT_NEAR(st.n[0] + st.n[1] + st.n[2], 0.0, 1e-13);
  }
}

TEST(LoadingDirection, EqualsStressRatioDirectionInTriaxialCompressionAndExtension) {
  // On the triaxial axes the Lode term 9 g' dev(r_hat^2) is parallel to r_hat, so n = r_hat.
  for (const Sym& sigma : {(Sym() << 200, 80, 80, 0, 0, 0).finished(),   // compression
                           (Sym() << 60, 110, 110, 0, 0, 0).finished()}) {  // extension
    const acst::StressRatioState st = acst::stress_ratio_state(sigma, c, R_tolerance, Sym::Zero());
    const Sym r_hat = dev(sigma) / tensor_norm(dev(sigma));
    EXPECT_LT(tensor_norm(st.n - r_hat), 1e-13);
  }
}

TEST(YieldGradient, MatchesFiniteDifferencesOfYieldFunctionInStress) {
  const double H = 0.4;  // H shifts f and must not affect its gradient
  for (const Sym& sigma : random_stresses(25)) {
    const acst::StressRatioState st = acst::stress_ratio_state(sigma, c, R_tolerance, Sym::Zero());
    const Sym grad = acst::yield_gradient(st, acst::mean_stress(sigma));
    const double p = (sigma[0] + sigma[1] + sigma[2]) / 3.0;
    // h = 1e-6 p: relative perturbation 1e-6, errors ~1e-10 of |df/dsigma| (see above).
    const Sym grad_fd = tensor_gradient([H](const Sym& s) { return yield(s, H); }, sigma, 1e-6 * p);
    EXPECT_LT(tensor_norm(grad - grad_fd), 1e-6 * tensor_norm(grad_fd)) << "sigma " << sigma.transpose();
  }
}

TEST(LoadingDirection, SmallStressRatioFallsBackToUnitDeviatoricStrainIncrement) {
  const Sym sigma = (Sym() << 100, 100, 100, 0, 0, 0).finished();  // R = 0 < R_tolerance
  const Sym deps = (Sym() << 1e-4, -2e-5, -3e-5, 1e-5, 0.0, 2e-5).finished();
  const acst::StressRatioState st = acst::stress_ratio_state(sigma, c, R_tolerance, deps);
  EXPECT_TRUE(st.small_R);
  const Sym expected = dev(deps) / tensor_norm(dev(deps));
  EXPECT_LT(tensor_norm(st.n - expected), 1e-14);
  // The notes: g = g(sin3theta = 0) = c(1+c)/(1+c^2) for that step.
  EXPECT_NEAR(st.lode.g, c * (1.0 + c) / (1.0 + c * c), 1e-15);
  // No strain direction either: n = 0 rather than NaN.
  const acst::StressRatioState none = acst::stress_ratio_state(sigma, c, R_tolerance, Sym::Zero());
  EXPECT_TRUE(none.n.allFinite());
  EXPECT_EQ(tensor_norm(none.n), 0.0);
}

// The cheap yield value of every elastic trial (acst::yield_value, written without tensor
// divisions) equals f = R/g - H from the definitions, for random stresses with |sin3theta| > 0.05
// (where the reference g of the notes is well conditioned) and also for p < 0, where r = s/p
// turns r_hat around.
TEST(YieldValue, EqualsTheDefinitionForRandomStresses) {
  std::mt19937 rng(20261124);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int checked = 0;
  for (int k = 0; k < 2000; ++k) {
    const double p = (k % 10 == 0 ? -1.0 : 1.0) * std::exp(6.0 * std::abs(u(rng)));
    Sym sigma;
    for (int i = 0; i < 6; ++i) sigma[i] = 0.6 * std::abs(p) * u(rng);
    sigma.head<3>().array() += p - (sigma[0] + sigma[1] + sigma[2]) / 3.0;
    const Eigen::Matrix3d m = matrix(sigma);
    if (std::abs(sin3theta_of((m - p * Eigen::Matrix3d::Identity()) / p)) < 0.05) continue;
    const double H = 0.3;
    const double reference = yield(sigma, H);
    EXPECT_NEAR(acst::yield_value(sigma, c, R_tolerance, H), reference, 1e-13 * (1.0 + std::abs(reference))) << k;
    ++checked;
  }
  EXPECT_GT(checked, 1500);
}

}  // namespace
}  // namespace loading_direction_test
