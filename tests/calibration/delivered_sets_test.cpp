// The calibrated Toyoura sets committed in data/parameters reproduce the objective their
// committed reports state, from a fresh clone: the fit descriptions, the lab files, the sets and
// the reports belong together.
#include <gtest/gtest.h>

#include <cmath>

#include "acst_calibration/fit_spec.hpp"
#include "acst_calibration/problem.hpp"
#include "test_materials.hpp"

namespace acst::calibration {
namespace {

using nlohmann::json;

struct Delivered {
  const char* name;
  const char* set;  // main parameter file; per-group files are set + "_" + group
};

class DeliveredSet : public ::testing::TestWithParam<Delivered> {};

TEST_P(DeliveredSet, ReproducesItsReport) {
  const Delivered d = GetParam();
  const FitSpec spec = read_fit_spec(std::string(ACST_SOURCE_DIR) + "/data/calibration/" + d.name + "_fit.json");
  const Problem problem(spec);
  const json report = json::parse(test::read_text(std::string("data/calibration/reports/") + d.name + "/" + d.name + "_report.json"));
  Eigen::VectorXd theta(static_cast<Eigen::Index>(problem.variables().size()));
  for (std::size_t j = 0; j < problem.variables().size(); ++j) {
    const FitVariable& v = problem.variables()[j];
    const bool own_file = !v.group.empty() && v.group != spec.reference_group;
    const json set = json::parse(test::read_text(std::string("data/parameters/") + d.set + (own_file ? "_" + v.group : "") + ".json"));
    theta[static_cast<Eigen::Index>(j)] = set["parameters"][v.parameter].get<double>();
    EXPECT_DOUBLE_EQ(theta[static_cast<Eigen::Index>(j)], report["parameters"][j]["value"].get<double>()) << v.label;
  }
  const double cost = problem.residuals({theta}).front().squaredNorm();
  EXPECT_NEAR(cost, report["objective"]["sum_of_squares"].get<double>(), 1e-6 * cost);
  EXPECT_EQ(report["experiments"].size(), spec.experiments.size());
}

INSTANTIATE_TEST_SUITE_P(Toyoura, DeliveredSet,
                         ::testing::Values(Delivered{"toyoura_acst", "toyoura_acst_calibrated"},
                                           Delivered{"toyoura_acst_li2002", "toyoura_acst_li2002_calibrated"},
                                           Delivered{"toyoura_isotropic", "toyoura_isotropic_calibrated"}));

// A candidate keeps its report (and only the reference group's set): the values the report
// states give the objective it states, closings, Table 1 peaks and a free critical state line included.
class CandidateReport : public ::testing::TestWithParam<std::string> {};

TEST_P(CandidateReport, ReproducesItsObjective) {
  const std::string name = GetParam();
  const FitSpec spec = read_fit_spec(std::string(ACST_SOURCE_DIR) + "/data/calibration/" + name + "_fit.json");
  const Problem problem(spec);
  const json report = json::parse(test::read_text("data/calibration/reports/" + name + "/" + name + "_report.json"));
  ASSERT_EQ(report["parameters"].size(), problem.variables().size());
  Eigen::VectorXd theta(static_cast<Eigen::Index>(problem.variables().size()));
  for (std::size_t j = 0; j < problem.variables().size(); ++j) {
    ASSERT_EQ(report["parameters"][j]["label"].get<std::string>(), problem.variables()[j].label);
    theta[static_cast<Eigen::Index>(j)] = report["parameters"][j]["value"].get<double>();
  }
  // The kept set is the report's values of the Tatsuoka specimens.
  const json kept = json::parse(test::read_text("data/calibration/reports/" + name + "/" + name + "_parameters_tatsuoka.json"));
  const Parameters tatsuoka = problem.parameters(theta, "tatsuoka");
  for (const FitVariable& v : problem.variables())
    if (v.group.empty() || v.group == "tatsuoka") {
      EXPECT_DOUBLE_EQ(kept["parameters"][v.parameter].get<double>(), tatsuoka.*parameter_info(v.parameter)->member) << v.label;
    }
  const double cost = problem.residuals({theta}).front().squaredNorm();
  EXPECT_NEAR(cost, report["objective"]["sum_of_squares"].get<double>(), 1e-6 * cost);
}

INSTANTIATE_TEST_SUITE_P(Toyoura, CandidateReport,
                         ::testing::Values("toyoura_acst_closing", "toyoura_acst_table1_line", "toyoura_acst_table1_slope"));

}  // namespace
}  // namespace acst::calibration
