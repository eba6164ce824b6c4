// acst_sweep (docs/sweeps.md): the description expands to the cases it names and refuses bad ones
// with their JSON path; a sweep runs, gathers rows that agree with each case's own summary, keeps
// finished cases, reports a failed one without stopping the others, and a sweep killed in the middle
// of a case resumes from the checkpoint to the same table as a run that was never interrupted.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>

#include "acst_common/files.hpp"
#include "acst_common/input_error.hpp"
#include "acst_footing_tool/fields.hpp"
#include "acst_footing_tool/first_peak.hpp"
#include "acst_sweep/kept_results.hpp"
#include "acst_sweep/sweep.hpp"
#include "acst_sweep/sweep_case.hpp"
#include "acst_sweep/sweep_runner.hpp"
#include "cli_capture.hpp"
#include "scratch.hpp"
#include "sweep_runs.hpp"

namespace fs = std::filesystem;
using nlohmann::json;
using namespace acst::mpm;
using sweep_runs::data_rows;
using sweep_runs::numbers_in;
using sweep_runs::parse_error;
using sweep_runs::relative_links;
using sweep_runs::comparable_rows;
using sweep_runs::read_json;
using sweep_runs::sweep;
using sweep_runs::write;
static const std::string& base_scene = sweep_runs::small_footing;

namespace {


// A description around the small footing; `cases` is the JSON array of cases, `extra` more keys.
std::string description(const std::string& cases, const std::string& extra = "") {
  return R"({"name": "t", "base": ")" + base_scene + R"(", "cases": )" + cases + (extra.empty() ? "" : ", " + extra) + "}";
}


using acst::test::Cli;






// (S/B, q) of each row of an acst_mpm load record, read by column name.
std::vector<std::vector<double>> load_record(const fs::path& csv) {
  std::istringstream in(acst::common::read_input_file(csv.string()));
  std::vector<std::vector<double>> rows;
  std::vector<std::string> header;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::istringstream cs(line);
    for (std::string cell; std::getline(cs, cell, ',');) cells.push_back(cell);
    if (header.empty()) {
      header = cells;
      continue;
    }
    auto at = [&](const std::string& name) {
      return std::stod(cells.at(static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin())));
    };
    rows.push_back({at("S_over_B"), at("q_kPa")});
  }
  return rows;
}

const std::string two_beddings = R"([{"name": "bedding_{alpha}", "group": "bedding",
    "vary": [{"name": "alpha", "path": "/bodies/0/bedding_angle_deg", "values": [0, 90]}]}])";

}  // namespace

TEST(SweepDescription, AProductOfVariablesGivesEveryCombinationInOrder) {
  const SweepSpec s = parse_sweep(description(R"([
      {"name": "V", "group": "one", "set": {"/footing/speed": 0.1}},
      {"name": "a{alpha}_b{beta}", "group": "grid",
       "vary": [{"name": "alpha", "path": "/bodies/0/bedding_angle_deg", "values": [0, 45]},
                {"name": "beta", "path": "/footing/inclination_deg", "values": [10, 20, 30.5]}]}])",
                                              R"("set": {"/stop/S_over_B": 0.05})"),
                                  "");
  ASSERT_EQ(s.cases.size(), 7u);
  EXPECT_EQ(s.cases[0].name, "V");
  EXPECT_DOUBLE_EQ(s.cases[0].scene.footing->speed, 0.1);
  const std::vector<double> betas{10, 20, 30.5};
  const std::vector<std::string> names{"a0_b10", "a0_b20", "a0_b30.5", "a45_b10", "a45_b20", "a45_b30.5"};
  for (std::size_t k = 0; k < names.size(); ++k) {
    const SweepCase& c = s.cases[k + 1];
    EXPECT_EQ(c.name, names[k]);
    EXPECT_EQ(c.groups, std::vector<std::string>{"grid"});
    EXPECT_EQ(c.scene.name, names[k]);
    EXPECT_DOUBLE_EQ(c.scene.bodies[0].bedding_angle_deg, k < 3 ? 0.0 : 45.0);
    EXPECT_DOUBLE_EQ(c.scene.footing->inclination_deg, betas[k % 3]);
    EXPECT_DOUBLE_EQ(*c.scene.stop.S_over_B, 0.05);  // the sweep's own "set" reaches every case
    EXPECT_DOUBLE_EQ(c.varied["beta"].get<double>(), betas[k % 3]);
  }
  // Relative file names in the base scene are read from the base scene's folder.
  EXPECT_NE(s.cases[0].scene.materials[0].json_text.find("\"model\""), std::string::npos);
}

TEST(SweepDescription, AVariableMaySetSeveralPathsAndACaseJoinSeveralGroups) {
  const SweepSpec s = parse_sweep(description(R"([{"name": "L{L}", "group": ["width", "all_widths"],
      "vary": [{"name": "L", "paths": ["/bodies/0/x_range/1", "/footing/centre_x"], "values": [[2.0, 1.0], [3.0, 1.5]]}]}])"),
                                  "");
  ASSERT_EQ(s.cases.size(), 2u);
  EXPECT_EQ(s.cases[1].name, "L3");  // the first path's value names the case
  EXPECT_DOUBLE_EQ(s.cases[1].scene.bodies[0].x_max, 3.0);
  EXPECT_DOUBLE_EQ(s.cases[1].scene.footing->centre_x, 1.5);
  EXPECT_EQ(s.cases[1].groups, (std::vector<std::string>{"width", "all_widths"}));
}

