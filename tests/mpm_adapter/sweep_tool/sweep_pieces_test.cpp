// A sweep in pieces (docs/sweeps.md, "Pieces, shards and budgets"): run whole, in two shards
// gathered into one folder, and under a budget that stops it while a case runs and then again to
// finish, it ends with one table, digit for digit; each case's kept results are written as it
// finishes and read back whole after a kill; a folder holding kept results alone (a recorded
// study in a fresh clone) runs only what is missing and runs again what no longer matches; bad
// flags are refused before anything is written.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "acst_common/files.hpp"
#include "acst_sweep/case_selection.hpp"
#include "acst_sweep/sweep.hpp"
#include "acst_sweep/sweep_findings.hpp"
#include "acst_sweep/sweep_runner.hpp"
#include "cli_capture.hpp"
#include "scratch.hpp"
#include "sweep_runs.hpp"

namespace acst::test::sweep_pieces_test {
namespace fs = std::filesystem;
using nlohmann::json;
using namespace acst::mpm;
using sweep_runs::comparable_rows;
using sweep_runs::read_json;
using sweep_runs::sweep;
using sweep_runs::write;

namespace {

std::string two_beddings(const std::string& extra = "") {
  return R"({"name": "pieces", "base": ")" + sweep_runs::small_footing + R"(",
      "cases": [{"name": "bedding_{alpha}", "group": "bedding",
                 "vary": [{"name": "alpha", "path": "/bodies/0/bedding_angle_deg", "values": [0, 90]}]}],
      "findings": [{"finding": "Bedding 0 carries more",
                    "checks": [{"expect": "greater", "cases": ["bedding_0", "bedding_90"], "column": "q_ult_kPa"}]}])" +
         extra + "}";
}


Cli run(const fs::path& out, const fs::path& description, std::vector<std::string> more = {}) {
  std::vector<std::string> args = {"--quiet", "--no-plot", "--threads", "1", "--output", out.string()};
  args.insert(args.end(), more.begin(), more.end());
  args.push_back(description.string());
  return sweep(args);
}

std::string text_of(const fs::path& p) { return acst::common::read_input_file(p.string()); }

}  // namespace

// LPT by hand: work 1, 5, 3, 4, 3, 2 taken as 5, 4, 3, 3, 2, 1 (cases 1, 3, 2, 4, 5, 0), each to
// the lighter shard (ties to the first): 1 -> A (5), 3 -> B (4), 2 -> B (7), 4 -> A (8), 5 -> B (9),
// 0 -> A (9).
TEST(SweepShards, AreTheLongestFirstScheduleAndCoverEveryCaseOnce) {
  EXPECT_EQ(shard_of_cases({1, 5, 3, 4, 3, 2}, 2), (std::vector<std::size_t>{0, 0, 1, 1, 0, 1}));
  EXPECT_EQ(shard_of_cases({1, 5, 3, 4, 3, 2}, 1), (std::vector<std::size_t>(6, 0)));
  const std::vector<std::size_t> three = shard_of_cases({7, 7, 7, 7}, 3);  // equal work: in the listed order
  EXPECT_EQ(three, (std::vector<std::size_t>{0, 1, 2, 0}));
  EXPECT_EQ(parse_shard("2/3").k, 2u);
  EXPECT_EQ(parse_only("V*,H86.7"), (std::vector<std::string>{"V*", "H86.7"}));
}

