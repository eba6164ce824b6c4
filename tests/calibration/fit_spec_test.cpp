// Fit descriptions: bad input is reported with the JSON path and what is allowed, nothing is
// run or written; weights are normalised per type and per test.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "acst_calibration/cli.hpp"
#include "acst_calibration/fit_spec.hpp"
#include "acst_calibration/problem.hpp"

namespace acst::calibration::calibration_fit_spec_test {
namespace {

const std::string base_dir = std::string(ACST_SOURCE_DIR) + "/data/calibration";

// A valid description; `patch` replaces text in it to make it invalid.
std::string description(const std::string& from = "", const std::string& to = "") {
  std::string s = R"({
    "material": {"file": "../parameters/toyoura_acst_guide.json"},
    "parameters": {"d1": {"start": 0.5, "bounds": [0.1, 2.0]}, "F0": {"bounds": [0.0, 0.9], "per_group": true}},
    "experiments": [
      {"data": "../lab/fukushima_tatsuoka_1984/ft84_fig5a_sc1p0.csv", "group": "a", "void_ratio_at_kPa": 29.4},
      {"data": "../lab/verdugo_ishihara_1996/wang34_Tokyo_TMD5.csv", "group": "b", "weight": 3},
      {"data": "../lab/lam_tatsuoka_1988/lt88_fig9_psc_w00_hw1p0.csv", "group": "a"},
      {"data": "../lab/lam_tatsuoka_1988/phi_vs_b.csv", "test": "peak_friction", "rows": {"xi_deg": [90], "omega_deg": [0]}, "group": "a"}
    ],
    "weights": {"types": {"drained_triaxial_compression": 2, "plane_strain_compression": 1, "peak_friction": 1}}
  })";
  if (!from.empty()) {
    const auto at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) s.replace(at, from.size(), to);
  }
  return s;
}

