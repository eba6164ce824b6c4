// Cross-validation (acst_fit --cross-validate, docs/calibration.md): each fold is fitted without
// its experiments and predicted with that fit. Checked against the same steps written by hand:
// the description without the fold fitted on its own, and a prediction of the fold with the
// values that fit found.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "acst_calibration/cli.hpp"
#include "acst_calibration/cross_validation.hpp"
#include "acst_calibration/least_squares.hpp"
#include "acst_calibration/problem.hpp"
#include "fit_descriptions.hpp"
#include "scratch.hpp"

namespace acst::calibration::calibration_cross_validation_test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const std::string& base_dir = test::calibration_dir;

json experiment(const std::string& file, const std::string& group) {
  json e = {{"data", file}, {"group", group}};
  if (file.find("fukushima") != std::string::npos) e["void_ratio_at_kPa"] = 29.4;
  return e;
}

// h1 fitted to two dense Fukushima & Tatsuoka curves and a loose Verdugo & Ishihara one.
json description() {
  return {{"name", "cv"},
          {"material", {{"file", "../parameters/toyoura_acst_guide.json"}}},
          {"parameters", {{"h1", {{"bounds", {0.05, 3.0}}}}}},
          {"defaults", {{"strain_increment_pct", 0.2}}},
          {"experiments",
           {experiment("../lab/fukushima_tatsuoka_1984/ft84_fig5a_sc1p0.csv", "a"),
            experiment("../lab/fukushima_tatsuoka_1984/ft84_fig5a_sc4p0.csv", "a"),
            experiment("../lab/verdugo_ishihara_1996/wang34_Tokyo_TMD5.csv", "b")}},
          {"optimizer", {{"design_points", 0}, {"starts", 1}, {"max_iterations", 15}, {"threads", 2}}},
          {"cross_validation", {{"folds", {{"dense", {"ft84_fig5a_sc4p0"}}, {"loose", {"wang34_Tokyo_TMD5"}}}}}}};
}

struct HandFit {
  double theta;
  std::vector<ExperimentError> errors;
};

HandFit fit_by_hand(json d) {
  d.erase("cross_validation");
  const FitSpec s = parse_fit_spec(d.dump(), base_dir, "hand");
  const Problem p(s);
  LeastSquaresProblem ls{p.start(), p.lower(), p.upper(), p.residual_count(),
                         [&](const std::vector<Eigen::VectorXd>& t) { return p.residuals(t); }};
  const FitResult r = fit(ls, s.optimizer);
  std::vector<TestRunOutcome> out;
  p.residuals(r.theta, out);
  return {r.theta.size() ? r.theta[0] : NAN, experiment_errors(p, out)};
}

TEST(CrossValidation, EachFoldIsTheFitWithoutItAndItsPrediction) {
  const json d = description();
  const FitSpec spec = parse_fit_spec(d.dump(), base_dir, "cv");
  ASSERT_EQ(spec.folds.size(), 2u);
  const CrossValidation cv = cross_validate(d, spec, {});
  ASSERT_EQ(cv.folds.size(), 2u);

  const HandFit all = fit_by_hand(d);
  EXPECT_EQ(cv.all_data_values["h1"].get<double>(), all.theta);
  for (std::size_t k = 0; k < 2; ++k) {
    const FoldResult& f = cv.folds[k];
    SCOPED_TRACE(f.fold.name);
    const std::string left_out = f.fold.experiments.front();
    // The training fit: the description without the fold's experiment, fitted by hand.
    json without = d;
    without["experiments"] = json::array();
    for (std::size_t i = 0; i < spec.experiments.size(); ++i)
      if (spec.experiments[i].id != left_out) without["experiments"].push_back(d["experiments"][i]);
    const HandFit training = fit_by_hand(without);
    EXPECT_EQ(f.values["h1"].get<double>(), training.theta);
    EXPECT_EQ(f.training_experiments, 2);
    // The prediction: the left-out experiment with h1 at the training fit's value, nothing fitted.
    json predict = d;
    predict.erase("cross_validation");
    predict["material"] = {{"file", "../parameters/toyoura_acst_guide.json"}};
    predict["parameters"] = json::object();
    predict["experiments"] = json::array();
    for (std::size_t i = 0; i < spec.experiments.size(); ++i)
      if (spec.experiments[i].id == left_out) predict["experiments"].push_back(d["experiments"][i]);
    const FitSpec ps = parse_fit_spec(predict.dump(), base_dir, "p");
    FitSpec with_h1 = ps;
    with_h1.material["parameters"]["h1"] = training.theta;
    const Problem pp(with_h1);
    std::vector<TestRunOutcome> out;
    pp.residuals(Eigen::VectorXd(0), out);
    const ExperimentError expected = experiment_errors(pp, out).front();
    ASSERT_EQ(f.predicted.size(), 1u);
    ASSERT_EQ(f.predicted[0].axes.size(), expected.axes.size());
    for (std::size_t i = 0; i < expected.axes.size(); ++i) {
      EXPECT_DOUBLE_EQ(f.predicted[0].axes[i].rms, expected.axes[i].rms);
      EXPECT_DOUBLE_EQ(f.predicted[0].axes[i].mean, expected.axes[i].mean);
    }
    // Beside it, the same experiment as fitted with all three.
    for (const ExperimentError& e : all.errors)
      if (e.id == left_out) {
        EXPECT_DOUBLE_EQ(f.fitted[0].axes[0].rms, e.axes[0].rms);
      }
    EXPECT_TRUE(f.borrowed_groups.empty());  // nothing is fitted per group
  }
  // Left out, the loose test is predicted worse than it was fitted: the two dense curves alone
  // pull h1 where the loose sand is not.
  EXPECT_GT(pooled_rms_normalised(cv.folds[1].predicted), pooled_rms_normalised(cv.folds[1].fitted));
}

