// The bounded least-squares solver and its uncertainty against closed forms: a straight-line fit
// (normal equations), the Rosenbrock valley, a parameter the residuals do not see, the logistic
// bound transformation, and the multi-start's abandoning of fits that lag far behind.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <random>

#include "acst_calibration/least_squares.hpp"

namespace acst::calibration {
namespace {

LeastSquaresProblem make(Eigen::VectorXd start, Eigen::VectorXd lower, Eigen::VectorXd upper, int n,
                         std::function<Eigen::VectorXd(const Eigen::VectorXd&)> r) {
  LeastSquaresProblem p;
  p.start = std::move(start);
  p.lower = std::move(lower);
  p.upper = std::move(upper);
  p.residual_count = n;
  p.residuals = [r](const std::vector<Eigen::VectorXd>& thetas) {
    std::vector<Eigen::VectorXd> out;
    for (const auto& t : thetas) out.push_back(r(t));
    return out;
  };
  return p;
}

// The multi-start: a design of `design_points` points, local fits from the best `starts` of them
// (the start included), at most `max_iterations` each; every other setting at its default.
OptimizerSettings multi_start(int design_points, int starts, int max_iterations) {
  OptimizerSettings o;
  o.design_points = design_points;
  o.starts = starts;
  o.max_iterations = max_iterations;
  return o;
}

TEST(BoundTransform, RoundTripDerivativeAndBounds) {
  BoundTransform t{Eigen::Vector2d(0.1, -3.0), Eigen::Vector2d(2.0, 5.0)};
  const Eigen::Vector2d theta(0.7, 4.2);
  EXPECT_LT((t.to_physical(t.to_scaled(theta)) - theta).norm(), 1e-12);
  const Eigen::Vector2d u = t.to_scaled(theta);
  for (int i = 0; i < 2; ++i) {
    Eigen::Vector2d up = u, um = u;
    up[i] += 1e-6;
    um[i] -= 1e-6;
    const double fd = (t.to_physical(up)[i] - t.to_physical(um)[i]) / 2e-6;
    EXPECT_NEAR(t.derivative(u)[i], fd, 1e-7 * std::abs(fd));
  }
  // However far the scaled variable goes, the physical value stays within its bounds.
  for (double far : {-50.0, -5.0, 0.0, 5.0, 50.0}) {
    const Eigen::Vector2d th = t.to_physical(Eigen::Vector2d(far, -far));
    EXPECT_GE(th[0], 0.1);
    EXPECT_LE(th[0], 2.0);
    EXPECT_GE(th[1], -3.0);
    EXPECT_LE(th[1], 5.0);
  }
}

// y = a + b t + noise: the optimum, the standard errors s^2 (X^T X)^-1 and the correlation
// follow from the normal equations, computed here independently of the solver.
TEST(LeastSquares, StraightLineMatchesTheNormalEquations) {
  const int n = 40;
  Eigen::VectorXd t(n), y(n);
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 0.05);
  for (int i = 0; i < n; ++i) {
    t[i] = 0.1 * i;
    y[i] = 1.5 - 0.8 * t[i] + noise(rng);
  }
  Eigen::MatrixXd X(n, 2);
  X.col(0).setOnes();
  X.col(1) = t;
  const Eigen::Vector2d exact = (X.transpose() * X).ldlt().solve(X.transpose() * y);
  const Eigen::VectorXd res = X * exact - y;
  const double s2 = res.squaredNorm() / (n - 2);
  const Eigen::Matrix2d cov = s2 * (X.transpose() * X).inverse();

