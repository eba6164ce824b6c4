// acst_sweep's folder against careless and hostile use (issue 57, docs/reliability.md): a second
// sweep into a folder in use is refused; a user's folder under cases/ named like a case, and a
// case record that is damaged or edited, are refused untouched and named; a variable named like
// a column of the table is refused with its JSON path; every case counts toward the cap, at once;
// a damaged checkpoint or fingerprint of an interrupted case is discarded and the case runs afresh.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "acst_common/files.hpp"
#include "acst_common/input_error.hpp"
#include "acst_sweep/sweep.hpp"
#include "acst_sweep/sweep_case.hpp"
#include "acst_sweep/sweep_runner.hpp"
#include "cli_capture.hpp"
#include "lock_holder.hpp"
#include "scratch.hpp"
#include "sweep_runs.hpp"

namespace acst::test::sweep_folder_test {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using namespace acst::mpm;
using sweep_runs::parse_error;
using sweep_runs::read_json;
using sweep_runs::sweep;
using sweep_runs::write;
const std::string& base_scene = sweep_runs::small_footing;


// Cases of the small footing stopped at S/B 0.005: a tenth of a second each in Release.
std::string description(const std::string& cases) {
  return R"({"name": "t", "base": ")" + base_scene + R"(", "set": {"/stop/S_over_B": 0.005}, "cases": )" + cases + "}";
}

const std::string two_cases = R"([{"name": "a"}, {"name": "b", "set": {"/bodies/0/bedding_angle_deg": 90}}])";





// Runs nothing and records what would be handed out: past the folder's checks, or not.
class NoWorkers : public CaseDistributor {
 public:
  bool coordinator() const override { return true; }
  int workers() const override { return 1; }
  bool all(bool ok) override { return ok; }
  void distribute(const std::vector<std::size_t>& pending, const RunOne&, const Finished&, const MayStart&) override { handed_out = pending; }
  std::vector<std::size_t> handed_out;
};

}  // namespace

// Two sweeps into one folder mixed their cases' frames, and the second's table said every case
// failed. The folder is locked for the run (flock on OUT/.acst_sweep.lock); the second is refused
// with exit 2, naming the folder and the holder's PID; a holder that was killed holds nothing.
// Fork first: this test's process has started no threads yet.
TEST(SweepFolder, ASecondSweepIntoAFolderInUseIsRefused) {
  const fs::path dir = scratch_folder("sweep_lock");
  const fs::path out = dir / "out", file = write(dir / "s.json", description(two_cases));
  const pid_t first = child_holding_lock(out.string(), sweep_lock_file, "acst_sweep");  // the first sweep, as far as its lock
  const std::vector<std::string> before = everything_under(dir);
  const Cli second = sweep({"--quiet", "--no-plot", "--output", out.string(), file.string()});
  EXPECT_EQ(second.rc, 2);
  EXPECT_NE(second.err.find("the output folder '" + out.string() + "' is in use by another acst_sweep (PID " +
                            std::to_string(first) + ")"),
            std::string::npos)
      << second.err;
  EXPECT_EQ(everything_under(dir), before);
  ::kill(first, SIGKILL);
  int status = 0;
  ::waitpid(first, &status, 0);
  // Killed, the first holds nothing: the next sweep gets past the lock (and runs nothing here).
  NoWorkers none;
  SweepRunOptions opt;
  opt.output_dir = out.string();
  opt.plot = false;
  opt.quiet = true;
  std::ostringstream o, e;
  EXPECT_EQ(run_sweep(parse_sweep(common::read_input_file(file.string()), file.string()), opt, none, o, e), 1) << e.str();
  EXPECT_EQ(none.handed_out, (std::vector<std::size_t>{0, 1}));
}

// A folder of the user's under cases/ named like a case, without a case record, was taken for a
// case not yet run and replaced by it (exit 0). It is refused untouched, as a file there is.
TEST(SweepFolder, AUsersFolderNamedLikeACaseIsRefusedUntouched) {
  const fs::path dir = scratch_folder("sweep_user_folder");
  const fs::path out = dir / "out", file = write(dir / "s.json", description(two_cases));
  fs::create_directories(out / "cases" / "a");
  write(out / "cases" / "a" / "notes.txt", "mine");
  const std::vector<std::string> before = everything_under(dir);
  const Cli c = sweep({"--quiet", "--no-plot", "--threads", "1", "--output", out.string(), file.string()});
  EXPECT_EQ(c.rc, 2);
  EXPECT_NE(c.err.find("holds 'a', a folder without a case record (sweep_case.json), which acst_sweep does not write"),
            std::string::npos)
      << c.err;
  EXPECT_EQ(everything_under(dir), before);
  EXPECT_EQ(common::read_input_file((out / "cases" / "a" / "notes.txt").string()), "mine");
}