TEST(SweepDescription, NullRemovesAMemberAndTheCommandLineSetComesLast) {
  const SweepSpec s = parse_sweep(description(R"([{"name": "a", "set": {"/footing/interface": null}}])",
                                              R"("set": {"/grid/cell_size": 0.2})"),
                                  "", R"({"/grid/cell_size": 0.15, "/stop/S_over_B": 0.2})");
  ASSERT_EQ(s.cases.size(), 1u);
  EXPECT_EQ(s.cases[0].scene.footing->interface, FootingInterface::rough);  // the reader's default
  EXPECT_EQ(json::parse(s.cases[0].scene.text)["footing"].count("interface"), 0u);
  EXPECT_DOUBLE_EQ(s.cases[0].scene.cell_size, 0.15);
  EXPECT_DOUBLE_EQ(*s.cases[0].scene.stop.S_over_B, 0.2);
  const std::string bad = [] {
    try {
      parse_sweep(description(R"([{"name": "a"}])"), "", R"({"/grid/cells": [)");
    } catch (const acst::common::InputError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  }();
  EXPECT_NE(bad.find("--set"), std::string::npos) << bad;
}

TEST(SweepDescription, LabelsNameCasesWhoseValuesAreNotNumbers) {
  const SweepSpec s = parse_sweep(description(R"([{"name": "m_{model}",
      "vary": [{"name": "model", "path": "/materials/sand", "labels": ["acst", "isotropic"],
                "values": ["../../data/parameters/toyoura_acst_calibrated.json",
                           "../../data/parameters/toyoura_isotropic_calibrated.json"]}]}])"),
                                  "");
  ASSERT_EQ(s.cases.size(), 2u);
  EXPECT_EQ(s.cases[1].name, "m_isotropic");
  EXPECT_NE(s.cases[1].scene.materials[0].source.find("toyoura_isotropic_calibrated"), std::string::npos);
  EXPECT_EQ(s.cases[0].groups, std::vector<std::string>{"all"});
}

