// What acst_element writes: the CSV states its convention in the header and has one complete
// row per record (strains in percent, ENGINEERING shear strain); files appear complete or not at
// all (no temporary files left); a failed run writes NAME.failed.csv and NAME.reproducer.json
// and leaves an existing good NAME.csv alone; the PNG is drawn when gnuplot is available.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "acst_driver/cli.hpp"
#include "acst_driver/lab_data.hpp"
#include "driver_scenes.hpp"
#include "output_folder.hpp"

namespace acst::test::driver_output_files_test {
namespace {

namespace fs = std::filesystem;

fs::path fresh_directory(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("acst_output_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::vector<std::string> files_in(const fs::path& d) {
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(d)) names.push_back(e.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

// A strain-controlled step with a shear strain: gamma_12 = 0.2 % is eps_12 = 0.1 % as a tensor.
const std::string shear_steps =
    "[{\"control\": {\"11\": {\"strain_pct\": 0.05}, \"22\": {\"stress\": 0}, \"33\": {\"stress\": 0},"
    " \"12\": {\"strain_pct\": 0.2}, \"13\": {\"stress\": 0}, \"23\": {\"stress\": 0}}, \"increments\": 20}]";

TEST(OutputFiles, CsvStatesItsConventionAndHasCompleteRows) {
  const fs::path dir = fresh_directory("csv");
  std::ofstream(dir / "shear.json") << scene_json(shear_steps, 100.0, 0.7, ", \"output\": {\"plot\": false}");
  std::ostringstream o, e;
  ASSERT_EQ(driver::element_cli({"--quiet", "--output", (dir / "out").string(), (dir / "shear.json").string()}, o, e), 0) << e.str();
  EXPECT_EQ(files_in(dir / "out"), std::vector<std::string>{"shear.csv"});
  const driver::LabCurve csv = driver::read_commented_csv((dir / "out" / "shear.csv").string(), true);
  std::ifstream in(dir / "out" / "shear.csv");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("COMPRESSION POSITIVE"), std::string::npos);
  EXPECT_NE(text.find("ENGINEERING gamma_ij = 2 eps_ij"), std::string::npos);
  EXPECT_NE(text.find("strains in percent"), std::string::npos);
  ASSERT_EQ(csv.columns.size(), 33u);
  EXPECT_EQ(csv.columns.front(), "increment");
  EXPECT_EQ(csv.columns.back(), "status");
  const auto increment = csv.column("increment"), gamma = csv.column("gamma_12_pct"), eps11 = csv.column("eps_11_pct");
  const auto sigma22 = csv.column("sigma_22_kPa"), eq = csv.column("e_q_pct"), ev = csv.column("e_v_pct");
  const auto e11 = csv.column("eps_11_pct"), e22 = csv.column("eps_22_pct"), e33 = csv.column("eps_33_pct");
  ASSERT_EQ(increment.size(), 21u);  // the start and 20 increments
  EXPECT_EQ(increment.front(), 0.0);
  EXPECT_EQ(increment.back(), 20.0);
  // Printed with 10 significant digits: compare to 1e-8 relative.
  EXPECT_NEAR(gamma.back(), 0.2, 1e-9);
  EXPECT_NEAR(eps11.back(), 0.05, 1e-10);
  EXPECT_NEAR(sigma22.back(), 100.0, 1e-6);
  // e_q = sqrt(2/3 e:e) from the printed strains (tensor shear = gamma/2), recomputed here.
  const std::size_t k = e11.size() - 1;
  const double m = ev[k] / 3.0, d1 = e11[k] - m, d2 = e22[k] - m, d3 = e33[k] - m, s12 = gamma[k] / 2.0;
  EXPECT_NEAR(eq[k], std::sqrt(2.0 / 3.0 * (d1 * d1 + d2 * d2 + d3 * d3 + 2.0 * s12 * s12)), 1e-8);
  EXPECT_NEAR(ev[k], e11[k] + e22[k] + e33[k], 1e-8);
  fs::remove_all(dir);
}

TEST(OutputFiles, FailedRunLeavesTheGoodCsvAndWritesReproducer) {
  const auto [dir, out] = used_output_folder("output_failed", {{"t.csv", "good results\n"}});
  // One 5 % increment, an integrator allowed 10 substeps and no cut-back: fails at once.
  std::ofstream(dir / "t.json") << scene_json(
      "[{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 5, \"increments\": 1}]", 100.0, 0.7,
      ", \"solver\": {\"max_halvings\": 0}",
      "{\"file\": \"" + parameter_file() + "\", \"integrator\": {\"max_substeps\": 10}}");
  std::ostringstream o, e;
  EXPECT_EQ(driver::element_cli({"--quiet", "--output", out.string(), (dir / "t.json").string()}, o, e), 1);
  EXPECT_NE(e.str().find("run failed: /steps/0 (drained_triaxial_compression), increment 1 of 1"), std::string::npos) << e.str();
  EXPECT_EQ(files_in(out), (std::vector<std::string>{"t.csv", "t.failed.csv", "t.reproducer.json"}));
  std::ifstream good(out / "t.csv");
  std::string line;
  std::getline(good, line);
  EXPECT_EQ(line, "good results");
  // The reproducer is itself a valid scene that fails the same way.
  std::ostringstream o2, e2;
  EXPECT_EQ(driver::element_cli({"--quiet", "--output", (dir / "replay").string(), (out / "t.reproducer.json").string()}, o2, e2), 1);
  EXPECT_NE(e2.str().find("more substeps than allowed"), std::string::npos) << e2.str();
  fs::remove_all(dir);
}

TEST(OutputFiles, FigureIsDrawnWhenGnuplotIsAvailable) {
  const bool gnuplot = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  const fs::path dir = fresh_directory("figure");
  std::ofstream(dir / "f.json") << scene_json(
      "[{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 2, \"increments\": 50}]", 98.0, 0.671,
      ", \"lab_data\": \"" + std::string(ACST_SOURCE_DIR) + "/data/lab/fukushima_tatsuoka_1984/ft84_fig5a_sc1p0.csv\"");
  std::ostringstream o, e;
  ASSERT_EQ(driver::element_cli({"--quiet", "--output", (dir / "out").string(), (dir / "f.json").string()}, o, e), 0) << e.str();
  if (gnuplot) {
    EXPECT_EQ(files_in(dir / "out"), (std::vector<std::string>{"f.csv", "f.gp", "f.png"})) << e.str();
    EXPECT_GT(fs::file_size(dir / "out" / "f.png"), 10000u);
  } else {
    EXPECT_NE(e.str().find("gnuplot was not found"), std::string::npos);
    EXPECT_EQ(files_in(dir / "out"), std::vector<std::string>{"f.csv"});
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace acst::test::driver_output_files_test
