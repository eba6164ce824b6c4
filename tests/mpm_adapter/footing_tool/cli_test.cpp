// The acst_mpm command line (acst::mpm::mpm_cli): help, bad options and bad scenes give the
// documented exit status and a message that says what is wrong; nothing is written then.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "acst_common/files.hpp"
#include "acst_driver/cli.hpp"
#include "acst_footing_tool/cli.hpp"
#include "acst_footing_tool/output.hpp"
#include "cli_capture.hpp"
#include "output_folder.hpp"
#include "scratch.hpp"

namespace fs = std::filesystem;
using acst::mpm::mpm_cli;

namespace {

using acst::test::Cli;

Cli run(const std::vector<std::string>& args) { return acst::test::run_cli(mpm_cli, args); }

fs::path scratch(const std::string& tag) { return acst::test::scratch_folder("mpm_cli_" + tag); }

}  // namespace

TEST(MpmCli, HelpExitsZeroWithUsage) {
  const Cli c = run({"--help"});
  EXPECT_EQ(c.rc, 0);
  EXPECT_NE(c.out.find("usage: acst_mpm"), std::string::npos);
}

TEST(MpmCli, BadCommandLinesExitTwo) {
  Cli c = run({"--frobnicate", "x.json"});
  EXPECT_EQ(c.rc, 2);
  EXPECT_NE(c.err.find("unknown option '--frobnicate'"), std::string::npos) << c.err;
  c = run({"--threads", "0", "x.json"});
  EXPECT_EQ(c.rc, 2);
  EXPECT_NE(c.err.find("--threads needs an integer in [1, 1024]"), std::string::npos) << c.err;
  c = run({"--threads"});
  EXPECT_EQ(c.rc, 2);
  EXPECT_NE(c.err.find("--threads needs a value"), std::string::npos) << c.err;
  c = run({});
  EXPECT_EQ(c.rc, 2);
  EXPECT_NE(c.err.find("no scene given"), std::string::npos) << c.err;
  c = run({"a.json", "b.json"});
  EXPECT_EQ(c.rc, 2);
  EXPECT_NE(c.err.find("one scene at a time"), std::string::npos) << c.err;
}

TEST(MpmCli, InvalidSceneExitsTwoWithItsJsonPathAndWritesNothing) {
  const fs::path dir = scratch("bad");
  std::ofstream(dir / "bad.json") << R"({"name": "x", "grid": {"cell_size": -1},
    "materials": {"soil": {"model": "linear_elastic", "parameters": {"E": 1000, "nu": 0.3}}},
    "bodies": [{"material": "soil", "x_range": [0, 2], "y_range": [0, 1], "density": 1000}], "stop": {"steps": 3}})";
  const fs::path out = dir / "out";
  const Cli c = run({"--output", out.string(), (dir / "bad.json").string()});
  EXPECT_EQ(c.rc, 2);
  EXPECT_NE(c.err.find("/grid/cell_size"), std::string::npos) << c.err;
  EXPECT_FALSE(fs::exists(out));
  const Cli missing = run({(dir / "none.json").string()});
  EXPECT_EQ(missing.rc, 2);
  EXPECT_NE(missing.err.find("the scene file '" + (dir / "none.json").string() + "': cannot open: "), std::string::npos) << missing.err;
  fs::remove_all(dir);
}

TEST(MpmCli, AGoodSceneRunsAndReportsWhereItWrote) {
  const fs::path dir = scratch("good");
  std::ofstream(dir / "elastic.json") << R"({"name": "elastic", "grid": {"cell_size": 0.5},
    "materials": {"soil": {"model": "linear_elastic", "parameters": {"E": 1000, "nu": 0.3}}},
    "bodies": [{"material": "soil", "x_range": [0, 2], "y_range": [0, 1], "density": 1000}],
    "stop": {"steps": 3}})";
  const Cli c = run({"--quiet", "--no-plot", "--threads", "1", "--output", (dir / "out").string(),
                     (dir / "elastic.json").string()});
  EXPECT_EQ(c.rc, 0) << c.err;
  EXPECT_NE(c.out.find("3 steps"), std::string::npos) << c.out;
  EXPECT_TRUE(fs::exists(dir / "out" / "summary.json"));
  fs::remove_all(dir);
}