TEST(CrossValidation, BadFoldsNameThePath) {
  json d = description();
  d["cross_validation"]["folds"]["dense"] = {"ft84_fig5a_sc9p9"};
  EXPECT_NE(test::fit_spec_error(d).find("/cross_validation/folds/dense/0: no experiment has the id 'ft84_fig5a_sc9p9'"), std::string::npos)
      << test::fit_spec_error(d);
  d = description();
  d["cross_validation"]["folds"]["loose"] = {"wang34_Tokyo_TMD5", "ft84_fig5a_sc4p0"};
  EXPECT_NE(test::fit_spec_error(d).find("is in two folds"), std::string::npos) << test::fit_spec_error(d);
  d = description();
  d["cross_validation"]["folds"] = {{"everything", {"ft84_fig5a_sc1p0", "ft84_fig5a_sc4p0", "wang34_Tokyo_TMD5"}}};
  EXPECT_NE(test::fit_spec_error(d).find("/cross_validation/folds/everything: leaves no experiment to fit"), std::string::npos) << test::fit_spec_error(d);
  d = description();
  d["cross_validation"]["folds"] = {{"../up", {"ft84_fig5a_sc1p0"}}};
  EXPECT_NE(test::fit_spec_error(d).find("/cross_validation/folds/../up"), std::string::npos) << test::fit_spec_error(d);
  d = description();
  d["cross_validation"]["k"] = 5;
  EXPECT_NE(test::fit_spec_error(d).find("/cross_validation/k"), std::string::npos) << test::fit_spec_error(d);
}

TEST(CrossValidationCli, WritesTheReportAndRefusesAForeignFolder) {
  const fs::path dir = test::scratch_folder("cv_cli");
  json d = description();
  d["material"]["file"] = base_dir + "/../parameters/toyoura_acst_guide.json";
  for (auto& e : d["experiments"]) e["data"] = base_dir + "/" + e["data"].get<std::string>();
  std::ofstream(dir / "cv.json") << d.dump();
  std::ostringstream out, err;
  const fs::path output = dir / "out";
  ASSERT_EQ(fit_cli({(dir / "cv.json").string(), "--cross-validate", "--quiet", "--no-plot", "--output", output.string()}, out, err), 0)
      << err.str();
  for (const char* f : {"cv_cv_report.md", "cv_cv_report.json", "cv_cv.csv", "cv_cv_dense_parameters.json", "cv_cv_loose_parameters.json"})
    EXPECT_TRUE(fs::exists(output / f)) << f;
  std::ifstream md(output / "cv_cv_report.md");
  std::stringstream text;
  text << md.rdbuf();
  EXPECT_NE(text.str().find("| loose | 1 | 2 |"), std::string::npos) << text.str();

  // A folder holding something else is refused before anything runs, and kept as it was.
  std::ofstream(output / "notes.txt") << "mine";
  std::ostringstream out2, err2;
  EXPECT_EQ(fit_cli({(dir / "cv.json").string(), "--cross-validate", "--quiet", "--output", output.string()}, out2, err2), 2);
  EXPECT_NE(err2.str().find("notes.txt"), std::string::npos) << err2.str();
  EXPECT_TRUE(fs::exists(output / "cv_cv_report.md"));

  // Without folds, --cross-validate is an error.
  d.erase("cross_validation");
  std::ofstream(dir / "plain.json") << d.dump();
  std::ostringstream out3, err3;
  EXPECT_EQ(fit_cli({(dir / "plain.json").string(), "--cross-validate", "--quiet", "--output", (dir / "o3").string()}, out3, err3), 2);
  EXPECT_NE(err3.str().find("/cross_validation"), std::string::npos) << err3.str();
  fs::remove_all(dir);
}

}  // namespace
}  // namespace acst::calibration::calibration_cross_validation_test
