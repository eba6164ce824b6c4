// gap_closing tests of a fit description: how the gap in sigma1'/sigma3' between two lab curves
// closes from one axial strain to another, measured from the files and simulated from the two
// runs alike; bad descriptions name their JSON path; a faster fabric closes the bedding gap more.
#include <gtest/gtest.h>

#include <cmath>

#include "acst_calibration/fit_spec.hpp"
#include "acst_calibration/problem.hpp"
#include "acst_driver/lab_data.hpp"

namespace acst::calibration::gap_closing_test {
namespace {

using nlohmann::json;

const std::string base_dir = std::string(ACST_SOURCE_DIR) + "/data/calibration";
const std::string w00 = "../lab/lam_tatsuoka_1988/lt88_fig5a_w00_hw1p0.csv", w90 = "../lab/lam_tatsuoka_1988/lt88_fig5a_w90_hw1p0.csv";

json closing_experiment() {
  return {{"id", "gap_0_90"}, {"test", "gap_closing"}, {"data", {w00, w90}}, {"at_axial_strain_pct", {6, 12}},
          {"scale", 0.5},     {"group", "tatsuoka"},   {"void_ratio_at_kPa", 29.4}};
}

json description(const json& closing = closing_experiment()) {
  return {{"material", {{"file", "../parameters/toyoura_acst_guide.json"}}},
          {"parameters", {{"k_f", {{"bounds", {0.0, 40.0}}}}}},
          {"defaults", {{"strain_increment_pct", 0.1}, {"fit", {"stress"}}}},
          {"experiments", {{{"data", "../lab/fukushima_tatsuoka_1984/ft84_fig5a_sc2p0.csv"}, {"void_ratio_at_kPa", 29.4}}, closing}},
          {"optimizer", {{"threads", 2}}}};
}

// sigma1'/sigma3' of a lab file at `at` % by a plain scan of its rows (linear between the two
// stress-ratio points around it).
double lab_ratio_at(const std::string& file, double at) {
  const driver::LabCurve lab = driver::read_lab_curve(base_dir + "/" + file);
  const auto ea = lab.column("eps_a_pct"), sr = lab.column("stress_ratio");
  double x0 = NAN, y0 = NAN;
  for (std::size_t i = 0; i < ea.size(); ++i) {
    if (std::isnan(sr[i])) continue;
    if (ea[i] >= at) return std::isnan(x0) ? sr[i] : y0 + (sr[i] - y0) * (at - x0) / (ea[i] - x0);
    x0 = ea[i];
    y0 = sr[i];
  }
  return NAN;
}

TEST(GapClosing, ClosedFormOnStraightLines) {
  // first 1 + x, second 1 + x/2: the gap x/2 doubles from 2 to 4 %.
  const std::vector<double> x = {0, 1, 2, 3, 4, 5}, a = {1, 2, 3, 4, 5, 6}, b = {1, 1.5, 2, 2.5, 3, 3.5};
  EXPECT_NEAR(gap_closing(x, a, x, b, 2.0, 4.0), 2.0, 1e-15);
  EXPECT_NEAR(gap_closing(x, a, x, b, 2.5, 3.5), 3.5 / 2.5, 1e-15);
  EXPECT_TRUE(std::isnan(gap_closing(x, a, x, a, 2.0, 4.0)));  // no gap at the first strain
  EXPECT_TRUE(std::isnan(gap_closing(x, a, x, b, 2.0, 6.0)));  // past the curves' end
}

TEST(GapClosing, MeasuredAndSimulatedAlike) {
  const Problem p(parse_fit_spec(description().dump(), base_dir, "t"));
  ASSERT_EQ(p.test_runs_of(1).size(), 2u);
  const Series& s = p.series(1).front();
  ASSERT_EQ(s.axis, Axis::closing);
  const double measured = (lab_ratio_at(w00, 12) - lab_ratio_at(w90, 12)) / (lab_ratio_at(w00, 6) - lab_ratio_at(w90, 6));
  EXPECT_NEAR(s.measured.front(), measured, 1e-12);
  EXPECT_NEAR(s.measured.front(), 0.567, 0.005);  // docs/calibration.md, from the report points in Python
  EXPECT_DOUBLE_EQ(s.scale, 0.5);
  EXPECT_NEAR(s.point_weight, experiment_weight(p.spec(), 1), 1e-15);
  // The runs take each file's conditions: 98 kPa, its void ratio at 29.4 kPa, its bedding angle.
  for (std::size_t t = 0; t < 2; ++t) {
    const TestRun& run = p.test_runs()[p.test_runs_of(1)[t]];
    EXPECT_DOUBLE_EQ(run.sigma3_kPa, 98.0);
    EXPECT_DOUBLE_EQ(run.bedding_angle_deg, t == 0 ? 0.0 : 90.0);
  }

  std::vector<TestRunOutcome> outcomes;
  const Eigen::VectorXd r = p.residuals(Eigen::VectorXd::Constant(1, 2.0), outcomes);
  const TestRunOutcome &a = outcomes[p.test_runs_of(1)[0]], &b = outcomes[p.test_runs_of(1)[1]];
  ASSERT_TRUE(a.ok && b.ok) << a.message << b.message;
  auto at = [](const TestRunOutcome& o, double x) {
    std::size_t i = 1;
    while (o.eps_a_pct[i] < x) ++i;
    const double w = (x - o.eps_a_pct[i - 1]) / (o.eps_a_pct[i] - o.eps_a_pct[i - 1]);
    return (1 - w) * o.stress[i - 1] + w * o.stress[i];
  };
  const double simulated = (at(a, 12) - at(b, 12)) / (at(a, 6) - at(b, 6));
  EXPECT_GT(at(a, 6), at(b, 6));  // the bedding 0 specimen is the stronger one
  EXPECT_NEAR(r[r.size() - 1], std::sqrt(s.point_weight) * (simulated - s.measured.front()) / s.scale, 1e-12);
}

// The fabric that turns faster toward the load (k_f) closes the bedding gap more: the ratio falls.
TEST(GapClosing, FasterFabricClosesTheGapMore) {
  const Problem p(parse_fit_spec(description().dump(), base_dir, "t"));
  std::vector<double> closing;
  for (double k_f : {0.0, 8.0, 20.0}) {
    std::vector<TestRunOutcome> outcomes;
    p.residuals(Eigen::VectorXd::Constant(1, k_f), outcomes);
    std::vector<const TestRunOutcome*> view;
    for (const auto& o : outcomes) view.push_back(&o);
    closing.push_back(p.simulated(1, p.series(1).front(), 0, view));
  }
  EXPECT_GT(closing[0] - closing[1], 0.1) << closing[0] << " " << closing[1];
  EXPECT_GT(closing[1] - closing[2], 0.05) << closing[1] << " " << closing[2];
  EXPECT_LT(closing[0], 1.2);  // without rotation the gap does not open much either
}

TEST(GapClosing, FailedRunIsTheBoundedPenalty) {
  json d = description();
  d["material"]["integrator"] = {{"max_substeps", 1}, {"stol", 1e-12}};
  const Problem p(parse_fit_spec(d.dump(), base_dir, "t"));
  std::vector<TestRunOutcome> outcomes;
  const Eigen::VectorXd r = p.residuals(Eigen::VectorXd::Constant(1, 2.0), outcomes);
  EXPECT_DOUBLE_EQ(r[r.size() - 1], p.spec().optimizer.penalty * std::sqrt(p.series(1).front().point_weight));
}

std::string error_of(const json& closing) {
  try {
    Problem p(parse_fit_spec(description(closing).dump(), base_dir, "t"));
  } catch (const acst::common::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(GapClosing, BadDescriptionsNameThePath) {
  auto with = [](const char* key, const json& v) {
    json c = closing_experiment();
    if (v.is_null()) c.erase(key);
    else c[key] = v;
    return c;
  };
  struct Case {
    json closing;
    const char* path;
    const char* says;
  };
  const Case cases[] = {
      {with("id", nullptr), "/experiments/1/id", "required"},
      {with("data", json::array({w00})), "/experiments/1/data", "[FIRST, SECOND]"},
      {with("data", json::array({w00, 3})), "/experiments/1/data/1", "file name"},
      {with("data", json::array({w00, "../lab/none.csv"})), "/experiments/1/data/1", "cannot open"},
      {with("data", json::array({w00, "../lab/lam_tatsuoka_1988/phi_vs_b.csv"})), "/experiments/1/data/1", "does not name a test"},
      {with("at_axial_strain_pct", json::array({12, 6})), "/experiments/1/at_axial_strain_pct", "0 < FROM < TO"},
      {with("at_axial_strain_pct", json::array({6, 30})), "/experiments/1/at_axial_strain_pct", "both curves must hold"},
      {with("at_axial_strain_pct", nullptr), "/experiments/1/at_axial_strain_pct", "required"},
      {with("scale", 0), "/experiments/1/scale", "out of range"},
      {with("fit", json::array({"stress"})), "/experiments/1/fit", "unknown key"},
      {with("void_ratio_at_kPa", 500), "/experiments/1/data/0", "void_ratio_at_kPa"},
      {with("data", json::array({w00, w00})), "/experiments/1/data", "no gap"},
  };
  for (const Case& c : cases) {
    const std::string e = error_of(c.closing);
    EXPECT_NE(e.find(c.path), std::string::npos) << c.closing.dump() << "\n" << e;
    EXPECT_NE(e.find(c.says), std::string::npos) << c.closing.dump() << "\n" << e;
  }
  // In /defaults a test type gap_closing would turn every curve into one: refused.
  json d = description();
  d["defaults"]["test"] = "gap_closing";
  try {
    parse_fit_spec(d.dump(), base_dir, "t");
    ADD_FAILURE() << "no error";
  } catch (const acst::common::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/defaults/test"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace acst::calibration::gap_closing_test
