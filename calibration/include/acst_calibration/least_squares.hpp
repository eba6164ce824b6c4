#pragma once
// Bounded nonlinear least squares: GSL's trust-region solver (gsl_multifit_nlinear, Levenberg-
// Marquardt steps) on parameters mapped to order one by a logistic transformation that keeps
// every bound, started from the user's start and the best points of a small space-filling
// design; uncertainty from the Jacobian at the optimum. Generic: it knows residual vectors, not
// sand.
#include <Eigen/Core>
#include <functional>
#include <string>
#include <vector>

#include "acst_calibration/fit_spec.hpp"

namespace acst::calibration {

// theta = lower + (upper - lower) / (1 + exp(-u)): u is of order one, every u is inside the bounds.
struct BoundTransform {
  Eigen::VectorXd lower, upper;
  Eigen::VectorXd to_scaled(const Eigen::VectorXd& theta) const;
  Eigen::VectorXd to_physical(const Eigen::VectorXd& u) const;
  Eigen::VectorXd derivative(const Eigen::VectorXd& u) const;  // d theta / d u, per component
};

struct LeastSquaresProblem {
  Eigen::VectorXd start, lower, upper;
  int residual_count = 0;
  // Residual vectors at several parameter points (physical values); may evaluate in parallel.
  std::function<std::vector<Eigen::VectorXd>(const std::vector<Eigen::VectorXd>&)> residuals;
};

struct LocalFit {
  Eigen::VectorXd from, theta;
  double start_cost = 0.0, cost = 0.0;  // cost = sum of squared residuals
  int iterations = 0;
  long evaluations = 0;                 // residual vectors computed
  std::string stop;                     // why GSL stopped, or why the fit was abandoned
  bool abandoned = false;               // OptimizerSettings::abandon_factor
};

struct Uncertainty {
  Eigen::VectorXd standard_error;       // NaN where not identifiable
  Eigen::VectorXd ci95_lower, ci95_upper;
  Eigen::MatrixXd covariance, correlation;
  std::vector<bool> at_bound;           // within 1e-3 of the range of a bound: interval not meaningful
  double residual_variance = 0.0;       // s^2 = cost / (N - p)
  double condition_number = 0.0;        // of the scaled J^T J
  int degrees_of_freedom = 0;
};

struct FitResult {
  Eigen::VectorXd theta, residuals;
  double cost = 0.0;
  std::vector<Eigen::VectorXd> design;  // points of the design (physical values)
  std::vector<double> design_costs;
  std::vector<LocalFit> local_fits;     // the best one is local_fits[best]
  std::size_t best = 0;
  Eigen::MatrixXd jacobian;             // d residual / d theta at the optimum
  Uncertainty uncertainty;
  long evaluations = 0;                 // residual vectors computed, all phases
  double design_seconds = 0.0, local_seconds = 0.0, jacobian_seconds = 0.0;
};

// Progress: phase ("design", "fit 1/2", ...), iteration, cost, evaluations so far.
using FitProgress = std::function<void(const std::string& phase, int iteration, double cost, long evaluations)>;

FitResult fit(const LeastSquaresProblem& problem, const OptimizerSettings& settings, const FitProgress& progress = {});

// Forward-difference Jacobian in physical units at theta, steps `step` in the scaled variables.
Eigen::MatrixXd jacobian(const LeastSquaresProblem& problem, const BoundTransform& transform, const Eigen::VectorXd& theta,
                         const Eigen::VectorXd& r0, double step);

// Covariance s^2 (J^T J)^-1 with s^2 = r.r / (N - p), standard errors, 95 % intervals (Student t)
// and correlations; directions that J does not see (singular values below 1e-10 of the largest
// after column scaling) get NaN.
Uncertainty uncertainty(const Eigen::MatrixXd& J, const Eigen::VectorXd& r, const Eigen::VectorXd& theta,
                        const Eigen::VectorXd& lower, const Eigen::VectorXd& upper);

}  // namespace acst::calibration
