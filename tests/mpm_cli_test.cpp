// The acst_mpm command line (acst::mpm::mpm_cli): help, bad options and bad scenes give the
// documented exit status and a message that says what is wrong; nothing is written then.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "acst_mpm/cli.hpp"

namespace fs = std::filesystem;
using acst::mpm::mpm_cli;

namespace {

struct Cli {
  int rc = -1;
  std::string out, err;
};

Cli run(const std::vector<std::string>& args) {
  std::ostringstream o, e;
  Cli c;
  c.rc = mpm_cli(args, o, e);
  c.out = o.str();
  c.err = e.str();
  return c;
}

fs::path scratch(const std::string& tag) {
  const fs::path d = fs::temp_directory_path() / ("acst_mpm_cli_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

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
  EXPECT_NE(missing.err.find("cannot open the scene file"), std::string::npos) << missing.err;
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