TEST(SweepDescription, BadDescriptionsNameTheirJsonPath) {
  struct Bad {
    std::string text, says;
  };
  const std::vector<Bad> bad{
      {description("[]"), "/cases: expected a non-empty array"},
      {description(R"([{"name": "a", "colour": 1}])"), "/cases/0/colour: unknown key"},
      {description(R"([{"name": "a", "set": {"/footing/nothing/x": 1}}])"), "/cases/0/set: '/footing/nothing/x': the scene has no /footing/nothing"},
      {description(R"([{"name": "a", "set": {"/bodies/3/density": 1}}])"), "the scene has no /bodies/3"},
      // Tokens that cannot index an array (found by fuzz_sweep_description): refused, not thrown.
      {description(R"([{"name": "a", "set": {"/bodies//density": 1}}])"), "the scene has no /bodies/"},
      {description(R"([{"name": "a", "set": {"/bodies/99999999999999999999999/density": 1}}])"), "the scene has no /bodies/99999999999999999999999"},
      {description(R"([{"name": "a", "set": {"/bodies/1": {}}}])"), "/bodies has elements 0 to 0"},
      {description(R"([{"name": "a", "set": {"footing": 1}}])"), "is not a JSON pointer"},
      {description(R"([{"name": "a", "set": {"/bodies/0/bedding_angle_deg": "steep"}}])"),
       "/cases/0: case 'a': its scene"},
      {description(R"([{"name": "a", "set": {"/bodies/0/bedding_angle_deg": "steep"}}])"),
       "/bodies/0/bedding_angle_deg: expected a number"},
      {description(R"([{"name": "a", "set": {"/footing/colour": 1}}])"), "/footing/colour: unknown key"},
      {description(R"([{"name": "a"}, {"name": "a"}])"), "/cases/1/name: a second case named 'a'"},
      {description(R"([{"name": "a", "vary": [{"name": "x", "path": "/footing/speed", "values": [0.1, 0.2]}]}])"),
       "does not show the variable 'x'"},
      {description(R"([{"name": "a{y}", "vary": [{"name": "x", "path": "/footing/speed", "values": [0.1]}]}])"),
       "'{y}' names no variable"},
      {description(R"([{"name": "a{x}", "vary": [{"name": "x", "path": "/footing/speed", "values": [{"v": 1}]}]}])"),
       "/cases/0/vary/0/values/0: a value that is not a number or a plain name needs 'labels'"},
      {description(R"([{"name": "../a"}])"), "/cases/0/name: '../a' is not a plain file stem"},
      {description(R"([{"name": "a{L}", "vary": [{"name": "L", "paths": ["/footing/speed", "/footing/width"], "values": [[0.1]]}]}])"),
       "/cases/0/vary/0/values/0: expected an array of 2 values, one per path"},
      {description(R"([{"name": "a{L}", "vary": [{"name": "L", "path": "/footing/speed", "paths": [], "values": [1]}]}])"),
       "give only one of path, paths"},
      {description(R"([{"name": "a", "group": ["ok", "../up"]}])"), "/cases/0/group/1"},
      {R"({"name": "t", "cases": [{"name": "a"}]})", "/cases/0: 'base' is required"},
      {R"({"name": "t", "base": "/nonexistent/scene.json", "cases": [{"name": "a"}]})", "/base: the base scene '/nonexistent/scene.json': cannot open: "},
      {description(R"([{"name": "a"}])", R"("gather": {"load_at_S_over_B": [-1]})"), "/gather/load_at_S_over_B/0"},
      {description(R"([{"name": "a"}])", R"("gather": {"case_figures": ["../x.png"]})"), "/gather/case_figures/0: '../x.png' is not a plain file stem"},
  };
  for (const Bad& b : bad) {
    const std::string message = parse_error(b.text);
    EXPECT_NE(message.find(b.says), std::string::npos) << "description: " << b.text << "\nmessage: " << message;
  }
}

TEST(SweepRun, GathersEveryCaseAndKeepsFinishedOnes) {
  const fs::path dir = acst::test::scratch_folder("sweep_run");
  const fs::path file = write(dir / "sweep.json", description(two_beddings, R"("gather": {"load_at_S_over_B": [0.03, 0.5]},
      "findings": [{"finding": "Bedding 0 carries more", "checks": [{"expect": "greater", "cases": ["bedding_0", "bedding_90"], "column": "q_ult_kPa"}]},
                   {"finding": "Bedding 90 carries more", "checks": [{"expect": "greater", "cases": ["bedding_90", "bedding_0"], "column": "q_ult_kPa"}]}])"));
  const std::string out = (dir / "out").string();
  const Cli first = sweep({"--quiet", "--no-plot", "--threads", "1", "--output", out, "--report", (dir / "report.md").string(), file.string()});
  ASSERT_EQ(first.rc, 0) << first.err;
  // The report judges each finding on the table (the comparison below checks the physics).
  for (const fs::path& report : {fs::path(out) / "report.md", dir / "report.md"}) {
    const std::string text = acst::common::read_input_file(report.string());
    EXPECT_NE(text.find("1. Bedding 0 carries more: **reproduced**"), std::string::npos) << text;
    EXPECT_NE(text.find("2. Bedding 90 carries more: **not reproduced**"), std::string::npos) << text;
    EXPECT_NE(text.find("acst_sweep --quiet --no-plot"), std::string::npos) << text;
  }
  const json rows = read_json(fs::path(out) / "table.json")["cases"];
  ASSERT_EQ(rows.size(), 2u);
  for (const json& r : rows) {
    const fs::path case_dir = fs::path(out) / "cases" / r["case"].get<std::string>();
    const json summary = read_json(case_dir / "summary.json");
    EXPECT_EQ(r["status"], "done");
    // The row's peak is read back from the load record, the summary's is the run's own: within
    // the record's 10 significant digits.
    EXPECT_NEAR(r["q_ult_kPa"].get<double>(), summary["q_ult_kPa"].get<double>(), 1e-6 * summary["q_ult_kPa"].get<double>());
    EXPECT_EQ(r["steps"], summary["steps"]);
    EXPECT_GT(r["q_ult_kPa"].get<double>(), 100.0);
    // q at S/B 0.03 lies between the two records around it; 0.5 is past the run's end (0.06).
    const std::vector<std::vector<double>> record = load_record(case_dir / "load_settlement.csv");
    for (std::size_t k = 1; k < record.size(); ++k) {
      if (!(record[k - 1][0] <= 0.03 && record[k][0] >= 0.03)) continue;
      EXPECT_GE(r["q_at_S_over_B_0.03_kPa"].get<double>(), std::min(record[k - 1][1], record[k][1]));
      EXPECT_LE(r["q_at_S_over_B_0.03_kPa"].get<double>(), std::max(record[k - 1][1], record[k][1]));
    }
    EXPECT_TRUE(r["q_at_S_over_B_0.5_kPa"].is_null());
    EXPECT_TRUE(fs::exists(case_dir / "sweep_case.json"));
    EXPECT_FALSE(fs::exists(case_dir / "checkpoint.bin"));
  }
  EXPECT_EQ(rows[0]["alpha"], 0);
  EXPECT_EQ(rows[1]["alpha"], 90);
  EXPECT_DOUBLE_EQ(rows[1]["bedding_angle_deg"].get<double>(), 90.0);
  // The bedding planes across the load (0 deg) carry more than along it (90 deg) on this dense sand.
  EXPECT_GT(rows[0]["q_ult_kPa"].get<double>(), rows[1]["q_ult_kPa"].get<double>());
  for (const char* f : {"table.csv", "table.md", "sweep.json", "report.md"}) EXPECT_TRUE(fs::exists(fs::path(out) / f)) << f;

  // Run again: both cases are kept as they are.
  const auto stamp = fs::last_write_time(fs::path(out) / "cases" / "bedding_0" / "summary.json");
  const Cli again = sweep({"--no-plot", "--output", out, file.string()});
  EXPECT_EQ(again.rc, 0) << again.err;
  EXPECT_NE(again.err.find("2 already run (kept), 0 to run"), std::string::npos) << again.err;
  EXPECT_EQ(fs::last_write_time(fs::path(out) / "cases" / "bedding_0" / "summary.json"), stamp);
  EXPECT_EQ(read_json(fs::path(out) / "table.json")["cases"], rows);

  // A changed scene is not mistaken for the finished case: refused, naming what changed.
  const fs::path changed = write(dir / "changed.json", description(two_beddings, R"("set": {"/footing/speed": 0.04})"));
  const Cli refused = sweep({"--no-plot", "--output", out, changed.string()});
  EXPECT_EQ(refused.rc, 2);
  EXPECT_NE(refused.err.find("case 'bedding_0'"), std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("/scene/footing/speed"), std::string::npos) << refused.err;
  EXPECT_EQ(fs::last_write_time(fs::path(out) / "cases" / "bedding_0" / "summary.json"), stamp);
}

TEST(SweepRun, AFailedCaseIsReportedAndTheOthersRun) {
  const fs::path dir = acst::test::scratch_folder("sweep_failed");
  // The first case stops on its quasi-static check (a limit no run meets), the second runs.
  const fs::path file = write(dir / "sweep.json", description(R"([
      {"name": "strict", "set": {"/quasi_static": {"kinetic_ratio_limit": 1e-12, "check_from_S_over_B": 0.01,
                                                    "on_excess": "stop"}}},
      {"name": "plain"}])"));
  const std::string out = (dir / "out").string();
  const Cli c = sweep({"--quiet", "--no-plot", "--threads", "1", "--output", out, file.string()});
  EXPECT_EQ(c.rc, 1);
  EXPECT_NE(c.out.find("1 of 2 cases done; not done: strict (failed)"), std::string::npos) << c.out;
  const json rows = read_json(fs::path(out) / "table.json")["cases"];
  EXPECT_EQ(rows[0]["status"], "failed");
  EXPECT_NE(rows[0]["message"].get<std::string>().find("not quasi-static"), std::string::npos);
  EXPECT_EQ(rows[0]["load_file"], "load_settlement.failed.csv");
  EXPECT_EQ(rows[1]["status"], "done");
  // Kept as failed on the next run, run again when asked.
  const Cli kept = sweep({"--no-plot", "--output", out, file.string()});
  EXPECT_EQ(kept.rc, 1);
  EXPECT_NE(kept.err.find("2 already run (kept), 0 to run"), std::string::npos) << kept.err;
  const Cli retried = sweep({"--no-plot", "--retry-failed", "--threads", "1", "--output", out, file.string()});
  EXPECT_EQ(retried.rc, 1);
  EXPECT_NE(retried.err.find("1 already run (kept), 1 to run"), std::string::npos) << retried.err;
}

TEST(SweepRun, AForeignFolderOrBadCommandLineIsRefusedAndLeftAlone) {
  const fs::path dir = acst::test::scratch_folder("sweep_foreign");
  const fs::path file = write(dir / "sweep.json", description(two_beddings));
  const fs::path out = dir / "out";
  fs::create_directories(out);
  write(out / "notes.txt", "mine");
  const Cli c = sweep({"--output", out.string(), file.string()});
  EXPECT_EQ(c.rc, 2);
  EXPECT_NE(c.err.find("notes.txt"), std::string::npos) << c.err;
  EXPECT_EQ(acst::test::everything_under(out), std::vector<std::string>{"notes.txt"});
  EXPECT_EQ(sweep({"--threads", "0", file.string()}).rc, 2);
  EXPECT_EQ(sweep({(dir / "missing.json").string()}).rc, 2);
  // A case that cannot start (its followed particle outside the soil) stops the sweep before any
  // case runs, naming the case and the scene's path.
  const fs::path unstartable = write(dir / "unstartable.json", description(R"([{"name": "fine"},
      {"name": "outside", "set": {"/output/particle_histories": [{"name": "P", "at": [30, 0.5]}]}}])"));
  const fs::path fresh = dir / "fresh";
  const Cli refused = sweep({"--output", fresh.string(), unstartable.string()});
  EXPECT_EQ(refused.rc, 2);
  EXPECT_NE(refused.err.find("case 'outside' (/cases/1): /output/particle_histories/0/at"), std::string::npos) << refused.err;
  EXPECT_FALSE(fs::exists(fresh / "cases" / "fine"));
  const Cli list = sweep({"--list", file.string()});
  EXPECT_EQ(list.rc, 0);
  EXPECT_NE(list.out.find("bedding_90  group bedding  from /cases/0"), std::string::npos) << list.out;
}

// The tool as a process: killed (SIGKILL) once its first case has written a checkpoint, then run
// again, it resumes that case and ends with the table of a sweep that ran straight through.
TEST(SweepRun, AKilledSweepResumesToTheSameTable) {
  const fs::path dir = acst::test::scratch_folder("sweep_kill");
  const fs::path file = write(dir / "sweep.json", description(two_beddings, R"("set": {"/output/checkpoint_every_s": 0.05})"));
  const std::string straight = (dir / "straight").string(), killed = (dir / "killed").string();
  ASSERT_EQ(sweep({"--quiet", "--no-plot", "--threads", "1", "--output", straight, file.string()}).rc, 0);

  const fs::path checkpoint = fs::path(killed) / "cases" / ".bedding_0.partial" / "checkpoint.bin";
  ASSERT_TRUE(sweep_runs::kill_sweep_when({"--output", killed, file.string()}, checkpoint))
      << "the sweep ended before it could be killed";
  ASSERT_TRUE(fs::exists(checkpoint));
  ASSERT_FALSE(fs::exists(fs::path(killed) / "cases" / "bedding_0"));

  const Cli resumed = sweep({"--no-plot", "--threads", "1", "--output", killed, file.string()});
  ASSERT_EQ(resumed.rc, 0) << resumed.err;
  EXPECT_NE(resumed.err.find("bedding_0: done"), std::string::npos) << resumed.err;
  EXPECT_NE(resumed.err.find("(resumed from its checkpoint)"), std::string::npos) << resumed.err;
  EXPECT_TRUE(read_json(fs::path(killed) / "table.json")["cases"][0]["resumed"].get<bool>());
  EXPECT_EQ(comparable_rows(killed), comparable_rows(straight));
  // The killed run's load record equals the straight one's row by row (every digit written).
  EXPECT_EQ(acst::common::read_input_file((fs::path(killed) / "cases/bedding_0/load_settlement.csv").string()),
            acst::common::read_input_file((fs::path(straight) / "cases/bedding_0/load_settlement.csv").string()));
}

namespace {

// Records the order in which a sweep hands its cases out to `n` workers, and runs none of them.
class RecordingWorkers : public CaseDistributor {
 public:
  explicit RecordingWorkers(int n) : n_(n) {}
  bool coordinator() const override { return true; }
  int workers() const override { return n_; }
  bool all(bool ok) override { return ok; }
  void distribute(const std::vector<std::size_t>& pending, const RunOne&, const Finished&, const MayStart&) override { order = pending; }
  std::vector<std::size_t> order;

 private:
  int n_;
};

}  // namespace

// Over several workers the longest case goes first (so that no worker idles at the end while
// another runs a long case); in turn the cases run as listed. Length: particles times steps, here
// set by the stop (0.02, 0.06, 0.04 of B) and by the half domain (half the particles).
TEST(SweepRun, SeveralWorkersGetTheLongestCasesFirst) {
  const fs::path dir = acst::test::scratch_folder("sweep_order");
  const std::string cases = R"([
      {"name": "short", "set": {"/stop/S_over_B": 0.02}},
      {"name": "long", "set": {"/stop/S_over_B": 0.06}},
      {"name": "middle", "set": {"/stop/S_over_B": 0.04}},
      {"name": "long_half", "set": {"/stop/S_over_B": 0.06, "/footing/symmetric_half": true}}])";
  const SweepSpec spec = parse_sweep(description(cases), dir.string());
  ASSERT_EQ(spec.cases.size(), 4u);
  for (int workers : {1, 2}) {
    RecordingWorkers where(workers);
    SweepRunOptions opt;
    opt.output_dir = (dir / ("out_" + std::to_string(workers))).string();
    opt.plot = false;
    opt.quiet = true;
    std::ostringstream out, err;
    EXPECT_EQ(run_sweep(spec, opt, where, out, err), 1) << err.str();  // none ran
    const std::vector<std::size_t> expected =
        workers == 1 ? std::vector<std::size_t>{0, 1, 2, 3} : std::vector<std::size_t>{1, 2, 3, 0};
    EXPECT_EQ(where.order, expected) << workers << " workers";
  }
}

// The left/right measures of the table, on four particles whose answer is known: areas count by
// where a particle started and only above the shear-strain limit; heave is the largest rise.
TEST(SideMeasures, CountEachSideByWhereItsParticlesStarted) {
  Particles P;
  P.n = 4;
  P.x_initial = {0.5, 1.5, 2.5, 3.5};
  P.y_initial = {1.0, 1.0, 1.0, 1.0};
  P.volume_initial = {0.01, 0.02, 0.04, 0.08};
  const std::vector<double> y_now{1.03, 0.98, 1.01, 1.0}, gamma{0.2, 0.06, 0.01, 0.5};
  const SideMeasures m = side_measures(P, y_now, gamma, 2.0, false);
  EXPECT_DOUBLE_EQ(m.sheared_area_left, 0.03);
  EXPECT_DOUBLE_EQ(m.sheared_area_right, 0.08);
  EXPECT_NEAR(m.heave_left, 0.03, 1e-12);
  EXPECT_NEAR(m.heave_right, 0.01, 1e-12);
  const SideMeasures half = side_measures(P, y_now, gamma, 2.0, true);
  EXPECT_DOUBLE_EQ(half.sheared_area_left, half.sheared_area_right);
  EXPECT_DOUBLE_EQ(half.heave_left, half.heave_right);
}

// A load inclined toward +x pushes the soil right of the footing up and shears more of it: the
// table's side measures and H say so (the reference study's asymmetry, on the small footing).
TEST(SweepRun, AnInclinedLoadShearsMoreSoilOnTheSideItPushesTowards) {
  const fs::path dir = acst::test::scratch_folder("sweep_inclined");
  const fs::path file = write(dir / "sweep.json", description(R"([{"name": "beta20", "set": {"/footing/inclination_deg": 20, "/stop/S_over_B": 0.1}}])",
                                                              R"("gather": {"case_figures": ["load_settlement.png"]})"));
  const std::string out = (dir / "out").string();
  const fs::path extra = dir / "docs" / "study.md";  // a report in another folder, as docs/reference-study.md
  fs::create_directories(extra.parent_path());
  ASSERT_EQ(sweep({"--quiet", "--threads", "1", "--output", out, "--report", extra.string(), file.string()}).rc, 0);
  // With figures: the group's overlay and the case's own figure the description asks for, linked.
  EXPECT_TRUE(fs::exists(fs::path(out) / "figures" / "all.png"));
  EXPECT_TRUE(fs::exists(fs::path(out) / "figures" / "cases" / "beta20_load_settlement.png"));
  EXPECT_NE(acst::common::read_input_file((fs::path(out) / "report.md").string())
                .find("[load_settlement.png](figures/cases/beta20_load_settlement.png)"),
            std::string::npos);
  // Every link either report holds resolves from the report's own folder.
  for (const fs::path& report : {fs::path(out) / "report.md", extra}) {
    const std::vector<std::string> links = relative_links(acst::common::read_input_file(report.string()));
    EXPECT_EQ(links.size(), 2u) << report;  // the overlay and the case's figure
    for (const std::string& link : links)
      EXPECT_TRUE(fs::exists(report.parent_path() / link)) << report << " links " << link;
  }
  const json row = read_json(fs::path(out) / "table.json")["cases"][0];
  EXPECT_GT(row["sheared_area_right_at_end_m2"].get<double>(), 1.5 * row["sheared_area_left_at_end_m2"].get<double>());
  EXPECT_GT(row["heave_right_at_end_m"].get<double>(), row["heave_left_at_end_m"].get<double>());
  EXPECT_GT(row["H_at_peak_kN_per_m"].get<double>(), 0.0);
  // The asymmetry column is |A_left - A_right| / (A_left + A_right) of the side measures.
  const double l = row["sheared_area_left_at_end_m2"].get<double>(), r = row["sheared_area_right_at_end_m2"].get<double>();
  EXPECT_NEAR(row["sheared_area_asymmetry_at_end"].get<double>(), (r - l) / (r + l), 1e-12);
  EXPECT_GT(row["sheared_area_asymmetry_at_end"].get<double>(), 0.2);
}

// A failed run's record ends in the failure's own spikes (an ejected particle's contact force):
// the row leaves out its last 0.02 of S/B, so the peak it reports is the one before, and that
// peak stands when the load had fallen 2 % below it before the failure.
TEST(SweepRow, AFailedRunsLastMomentsDoNotMakeItsPeak) {
  const SweepSpec s = parse_sweep(description(R"([{"name": "a"}])"), "");
  const fs::path dir = acst::test::scratch_folder("sweep_row");
  std::string csv = "# a failed record\nstep,S_over_B,V_kN_per_m,H_kN_per_m,M_kNm_per_m,q_kPa\n";
  // q rises to 1000 kPa at S/B 0.1, falls to 500 at 0.3, then spikes to 5000 at 0.305.
  for (int k = 0; k <= 61; ++k) {
    const double sb = 0.005 * k, q = k == 61 ? 5000.0 : sb <= 0.1 ? 10000.0 * sb : 1000.0 - 2500.0 * (sb - 0.1);
    csv += std::to_string(k) + "," + std::to_string(sb) + "," + std::to_string(0.3 * q) + ",0,0," + std::to_string(q) + "\n";
  }
  write(dir / "load_settlement.failed.csv", csv);
  const json row = case_row(s.cases[0], dir.string(), CaseStatus::failed, "it failed", {0.2, 0.3});
  EXPECT_NEAR(row["q_ult_kPa"].get<double>(), 1000.0, 1e-6);
  EXPECT_NEAR(row["S_ult_over_B"].get<double>(), 0.1, 1e-9);
  EXPECT_TRUE(row["peak_reached"].get<bool>());
  EXPECT_NEAR(row["q_at_S_over_B_0.2_kPa"].get<double>(), 750.0, 1e-6);
  EXPECT_TRUE(row["q_at_S_over_B_0.3_kPa"].is_null());  // within the failure's approach
  EXPECT_NEAR(row["final_S_over_B"].get<double>(), 0.305, 1e-9);
  EXPECT_NEAR(row["q_first_peak_kPa"].get<double>(), 1000.0, 1e-6);  // the same peak: it is the only one
  EXPECT_NEAR(row["S_first_peak_over_B"].get<double>(), 0.1, 1e-9);
  // The same record from a run that ended: every row counts.
  fs::rename(dir / "load_settlement.failed.csv", dir / "load_settlement.csv");
  EXPECT_NEAR(case_row(s.cases[0], dir.string(), CaseStatus::done, "", {})["q_ult_kPa"].get<double>(), 5000.0, 1e-6);
}

// A curve sampled every 0.001 B: q(S/B) given piecewise linear through the points (S, q).
static std::pair<std::vector<double>, std::vector<double>> sampled(const std::vector<std::pair<double, double>>& knots) {
  std::vector<double> S, q;
  for (int k = 0; 0.001 * k <= knots.back().first + 1e-12; ++k) {
    const double s = 0.001 * k;
    std::size_t i = 1;
    while (i + 1 < knots.size() && knots[i].first < s) ++i;
    const auto [s0, q0] = knots[i - 1];
    const auto [s1, q1] = knots[i];
    S.push_back(s);
    q.push_back(q0 + (q1 - q0) * (s - s0) / (s1 - s0));
  }
  return {S, q};
}

// Dense sand's footing curve may rise to a first peak, dip and rise to a higher hump (docs/footing-study.md,
// "Loading rate"): the first peak is the first load that no load within 0.01 B of it exceeds.
TEST(FirstPeak, IsTheOnsetOfSofteningNotTheLargestLoad) {
  // Up to 1000 at S/B 0.09, down to 950 at 0.1, up to 1300 at 0.15, down to 800 at 0.2.
  const auto [S, q] = sampled({{0.0, 0.0}, {0.09, 1000.0}, {0.1, 950.0}, {0.15, 1300.0}, {0.2, 800.0}});
  const auto f = acst::mpm::first_peak(S, q);
  ASSERT_TRUE(f.has_value());
  EXPECT_NEAR(S[*f], 0.09, 1e-9);
  EXPECT_NEAR(q[*f], 1000.0, 1e-9);
}

TEST(FirstPeak, IgnoresTheStartAndDipsShorterThanItsWindow) {
  // A start transient at S/B 0.01 (600, then 300 at 0.02) comes before 0.03; a local maximum at
  // 0.05 that the load passes again within 0.008 B is no peak; the next one, at 0.12, is.
  const auto [S, q] = sampled({{0.0, 0.0}, {0.01, 600.0}, {0.02, 300.0}, {0.05, 1000.0}, {0.054, 990.0},
                               {0.058, 1010.0}, {0.12, 1400.0}, {0.2, 900.0}});
  const auto f = acst::mpm::first_peak(S, q);
  ASSERT_TRUE(f.has_value());
  EXPECT_NEAR(S[*f], 0.12, 1e-9);
}

TEST(FirstPeak, NoneWhileTheLoadRisesOrWithinAWindowOfTheEnd) {
  const auto rising = sampled({{0.0, 0.0}, {0.2, 2000.0}});
  EXPECT_FALSE(acst::mpm::first_peak(rising.first, rising.second).has_value());
  // The largest load 0.005 B before the record ends: the curve may still rise past it.
  const auto late = sampled({{0.0, 0.0}, {0.195, 2000.0}, {0.2, 1900.0}});
  EXPECT_FALSE(acst::mpm::first_peak(late.first, late.second).has_value());
  EXPECT_FALSE(acst::mpm::first_peak({}, {}).has_value());
}


TEST(KeptResults, ARecordIsThinnedToItsRowsWithItsEndsAndPeak) {
  std::string text = "# a comment\nS_over_B,q_kPa\n";
  for (int i = 0; i < 1000; ++i) text += std::to_string(i) + "," + std::to_string(i == 617 ? 5000 : i) + "\n";
  const std::string thin = decimated_csv(text, 250, "q_kPa");
  EXPECT_EQ(thin.rfind("# a comment\nS_over_B,q_kPa\n", 0), 0u);
  const std::vector<std::string> rows = data_rows(thin);
  ASSERT_GE(rows.size(), 250u);
  EXPECT_LE(rows.size(), 251u);  // the peak may fall between two evenly spread rows
  EXPECT_EQ(rows.front(), "0,0");
  EXPECT_EQ(rows.back(), "999,999");
  EXPECT_NE(std::find(rows.begin(), rows.end(), "617,5000"), rows.end());
  // Evenly spread: no gap of more than two of the 999 / 249 steps between kept rows.
  for (std::size_t k = 1; k < rows.size(); ++k)
    EXPECT_LE(std::stoi(rows[k]) - std::stoi(rows[k - 1]), 5) << rows[k];
  // A record within the budget is kept whole.
  EXPECT_EQ(decimated_csv("a,b\n1,2\n3,4\n", 250, "b"), "a,b\n1,2\n3,4\n");
}

TEST(KeptResults, AMapIsAveragedOnCellsOfItsWindow) {
  // Four particles in the cell [0, 0.5) x [0, 0.5), one in [0.5, 1) x [0, 0.5), one outside.
  const std::string map = "x_m,y_m,value\n0.1,0.1,1\n0.2,0.3,2\n0.4,0.4,3\n0.3,0.1,6\n0.7,0.2,-1.23456\n2.0,0.2,100\n";
  const std::vector<std::string> rows = data_rows(rastered_map(map, 0.5, 0.0, 1.0, 0.0, 1.0));
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0], "0.25,0.25,3,4");         // (1 + 2 + 3 + 6) / 4
  EXPECT_EQ(rows[1], "0.75,0.25,-1.235,1");    // 4 significant digits
  EXPECT_EQ(data_rows(rastered_map(map, 0.5, 5.0, 6.0, 0.0, 1.0)).size(), 0u);
}