TEST(SweepPieces, WholeShardsAndABudgetEndInOneTable) {
  const fs::path dir = acst::test::scratch_folder("sweep_pieces");
  const fs::path file = write(dir / "sweep.json", two_beddings());
  ASSERT_EQ(run(dir / "whole", file).rc, 0);
  const json whole = comparable_rows(dir / "whole");

  // Two shards into two folders, one case each, gathered into a third.
  for (const char* k : {"1", "2"}) {
    const Cli shard = run(dir / ("shard" + std::string(k)), file, {"--shard", std::string(k) + "/2"});
    EXPECT_EQ(shard.rc, 0) << shard.err;
    EXPECT_EQ(acst::test::everything_under(dir / ("shard" + std::string(k)) / "kept").size(), 4u)
        << "one case with its record, summary and load record";
    // Before the gather, each shard's report leaves the finding undecided, not judged on half.
    EXPECT_NE(text_of(dir / ("shard" + std::string(k)) / "report.md").find("**not decided: cases pending**"),
              std::string::npos);
  }
  const Cli gathered = sweep({"--quiet", "--no-plot", "--gather", (dir / "shard1").string(), (dir / "shard2").string(),
                              "--output", (dir / "gathered").string(), file.string()});
  ASSERT_EQ(gathered.rc, 0) << gathered.err;
  EXPECT_EQ(comparable_rows(dir / "gathered"), whole);
  EXPECT_NE(text_of(dir / "gathered" / "report.md").find("Bedding 0 carries more: **reproduced**"), std::string::npos);

  // A budget that ends while the first case runs (0.3 s, the case about 0.7 s on one thread; the
  // rate assumed so high that the case starts): that case is checkpointed, the table lists both
  // as pending, exit 75 with the line that says how to go on.
  const SweepSpec spec = read_sweep(file.string());
  SweepRunOptions opt;
  opt.output_dir = (dir / "budget").string();
  opt.threads = 1;
  opt.plot = false;
  opt.quiet = true;
  opt.budget_minutes = 0.005;
  opt.assumed_rate = 1e15;
  InTurn in_turn;
  std::ostringstream out, err;
  ASSERT_EQ(run_sweep(spec, opt, in_turn, out, err), exit_budget_spent) << out.str() << err.str();
  EXPECT_NE(out.str().find("0 of 2 cases done, 2 wait (1 checkpointed)"), std::string::npos) << out.str();
  EXPECT_NE(out.str().find("; run the same command again to go on"), std::string::npos) << out.str();
  EXPECT_TRUE(fs::exists(dir / "budget" / "cases" / ".bedding_0.partial" / "checkpoint.bin"));
  const json stopped = read_json(dir / "budget" / "table.json");
  for (const json& r : stopped["cases"]) EXPECT_EQ(r["status"], "pending");
  // Again without a budget: the first case resumes from its checkpoint, the second runs.
  const Cli finish = sweep({"--no-plot", "--threads", "1", "--output", (dir / "budget").string(), file.string()});
  ASSERT_EQ(finish.rc, 0) << finish.err;
  EXPECT_NE(finish.err.find("(resumed from its checkpoint)"), std::string::npos) << finish.err;
  EXPECT_EQ(comparable_rows(dir / "budget"), whole);
  EXPECT_EQ(text_of(dir / "budget" / "kept" / "bedding_0" / "load_settlement.csv"),
            text_of(dir / "whole" / "kept" / "bedding_0" / "load_settlement.csv"));

  // A budget too small for any case (the assumed rate): says so, starts none, exit 75.
  const Cli small = run(dir / "small", file, {"--budget", "0.0001"});
  EXPECT_EQ(small.rc, exit_budget_spent);
  EXPECT_NE(small.out.find("too small for any case"), std::string::npos) << small.out;
  EXPECT_FALSE(fs::exists(dir / "small" / "cases" / ".bedding_0.partial"));
}

// Killed (SIGKILL) the moment its first case is published, the sweep has either kept that case
// whole or not at all; the next run keeps it from its case folder and runs only the other.
TEST(SweepPieces, AKilledSweepLosesNoFinishedCase) {
  const fs::path dir = acst::test::scratch_folder("sweep_pieces_kill");
  const fs::path file = write(dir / "sweep.json", two_beddings());
  const fs::path out = dir / "killed";
  const fs::path published = out / "cases" / "bedding_0" / "sweep_case.json";
  sweep_runs::kill_sweep_when({"--output", out.string(), file.string()}, published);
  ASSERT_TRUE(fs::exists(published));
  const fs::path kept = out / "kept" / "bedding_0" / "sweep_case.json";
  if (fs::exists(kept)) {
    EXPECT_EQ(read_json(kept), read_json(published)) << "a kept case reads back whole";
  }
  const Cli again = run(out, file);
  ASSERT_EQ(again.rc, 0) << again.err;
  EXPECT_EQ(read_json(kept), read_json(published));
  EXPECT_TRUE(fs::exists(out / "kept" / "bedding_0" / "load_settlement.csv"));
}