  const auto p = make(Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(-10, -10), Eigen::Vector2d(10, 10), n,
                      [&](const Eigen::VectorXd& th) -> Eigen::VectorXd { return (th[0] + th[1] * t.array()).matrix() - y; });
  OptimizerSettings o = multi_start(4, 2, 200);
  o.xtol = 1e-12;
  o.gtol = 1e-12;
  const FitResult f = fit(p, o);
  EXPECT_NEAR(f.theta[0], exact[0], 1e-6);
  EXPECT_NEAR(f.theta[1], exact[1], 1e-6);
  EXPECT_NEAR(f.cost, res.squaredNorm(), 1e-10);
  // Forward differences of a linear residual are exact up to rounding.
  EXPECT_NEAR(f.uncertainty.standard_error[0], std::sqrt(cov(0, 0)), 1e-4 * std::sqrt(cov(0, 0)));
  EXPECT_NEAR(f.uncertainty.standard_error[1], std::sqrt(cov(1, 1)), 1e-4 * std::sqrt(cov(1, 1)));
  EXPECT_NEAR(f.uncertainty.correlation(0, 1), cov(0, 1) / std::sqrt(cov(0, 0) * cov(1, 1)), 1e-4);
  EXPECT_EQ(f.uncertainty.degrees_of_freedom, n - 2);
  EXPECT_EQ(f.local_fits.size(), 2u);
  EXPECT_EQ(f.design.size(), 4u);
}

TEST(LeastSquares, RosenbrockValleyWithinBounds) {
  const auto p = make(Eigen::Vector2d(-1.2, 1.0), Eigen::Vector2d(-2, -1), Eigen::Vector2d(2, 3), 2,
                      [](const Eigen::VectorXd& x) -> Eigen::VectorXd {
                        return Eigen::Vector2d(10.0 * (x[1] - x[0] * x[0]), 1.0 - x[0]);
                      });
  OptimizerSettings o = multi_start(0, 1, 500);
  o.xtol = 1e-12;
  o.gtol = 1e-14;
  o.fd_step = 1e-7;
  const FitResult f = fit(p, o);
  EXPECT_NEAR(f.theta[0], 1.0, 1e-5);
  EXPECT_NEAR(f.theta[1], 1.0, 1e-5);
}

// An upper bound below the unconstrained optimum holds, and the result says it is at the bound.
TEST(LeastSquares, BoundHoldsAndIsReported) {
  const auto p = make(Eigen::VectorXd::Constant(1, 0.5), Eigen::VectorXd::Constant(1, 0.0), Eigen::VectorXd::Constant(1, 1.0), 3,
                      [](const Eigen::VectorXd& x) -> Eigen::VectorXd { return Eigen::Vector3d(x[0] - 2.0, x[0] - 2.1, x[0] - 1.9); });
  const OptimizerSettings o = multi_start(2, 1, 300);
  const FitResult f = fit(p, o);
  EXPECT_LE(f.theta[0], 1.0);
  EXPECT_GT(f.theta[0], 0.99);
  EXPECT_TRUE(f.uncertainty.at_bound[0]);
}

// cost = sin^2 x + 0.09 (x - 0.5)^2 has its global minimum near x = 0.05 (cost 0.02) and local
// minima near -pi, pi and 2 pi (cost 1.2, 0.62 and 3.0). Started at 0.2, the first fit finds the
// global one; a fit from a design point that, after one iteration, is still above ten times that
// cost is abandoned. What the multi-start returns stays the same; the price is that such a fit
// might have found a better minimum later (not here: run to their ends, none beats the first).
TEST(LeastSquares, AFitFarBehindTheBestIsAbandonedWithoutChangingTheResult) {
  const auto p = make(Eigen::VectorXd::Constant(1, 0.2), Eigen::VectorXd::Constant(1, -8.0), Eigen::VectorXd::Constant(1, 8.0), 2,
                      [](const Eigen::VectorXd& x) -> Eigen::VectorXd { return Eigen::Vector2d(std::sin(x[0]), 0.3 * (x[0] - 0.5)); });
  OptimizerSettings o = multi_start(8, 5, 100);
  o.xtol = 1e-12;
  const FitResult all = fit(p, o);
  o.abandon_factor = 10.0;
  o.abandon_after = 1;
  const FitResult raced = fit(p, o);

  ASSERT_EQ(all.best, 0u);
  EXPECT_EQ(raced.best, all.best);
  EXPECT_EQ(raced.theta[0], all.theta[0]);  // the same iterates: bit for bit
  EXPECT_EQ(raced.cost, all.cost);
  ASSERT_EQ(raced.local_fits.size(), all.local_fits.size());
  int abandoned = 0;
  for (std::size_t k = 0; k < raced.local_fits.size(); ++k) {
    const LocalFit& r = raced.local_fits[k];
    const LocalFit& a = all.local_fits[k];
    EXPECT_FALSE(a.abandoned);
    if (r.abandoned) {
      ++abandoned;
      EXPECT_GT(k, 0u);  // the first fit has nothing to lag behind
      EXPECT_EQ(r.iterations, 1);
      EXPECT_GT(r.cost, 10.0 * raced.local_fits[0].cost);
      EXPECT_GE(a.cost, all.cost);  // run to its end, it would not have won (here one reaches the same minimum)
      EXPECT_NE(r.stop.find("abandoned"), std::string::npos) << r.stop;
    } else {
      EXPECT_EQ(r.theta[0], a.theta[0]);
      EXPECT_EQ(r.iterations, a.iterations);
    }
  }
  EXPECT_GE(abandoned, 1);
  EXPECT_LT(raced.evaluations, all.evaluations);
}

// A parameter the residuals do not depend on gets no standard error (NaN), the others keep theirs.
TEST(LeastSquares, UnseenParameterHasNoStandardError) {
  Eigen::MatrixXd J(3, 2);
  J << 1, 0, 2, 0, 3, 0;
  const Eigen::Vector3d r(0.1, -0.2, 0.1);
  const Uncertainty u = uncertainty(J, r, Eigen::Vector2d(1, 1), Eigen::Vector2d(0, 0), Eigen::Vector2d(2, 2));
  EXPECT_TRUE(std::isnan(u.standard_error[1]));
  const double s2 = r.squaredNorm() / 1.0;
  EXPECT_NEAR(u.standard_error[0], std::sqrt(s2 / 14.0), 1e-12);
}

}  // namespace
}  // namespace acst::calibration