TEST(KeptResults, EachCaseKeepsItsSummaryRecordHistoriesAndMapsInBudget) {
  const fs::path dir = acst::test::scratch_folder("sweep_kept");
  const std::string one = R"([{"name": "dense", "set": {"/output/particle_histories": [{"name": "A", "at": [1.05, 1.05]}],
      "/output/contours_at_S_over_B": [0.03], "/output/contour_fields": ["shear_strain", "N"]}}])";
  const fs::path file = write(dir / "sweep.json", description(one, R"("gather": {"keep": {"rows": 40,
      "maps": ["shear_strain_SB0.030", "N_SB0.030", "void_ratio_SB0.030"]}})"));
  const std::string out = (dir / "out").string();
  const Cli run = sweep({"--quiet", "--threads", "1", "--output", out, file.string()});  // maps need the plots
  ASSERT_EQ(run.rc, 0) << run.err;
  // The case wrote no void-ratio map: said, not fatal.
  EXPECT_NE(run.err.find("case 'dense': it wrote no map void_ratio_SB0.030.csv"), std::string::npos) << run.err;
  const fs::path cases = fs::path(out) / "cases" / "dense", kept = fs::path(out) / "kept" / "dense";
  EXPECT_EQ(acst::common::read_input_file((kept / "summary.json").string()),
            acst::common::read_input_file((cases / "summary.json").string()));
  const std::string record = acst::common::read_input_file((cases / "load_settlement.csv").string());
  const std::vector<std::string> all = data_rows(record), thin = data_rows(
      acst::common::read_input_file((kept / "load_settlement.csv").string()));
  ASSERT_GT(all.size(), 40u);
  EXPECT_LE(thin.size(), 41u);
  EXPECT_EQ(thin.front(), all.front());
  EXPECT_EQ(thin.back(), all.back());
  // The kept record still gives the case's peak to the summary's digits.
  const json summary = read_json(cases / "summary.json");
  double peak = 0.0;
  for (const std::vector<double>& r : load_record(kept / "load_settlement.csv")) peak = std::max(peak, r[1]);
  EXPECT_NEAR(peak, summary["q_ult_kPa"].get<double>(), 1e-6 * peak);
  EXPECT_LE(data_rows(acst::common::read_input_file((kept / "particle_A.csv").string())).size(), 41u);
  // The maps: cells of B/15 = 0.02 m over 4 B x 1.75 B (60 x 27 at most), every particle of the
  // window counted once, and the mean of the shear strain over them that of the particles.
  for (const char* m : {"shear_strain_SB0.030", "N_SB0.030"}) {
    const std::string full = acst::common::read_input_file((cases / (std::string(m) + ".csv")).string());
    const std::vector<std::string> cells = data_rows(acst::common::read_input_file((kept / (std::string(m) + ".csv")).string()));
    ASSERT_FALSE(cells.empty()) << m;
    EXPECT_LE(cells.size(), 60u * 27u) << m;
    long counted = 0, inside = 0;
    double sum_cells = 0.0, sum_particles = 0.0;
    for (const std::string& c : cells) {
      const std::vector<double> v = numbers_in(c);
      counted += static_cast<long>(v[3]);
      sum_cells += v[2] * v[3];
      EXPECT_GE(v[0], 1.2 - 0.6) << c;
      EXPECT_LE(v[0], 1.2 + 0.6) << c;
    }
    for (const std::string& p : data_rows(full)) {
      const std::vector<double> v = numbers_in(p);
      if (v[0] >= 0.6 && v[0] <= 1.8 && v[1] >= 1.2 - 0.45 && v[1] <= 1.2 + 0.075) ++inside, sum_particles += v[2];
    }
    EXPECT_EQ(counted, inside) << m;
    EXPECT_NEAR(sum_cells, sum_particles, 1e-3 * (1.0 + std::abs(sum_particles))) << m;  // 4 digits a cell
  }
  // The budget (docs/sweeps.md, "Kept results"): under 350 kB a case.
  std::uintmax_t bytes = 0;
  for (const fs::directory_entry& e : fs::directory_iterator(kept)) bytes += fs::file_size(e.path());
  EXPECT_LT(bytes, 350u * 1024u);
  // The kept folder is the sweep's own: a second run into the folder is not refused.
  const Cli again = sweep({"--quiet", "--no-plot", "--output", out, file.string()});
  EXPECT_EQ(again.rc, 0) << again.err;
}