// The error message of an invalid description (empty if it is valid).
std::string error_of(const std::string& text) {
  try {
    parse_fit_spec(text, base_dir, "t");
  } catch (const acst::common::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(FitSpec, ValidDescriptionAndNormalisedWeights) {
  const FitSpec s = parse_fit_spec(description(), base_dir, "t");
  ASSERT_EQ(s.experiments.size(), 4u);
  EXPECT_EQ(s.experiments[0].test, TestType::drained_triaxial_compression);  // from the file's kind: TC
  EXPECT_EQ(s.experiments[2].test, TestType::plane_strain_compression);      // kind: PSC
  EXPECT_DOUBLE_EQ(s.experiments[0].sigma3_kPa, 98.0);                       // from the file's header
  EXPECT_DOUBLE_EQ(s.experiments[0].void_ratio, 0.671);
  EXPECT_EQ(s.groups, (std::vector<std::string>{"a", "b"}));
  EXPECT_NEAR(s.type_weights.at(TestType::drained_triaxial_compression), 0.5, 1e-15);
  double total = 0.0;
  for (std::size_t k = 0; k < s.experiments.size(); ++k) total += experiment_weight(s, k);
  EXPECT_NEAR(total, 1.0, 1e-14);
  // Inside a type the relative weights 1 and 3 become 1/4 and 3/4 of the type's 0.5.
  EXPECT_NEAR(experiment_weight(s, 0), 0.125, 1e-15);
  EXPECT_NEAR(experiment_weight(s, 1), 0.375, 1e-15);

  // The points' weights of a whole problem sum to one as well (each axis of each test).
  const Problem p(s);
  double points = 0.0;
  for (std::size_t k = 0; k < s.experiments.size(); ++k)
    for (const Series& ser : p.series(k)) points += ser.point_weight * static_cast<double>(ser.x.size());
  EXPECT_NEAR(points, 1.0, 1e-12);
  EXPECT_EQ(p.variables().size(), 3u);  // d1, F0[a], F0[b]
  EXPECT_EQ(p.test_runs().size(), 6u);  // 3 curves + the table rows with xi 90 and omega 0 (TC, PSC, TE)
}

// max_cutbacks from the defaults or the experiment reaches the scene of every run built from it
// (the driver's solver/max_cutbacks); without it a run has no limit.
TEST(FitSpec, MaxCutbacksReachesEveryRunsScene) {
  const FitSpec none = parse_fit_spec(description(), base_dir, "t");
  const Problem unlimited(none);
  for (const TestRun& sim : unlimited.test_runs()) EXPECT_EQ(sim.scene.solver.max_cutbacks, 0);
  std::string text = description("\"weights\"", "\"defaults\": {\"max_cutbacks\": 700}, \"weights\"");
  const std::string second = "\"group\": \"b\", \"weight\": 3";
  text.replace(text.find(second), second.size(), second + ", \"max_cutbacks\": 9");
  const FitSpec s = parse_fit_spec(text, base_dir, "t");
  const Problem p(s);
  for (std::size_t k = 0; k < s.experiments.size(); ++k)
    for (std::size_t i : p.test_runs_of(k)) EXPECT_EQ(p.test_runs()[i].scene.solver.max_cutbacks, k == 1 ? 9 : 700) << k;
}

struct BadCase {
  const char* from;
  const char* to;
  const char* path;
  const char* says;
};

class FitSpecErrors : public ::testing::TestWithParam<BadCase> {};

TEST_P(FitSpecErrors, NamePathAndReason) {
  const BadCase& c = GetParam();
  const std::string e = error_of(description(c.from, c.to));
  EXPECT_NE(e.find(c.path), std::string::npos) << e;
  EXPECT_NE(e.find(c.says), std::string::npos) << e;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, FitSpecErrors,
    ::testing::Values(
        BadCase{"ft84_fig5a_sc1p0.csv", "no_such_file.csv", "/experiments/0/data", "cannot open"},
        BadCase{"\"d1\": {", "\"dd1\": {", "/parameters/dd1", "unknown or unfittable parameter"},
        BadCase{"[0.1, 2.0]", "[2.0, 0.1]", "/parameters/d1/bounds", "must be below the upper bound"},
        BadCase{"\"start\": 0.5", "\"start\": 3.0", "/parameters/d1/start", "out of range"},
        BadCase{"\"group\": \"b\"", "\"group\": \"b\", \"test\": \"cyclic_torsion\"", "/experiments/1/test", "unknown test type"},
        BadCase{"\"group\": \"b\"", "\"group\": \"b\", \"colour\": 1", "/experiments/1/colour", "unknown key"},
        BadCase{"\"weights\"", "\"weight\"", "/weight", "unknown key"},
        BadCase{"\"d1\": {\"start\": 0.5, \"bounds\": [0.1, 2.0]}", "\"c\": {\"bounds\": [0.75, 1.2]}", "/parameters/c/bounds/1", "c"},
        BadCase{"\"void_ratio_at_kPa\": 29.4", "\"void_ratio_at_kPa\": 200", "/experiments/0/void_ratio_at_kPa", "out of range"},
        BadCase{"\"peak_friction\": 1", "\"peak_friction\": 1, \"oedometer\": 1", "/weights/types/oedometer", "unknown test type"},
        BadCase{"\"xi_deg\": [90]", "\"chi_deg\": [90]", "/experiments/3/rows/chi_deg", "no column"},
        BadCase{"\"per_group\": true", "\"per_group\": true, \"group_start\": {\"z\": 0.3}", "/parameters/F0/group_start/z", "no experiment"},
        BadCase{"\"void_ratio_at_kPa\": 29.4", "\"void_ratio_at_kPa\": 29.4, \"strain_range_pct\": [5, 1]", "/experiments/0/strain_range_pct", "lower < upper"},
        BadCase{"\"weights\"", "\"optimizer\": {\"abandon_factor\": 0.5}, \"weights\"", "/optimizer/abandon_factor", "at least 1"},
        BadCase{"\"weights\"", "\"optimizer\": {\"abandon_after\": 0}, \"weights\"", "/optimizer/abandon_after", "out of range"},
        BadCase{"\"void_ratio_at_kPa\": 29.4", "\"void_ratio_at_kPa\": 29.4, \"max_cutbacks\": 0", "/experiments/0/max_cutbacks", "out of range"},
        BadCase{"{\"file\": \"../parameters/toyoura_acst_guide.json\"}", "{\"file\": \"../parameters/toyoura_isotropic_literature.json\"}",
                "/parameters/F0", "isotropic model has no fabric"}));

TEST(FitSpec, NotJsonAndMissingFile) {
  EXPECT_NE(error_of("{\"material\": ").find("not valid JSON"), std::string::npos);
  try {
    read_fit_spec(base_dir + "/no_such_fit.json");
    FAIL() << "no error";
  } catch (const acst::common::InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("the fit description '" + base_dir + "/no_such_fit.json': cannot open: ", 0), 0u) << e.what();
  }
}

// The command line rejects an invalid description with status 2 and writes nothing.
TEST(FitCli, InvalidDescriptionWritesNothing) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("acst_fit_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path file = dir / "bad.json";
  {
    std::ofstream f(file);
    std::string text = description("[0.1, 2.0]", "[2.0, 0.1]");
    // Paths inside are relative to the description's folder: make them absolute.
    for (std::size_t at = text.find("\"../"); at != std::string::npos; at = text.find("\"../", at + 1))
      text.replace(at + 1, 0, base_dir + "/");
    f << text;
  }
  std::ostringstream out, err;
  const fs::path output = dir / "out";
  EXPECT_EQ(fit_cli({file.string(), "--output", output.string()}, out, err), 2);
  EXPECT_NE(err.str().find("/parameters/d1/bounds"), std::string::npos) << err.str();
  EXPECT_FALSE(fs::exists(output));
  EXPECT_EQ(fit_cli({"--threads", "x", file.string()}, out, err), 2);
  EXPECT_EQ(fit_cli({}, out, err), 2);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace acst::calibration::calibration_fit_spec_test