// A material failure stops the run with exit 1 and leaves, beside the partial load record, the
// failing update as an element-test scene; acst_element replays it and fails the same way.
TEST(MpmCli, AMaterialFailureLeavesAReproducerThatTheElementDriverReplays) {
  const fs::path dir = scratch("fail");
  std::ifstream in(std::string(ACST_SOURCE_DIR) + "/data/parameters/toyoura_acst_calibrated.json");
  nlohmann::json material = nlohmann::json::parse(in);
  material["integrator"] = {{"max_substeps", 1}};  // any increment that needs substeps fails
  const nlohmann::json scene = {
      {"name", "fail"},
      {"grid", {{"cell_size", 0.25}}},
      {"materials", {{"sand", material}}},
      {"bodies", {{{"material", "sand"}, {"x_range", {0, 2}}, {"y_range", {0, 1}}, {"density", 1600},
                   {"relative_density_pct", 80}, {"bedding_angle_deg", 0}}}},
      {"gravity", 9.8},
      {"initial_stress", {{"type", "geostatic"}, {"K0", 0.4}}},
      {"footing", {{"width", 0.5}, {"centre_x", 1}, {"speed", 5}}},
      {"stop", {{"S_over_B", 0.2}}}};
  std::ofstream(dir / "fail.json") << scene.dump();
  const fs::path out = dir / "out";
  const Cli c = run({"--quiet", "--no-plot", "--threads", "1", "--output", out.string(), (dir / "fail.json").string()});
  EXPECT_EQ(c.rc, 1);
  EXPECT_NE(c.err.find("more substeps than allowed"), std::string::npos) << c.err;
  EXPECT_NE(c.err.find("failure_reproducer.json"), std::string::npos) << c.err;
  ASSERT_TRUE(fs::exists(out / "failure_reproducer.json"));
  EXPECT_TRUE(fs::exists(out / "load_settlement.failed.csv"));
  EXPECT_FALSE(fs::exists(out / "load_settlement.csv")) << "no final record after a failure";

  std::ostringstream o, e;
  const int replay = acst::driver::element_cli(
      {"--quiet", "--output", (dir / "replay").string(), (out / "failure_reproducer.json").string()}, o, e);
  EXPECT_EQ(replay, 1) << e.str();
  EXPECT_NE(e.str().find("more substeps than allowed"), std::string::npos) << e.str();
  fs::remove_all(dir);
}

namespace {

void write_elastic_scene(const fs::path& file, int steps) {
  std::ofstream(file) << R"({"name": "elastic", "grid": {"cell_size": 0.5},
    "materials": {"soil": {"model": "linear_elastic", "parameters": {"E": 1000, "nu": 0.3}}},
    "bodies": [{"material": "soil", "x_range": [0, 2], "y_range": [0, 1], "density": 1000}],
    "output": {"checkpoint_every_s": 1e-9}, "stop": {"steps": )" + std::to_string(steps) + "}}";
}

std::string text_of(const fs::path& file) { return acst::common::read_input_file(file.string()); }

}  // namespace

// A new run into a used folder never leaves the files of two runs side by side: the earlier
// run's files go into previous/ (replacing an older one) before the first frame is written.
TEST(MpmCli, ARerunSetsTheEarlierRunAsideInsteadOfMixingFrames) {
  const fs::path dir = scratch("rerun");
  const fs::path out = dir / "out";
  write_elastic_scene(dir / "elastic.json", 3);
  ASSERT_EQ(run({"--quiet", "--no-plot", "--threads", "1", "--output", out.string(), (dir / "elastic.json").string()}).rc, 0);
  const std::string first_summary = text_of(out / "summary.json");
  std::ofstream(out / "particles_0042.vtp") << "a frame of the earlier run";  // as an interrupted longer run leaves
  write_elastic_scene(dir / "elastic.json", 2);
  const Cli again = run({"--quiet", "--no-plot", "--threads", "1", "--output", out.string(), (dir / "elastic.json").string()});
  ASSERT_EQ(again.rc, 0) << again.err;
  EXPECT_FALSE(fs::exists(out / "particles_0042.vtp")) << "no frame of the earlier run beside the new ones";
  EXPECT_TRUE(fs::exists(out / "previous" / "particles_0042.vtp"));
  EXPECT_EQ(text_of(out / "previous" / "summary.json"), first_summary);
  EXPECT_NE(text_of(out / "summary.json").find("\"steps\": 2"), std::string::npos);
  // a third run replaces previous/ with the second run
  ASSERT_EQ(run({"--quiet", "--no-plot", "--threads", "1", "--output", out.string(), (dir / "elastic.json").string()}).rc, 0);
  EXPECT_FALSE(fs::exists(out / "previous" / "particles_0042.vtp"));
  EXPECT_NE(text_of(out / "previous" / "summary.json").find("\"steps\": 2"), std::string::npos);
  fs::remove_all(dir);
}

