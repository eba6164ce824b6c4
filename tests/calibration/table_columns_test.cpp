// peak_friction tables whose rows carry their own confining stress and void ratio (`columns`,
// docs/calibration.md), and descriptions that fit nothing: a prediction of the material as given.
#include <gtest/gtest.h>

#include <filesystem>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "acst_calibration/cli.hpp"
#include "acst_calibration/fit_spec.hpp"
#include "acst_calibration/least_squares.hpp"
#include "acst_calibration/problem.hpp"
#include "fit_descriptions.hpp"
#include "scratch.hpp"

namespace acst::calibration::calibration_table_columns_test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string& base_dir = test::calibration_dir;

// A Table-1-like file (triaxial compression, no b nor bedding column): rows 0 and 1 differ in
// density, 0 and 2 in pressure; row 3 lies below the 29.4 kPa at which e was measured.
fs::path write_table() {
  const fs::path file = test::scratch_folder("table_columns") / "peaks.csv";
  std::ofstream(file) << "# kind: TC, peak values only\n# bedding_angle_deg: 0\n"
                         "test,s3_kPa,e_0p3,phi_uncorrected\n"
                         "1,50,0.70,40\n2,50,0.85,36\n3,400,0.70,38\n4,10,0.70,42\n";
  return file;
}

json description(const fs::path& table) {
  return {{"material", {{"file", "../parameters/toyoura_acst_calibrated.json"}}},
          {"parameters", json::object()},
          {"experiments",
           {{{"data", table.string()},
             {"test", "peak_friction"},
             {"b", 0},
             {"void_ratio_at_kPa", 29.4},
             {"columns", {{"phi_deg", "phi_uncorrected"}, {"sigma3_kPa", "s3_kPa"}, {"void_ratio", "e_0p3"}}},
             {"peak_search_strain_pct", 15}}}},
          {"optimizer", {{"design_points", 0}, {"starts", 1}, {"threads", 2}}}};
}

TEST(TableColumns, EveryRowRunsAtItsOwnStressAndDensity) {
  const fs::path table = write_table();
  const Problem p(parse_fit_spec(description(table).dump(), base_dir, "t"));
  ASSERT_EQ(p.test_runs().size(), 4u);
  const double s3[] = {50, 50, 400, 10}, e0[] = {0.70, 0.85, 0.70, 0.70};
  for (std::size_t i = 0; i < 4; ++i) {
    const TestRun& s = p.test_runs()[i];
    EXPECT_DOUBLE_EQ(s.sigma3_kPa, s3[i]);
    EXPECT_DOUBLE_EQ(s.void_ratio, e0[i]);
    EXPECT_DOUBLE_EQ(s.b, 0.0);
    EXPECT_DOUBLE_EQ(s.bedding_angle_deg, 0.0);  // from the file's header
    // Consolidated from 29.4 kPa where the row's stress is above it; row 3 starts at its own.
    EXPECT_EQ(s.shear_step, i == 3 ? 0 : 1);
  }
  // The peaks follow the rows' conditions: denser is stronger, higher pressure weaker.
  std::vector<TestRunOutcome> out;
  p.residuals(Eigen::VectorXd(0), out);
  ASSERT_EQ(out.size(), 4u);
  for (const auto& o : out) ASSERT_TRUE(o.ok) << o.message;
  std::printf("peaks: %.2f %.2f %.2f %.2f deg\n", out[0].peak_phi_deg, out[1].peak_phi_deg, out[2].peak_phi_deg, out[3].peak_phi_deg);
  EXPECT_GT(out[0].peak_phi_deg - out[1].peak_phi_deg, 2.0);  // e 0.70 against 0.85 at 50 kPa
  EXPECT_GT(out[0].peak_phi_deg - out[2].peak_phi_deg, 0.5);  // 50 against 400 kPa at e 0.70
  EXPECT_GT(out[3].peak_phi_deg, out[0].peak_phi_deg);        // 10 kPa: the strongest
  fs::remove_all(table.parent_path());
}

TEST(TableColumns, BadColumnsNameThePathAndTheReason) {
  const fs::path table = write_table();
  struct Case {
    json patch;
    const char* path;
    const char* says;
  };
  const Case cases[] = {
      {{{"columns", {{"sigma3_kPa", "sigma3"}}}}, "/experiments/0/columns/sigma3_kPa", "has no column 'sigma3'"},
      {{{"columns", {{"porosity", "e_0p3"}}}}, "/experiments/0/columns/porosity", "unknown key"},
      {{{"columns", {{"phi_deg", "phi_uncorrected"}, {"sigma3_kPa", "s3_kPa"}, {"void_ratio", "e_0p3"}}}, {"sigma3_kPa", 50}},
       "/experiments/0/sigma3_kPa", "column 's3_kPa' gives it"},
      {{{"b", nullptr}}, "/experiments/0/b", "the table has no b column"},
      {{{"columns", {{"phi_deg", "phi_uncorrected"}, {"sigma3_kPa", "s3_kPa"}, {"void_ratio", "e_0p3"}}}, {"bedding_angle_deg", 200}},
       "/experiments/0/bedding_angle_deg", "out of range"},
  };
  for (const Case& c : cases) {
    json j = description(table);
    for (const auto& item : c.patch.items()) {
      if (item.value().is_null()) j["experiments"][0].erase(item.key());
      else j["experiments"][0][item.key()] = item.value();
    }
    const std::string e = test::fit_spec_error(j);
    EXPECT_NE(e.find(c.path), std::string::npos) << e;
    EXPECT_NE(e.find(c.says), std::string::npos) << e;
  }
  fs::remove_all(table.parent_path());
}

