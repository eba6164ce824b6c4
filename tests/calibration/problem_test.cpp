// The calibration problem on the bundled lab files: runs in parallel give the same residuals as
// one thread, a failed element test is a finite penalty, and the residuals are the normalised
// differences the report states (checked against an independent interpolation of one point).
#include <gtest/gtest.h>

#include <cmath>

#include "acst_calibration/fit_spec.hpp"
#include "acst_calibration/problem.hpp"
#include "acst_driver/lab_data.hpp"

namespace acst::calibration::calibration_problem_test {
namespace {

using nlohmann::json;

const std::string base_dir = std::string(ACST_SOURCE_DIR) + "/data/calibration";

FitSpec spec(int threads, const json& integrator = json::object()) {
  json j = {{"material", {{"file", "../parameters/toyoura_acst_guide.json"}}},
            {"parameters", {{"h1", {{"bounds", {0.05, 3.0}}}}}},
            {"defaults", {{"strain_increment_pct", 0.1}}},
            {"experiments",
             {{{"data", "../lab/fukushima_tatsuoka_1984/ft84_fig5a_sc2p0.csv"}, {"void_ratio_at_kPa", 29.4}},
              {{"data", "../lab/chen_yang_2025/wang33_HKU_TMD7.csv"}},
              {{"data", "../lab/lam_tatsuoka_1988/phi_vs_b.csv"}, {"test", "peak_friction"}, {"rows", {{"xi_deg", {90}}, {"omega_deg", {0, 90}}}}}}},
            {"optimizer", {{"threads", threads}}}};
  if (!integrator.empty()) j["material"]["integrator"] = integrator;
  return parse_fit_spec(j.dump(), base_dir, "t");
}

TEST(CalibrationProblem, ParallelRunsEqualOneThread) {
  const Problem one(spec(1)), two(spec(2));
  const Eigen::VectorXd a = Eigen::VectorXd::Constant(1, 0.44), b = Eigen::VectorXd::Constant(1, 0.8);
  const auto r1 = one.residuals({a, b});
  const auto r2 = two.residuals({a, b});
  ASSERT_EQ(r1.size(), 2u);
  EXPECT_EQ(r1[0], r2[0]);  // bit for bit: each run is independent of the thread that ran it
  EXPECT_EQ(r1[1], r2[1]);
  EXPECT_GT((r1[0] - r1[1]).norm(), 0.0);  // and h1 matters
}

TEST(CalibrationProblem, FailedRunIsAFinitePenalty) {
  // One substep per increment at a tolerance no step meets: every element test fails.
  const Problem p(spec(2, {{"max_substeps", 1}, {"stol", 1e-12}}));
  std::vector<TestRunOutcome> outcomes;
  const Eigen::VectorXd r = p.residuals(Eigen::VectorXd::Constant(1, 0.44), outcomes);
  for (const auto& o : outcomes) EXPECT_FALSE(o.ok);
  Eigen::Index at = 0;
  for (std::size_t k = 0; k < p.spec().experiments.size(); ++k)
    for (const Series& s : p.series(k))
      for (std::size_t i = 0; i < s.x.size(); ++i, ++at)
        EXPECT_DOUBLE_EQ(r[at], p.spec().optimizer.penalty * std::sqrt(s.point_weight));
  EXPECT_EQ(at, r.size());
}

TEST(CalibrationProblem, ResidualIsTheWeightedNormalisedDifference) {
  const Problem p(spec(2));
  std::vector<TestRunOutcome> outcomes;
  const Eigen::VectorXd r = p.residuals(Eigen::VectorXd::Constant(1, 0.44), outcomes);
  const auto& o = outcomes[p.test_runs_of(0).front()];
  ASSERT_TRUE(o.ok) << o.message;
  // First stress point of the first test, interpolated here by hand between the two run rows around it.
  const Series& s = p.series(0).front();
  const double x = s.x.front();
  std::size_t i = 1;
  while (o.eps_a_pct[i] < x) ++i;
  const double w = (x - o.eps_a_pct[i - 1]) / (o.eps_a_pct[i] - o.eps_a_pct[i - 1]);
  const double simulated = (1 - w) * o.stress[i - 1] + w * o.stress[i];
  EXPECT_NEAR(r[0], std::sqrt(s.point_weight) * (simulated - s.measured.front()) / s.scale, 1e-12);
  // The scale is the measured range of sigma1'/sigma3' inside the strain range of the file.
  const driver::LabCurve lab = driver::read_lab_curve(p.spec().experiments[0].data_file);
  double lo = INFINITY, hi = -INFINITY;
  const auto ea = lab.column("eps_a_pct"), sr = lab.column("stress_ratio");
  for (std::size_t k = 0; k < ea.size(); ++k)
    if (!std::isnan(sr[k]) && ea[k] > 0.0 && ea[k] >= 0.7061 && ea[k] <= 13.5) {
      lo = std::min(lo, sr[k]);
      hi = std::max(hi, sr[k]);
    }
  EXPECT_DOUBLE_EQ(s.scale, hi - lo);
  // The table rows: peak friction angles between 30 and 55 deg, as a sand's must be.
  for (std::size_t k : p.test_runs_of(2)) {
    EXPECT_GT(outcomes[k].peak_phi_deg, 30.0);
    EXPECT_LT(outcomes[k].peak_phi_deg, 55.0);
  }
  EXPECT_EQ(p.test_runs_of(2).size(), 6u);  // TC, PSC, TE at omega 0 and 90
}

}  // namespace
}  // namespace acst::calibration::calibration_problem_test
