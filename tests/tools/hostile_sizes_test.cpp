// Sizes that pass the range checks of each key but cannot work together (issue 14): a cell of
// 1e-300 m, a grid of 1e9 cells, an element test of 1e7 increments x 1e6 cycles, a run of 1e10
// time steps, a lab curve that asks for 1e16 increments. Each is refused at once with exit 2, a
// message that names the JSON path and the computed size, and nothing written. And the element
// runner streams its rows: its memory does not grow with the number of increments, and a run
// that fails after many rows leaves an earlier good CSV whole.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "acst_calibration/cli.hpp"
#include "acst_common/files.hpp"
#include "acst_driver/cli.hpp"
#include "acst_driver/output.hpp"
#include "acst_footing_tool/cli.hpp"
#include "driver_scenes.hpp"
#include "scratch.hpp"

namespace acst::test::hostile_sizes_test {
namespace {

namespace fs = std::filesystem;
using Cli = int (*)(const std::vector<std::string>&, std::ostream&, std::ostream&);

void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// Runs the tool on the input file (output into dir/out); expects exit 2 within a second, every
// piece of `says` in the message, and the scratch folder as it was.
void expect_refused(Cli cli, const fs::path& dir, const std::string& input_text, const std::vector<std::string>& says) {
  write(dir / "input.json", input_text);
  const std::vector<std::string> before = everything_under(dir);
  std::ostringstream out, err;
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_EQ(cli({"--quiet", "--no-plot", "--output", (dir / "out").string(), (dir / "input.json").string()}, out, err), 2)
      << err.str();
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 1.0);
  for (const std::string& s : says) EXPECT_NE(err.str().find(s), std::string::npos) << "missing '" << s << "' in: " << err.str();
  EXPECT_EQ(everything_under(dir), before);
}

std::string mpm_scene(const std::string& cell_size, const std::string& extent, const std::string& rest) {
  return "{\"name\": \"s\", \"grid\": {\"cell_size\": " + cell_size + "}, \"materials\": {\"soil\": "
         "{\"model\": \"linear_elastic\", \"parameters\": {\"E\": 1000, \"nu\": 0.3}}}, \"bodies\": [{\"material\": "
         "\"soil\", \"x_range\": [0, " + extent + "], \"y_range\": [0, " + extent + "], \"density\": 1000}], " + rest + "}";
}

TEST(HostileSizes, MpmSceneAsksForTooMuch) {
  const fs::path dir = scratch_folder("sizes_mpm");
  const Cli cli = mpm::mpm_cli;
  // 1e-300 m cells: 1e300 of them per direction would overflow an int (the run was empty).
  expect_refused(cli, dir, mpm_scene("1e-300", "1", "\"stop\": {\"steps\": 3}"),
                 {"/grid/cell_size: 1e-300 m is below 1e-06 of the soil's extent (1 m)"});
  // 32000 x 32000 cells: every count fits an int, but some 1e9 nodes and 1e9 particles need
  // more than 64 GiB (at least 136 bytes a node and 600 a particle).
  expect_refused(cli, dir, mpm_scene("0.03125", "1000", "\"stop\": {\"steps\": 3}"),
                 {"/grid/cell_size: the scene needs about", "GiB of memory for 1.02", "e+09 grid nodes", "1.024e+09 particles"});
  // A one-metre block, 0.5 m cells: the first time step is cfl h / c = 0.5 * 0.5 / 37 m/s (c =
  // sqrt(M / rho), M = 1346 kPa), some 7e-3 s; 1e8 s of soil time are 1.5e10 steps.
  expect_refused(cli, dir, mpm_scene("0.5", "1", "\"stop\": {\"time\": 1e8}"),
                 {"/stop/time: the run would take about 1.", "e+10 steps", "more than the 1e+09 allowed"});
  // A frame every 1e-6 s over 1e4 s: one a step (at most), some 1.5e6 frames.
  expect_refused(cli, dir, mpm_scene("0.5", "1", "\"stop\": {\"time\": 1e4}, \"output\": {\"vtk_every_time\": 1e-6}"),
                 {"/output/vtk_every_time: the run would write up to 1.", "e+06 VTK frames", "more than the 10000 allowed"});
  expect_refused(cli, dir, mpm_scene("0.5", "1", "\"stop\": {\"steps\": 2e9}"), {"/stop/steps: 2e+09 is out of range"});
  // A load-record row every step of 1e9: some 1e9 x 300 bytes held until the CSV is written.
  expect_refused(cli, dir, mpm_scene("0.5", "1", "\"stop\": {\"steps\": 1e9}, \"output\": {\"every_step_csv\": true}"),
                 {"/stop/steps: the scene needs about", "1.05e+09 load-record rows (/stop/steps, /output/every_step_csv)",
                  "run fewer steps or record fewer rows"});
  fs::remove_all(dir);
}

const std::string strain_step =
    "{\"control\": {\"11\": {\"strain_pct\": 0.0001}, \"22\": {\"strain_pct\": 0}, \"33\": {\"strain_pct\": 0},"
    " \"12\": {\"strain_pct\": 0}, \"13\": {\"strain_pct\": 0}, \"23\": {\"strain_pct\": 0}}, \"increments\": ";

TEST(HostileSizes, ElementTestAsksForTooMuch) {
  const fs::path dir = scratch_folder("sizes_element");
  const Cli cli = driver::element_cli;
  // 1e7 increments x 1e6 cycles passed every key's range and tried to allocate (1.8 GB after 20 s).
  expect_refused(cli, dir, scene_json("[{\"repeat\": {\"cycles\": 1000000, \"steps\": [" + strain_step + "10000000}]}}]"),
                 {"/steps: the scene asks for 1e+13 increments in all",
                  "/steps/0/repeat: 1e+07 increments per cycle x 1000000 cycles", "more than the 1e+09"});
  // 1e8 increments every one written: 1e8 rows and one per step end are over the CSV's cap.
  std::string ten_steps = "[";
  for (int i = 0; i < 10; ++i) ten_steps += (i ? ", " : "") + strain_step + "10000000}";
  expect_refused(cli, dir, scene_json(ten_steps + "]"), {"/output/every: the run would write about 1e+08 CSV rows"});
  fs::remove_all(dir);
}

TEST(HostileSizes, FitAsksForTooManyIncrements) {
  const fs::path dir = scratch_folder("sizes_fit");
  // A sorted lab curve reaching 1e12 % strain: at the default 0.05 % an increment that is 2e13
  // increments, beyond an int and any element test.
  write(dir / "lab.csv", "# kind: TC\n# sigma3_kPa: 100\n# e0: 0.7\n# bedding_angle_deg: 0\neps_a_pct,stress_ratio,eps_v_pct\n"
                         "0,1,0\n1,2,0.1\n1e12,3,0.2\n");
  const std::string fit = "{\"material\": {\"file\": \"" + parameter_file() + "\"}, \"parameters\": {\"d1\": {\"start\": 0.5,"
                          " \"bounds\": [0.1, 2.0]}}, \"experiments\": [{\"data\": \"" + (dir / "lab.csv").string() +
                          "\", \"strain_range_pct\": [0, 1e13]}]}";
  expect_refused(calibration::fit_cli, dir, fit,
                 {"/experiments/0/strain_increment_pct: a run to 1e+12 % in steps of 0.05 % takes 2e+13 increments"});
  fs::remove_all(dir);
}

long max_rss_kb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

// A strain path inside the elastic range, `n` increments, every row written.
std::string long_elastic_scene(long n) {
  return scene_json("[" + strain_step + std::to_string(n) + "}]", 100.0, 0.7, ", \"output\": {\"plot\": false}");
}

TEST(HostileSizes, ElementRunnerMemoryDoesNotGrowWithTheIncrements) {
  const fs::path dir = scratch_folder("sizes_stream");
  auto run = [&](long n) {
    write(dir / "long.json", long_elastic_scene(n));
    std::ostringstream out, err;
    EXPECT_EQ(driver::element_cli({"--quiet", "--output", (dir / "out").string(), (dir / "long.json").string()}, out, err), 0)
        << err.str();
    // Every row was written: the header, the initial row and one per increment.
    std::ifstream csv(dir / "out" / "long.csv");
    long rows = 0;
    for (std::string line; std::getline(csv, line);) rows += !line.empty() && line[0] != '#';
    EXPECT_EQ(rows, n + 2);
  };
  run(1000);  // the first run's allocations (material, files) set the baseline
  const long before = max_rss_kb();
  const long n = 200000;
  run(n);
  const long grown_kb = max_rss_kb() - before;
  // Holding the rows would take n records plus n CSV lines of some 230 characters: at least
  // n * (sizeof(Record) + 230) bytes (some 100 MB). Streamed, the peak stays within 8 MB.
  const double held_kb = n * (sizeof(driver::Record) + 230.0) / 1024.0;
  EXPECT_LT(8 * 1024, held_kb / 4);  // the bound could catch rows held in memory
  EXPECT_LT(grown_kb, 8 * 1024) << "peak memory grew by " << grown_kb << " kB over " << n << " increments";
  fs::remove_all(dir);
}

TEST(HostileSizes, FailedRunAfterManyRowsLeavesTheGoodCsvWhole) {
  const fs::path dir = scratch_folder("sizes_failed");
  const fs::path out = dir / "out";
  const std::string material = "{\"file\": \"" + parameter_file() + "\", \"integrator\": {\"max_substeps\": 10}}";
  // 5000 rows of an elastic path, then one 5 % increment the integrator cannot do without cut-back.
  const std::string steps = "[" + strain_step + "5000}, {\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 5, \"increments\": 1}]";
  write(dir / "t.json", scene_json(steps, 100.0, 0.7, ", \"solver\": {\"max_halvings\": 0}, \"output\": {\"plot\": false}", material));
  fs::create_directories(out);
  const std::string good = "a good result of an earlier run\n";
  write(out / "t.csv", good);
  std::ostringstream o, e;
  EXPECT_EQ(driver::element_cli({"--quiet", "--output", out.string(), (dir / "t.json").string()}, o, e), 1) << e.str();
  // The good CSV is untouched, no temporary file is left, and the failed one holds every row.
  EXPECT_EQ(common::read_input_file((out / "t.csv").string()), good);
  EXPECT_EQ(everything_under(out), (std::vector<std::string>{"t.csv", "t.failed.csv", "t.reproducer.json"}));
  const std::string failed = common::read_input_file((out / "t.failed.csv").string());
  // Streamed, it is the same text as the whole run written at once: the failure line above the
  // column names, then the 5001 rows.
  const driver::ElementScene scene = driver::read_scene((dir / "t.json").string());
  const driver::RunResult r = driver::run_scene(scene);
  ASSERT_FALSE(r.ok);
  ASSERT_EQ(r.records.size(), 5001u);
  EXPECT_EQ(failed, driver::csv_text(scene, r));
  EXPECT_NE(failed.find("# RUN FAILED: /steps/1 (drained_triaxial_compression)"), std::string::npos);
  EXPECT_LT(failed.find("# RUN FAILED"), failed.find("increment,time,"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace acst::test::hostile_sizes_test
