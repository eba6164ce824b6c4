// Names from the input that become file names or reach a generated gnuplot script (issue 14:
// command execution, writing outside the output folder), in the three tools: every such name is
// a plain stem (common::require_plain_stem), a bad one is refused with exit 2, its JSON path and
// nothing written; free text (titles, labels) reaches a script only through common::gp_quoted and
// runs nothing; a good run writes only inside its output folder.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "acst_calibration/cli.hpp"
#include "acst_common/files.hpp"
#include "acst_common/gnuplot.hpp"
#include "acst_driver/cli.hpp"
#include "acst_footing_tool/cli.hpp"
#include "acst_footing_tool/output.hpp"
#include "acst_footing_tool/scene.hpp"
#include "driver_scenes.hpp"
#include "scratch.hpp"

namespace acst::test::hostile_names_test {
namespace {

namespace fs = std::filesystem;
using Cli = int (*)(const std::vector<std::string>&, std::ostream&, std::ostream&);

struct Outcome {
  int rc;
  std::string err;
};

Outcome run(Cli cli, const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int rc = cli(args, out, err);
  return {rc, err.str()};
}

void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// The tool refuses the input with exit 2, names `json_path` and says what a plain stem is, and
// the scratch folder holds afterwards exactly what it held before.
void expect_refused(Cli cli, const fs::path& dir, const fs::path& input, const std::string& json_path) {
  const std::vector<std::string> before = everything_under(dir);
  const Outcome o = run(cli, {"--quiet", "--output", (dir / "out").string(), input.string()});
  EXPECT_EQ(o.rc, 2) << o.err;
  EXPECT_NE(o.err.find(json_path + ": '"), std::string::npos) << o.err;
  EXPECT_NE(o.err.find("is not a plain file stem"), std::string::npos) << o.err;
  EXPECT_EQ(everything_under(dir), before) << o.err;
}

const std::string hostile_name = "x'\\nsystem('touch pwned')\\n'";  // as JSON text
const std::string data = std::string(ACST_SOURCE_DIR) + "/data";

// ---- acst_element ------------------------------------------------------------------------

const std::string short_shear =
    "[{\"control\": {\"11\": {\"strain_pct\": 0.05}, \"22\": {\"stress\": 0}, \"33\": {\"stress\": 0},"
    " \"12\": {\"strain_pct\": 0.2}, \"13\": {\"stress\": 0}, \"23\": {\"stress\": 0}}, \"increments\": 5}]";

TEST(HostileNames, ElementOutputNameMustBeAPlainStem) {
  const fs::path dir = scratch_folder("names_element");
  for (const std::string& name : {hostile_name, std::string(".."), std::string("../escape"), std::string("a b")}) {
    write(dir / "scene.json", scene_json(short_shear, 100.0, 0.7, ", \"output\": {\"name\": \"" + name + "\"}"));
    expect_refused(driver::element_cli, dir, dir / "scene.json", "/output/name");
  }
  fs::remove_all(dir);
}

TEST(HostileNames, ElementSceneFileNameWithoutAnOutputNameMustBeAPlainStem) {
  const fs::path dir = scratch_folder("names_element_file");
  const fs::path scene = dir / "it's\nsystem('touch pwned').json";
  write(scene, scene_json(short_shear));
  expect_refused(driver::element_cli, dir, scene, "/output/name (not given; the scene file's name would be used)");
  fs::remove_all(dir);
}

// A lab file's id is free text: it reaches the figure's script as a key title, quoted.
TEST(HostileNames, ElementLabIdReachesTheFigureQuotedAndRunsNothing) {
  if (!common::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = scratch_folder("names_element_lab");
  write(dir / "lab.csv", "# id: `touch " + (dir / "marker").string() + "` it's \" ; system('touch " + (dir / "marker").string() +
                             "')\n# sigma3_kPa: 100\neps_a_pct,q_kPa\n0,0\n0.05,20\n");
  write(dir / "t.json", scene_json(short_shear, 100.0, 0.7, ", \"lab_data\": \"lab.csv\""));
  const Outcome o = run(driver::element_cli, {"--quiet", "--output", (dir / "out").string(), (dir / "t.json").string()});
  EXPECT_EQ(o.rc, 0) << o.err;
  EXPECT_EQ(o.err, "");  // no gnuplot warning: the script is valid
  EXPECT_TRUE(fs::exists(dir / "out" / "t.png"));
  EXPECT_FALSE(fs::exists(dir / "marker"));
  EXPECT_EQ(everything_under(dir, dir / "out"), (std::vector<std::string>{"lab.csv", "out", "t.json"}));
  fs::remove_all(dir);
}

// ---- acst_fit ----------------------------------------------------------------------------

std::string fit_description(const std::string& extra_top = "", const std::string& extra_experiment = "",
                            const std::string& data_file = data + "/lab/fukushima_tatsuoka_1984/ft84_fig5a_sc1p0.csv") {
  return "{\"material\": {\"file\": \"" + data + "/parameters/toyoura_acst_guide.json\"}," +
         " \"parameters\": {\"d1\": {\"start\": 0.5, \"bounds\": [0.1, 2.0]}}," +
         " \"experiments\": [{\"data\": \"" + data_file + "\"" + extra_experiment + "}]," +
         " \"optimizer\": {\"design_points\": 0, \"starts\": 1, \"max_iterations\": 1, \"threads\": 1}" + extra_top + "}";
}

TEST(HostileNames, FitNameIdAndGroupMustBePlainStems) {
  const fs::path dir = scratch_folder("names_fit");
  const struct {
    std::string top, experiment, path;
  } cases[] = {{", \"name\": \"../escape\"", "", "/name"},
               {", \"name\": \"" + hostile_name + "\"", "", "/name"},
               {"", ", \"id\": \"../../escape\"", "/experiments/0/id"},
               {"", ", \"id\": \"" + hostile_name + "\"", "/experiments/0/id"},
               {"", ", \"group\": \"a/../../b\"", "/experiments/0/group"},
               {", \"defaults\": {\"group\": \".\"}", "", "/defaults/group"}};
  for (const auto& c : cases) {
    write(dir / "fit.json", fit_description(c.top, c.experiment));
    expect_refused(calibration::fit_cli, dir, dir / "fit.json", c.path);
  }
  fs::remove_all(dir);
}

TEST(HostileNames, FitDefaultNamesFromFileNamesMustBePlainStems) {
  const fs::path dir = scratch_folder("names_fit_files");
  // The description's file name names the outputs when /name is not given.
  write(dir / "fit '1'.json", fit_description());
  expect_refused(calibration::fit_cli, dir, dir / "fit '1'.json", "/name (not given; the description file's name would be used)");
  fs::remove(dir / "fit '1'.json");
  // The data file's name is the experiment's id when /id is not given.
  fs::copy_file(data + "/lab/fukushima_tatsuoka_1984/ft84_fig5a_sc1p0.csv", dir / "lab`x`.csv");
  write(dir / "fit.json", fit_description("", "", (dir / "lab`x`.csv").string()));
  expect_refused(calibration::fit_cli, dir, dir / "fit.json", "/experiments/0/id (not given; the data file's name would be used)");
  fs::remove_all(dir);
}

TEST(HostileNames, AFitWritesOnlyInsideItsOutputFolder) {
  const fs::path dir = scratch_folder("names_fit_good");
  write(dir / "fit.json", fit_description(", \"description\": \"quotes \\\" and \\\\ and a\\nbreak\"", ", \"id\": \"ft84\", \"group\": \"dense\""));
  const Outcome o = run(calibration::fit_cli, {"--quiet", "--output", (dir / "out").string(), (dir / "fit.json").string()});
  EXPECT_EQ(o.rc, 0) << o.err;
  EXPECT_EQ(everything_under(dir, dir / "out"), (std::vector<std::string>{"fit.json", "out"}));
  EXPECT_TRUE(fs::exists(dir / "out" / "fit_report.json"));
  EXPECT_TRUE(fs::exists(dir / "out" / "curves" / "ft84.csv"));
  // The free-text description goes into the JSON report through the JSON library: it reads back.
  const auto report = nlohmann::json::parse(common::read_input_file((dir / "out" / "fit_report.json").string()));
  EXPECT_EQ(report["description"], "quotes \" and \\ and a\nbreak");
  if (common::gnuplot_available()) {
    EXPECT_TRUE(fs::exists(dir / "out" / "curves" / "ft84.png")) << o.err;
  }
  fs::remove_all(dir);
}

// ---- acst_mpm ----------------------------------------------------------------------------

std::string mpm_scene(const std::string& name, const std::string& output = "") {
  return "{\"name\": \"" + name + "\", \"grid\": {\"cell_size\": 0.5}," +
         " \"materials\": {\"soil\": {\"model\": \"linear_elastic\", \"parameters\": {\"E\": 1000, \"nu\": 0.3}}}," +
         " \"bodies\": [{\"material\": \"soil\", \"x_range\": [0, 2], \"y_range\": [0, 1], \"density\": 1000}]," +
         " \"stop\": {\"steps\": 3}" + output + "}";
}

TEST(HostileNames, MpmSceneNameMustBeAPlainStem) {
  const fs::path dir = scratch_folder("names_mpm");
  for (const std::string& name : {std::string("."), std::string(".."), std::string("../escape"), hostile_name}) {
    write(dir / "scene.json", mpm_scene(name));
    expect_refused(mpm::mpm_cli, dir, dir / "scene.json", "/name");
  }
  fs::remove_all(dir);
}

// The lab label is free text: it reaches the load-settlement script as a key title, quoted.
TEST(HostileNames, MpmLabLabelReachesTheFigureQuotedAndRunsNothing) {
  if (!common::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = scratch_folder("names_mpm_label");
  const std::string marker = (dir / "marker").string();
  write(dir / "lab.csv", "S_over_B,q_kPa\n0,0\n0.1,100\n");
  write(dir / "load.csv", "S_over_B,q_kPa\n0,0\n0.1,90\n");
  // A backquote, quotes, and a line break before a shell escape ('!'), which ran through the
  // former single-quoted literal (a string left open at the end of a line ends there).
  const std::string label = "`touch " + marker + "` it's \\\"q\\\"\\n!touch " + marker + "\\n";
  const mpm::Scene scene = mpm::parse_scene(
      mpm_scene("label", ", \"output\": {\"lab_curve\": \"lab.csv\", \"lab_label\": \"" + label + "\"}"), (dir / "s.json").string());
  EXPECT_EQ(mpm::write_load_figure(scene, dir.string(), "load.csv"), "");
  EXPECT_TRUE(fs::exists(dir / "load_settlement.png"));
  EXPECT_FALSE(fs::exists(marker));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace acst::test::hostile_names_test