// A variable named like a column overwrote it (status: every case pending), was dropped (a result
// column written after it), or ended in a raw library message after the tables were written
// (resumed, message). Every column name, and those of the made columns' forms, is refused.
TEST(SweepFolder, AVariableNamedLikeATableColumnIsRefusedWithItsPath) {
  for (const std::string name : {"case", "group", "status", "message", "resumed", "q_ult_kPa", "steps", "load_file",
                                 "q_at_S_over_B_1_kPa", "heave_left_at_end_m", "sheared_area_right_at_peak_m2"}) {
    const std::string text = description(R"([{"name": "c{)" + name + R"(}", "vary": [{"name": ")" + name +
                                         R"(", "path": "/footing/speed", "values": [0.05]}]}])");
    const std::string message = parse_error(text);
    EXPECT_NE(message.find("/cases/0/vary/0/name: '" + name + "' is a column of the sweep's table"), std::string::npos)
        << message;
  }
  // Names that are not columns stay variables.
  EXPECT_EQ(parse_error(description(R"([{"name": "c{speed}", "vary": [{"name": "speed", "path": "/footing/speed", "values": [0.05]}]}])")),
            "accepted");
}

// The list of reserved names is checked against the row a real case gets (done, with acst_mpm's
// summary and its side measures): every column but the variables' is one of them.
TEST(SweepFolder, EveryColumnOfARowIsAReservedName) {
  const fs::path dir = scratch_folder("sweep_columns");
  const fs::path file = write(dir / "s.json", description(R"([{"name": "c{alpha}", "vary": [{"name": "alpha",
      "path": "/bodies/0/bedding_angle_deg", "values": [30]}]}])"));
  const fs::path out = dir / "out";
  const Cli c = sweep({"--quiet", "--no-plot", "--threads", "1", "--output", out.string(), file.string()});
  ASSERT_EQ(c.rc, 0) << c.err;
  const json row = read_json(out / "table.json")["cases"][0];
  ASSERT_TRUE(row.contains("heave_left_at_end_m")) << row.dump();
  for (const auto& item : row.items()) {
    if (item.key() == "alpha") continue;
    EXPECT_TRUE(is_table_column(item.key())) << item.key();
  }
  EXPECT_FALSE(is_table_column("alpha"));
}

// A case record edited or damaged ended in the library's own message ("type must be string, but
// is number") naming no file. Each field the next run reads is checked: exit 2, the file and the
// field named, the folder as it was.
TEST(SweepFolder, ADamagedCaseRecordIsRefusedNamingItsFileAndField) {
  const fs::path dir = scratch_folder("sweep_record");
  const fs::path out = dir / "out", file = write(dir / "s.json", description(R"([{"name": "a"}])"));
  ASSERT_EQ(sweep({"--quiet", "--no-plot", "--threads", "1", "--output", out.string(), file.string()}).rc, 0);
  const fs::path record = out / "cases" / "a" / "sweep_case.json";
  const json good = read_json(record);
  struct Damage {
    std::string what, says;
    void (*spoil)(json&);
  };
  const std::vector<Damage> damages{
      {"a number as message", "/row/message: expected a string, got number", [](json& r) { r["row"]["message"] = 5; }},
      {"text as resumed", "/row/resumed: expected true or false, got string", [](json& r) { r["row"]["resumed"] = "yes"; }},
      {"an unknown status", "/row/status: 'finished' is not one of pending, done, failed",
       [](json& r) { r["row"]["status"] = "finished"; }},
      {"no status", "/row: 'status' is required", [](json& r) { r["row"].erase("status"); }},
      {"no row", "'row' is required", [](json& r) { r.erase("row"); }},
      {"a string as fingerprint", "/fingerprint: expected a JSON object, got string", [](json& r) { r["fingerprint"] = "x"; }},
      {"an array as record", "expected a JSON object, got array", [](json& r) { r = json::array(); }},
  };
  for (const Damage& d : damages) {
    json spoilt = good;
    d.spoil(spoilt);
    write(record, spoilt.dump(2));
    const std::vector<std::string> before = everything_under(dir);
    const Cli c = sweep({"--quiet", "--no-plot", "--output", out.string(), file.string()});
    EXPECT_EQ(c.rc, 2) << d.what;
    EXPECT_NE(c.err.find("the case record '" + record.string() + "': "), std::string::npos) << d.what << ": " << c.err;
    EXPECT_NE(c.err.find(d.says), std::string::npos) << d.what << ": " << c.err;
    EXPECT_EQ(everything_under(dir), before) << d.what;
  }
  write(record, "{\"row\": ");
  const Cli c = sweep({"--quiet", "--no-plot", "--output", out.string(), file.string()});
  EXPECT_EQ(c.rc, 2);
  EXPECT_NE(c.err.find("the case record '" + record.string() + "': not valid JSON"), std::string::npos) << c.err;
  // The kept case's summary, read for its row's side measures, likewise (it ended in
  // basic_string::substr naming nothing).
  write(record, good.dump(2));
  const fs::path summary = out / "cases" / "a" / "summary.json";
  json spoilt = read_json(summary);
  spoilt["sides"]["at_peak"] = 5;
  write(summary, spoilt.dump(2));
  const Cli s = sweep({"--quiet", "--no-plot", "--output", out.string(), file.string()});
  EXPECT_EQ(s.rc, 2);
  EXPECT_NE(s.err.find("the run's summary '" + summary.string() + "': /sides/at_peak: expected a JSON object"), std::string::npos)
      << s.err;
}

