// Bounded nonlinear least squares with GSL's trust-region solver, a multi-start design and the
// covariance at the optimum (see least_squares.hpp).
#include "acst_calibration/least_squares.hpp"

#include <gsl/gsl_cdf.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>

#include <Eigen/SVD>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <random>
#include <sstream>

namespace acst::calibration {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// What the GSL callbacks share: the problem, the transform and the last evaluated point.
struct Session {
  Session(const LeastSquaresProblem* p, const BoundTransform* t, double step) : problem(p), transform(t), fd_step(step) {}
  const LeastSquaresProblem* problem;
  const BoundTransform* transform;
  double fd_step;
  long evaluations = 0;
  Eigen::VectorXd last_u, last_r;
};

Eigen::VectorXd to_eigen(const gsl_vector* v) {
  Eigen::VectorXd e(static_cast<Eigen::Index>(v->size));
  for (std::size_t i = 0; i < v->size; ++i) e[static_cast<Eigen::Index>(i)] = gsl_vector_get(v, i);
  return e;
}

Eigen::VectorXd residual_at(Session& s, const Eigen::VectorXd& u) {
  if (s.last_u.size() == u.size() && s.last_u == u) return s.last_r;
  s.last_r = s.problem->residuals({s.transform->to_physical(u)}).front();
  s.last_u = u;
  ++s.evaluations;
  return s.last_r;
}

int gsl_f(const gsl_vector* x, void* data, gsl_vector* f) {
  Session& s = *static_cast<Session*>(data);
  const Eigen::VectorXd r = residual_at(s, to_eigen(x));
  for (Eigen::Index i = 0; i < r.size(); ++i) gsl_vector_set(f, static_cast<std::size_t>(i), r[i]);
  return GSL_SUCCESS;
}

// Forward differences in the scaled variables, all columns evaluated in one parallel batch.
Eigen::MatrixXd scaled_jacobian(Session& s, const Eigen::VectorXd& u, const Eigen::VectorXd& r0) {
  std::vector<Eigen::VectorXd> points;
  std::vector<double> steps;
  for (Eigen::Index j = 0; j < u.size(); ++j) {
    Eigen::VectorXd v = u;
    const double h = s.fd_step * std::max(1.0, std::abs(u[j]));
    v[j] += h;
    steps.push_back(v[j] - u[j]);
    points.push_back(s.transform->to_physical(v));
  }
  const std::vector<Eigen::VectorXd> r = s.problem->residuals(points);
  s.evaluations += static_cast<long>(points.size());
  Eigen::MatrixXd J(r0.size(), u.size());
  for (Eigen::Index j = 0; j < u.size(); ++j) J.col(j) = (r[static_cast<std::size_t>(j)] - r0) / steps[static_cast<std::size_t>(j)];
  return J;
}

int gsl_df(const gsl_vector* x, void* data, gsl_matrix* J) {
  Session& s = *static_cast<Session*>(data);
  const Eigen::VectorXd u = to_eigen(x);
  const Eigen::MatrixXd Ju = scaled_jacobian(s, u, residual_at(s, u));
  for (Eigen::Index i = 0; i < Ju.rows(); ++i)
    for (Eigen::Index j = 0; j < Ju.cols(); ++j) gsl_matrix_set(J, static_cast<std::size_t>(i), static_cast<std::size_t>(j), Ju(i, j));
  return GSL_SUCCESS;
}

struct CallbackData {
  const FitProgress* progress;
  std::string phase;
  Session* session;
};

double cost_of(const gsl_multifit_nlinear_workspace* w) {
  const gsl_vector* f = gsl_multifit_nlinear_residual(w);
  double cost = 0.0;
  for (std::size_t i = 0; i < f->size; ++i) cost += gsl_vector_get(f, i) * gsl_vector_get(f, i);
  return cost;
}

void report_progress(const CallbackData& c, std::size_t iteration, const gsl_multifit_nlinear_workspace* w) {
  if (*c.progress) (*c.progress)(c.phase, static_cast<int>(iteration), cost_of(w), c.session->evaluations);
}

// gsl_multifit_nlinear_driver (GSL 2.7, multifit_nlinear/fdf.c) step for step, so a fit is the
// same iterates either way, with one addition: a fit whose cost after `abandon_after` iterations
// is still above `abandon_above` is stopped (*abandoned): a bet that a fit that far behind the
// best after that many steps would not overtake it, which saves the evaluations it would spend.
int drive(gsl_multifit_nlinear_workspace* w, const OptimizerSettings& o, const CallbackData& cb, double abandon_above,
          int* info, bool* abandoned) {
  const std::size_t max_iterations = static_cast<std::size_t>(o.max_iterations);
  std::size_t iter = 0;
  int status = GSL_CONTINUE;
  *abandoned = false;
  report_progress(cb, iter, w);
  do {
    status = gsl_multifit_nlinear_iterate(w);
    if (status == GSL_ENOPROG && iter == 0) {  // not one step lowered the cost: more will not help
      *info = status;
      return GSL_EMAXITER;
    }
    ++iter;
    report_progress(cb, iter, w);
    status = gsl_multifit_nlinear_test(o.xtol, o.gtol, o.ftol, info, w);
    if (status == GSL_CONTINUE && iter >= static_cast<std::size_t>(o.abandon_after) && cost_of(w) > abandon_above) {
      *abandoned = true;
      return GSL_SUCCESS;
    }
  } while (status == GSL_CONTINUE && iter < max_iterations);
  if (status == GSL_ETOLF || status == GSL_ETOLX || status == GSL_ETOLG) {
    *info = status;
    status = GSL_SUCCESS;
  }
  if (iter >= max_iterations && status != GSL_SUCCESS) status = GSL_EMAXITER;
  return status;
}

std::string stop_reason(int status, int info) {
  if (status == GSL_EMAXITER) return "iteration limit";
  if (status == GSL_ENOPROG) return "no further progress (trust region collapsed)";
  if (status != GSL_SUCCESS) return std::string("GSL: ") + gsl_strerror(status);
  return info == 1 ? "small step (xtol)" : info == 2 ? "small gradient (gtol)" : "converged";
}

std::string abandon_reason(double factor, int iterations) {
  std::ostringstream s;
  s << "abandoned: cost above " << factor << " x the best before it after " << iterations
    << (iterations == 1 ? " iteration" : " iterations");
  return s.str();
}

LocalFit local_fit(const LeastSquaresProblem& problem, const BoundTransform& transform, const OptimizerSettings& o,
                   const Eigen::VectorXd& from, double abandon_above, const std::string& phase, const FitProgress& progress) {
  const std::size_t n = static_cast<std::size_t>(problem.residual_count), p = static_cast<std::size_t>(from.size());
  Session session(&problem, &transform, o.fd_step);
  gsl_multifit_nlinear_parameters params = gsl_multifit_nlinear_default_parameters();
  params.trs = gsl_multifit_nlinear_trs_lm;
  params.scale = gsl_multifit_nlinear_scale_more;
  gsl_multifit_nlinear_workspace* w = gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &params, n, p);
  gsl_multifit_nlinear_fdf fdf;
  fdf.f = gsl_f;
  fdf.df = gsl_df;
  fdf.fvv = nullptr;
  fdf.n = n;
  fdf.p = p;
  fdf.params = &session;
  const Eigen::VectorXd u0 = transform.to_scaled(from);
  gsl_vector* x0 = gsl_vector_alloc(p);
  for (std::size_t i = 0; i < p; ++i) gsl_vector_set(x0, i, u0[static_cast<Eigen::Index>(i)]);
  LocalFit fit;
  fit.from = from;
  fit.start_cost = residual_at(session, u0).squaredNorm();
  gsl_multifit_nlinear_init(x0, &fdf, w);
  CallbackData cb{&progress, phase, &session};
  int info = 0;
  bool abandoned = false;
  const int status = drive(w, o, cb, abandon_above, &info, &abandoned);
  const Eigen::VectorXd u = to_eigen(gsl_multifit_nlinear_position(w));
  fit.theta = transform.to_physical(u);
  fit.cost = to_eigen(gsl_multifit_nlinear_residual(w)).squaredNorm();
  fit.iterations = static_cast<int>(gsl_multifit_nlinear_niter(w));
  fit.evaluations = session.evaluations;
  fit.abandoned = abandoned;
  fit.stop = abandoned ? abandon_reason(o.abandon_factor, fit.iterations)
                       : stop_reason(status, info);
  gsl_vector_free(x0);
  gsl_multifit_nlinear_free(w);
  return fit;
}