// A folder with the kept results alone, as a recorded study in a fresh clone: nothing runs again;
// a case without its kept folder runs; a description that changed the scene runs every case
// again and its rows say so.
TEST(SweepPieces, AFolderOfKeptResultsRunsOnlyWhatIsMissingOrChanged) {
  const fs::path dir = acst::test::scratch_folder("sweep_pieces_kept");
  const fs::path file = write(dir / "sweep.json", two_beddings());
  ASSERT_EQ(run(dir / "whole", file).rc, 0);
  const fs::path recorded = dir / "recorded";
  fs::create_directories(recorded);
  fs::copy(dir / "whole" / "kept", recorded / "kept", fs::copy_options::recursive);
  for (const char* f : {"table.json", "table.csv", "table.md", "report.md", "sweep.json"})
    fs::copy_file(dir / "whole" / f, recorded / f);
  const Cli nothing = sweep({"--no-plot", "--output", recorded.string(), file.string()});
  ASSERT_EQ(nothing.rc, 0) << nothing.err;
  EXPECT_NE(nothing.err.find("2 already run (kept), 0 to run"), std::string::npos) << nothing.err;
  EXPECT_FALSE(fs::exists(recorded / "cases" / "bedding_0"));
  EXPECT_EQ(comparable_rows(recorded), comparable_rows(dir / "whole"));
  // The table and report redrawn from the kept results alone, one case missing: it is pending.
  fs::remove_all(recorded / "kept" / "bedding_90");
  const Cli replot = sweep({"--no-plot", "--replot", "--output", recorded.string(), file.string()});
  ASSERT_EQ(replot.rc, 0) << replot.err;
  EXPECT_EQ(read_json(recorded / "table.json")["cases"][1]["status"], "pending");
  EXPECT_NE(text_of(recorded / "report.md").find("**not decided: cases pending**"), std::string::npos);
  const Cli missing = run(recorded, file);
  ASSERT_EQ(missing.rc, 0) << missing.err;
  EXPECT_FALSE(fs::exists(recorded / "cases" / "bedding_0"));
  EXPECT_TRUE(fs::exists(recorded / "cases" / "bedding_90"));
  EXPECT_EQ(comparable_rows(recorded), comparable_rows(dir / "whole"));

  // A folder recorded before kept results held records (its rows in table.json alone): --replot
  // keeps those rows and leaves its figures as they are, having no load record to draw them from.
  const fs::path legacy = dir / "legacy";
  fs::create_directories(legacy / "figures");
  for (const char* f : {"table.json", "sweep.json"}) fs::copy_file(dir / "whole" / f, legacy / f);
  write(legacy / "figures" / "bedding.png", "a figure drawn when the cases were there");
  const Cli old = sweep({"--quiet", "--replot", "--output", legacy.string(), file.string()});
  ASSERT_EQ(old.rc, 0) << old.err;
  EXPECT_NE(old.out.find("2 rows from its table.json alone"), std::string::npos) << old.out;
  EXPECT_EQ(comparable_rows(legacy), comparable_rows(dir / "whole"));
  EXPECT_EQ(text_of(legacy / "figures" / "bedding.png"), "a figure drawn when the cases were there");

  const fs::path changed = write(dir / "changed.json", two_beddings(R"(, "set": {"/footing/speed": 0.04})"));
  fs::remove_all(recorded / "cases");
  const Cli rerun = run(recorded, changed);
  ASSERT_EQ(rerun.rc, 0) << rerun.err;
  const json rerun_table = read_json(recorded / "table.json");
  for (const json& r : rerun_table["cases"]) {
    EXPECT_EQ(r["message"].get<std::string>().rfind("run again: its kept result was of another description", 0), 0u) << r;
    EXPECT_NE(r["message"].get<std::string>().find("/scene/footing/speed"), std::string::npos) << r;
  }
  EXPECT_NE(comparable_rows(recorded)[0]["q_ult_kPa"], comparable_rows(dir / "whole")[0]["q_ult_kPa"]);
}

TEST(SweepPieces, BadFlagsAreRefusedWithNothingWrittenOrRemoved) {
  const fs::path dir = acst::test::scratch_folder("sweep_pieces_flags");
  const fs::path file = write(dir / "sweep.json", two_beddings());
  const std::vector<std::pair<std::vector<std::string>, std::string>> bad = {
      {{"--shard", "3/2"}, "--shard '3/2'"}, {{"--shard", "0/2"}, "--shard '0/2'"},
      {{"--shard", "1/0"}, "--shard '1/0'"}, {{"--shard", "1"}, "--shard '1'"},
      {{"--budget", "-1"}, "--budget '-1'"}, {{"--budget", "abc"}, "--budget 'abc'"},
      {{"--budget", "nan"}, "--budget 'nan'"}, {{"--only", "nothing_like_it*"}, "--only: 'nothing_like_it*'"},
      {{"--only", "bedding_0,"}, "--only 'bedding_0,'"}};
  for (const auto& [flags, says] : bad) {
    const Cli c = run(dir / "out", file, flags);
    EXPECT_EQ(c.rc, 2) << says;
    EXPECT_NE(c.err.find(says), std::string::npos) << c.err;
    EXPECT_FALSE(fs::exists(dir / "out")) << says;
  }
  // --gather of folders of two different descriptions: refused naming the folder, the output untouched.
  ASSERT_EQ(run(dir / "one", file, {"--only", "bedding_0"}).rc, 0);
  const fs::path other = write(dir / "other.json", two_beddings(R"(, "set": {"/footing/speed": 0.04})"));
  ASSERT_EQ(run(dir / "two", other, {"--only", "bedding_90"}).rc, 0);
  const Cli mixed = sweep({"--quiet", "--no-plot", "--gather", (dir / "one").string(), (dir / "two").string(), "--output",
                           (dir / "out").string(), file.string()});
  EXPECT_EQ(mixed.rc, 2);
  EXPECT_NE(mixed.err.find("--gather '" + (dir / "two").string() + "': a folder of another description"), std::string::npos)
      << mixed.err;
  EXPECT_FALSE(fs::exists(dir / "out"));
  const Cli no_output = sweep({"--gather", (dir / "one").string(), file.string()});
  EXPECT_EQ(no_output.rc, 2);
  EXPECT_NE(no_output.err.find("--output"), std::string::npos) << no_output.err;
}