// The cap of 10000 cases counted only the products of 'vary': two million plain entries ended
// in std::bad_alloc after 86 s. Every case counts, before any scene is made.
TEST(SweepFolder, EveryCaseCountsTowardTheCapAtOnce) {
  std::string plain = "[";
  for (int k = 0; k <= 10000; ++k) plain += (k ? ", " : "") + std::string("{\"name\": \"c") + std::to_string(k) + "\"}";
  plain += "]";
  const auto t0 = std::chrono::steady_clock::now();
  std::string message = parse_error(description(plain));
  EXPECT_NE(message.find("/cases: its 10001 entries make 10001 cases (each entry one, or its 'vary' lists' product); at "
                         "most 10000 are allowed"),
            std::string::npos)
      << message.substr(0, 300);
  // Building the 10001 scenes takes seconds; counting them, a small part of one (2 s allows for
  // the sanitizers' build).
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 2.0);
  // 9000 plain entries and one of 10 x 101 values: 10010 cases.
  std::string values = "[";
  for (int k = 0; k < 101; ++k) values += (k ? ", " : "") + std::to_string(k);
  values += "]";
  std::string mixed = plain.substr(0, plain.find("{\"name\": \"c9000\"}")) +
                      R"({"name": "v{x}_{y}", "vary": [{"name": "x", "path": "/footing/speed", "values": [1, 2, 3, 4, 5, 6, 7, 8, 9, 10]},
                          {"name": "y", "path": "/footing/width", "values": )" + values + "}]}]";
  message = parse_error(description(mixed));
  EXPECT_NE(message.find("/cases: its 9001 entries make 10010 cases"), std::string::npos) << message.substr(0, 300);
}

// An interrupted case whose checkpoint was damaged was published as failed, citing the checkpoint
// that was gone by then, with the half run's files as the case; a damaged fingerprint beside the
// partial folder failed the case at every run. A checkpoint is only a shortcut: discarded, the
// case runs afresh to the numbers of a case never interrupted, and its row says so.
TEST(SweepFolder, AnInterruptedCaseWithADamagedCheckpointRunsAfresh) {
  const fs::path dir = scratch_folder("sweep_damaged_checkpoint");
  const fs::path file = write(dir / "s.json", description(R"([{"name": "a"}])"));
  const SweepSpec spec = parse_sweep(common::read_input_file(file.string()), file.string());
  const fs::path straight = dir / "straight";
  ASSERT_EQ(sweep({"--quiet", "--no-plot", "--threads", "1", "--output", straight.string(), file.string()}).rc, 0);
  const json expected = read_json(straight / "table.json")["cases"][0];
  struct Damage {
    std::string what, fingerprint, checkpoint, says;
  };
  const std::vector<Damage> damages{
      {"a damaged checkpoint", case_fingerprint(spec.cases[0]).dump(), "not a checkpoint",
       "is not an acst_mpm checkpoint: discarded, the case ran afresh"},
      {"a damaged fingerprint", "{\"scene\": ", "ACSTMPM8 cut short",
       "the interrupted run's fingerprint '"},
  };
  for (const Damage& d : damages) {
    const fs::path out = dir / ("out_" + std::to_string(&d - damages.data()));
    fs::create_directories(out / "cases" / ".a.partial");
    write(out / "cases" / ".a.partial.json", d.fingerprint);
    write(out / "cases" / ".a.partial" / "checkpoint.bin", d.checkpoint);
    const Cli c = sweep({"--no-plot", "--threads", "1", "--output", out.string(), file.string()});
    ASSERT_EQ(c.rc, 0) << d.what << ": " << c.err;
    const json row = read_json(out / "table.json")["cases"][0];
    EXPECT_EQ(row["status"], "done") << d.what;
    EXPECT_FALSE(row["resumed"].get<bool>()) << d.what;
    EXPECT_NE(row["message"].get<std::string>().find(d.says), std::string::npos) << d.what << ": " << row["message"];
    EXPECT_NE(row["message"].get<std::string>().find("ran afresh"), std::string::npos) << d.what;
    EXPECT_NE(c.err.find("a: done"), std::string::npos) << c.err;
    for (const char* k : {"q_ult_kPa", "S_ult_over_B", "steps", "final_S_over_B"}) EXPECT_EQ(row[k], expected[k]) << d.what << " " << k;
    EXPECT_EQ(everything_under(out / "cases"), everything_under(straight / "cases")) << d.what;
  }
}

}  // namespace acst::test::sweep_folder_test