// Latin hypercube in the scaled variables, each coordinate in the middle 80 % of its range.
std::vector<Eigen::VectorXd> design(const BoundTransform& t, int points, unsigned seed) {
  const Eigen::Index p = t.lower.size();
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Eigen::VectorXd> u(static_cast<std::size_t>(points), Eigen::VectorXd(p));
  for (Eigen::Index j = 0; j < p; ++j) {
    std::vector<int> strata(static_cast<std::size_t>(points));
    std::iota(strata.begin(), strata.end(), 0);
    std::shuffle(strata.begin(), strata.end(), rng);
    for (int k = 0; k < points; ++k) {
      const double q = 0.1 + 0.8 * (strata[static_cast<std::size_t>(k)] + unit(rng)) / points;
      u[static_cast<std::size_t>(k)][j] = std::log(q / (1.0 - q));
    }
  }
  std::vector<Eigen::VectorXd> theta;
  for (const auto& v : u) theta.push_back(t.to_physical(v));
  return theta;
}

}  // namespace

Eigen::VectorXd BoundTransform::to_scaled(const Eigen::VectorXd& theta) const {
  Eigen::VectorXd u(theta.size());
  for (Eigen::Index i = 0; i < theta.size(); ++i) {
    const double q = std::clamp((theta[i] - lower[i]) / (upper[i] - lower[i]), 1e-12, 1.0 - 1e-12);
    u[i] = std::log(q / (1.0 - q));
  }
  return u;
}