// A finding reads a case that has not run: not decided, never judged on the others.
TEST(SweepFindings, ACheckOnAPendingCaseIsNotDecided) {
  FindingCheck check;
  check.expect = Expectation::greater;
  check.cases = {"a", "b"};
  check.columns = {"q_ult_kPa"};
  const std::vector<nlohmann::ordered_json> rows = {{{"case", "a"}, {"status", "done"}, {"q_ult_kPa", 2.0}},
                                                    {{"case", "b"}, {"status", "pending"}}};
  const CheckResult r = judge(check, rows);
  EXPECT_EQ(r.status, CheckStatus::pending);
  EXPECT_EQ(verdict({r, CheckResult{CheckStatus::holds, ""}}), "not decided: cases pending");
  const std::vector<nlohmann::ordered_json> failed = {rows[0], {{"case", "b"}, {"status", "failed"}}};
  EXPECT_EQ(judge(check, failed).status, CheckStatus::open);
}

}  // namespace acst::test::sweep_pieces_test

namespace acst::test::sweep_pieces_test {

// Links planted in a sweep's folder (at figures/, kept/, a kept case, a kept file: to the user's
// folder, /dev/zero or a FIFO) are refused by a run, --replot and --gather alike, naming the
// entry, before anything is read or written; the user's files they point to are left as they are.
TEST(SweepPieces, ASweepNeverFollowsALinkOrReadsASpecialFileInItsFolder) {
  const fs::path dir = acst::test::scratch_folder("sweep_pieces_links");
  const fs::path file = write(dir / "sweep.json", two_beddings());
  ASSERT_EQ(run(dir / "made", file).rc, 0);
  const fs::path users = dir / "users";
  fs::create_directories(users / "bedding_0");
  write(users / "bedding_0" / "sweep_case.json", "mine");
  write(users / "table.json", "mine too");
  fs::create_directories(dir / "fifo_dir");
  ASSERT_EQ(mkfifo((dir / "fifo_dir" / "fifo").c_str(), 0600), 0);
  struct Plant {
    std::string at;       // the entry replaced by a link, under the sweep folder
    fs::path to;          // what it points to; empty: a FIFO in its place
    std::string says;     // in the refusal
  };
  const std::vector<Plant> plants = {
      {"figures", users, "holds 'figures', a link"},
      {"kept", users, "holds 'kept', a link"},
      {"kept/bedding_0", users / "bedding_0", "holds 'bedding_0', a link"},
      {"kept/bedding_0/load_settlement.csv", "/dev/zero", "holds 'load_settlement.csv', a link"},
      {"kept/bedding_0/summary.json", dir / "fifo_dir" / "fifo", "holds 'summary.json', a link"},
      {"kept/bedding_0/load_settlement.csv", "", "holds 'load_settlement.csv', something other than a plain file"},
  };
  for (const Plant& p : plants) {
    const fs::path out = dir / ("planted_" + std::to_string(&p - plants.data()));
    fs::copy(dir / "made", out, fs::copy_options::recursive);
    fs::remove_all(out / "cases");
    fs::remove_all(out / p.at);
    fs::create_directories(out / p.at);
    fs::remove(out / p.at);
    if (p.to.empty())  // a FIFO in place of the file
      ASSERT_EQ(mkfifo((out / p.at).c_str(), 0600), 0);
    else
      fs::create_symlink(p.to, out / p.at);
    const std::vector<std::string> before = acst::test::everything_under(dir);
    for (const std::vector<std::string>& mode : {std::vector<std::string>{}, std::vector<std::string>{"--replot"}}) {
      const Cli c = run(out, file, mode);
      EXPECT_EQ(c.rc, 2) << p.at;
      EXPECT_NE(c.err.find(p.says), std::string::npos) << c.err;
    }
    const Cli g = sweep({"--quiet", "--no-plot", "--gather", out.string(), "--output", (dir / "gathered").string(), file.string()});
    EXPECT_EQ(g.rc, 2) << p.at;
    EXPECT_NE(g.err.find(p.says), std::string::npos) << g.err;
    EXPECT_EQ(acst::test::everything_under(dir), before) << p.at;
  }
  EXPECT_EQ(text_of(users / "bedding_0" / "sweep_case.json"), "mine");
  EXPECT_EQ(text_of(users / "table.json"), "mine too");
}

}  // namespace acst::test::sweep_pieces_test
