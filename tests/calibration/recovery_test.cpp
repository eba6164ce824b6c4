// Synthetic recovery: drained triaxial curves computed with known parameters (at a finer strain
// increment than the fit uses) plus Gaussian noise are fitted back from a perturbed start. The
// known values must come back within a few standard errors and inside the reported 95 %
// intervals; fixed parameters stay fixed; a bound below the known value holds.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "acst_calibration/fit_spec.hpp"
#include "acst_calibration/least_squares.hpp"
#include "acst_calibration/problem.hpp"
#include "acst_calibration/report.hpp"
#include "acst_common/interpolate.hpp"
#include "acst_driver/record.hpp"
#include "test_materials.hpp"

namespace acst::calibration {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

const double true_d1 = 0.6, true_h1 = 0.5, true_n = 1.8;

json true_material() {
  json m = json::parse(test::read_text("data/parameters/toyoura_acst_guide.json"));
  m["parameters"]["d1"] = true_d1;
  m["parameters"]["h1"] = true_h1;
  m["parameters"]["n"] = true_n;
  return m;
}

// Writes a lab-format file of a drained triaxial test with noise: sr +- 0.01, e_v +- 0.02 %.
void write_synthetic(const fs::path& file, double sigma3, double e0, unsigned seed) {
  const json scene = {{"material", true_material()},
                      {"initial_state", {{"confining_pressure", sigma3}, {"void_ratio", e0}, {"bedding_angle_deg", 0}}},
                      {"steps", json::array({{{"preset", "drained_triaxial_compression"}, {"axial_strain_pct", 8.5}, {"increments", 850}}})}};
  const driver::RunResult run = driver::run_scene(driver::parse_scene(scene.dump(), "", "synthetic"));
  ASSERT_TRUE(run.ok) << run.message;
  std::vector<double> ea, sr, ev;
  for (const auto& r : run.records) {
    ea.push_back(driver::axial_strain_pct(r.strain));
    sr.push_back(r.stress[0] / r.stress[2]);
    ev.push_back(driver::volumetric_strain_pct(r.strain));
  }
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  std::ofstream f(file);
  f << "# kind: TC\n# sigma3_kPa: " << sigma3 << "\n# e0: " << e0 << "\n# bedding_angle_deg: 0\n# strain_range_pct: 0.25 8\n"
    << "eps_a_pct,stress_ratio,q_kPa,eps_v_pct\n0,1,0,0\n";
  for (int i = 1; i <= 32; ++i) {
    const double x = 0.25 * i, s = acst::common::interpolate(ea, sr, x) + 0.01 * noise(rng);
    f << x << ',' << s << ',' << (s - 1.0) * sigma3 << ',' << acst::common::interpolate(ea, ev, x) + 0.02 * noise(rng) << '\n';
  }
}

class Recovery : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("acst_recovery_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    write_synthetic(dir_ / "dense.csv", 100.0, 0.70, 11);
    write_synthetic(dir_ / "loose.csv", 400.0, 0.82, 12);
    std::ofstream(dir_ / "material.json") << json::parse(test::read_text("data/parameters/toyoura_acst_guide.json")).dump();
  }
  void TearDown() override { fs::remove_all(dir_); }

  FitSpec spec(double n_upper) const {
    const json j = {{"material", {{"file", "material.json"}}},
                    {"parameters",
                     {{"d1", {{"start", 0.45}, {"bounds", {0.1, 2.0}}}},
                      {"h1", {{"start", 0.7}, {"bounds", {0.05, 3.0}}}},
                      {"n", {{"start", std::min(1.3, 0.9 * n_upper)}, {"bounds", {0.3, n_upper}}}}}},
                    {"experiments", {{{"data", "dense.csv"}}, {{"data", "loose.csv"}}}},
                    {"optimizer", {{"design_points", 3}, {"starts", 2}, {"max_iterations", 60}, {"threads", 2}}}};
    return parse_fit_spec(j.dump(), dir_.string(), "recovery");
  }

  static FitResult run(const Problem& p) {
    LeastSquaresProblem ls{p.start(), p.lower(), p.upper(), p.residual_count(),
                           [&](const std::vector<Eigen::VectorXd>& t) { return p.residuals(t); }};
    return fit(ls, p.spec().optimizer);
  }

  fs::path dir_;
};

TEST_F(Recovery, KnownParametersComeBackInsideTheirIntervals) {
  const Problem p(spec(5.0));
  const FitResult f = run(p);
  const double truth[] = {true_d1, true_h1, true_n};
  for (int j = 0; j < 3; ++j) {
    const double se = f.uncertainty.standard_error[j];
    SCOPED_TRACE(p.variables()[static_cast<std::size_t>(j)].label);
    // The noise (about 0.5 % of each measured range) allows a few per cent at most.
    EXPECT_NEAR(f.theta[j], truth[j], 0.03 * truth[j]);
    EXPECT_LE(f.uncertainty.ci95_lower[j], truth[j]);
    EXPECT_GE(f.uncertainty.ci95_upper[j], truth[j]);
    EXPECT_GT(se, 0.0);
    EXPECT_FALSE(f.uncertainty.at_bound[static_cast<std::size_t>(j)]);
    std::printf("%s: fitted %.5f, known %.5f, standard error %.2e\n", p.variables()[static_cast<std::size_t>(j)].label.c_str(),
                f.theta[j], truth[j], se);
  }
  // Residuals at the optimum are noise: RMS normalised error near the noise level (~0.005-0.01).
  EXPECT_LT(std::sqrt(f.cost), 0.02);
  // Fixed parameters keep the base material's values in the fitted material.
  const json fitted = fitted_material(p, f.theta, p.spec().groups.front());
  const json base = json::parse(test::read_text("data/parameters/toyoura_acst_guide.json"));
  for (const auto& item : base["parameters"].items()) {
    if (item.key() == "d1" || item.key() == "h1" || item.key() == "n") continue;
    EXPECT_EQ(fitted["parameters"][item.key()], item.value()) << item.key();
  }
  EXPECT_NEAR(fitted["parameters"]["d1"].get<double>(), f.theta[0], 0.0);
}

TEST_F(Recovery, BoundBelowTheKnownValueHolds) {
  const Problem p(spec(1.5));
  const FitResult f = run(p);
  EXPECT_LE(f.theta[2], 1.5);
  EXPECT_TRUE(f.uncertainty.at_bound[2]);
  for (int j = 0; j < 3; ++j) {
    EXPECT_GE(f.theta[j], p.lower()[j]);
    EXPECT_LE(f.theta[j], p.upper()[j]);
  }
}

}  // namespace
}  // namespace acst::calibration