Eigen::VectorXd BoundTransform::to_physical(const Eigen::VectorXd& u) const {
  Eigen::VectorXd theta(u.size());
  for (Eigen::Index i = 0; i < u.size(); ++i) theta[i] = lower[i] + (upper[i] - lower[i]) / (1.0 + std::exp(-u[i]));
  return theta;
}

Eigen::VectorXd BoundTransform::derivative(const Eigen::VectorXd& u) const {
  Eigen::VectorXd d(u.size());
  for (Eigen::Index i = 0; i < u.size(); ++i) {
    const double s = 1.0 / (1.0 + std::exp(-u[i]));
    d[i] = (upper[i] - lower[i]) * s * (1.0 - s);
  }
  return d;
}

Eigen::MatrixXd jacobian(const LeastSquaresProblem& problem, const BoundTransform& transform, const Eigen::VectorXd& theta,
                         const Eigen::VectorXd& r0, double step) {
  Session s(&problem, &transform, step);
  const Eigen::VectorXd u = transform.to_scaled(theta);
  const Eigen::MatrixXd Ju = scaled_jacobian(s, u, r0);
  return Ju * transform.derivative(u).cwiseInverse().asDiagonal();
}

Uncertainty uncertainty(const Eigen::MatrixXd& J, const Eigen::VectorXd& r, const Eigen::VectorXd& theta,
                        const Eigen::VectorXd& lower, const Eigen::VectorXd& upper) {
  const Eigen::Index n = J.rows(), p = J.cols();
  Uncertainty u;
  u.degrees_of_freedom = static_cast<int>(std::max<Eigen::Index>(1, n - p));
  u.residual_variance = r.squaredNorm() / u.degrees_of_freedom;
  Eigen::VectorXd c = J.colwise().norm().transpose();
  for (Eigen::Index j = 0; j < p; ++j)
    if (!(c[j] > 0.0)) c[j] = 1.0;  // a parameter without effect: its singular value is zero
  const Eigen::MatrixXd Js = J * c.cwiseInverse().asDiagonal();
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(Js, Eigen::ComputeThinV);
  const Eigen::VectorXd sv = svd.singularValues();
  const Eigen::MatrixXd& V = svd.matrixV();
  std::vector<bool> unseen(static_cast<std::size_t>(p), false);
  Eigen::VectorXd inv_sq = Eigen::VectorXd::Zero(p);
  for (Eigen::Index i = 0; i < p; ++i) {
    if (sv[i] > 1e-10 * sv[0]) {
      inv_sq[i] = 1.0 / (sv[i] * sv[i]);
    } else {
      for (Eigen::Index j = 0; j < p; ++j)
        if (std::abs(V(j, i)) > 1e-3) unseen[static_cast<std::size_t>(j)] = true;
    }
  }
  u.condition_number = sv[p - 1] > 0.0 ? (sv[0] * sv[0]) / (sv[p - 1] * sv[p - 1]) : INFINITY;
  u.covariance = u.residual_variance * c.cwiseInverse().asDiagonal() * V * inv_sq.asDiagonal() * V.transpose() *
                 c.cwiseInverse().asDiagonal();
  const double t = gsl_cdf_tdist_Pinv(0.975, u.degrees_of_freedom);
  u.standard_error.resize(p);
  u.ci95_lower.resize(p);
  u.ci95_upper.resize(p);
  u.correlation.resize(p, p);
  u.at_bound.resize(static_cast<std::size_t>(p));
  for (Eigen::Index j = 0; j < p; ++j) {
    const double se = unseen[static_cast<std::size_t>(j)] ? NAN : std::sqrt(std::max(0.0, u.covariance(j, j)));
    u.standard_error[j] = se;
    u.ci95_lower[j] = theta[j] - t * se;
    u.ci95_upper[j] = theta[j] + t * se;
    const double q = (theta[j] - lower[j]) / (upper[j] - lower[j]);
    u.at_bound[static_cast<std::size_t>(j)] = q < 1e-3 || q > 1.0 - 1e-3;
  }
  for (Eigen::Index i = 0; i < p; ++i)
    for (Eigen::Index j = 0; j < p; ++j)
      u.correlation(i, j) = u.covariance(i, j) / std::sqrt(u.covariance(i, i) * u.covariance(j, j));
  return u;
}

