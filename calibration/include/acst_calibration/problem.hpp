#pragma once
// The calibration problem: the fitted variables (a shared parameter, or one value per group of
// experiments), the driver runs that one evaluation needs, and the weighted residuals against
// the measured points (docs/calibration.md, "Objective").
//
// Residual of a curve point:  sqrt(w_type w_test w_axis / n_points) (simulated - measured) / range
// with `range` the measured range of that series inside the strain range (floored, see
// series_scale), so that the sum of squares is a weighted mean of squared normalised errors and
// the weights of the types, of the tests inside a type and of the two axes each sum to one.
// A gap_closing test has one residual, sqrt(w_type w_test) (simulated - measured) / scale, with the
// closings computed alike from the two simulated and the two measured curves (gap_closing) and
// the description's scale (default 1: a closing runs from 1, the gap kept, to 0, the gap gone).
// A failed or too short simulation gives `penalty` instead of the normalised error: large and
// finite, never an exception.
#include <Eigen/Core>
#include <atomic>
#include <string>
#include <vector>

#include "acst/parameters.hpp"
#include "acst_calibration/fit_spec.hpp"
#include "acst_driver/runner.hpp"
#include "acst_driver/scene.hpp"

namespace acst::calibration {

// One variable of the least-squares problem: a fitted material constant, shared by all
// experiments or one group's own.
struct FitVariable {
  std::string parameter;  // material constant
  std::string group;      // "" when shared by all experiments
  std::string label;      // "F0" or "F0[tatsuoka]"
  double start = 0.0, lower = 0.0, upper = 0.0;
};

// Measured points of one axis of one experiment, inside its strain range (a gap_closing test: its
// one closing, at the second strain).
struct Series {
  Axis axis = Axis::stress;
  std::vector<double> x;       // axial strain % (curves, closings) or table row index (tables)
  std::vector<double> measured;
  double scale = 1.0;          // normalising range
  double point_weight = 0.0;   // w_type w_test w_axis / n_points
};

// One element test run by the driver: a whole curve, or one row of a table test.
struct TestRun {
  std::size_t experiment = 0;
  int row = -1;  // table row, -1 for curves
  double b = 0.0, bedding_angle_deg = 0.0;  // of the shearing step
  double sigma3_kPa = 0.0, void_ratio = 0.0;  // the conditions it starts from (a table row: its own)
  driver::ElementScene scene;
  int shear_step = 0;  // index of the shearing step (1 after an isotropic consolidation)
  long increments = 0;
};

// What one run produced, reduced to what the residuals need.
struct TestRunOutcome {
  bool ok = false;
  std::string message;
  std::vector<double> eps_a_pct, stress, eps_v_pct;  // shearing part, from the start of shearing
  double peak_phi_deg = 0.0;
  driver::RunResult run;  // kept only when asked (reports)
};

// Work counters over all evaluations (thread-safe).
struct WorkCounters {
  std::atomic<long> simulations{0}, failed{0}, increments{0}, substeps{0}, iterations{0};
  std::atomic<long long> simulation_ns{0};
};

// A batch of evaluations must fit in the smaller of this and the machine's physical memory.
inline constexpr double max_memory_bytes = 64.0 * 1024 * 1024 * 1024;

class Problem {
 public:
  explicit Problem(const FitSpec& spec);

  const FitSpec& spec() const { return spec_; }
  const std::vector<FitVariable>& variables() const { return variables_; }
  const std::vector<Series>& series(std::size_t experiment) const { return series_[experiment]; }
  const std::vector<TestRun>& test_runs() const { return test_runs_; }
  // Indices into test_runs() of experiment k's runs (a table: one per selected row, in order).
  const std::vector<std::size_t>& test_runs_of(std::size_t k) const { return runs_of_[k]; }
  int residual_count() const { return residual_count_; }
  Eigen::VectorXd start() const;
  Eigen::VectorXd lower() const;
  Eigen::VectorXd upper() const;

  // The material constants of one group at the variable values `theta`.
  Parameters parameters(const Eigen::VectorXd& theta, const std::string& group) const;

  // Residuals at several points; all runs of all points share one pool of `threads` threads.
  std::vector<Eigen::VectorXd> residuals(const std::vector<Eigen::VectorXd>& thetas) const;
  // Residuals at one point, with the outcome of every simulation (for reports).
  Eigen::VectorXd residuals(const Eigen::VectorXd& theta, std::vector<TestRunOutcome>& outcomes) const;

  // The simulated value at point i of series s of experiment k (NaN when the run failed or
  // ended before that strain); outcomes are indexed like test_runs().
  double simulated(std::size_t k, const Series& s, std::size_t i, const std::vector<const TestRunOutcome*>& outcomes) const;
  // (simulated - measured) / scale at point i of s, as the residuals use it: the penalty where the
  // value is not a number, and a closing held within +-penalty.
  double normalised_error(const Series& s, std::size_t i, double simulated) const;

  WorkCounters& counters() const { return counters_; }
  int threads() const { return threads_; }

 private:
  TestRunOutcome simulate(const TestRun& sim, const Eigen::VectorXd& theta, bool keep_run) const;
  void assemble(const std::vector<const TestRunOutcome*>& outcomes, Eigen::VectorXd& r) const;
  void check_size() const;

  FitSpec spec_;
  Parameters base_;
  std::vector<FitVariable> variables_;
  std::vector<std::vector<Series>> series_;     // per experiment
  std::vector<std::vector<std::size_t>> runs_of_;  // per experiment: its test runs
  std::vector<TestRun> test_runs_;
  std::vector<std::size_t> schedule_;           // test runs, longest first
  int residual_count_ = 0;
  int threads_ = 1;
  mutable WorkCounters counters_;
};

// Normalising range of a measured series: max - min, floored at 5 % of max |value| and at an
// absolute floor for the axis (and, on the stress axis, its measure) so that flat series do not
// blow up.
double series_scale(const std::vector<double>& measured, Axis axis, StressMeasure measure);

// The closing of the gap between two sigma1'/sigma3' curves (first minus second) from one axial
// strain to another: gap(to_pct) / gap(from_pct); NaN where a curve does not reach a strain or the
// first gap is zero.
double gap_closing(const std::vector<double>& first_eps_a, const std::vector<double>& first_ratio,
                   const std::vector<double>& second_eps_a, const std::vector<double>& second_ratio, double from_pct,
                   double to_pct);

// Peak friction angle (deg) of a stress state: asin((s1 - s3)/(s1 + s3)) over principal stresses.
double friction_angle_deg(const Sym& stress);

}  // namespace acst::calibration
