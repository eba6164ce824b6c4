// A full disk while the figures are drawn (issue 57), in the four tools: gnuplot exits 0 after a
// write that failed, and its cut PNG replaced the earlier figure (acst_fit even published its
// *.png.tmp files) with exit 0. Simulated by a file-size limit of 24 kB with SIGXFSZ ignored
// (tests/support/file_size_limit.hpp; a small full tmpfs behaves the same, docs/reliability.md), above every CSV, JSON and VTK file of these small runs
// (at most 17 kB) and below every figure (35-95 kB). Each tool ends as a missing figure makes it
// end (exit 0, a warning: the numbers are complete), with every PNG it leaves whole, no temporary
// file, and an earlier figure at the same name byte for byte as it was.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "acst_calibration/cli.hpp"
#include "acst_common/files.hpp"
#include "acst_common/gnuplot.hpp"
#include "acst_common/png_file.hpp"
#include "acst_driver/cli.hpp"
#include "acst_footing_tool/cli.hpp"
#include "acst_sweep/sweep_runner.hpp"
#include "file_size_limit.hpp"
#include "scratch.hpp"

namespace acst::test::full_disk_test {
namespace {

namespace fs = std::filesystem;
using Tool = int (*)(const std::vector<std::string>&, std::ostream&, std::ostream&);

const std::string data = std::string(ACST_SOURCE_DIR) + "/data";
constexpr rlim_t full_disk_bytes = 24 * 1024;

struct Outcome {
  int rc;
  std::string err;
};

enum class Disk { room, full, limit_kills_writer };

Outcome run(Tool tool, const fs::path& out, const fs::path& input, Disk disk) {
  std::ostringstream o, e;
  int rc = 0;
  {
    const std::unique_ptr<FileSizeLimit> limit(
        disk == Disk::room ? nullptr : new FileSizeLimit(full_disk_bytes, disk == Disk::limit_kills_writer));
    // One thread where a tool takes --threads: acst_element runs one anyway.
    std::vector<std::string> args{"--quiet", "--output", out.string(), input.string()};
    if (tool != driver::element_cli) args.insert(args.begin(), {"--threads", "1"});
    rc = tool(args, o, e);
  }
  return {rc, e.str()};
}

int sweep_tool(const std::vector<std::string>& a, std::ostream& o, std::ostream& e) { return mpm::sweep_cli(a, o, e); }

// The tool run twice into `out`, the second time on a full disk: `kept` (figures of the first run
// that the second writes again in their place) must come through byte for byte.
void expect_figures_whole(Tool tool, const fs::path& out, const fs::path& input, const std::vector<fs::path>& kept) {
  const Outcome first = run(tool, out, input, Disk::room);
  ASSERT_EQ(first.rc, 0) << first.err;
  std::vector<std::string> earlier;
  for (const fs::path& f : kept) {
    ASSERT_EQ(common::png_problem((out / f).string()), "") << f;
    earlier.push_back(common::read_input_file((out / f).string()));
  }
  const Outcome second = run(tool, out, input, Disk::full);
  EXPECT_EQ(second.rc, 0) << second.err;
  EXPECT_NE(second.err.find("(a full disk?)"), std::string::npos) << second.err;
  for (std::size_t k = 0; k < kept.size(); ++k)
    EXPECT_TRUE(common::read_input_file((out / kept[k]).string()) == earlier[k]) << kept[k] << " is not the earlier figure";
  for (const std::string& name : everything_under(out)) {
    EXPECT_EQ(name.find(".tmp"), std::string::npos) << "a temporary file left: " << name;
    if (fs::path(name).extension() != ".png") continue;
    EXPECT_EQ(common::png_problem((out / name).string()), "") << name;
  }
}

std::string small_footing() { return common::read_input_file(std::string(ACST_SOURCE_DIR) + "/tests/sweeps/small_footing.json"); }

}  // namespace

TEST(FullDisk, ElementToolKeepsTheEarlierFigure) {
  if (!common::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = scratch_folder("full_disk_element");
  std::ofstream(dir / "t.json") << "{\"material\": {\"file\": \"" << data << "/parameters/toyoura_acst_guide.json\"},"
                                << " \"initial_state\": {\"confining_pressure\": 100, \"void_ratio\": 0.7, \"bedding_angle_deg\": 0},"
                                << " \"steps\": [{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 5, \"increments\": 20}]}";
  expect_figures_whole(driver::element_cli, dir / "out", dir / "t.json", {"t.png"});
}

// A new run sets the earlier one aside into previous/; its own figures, cut short, are not kept.
TEST(FullDisk, MpmToolLeavesNoCutFigure) {
  if (!common::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = scratch_folder("full_disk_mpm");
  std::string scene = small_footing();
  scene.replace(scene.find("\"../../data"), 11, "\"" + data);
  scene.replace(scene.find("\"cell_size\": 0.1"), 16, "\"cell_size\": 0.15");
  scene.replace(scene.find("\"S_over_B\": 0.06"), 16, "\"S_over_B\": 0.005");
  std::ofstream(dir / "s.json") << scene;
  expect_figures_whole(mpm::mpm_cli, dir / "out", dir / "s.json", {});
  EXPECT_FALSE(fs::exists(dir / "out" / "load_settlement.png"));
  EXPECT_TRUE(fs::exists(dir / "out" / "previous" / "load_settlement.png"));
}

TEST(FullDisk, SweepToolKeepsTheEarlierGroupFigure) {
  if (!common::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = scratch_folder("full_disk_sweep");
  std::ofstream(dir / "s.json") << "{\"name\": \"s\", \"base\": \"" << ACST_SOURCE_DIR << "/tests/sweeps/small_footing.json\","
                                << " \"set\": {\"/grid/cell_size\": 0.15, \"/stop/S_over_B\": 0.005},"
                                << " \"cases\": [{\"name\": \"a\"}]}";
  // The second run keeps the case and draws the group figure again.
  expect_figures_whole(sweep_tool, dir / "out", dir / "s.json", {"figures/all.png"});
}

// The result set replaces the earlier one whole: a figure cut short is left out of it, and no
// *.png.tmp is published.
TEST(FullDisk, FitToolPublishesNoCutOrTemporaryFigure) {
  if (!common::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = scratch_folder("full_disk_fit");
  std::ofstream(dir / "f.json") << "{\"name\": \"fit\", \"material\": {\"file\": \"" << data << "/parameters/toyoura_acst_guide.json\"},"
                                << " \"parameters\": {\"d1\": {\"start\": 0.5, \"bounds\": [0.1, 2.0]}},"
                                << " \"experiments\": [{\"id\": \"first\", \"data\": \"" << data
                                << "/lab/fukushima_tatsuoka_1984/ft84_fig5a_sc1p0.csv\"}],"
                                << " \"optimizer\": {\"design_points\": 0, \"starts\": 1, \"max_iterations\": 1, \"threads\": 1}}";
  expect_figures_whole(calibration::fit_cli, dir / "out", dir / "f.json", {});
  EXPECT_TRUE(fs::exists(dir / "out" / "fit_parameters.json"));
  EXPECT_FALSE(fs::exists(dir / "out" / "fit_overview.png"));
  // With gnuplot killed at the limit (SIGXFSZ, as under `ulimit -f`) the half-written *.png.tmp
  // were published in the set.
  const Outcome killed = run(calibration::fit_cli, dir / "out", dir / "f.json", Disk::limit_kills_writer);
  EXPECT_EQ(killed.rc, 0) << killed.err;
  EXPECT_NE(killed.err.find("gnuplot failed"), std::string::npos) << killed.err;
  for (const std::string& name : everything_under(dir / "out")) EXPECT_EQ(name.find(".tmp"), std::string::npos) << name;
}

}  // namespace acst::test::full_disk_test