FitResult fit(const LeastSquaresProblem& problem, const OptimizerSettings& o, const FitProgress& progress) {
  // GSL's default error handler aborts; this library reports statuses instead.
  gsl_set_error_handler_off();
  const BoundTransform transform{problem.lower, problem.upper};
  FitResult result;
  if (problem.residual_count < problem.start.size())
    throw common::InputError("/parameters: " + std::to_string(problem.start.size()) + " fitted values but only " +
                   std::to_string(problem.residual_count) + " measured points");

  auto t0 = std::chrono::steady_clock::now();
  if (problem.start.size() == 0) {  // nothing to fit: the material as given, evaluated once
    result.theta = problem.start;
    result.residuals = problem.residuals({result.theta}).front();
    result.cost = result.residuals.squaredNorm();
    result.evaluations = 1;
    result.local_seconds = seconds_since(t0);
    return result;
  }
  std::vector<Eigen::VectorXd> candidates{problem.start};
  if (o.design_points > 0) {
    result.design = design(transform, o.design_points, o.seed);
    if (progress) progress("design", 0, NAN, 0);
    const std::vector<Eigen::VectorXd> r = problem.residuals(result.design);
    result.evaluations += static_cast<long>(r.size());
    for (const auto& v : r) result.design_costs.push_back(v.squaredNorm());
    std::vector<std::size_t> order(r.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return result.design_costs[a] < result.design_costs[b]; });
    for (std::size_t k = 0; k + 1 < static_cast<std::size_t>(o.starts) && k < order.size(); ++k)
      candidates.push_back(result.design[order[k]]);
  }
  result.design_seconds = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  for (std::size_t k = 0; k < candidates.size(); ++k) {
    const std::string phase = "fit " + std::to_string(k + 1) + "/" + std::to_string(candidates.size());
    const double abandon_above = k > 0 && o.abandon_factor > 0.0 ? o.abandon_factor * result.local_fits[result.best].cost : INFINITY;
    result.local_fits.push_back(local_fit(problem, transform, o, candidates[k], abandon_above, phase, progress));
    result.evaluations += result.local_fits.back().evaluations;
    if (result.local_fits.back().cost < result.local_fits[result.best].cost) result.best = k;
  }
  result.local_seconds = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  result.theta = result.local_fits[result.best].theta;
  result.residuals = problem.residuals({result.theta}).front();
  result.cost = result.residuals.squaredNorm();
  result.jacobian = jacobian(problem, transform, result.theta, result.residuals, o.fd_step);
  result.evaluations += 1 + problem.start.size();
  result.uncertainty = uncertainty(result.jacobian, result.residuals, result.theta, problem.lower, problem.upper);
  result.jacobian_seconds = seconds_since(t0);
  return result;
}

}  // namespace acst::calibration