// A folder holding anything acst_mpm does not write is refused (exit 2) and left as it was.
TEST(MpmCli, AFolderWithOtherFilesIsRefusedAndLeftAlone) {
  const auto [dir, out] =
      acst::test::used_output_folder("mpm_cli_foreign", {{"thesis.tex", "years of work"}, {"summary.json", "{}"}});
  write_elastic_scene(dir / "elastic.json", 2);
  const std::vector<std::string> before = acst::test::everything_under(out);
  const Cli c = run({"--quiet", "--no-plot", "--output", out.string(), (dir / "elastic.json").string()});
  acst::test::expect_foreign_file_refused(c.rc, c.err, "thesis.tex", out, before);
  EXPECT_EQ(text_of(out / "thesis.tex"), "years of work");
  fs::remove_all(dir);
}

// --resume with a damaged checkpoint: exit 2, the message names the file, and the folder of the
// interrupted run is left as it was (its good files are not set aside or overwritten).
TEST(MpmCli, ADamagedCheckpointIsRefusedWithExitTwo) {
  const fs::path dir = scratch("damaged");
  const fs::path out = dir / "out";
  write_elastic_scene(dir / "elastic.json", 3);
  ASSERT_EQ(run({"--quiet", "--no-plot", "--threads", "1", "--output", out.string(), (dir / "elastic.json").string()}).rc, 0);
  ASSERT_TRUE(fs::exists(out / "checkpoint.bin"));
  std::string bytes = text_of(out / "checkpoint.bin");
  bytes[bytes.size() / 2] ^= 0x10;
  std::ofstream(out / "checkpoint.bin", std::ios::binary) << bytes;
  const std::vector<std::string> before = acst::test::everything_under(out);
  const std::string summary = text_of(out / "summary.json");
  const Cli c = run({"--quiet", "--no-plot", "--threads", "1", "--output", out.string(), "--resume",
                     (out / "checkpoint.bin").string(), (dir / "elastic.json").string()});
  EXPECT_EQ(c.rc, 2);
  EXPECT_NE(c.err.find("is damaged"), std::string::npos) << c.err;
  EXPECT_NE(c.err.find("checkpoint.bin"), std::string::npos) << c.err;
  EXPECT_EQ(acst::test::everything_under(out), before);
  EXPECT_EQ(text_of(out / "summary.json"), summary);
  fs::remove_all(dir);
}

// The names a run writes (docs/mpm.md, "Outputs") and nothing else count as an earlier run's.
TEST(MpmCli, OnlyTheRunsOwnFileNamesCountAsAnEarlierRun) {
  using acst::mpm::is_run_output_name;
  for (const char* own : {"load_settlement.csv", "load_settlement.png", "load_settlement.gp", "load_settlement.partial.csv",
                          "load_settlement.failed.csv", "particles.pvd", "particles_0000.vtp", "particles_12345.vtp",
                          "summary.json", "checkpoint.bin", "failure_reproducer.json", "shear_strain_SB0.100.png",
                          "displacement_peak.csv", "shear_strain_peak.gp", ".summary.json.tmp123", "particle_centre_B4.csv"})
    EXPECT_TRUE(is_run_output_name(own)) << own;
  for (const char* other : {"thesis.tex", "particles_.vtp", "particles_12a.vtp", "particles_0001.vtp.bak", "summary.json~",
                            "shear_strain_.png", "shear_strain_a b.png", "displacement_x.pdf", "load_settlement.txt",
                            "previous", ".tmp1", "checkpoint.bin.old", "particle_.csv", "particle_a b.csv",
                            "particle_x.csv.bak"})
    EXPECT_FALSE(is_run_output_name(other)) << other;
}