TEST(KeptResults, BadKeepDescriptionsNameTheirJsonPath) {
  const std::string one = R"([{"name": "a"}])";
  EXPECT_NE(parse_error(description(one, R"("gather": {"keep": {"rows": 1}})")).find("/gather/keep/rows"), std::string::npos);
  EXPECT_NE(parse_error(description(one, R"("gather": {"keep": {"maps": ["../x"]}})")).find("/gather/keep/maps/0"),
            std::string::npos);
  EXPECT_NE(parse_error(description(one, R"("gather": {"keep": {"map_cell_over_B": 0}})")).find("/gather/keep/map_cell_over_B"),
            std::string::npos);
  EXPECT_NE(parse_error(description(one, R"("gather": {"keep": {"map_window_over_B": [4]}})")).find("/gather/keep/map_window_over_B"),
            std::string::npos);
  EXPECT_NE(parse_error(description(one, R"("gather": {"keep": {"colour": 1}})")).find("colour"), std::string::npos);
  // A map named like another kept file replaced it with a raster: a map's name has a map's form.
  for (const char* name : {"load_settlement", "particle_A", "summary", "sweep_case", "load_settlement.failed", "N_SB", "_peak"}) {
    const std::string message =
        parse_error(description(one, std::string(R"("gather": {"keep": {"maps": ["N_SB0.5", ")") + name + R"("]}})"));
    EXPECT_NE(message.find("/gather/keep/maps/1: '" + std::string(name) + "' is not a map's name"), std::string::npos) << message;
  }
}