// A description with nothing to fit is evaluated once at the material's values: the result is
// the residual vector there, and the report says it is a prediction.
TEST(Prediction, NothingFittedEvaluatesTheMaterialOnce) {
  const fs::path table = write_table();
  const FitSpec spec = parse_fit_spec(description(table).dump(), base_dir, "t");
  const Problem p(spec);
  ASSERT_TRUE(p.variables().empty());
  LeastSquaresProblem ls{p.start(), p.lower(), p.upper(), p.residual_count(),
                         [&](const std::vector<Eigen::VectorXd>& t) { return p.residuals(t); }};
  const FitResult r = fit(ls, spec.optimizer);
  EXPECT_EQ(r.evaluations, 1);
  EXPECT_TRUE(r.local_fits.empty());
  const Eigen::VectorXd direct = p.residuals({Eigen::VectorXd(0)}).front();
  EXPECT_EQ(r.residuals, direct);
  EXPECT_DOUBLE_EQ(r.cost, direct.squaredNorm());

  fs::path file = table.parent_path() / "predict.json";
  std::ofstream(file) << [&] {
    json j = description(table);
    j["material"]["file"] = base_dir + "/../parameters/toyoura_acst_calibrated.json";
    return j.dump();
  }();
  const fs::path output = table.parent_path() / "out";
  std::ostringstream out, err;
  ASSERT_EQ(fit_cli({file.string(), "--quiet", "--no-plot", "--output", output.string()}, out, err), 0) << err.str();
  std::ifstream md(output / "predict_report.md");
  std::stringstream text;
  text << md.rdbuf();
  EXPECT_NE(text.str().find("Nothing is fitted"), std::string::npos);
  EXPECT_NE(text.str().find("No parameter is fitted"), std::string::npos);
  std::ifstream pts(output / "curves" / "peaks_points.csv");
  std::string header;
  std::getline(pts, header);
  EXPECT_EQ(header, "row,omega_deg,b,sigma3_kPa,void_ratio,measured,simulated");
  fs::remove_all(table.parent_path());
}

// The bundled descriptions stay valid: the Table 1 prediction selects every one of its 78 rows,
// the all-data candidate its 57 rows at 9.8-392 kPa, and every description with folds names
// experiments it has.
TEST(BundledDescriptions, TableRowsAndFolds) {
  std::size_t rows = 0, descriptions = 0;
  for (const auto& entry : fs::directory_iterator(base_dir)) {
    if (entry.path().extension() != ".json") continue;
    const FitSpec s = read_fit_spec(entry.path().string());
    ++descriptions;
    if (s.name == "toyoura_acst_table1_prediction" || s.name == "toyoura_acst_all_data") {
      const Problem p(s);
      std::size_t table = 0;
      for (const TestRun& sim : p.test_runs()) table += sim.row >= 0 && sim.sigma3_kPa != 98.0;  // lt88's rows: 98 kPa
      EXPECT_EQ(table, s.name == "toyoura_acst_all_data" ? 57u : 78u) << s.name;
      rows += table;
    }
  }
  EXPECT_GE(descriptions, 5u);
  EXPECT_EQ(rows, 78u + 57u);
}

}  // namespace
}  // namespace acst::calibration::calibration_table_columns_test

namespace acst::calibration::calibration_table_columns_test {

// A cell of text in a column the experiment reads (4O.3 with a letter O, x, nan, inf) is refused
// with the file, its line and the column, where the row used to be dropped silently; an empty
// cell still leaves its row out, and text in a column the experiment does not read is no matter.
TEST(TableColumns, TextInAColumnTheExperimentReadsIsRefusedWithItsLine) {
  const fs::path dir = test::scratch_folder("table_text");
  const auto problem_with = [&](const std::string& row) {
    const fs::path file = dir / "peaks.csv";
    std::ofstream(file) << "# kind: TC\n# bedding_angle_deg: 0\ntest,s3_kPa,e_0p3,phi_uncorrected,note\n"
                           "1,50,0.70,40,fine\n" << row << "\n";
    return Problem(parse_fit_spec(description(file).dump(), base_dir, "t"));
  };
  for (const char* bad : {"2,50,0.85,4O.3,x", "2,50,x,36,x", "2,nan,0.85,36,x", "2,50,0.85,inf,x"}) {
    try {
      problem_with(bad);
      ADD_FAILURE() << bad << ": accepted";
    } catch (const common::InputError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("peaks.csv':5: column "), std::string::npos) << m;
      EXPECT_NE(m.find("is not a number"), std::string::npos) << m;
    }
  }
  for (const char* angle : {"-10", "95", "1e308", "0"}) {
    try {
      problem_with(std::string("2,50,0.85,") + angle + ",x");
      ADD_FAILURE() << angle << ": accepted";
    } catch (const common::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("allowed: between 0 and 90 deg"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(problem_with("2,50,0.85,,a note").test_runs().size(), 1u);  // empty: the row left out
  EXPECT_EQ(problem_with("2,50,0.85,36,a note").test_runs().size(), 2u);
  fs::remove_all(dir);
}

}  // namespace acst::calibration::calibration_table_columns_test
