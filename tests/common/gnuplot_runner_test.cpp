// The gnuplot runner every tool uses (common/src/gnuplot.cpp; issue 57): gnuplot's messages come
// back through a pipe, so no file of the tools' lies under the shared temporary folder where a
// link planted at a guessable name would be followed; and a figure is checked (not empty, the PNG
// signature first, the IEND chunk last) before it takes an earlier one's place, since gnuplot
// exits 0 after a write that failed on a full disk.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "acst_common/files.hpp"
#include "acst_common/gnuplot.hpp"
#include "acst_common/png_file.hpp"
#include "file_size_limit.hpp"
#include "scratch.hpp"

namespace acst::test::gnuplot_runner_test {
namespace {

namespace fs = std::filesystem;

// A figure of some 10-30 kB: larger than the file-size limit below, whatever gnuplot's version.
std::string figure_script() {
  return "set terminal pngcairo size 800,600\nif (!exists('png')) png = 'x.png'\nset output png\n"
         "set samples 2000\nplot sin(x) * exp(-x / 10) title 'damped', cos(3 * x) title 'fast'\n";
}

std::string bytes_of(const fs::path& p) { return common::read_input_file(p.string()); }

// TMPDIR set for the test's duration (std::filesystem::temp_directory_path reads it each time).
class TemporaryFolder {
 public:
  explicit TemporaryFolder(const fs::path& dir) {
    if (const char* t = std::getenv("TMPDIR")) before_ = t, had_ = true;
    ::setenv("TMPDIR", dir.c_str(), 1);
  }
  ~TemporaryFolder() {
    if (had_) ::setenv("TMPDIR", before_.c_str(), 1);
    else ::unsetenv("TMPDIR");
  }

 private:
  std::string before_;
  bool had_ = false;
};

}  // namespace

// Every tool wrote gnuplot's log to $TMPDIR/.acst_gnuplot.log.tmp<PID>_<N> through a shell
// redirection, which followed a link planted at that name and truncated the file it named. Links
// at all those names of this process (N of its first 1000 runs) are left as they were, their
// target untouched, and nothing is written into the temporary folder; gnuplot's messages still
// reach the warning.
TEST(GnuplotRunner, LinksPlantedAtTheOldLogNamesAreNotFollowed) {
  if (!common::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = scratch_folder("gnuplot_links"), tmp = dir / "tmp";
  fs::create_directories(tmp);
  const fs::path victim = dir / "victim.txt";
  std::ofstream(victim) << "a file of the user's";
  for (int n = 0; n < 1000; ++n)
    fs::create_symlink(victim, tmp / (".acst_gnuplot.log.tmp" + std::to_string(::getpid()) + "_" + std::to_string(n)));
  const std::vector<std::string> planted = everything_under(tmp);
  {
    const TemporaryFolder in(tmp);
    EXPECT_EQ(common::run_gnuplot(figure_script(), (dir / "a.gp").string(), (dir / "a.png").string()), "");
    const std::string w = common::run_gnuplot_command(dir.string(), "-e " + common::shell_quoted("print undefined_thing"));
    EXPECT_NE(w.find("undefined_thing"), std::string::npos) << "gnuplot's own message in the warning: " << w;
  }
  EXPECT_EQ(bytes_of(victim), "a file of the user's");
  EXPECT_EQ(everything_under(tmp), planted);
  EXPECT_EQ(common::png_problem((dir / "a.png").string()), "");
}

// What png_problem tells apart: a whole PNG, an empty file, one cut short, one that is no PNG.
TEST(GnuplotRunner, AFigureIsWholeOnlyWithItsSignatureAndItsIendChunk) {
  if (!common::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = scratch_folder("png_problem");
  ASSERT_EQ(common::run_gnuplot(figure_script(), (dir / "whole.gp").string(), (dir / "whole.png").string()), "");
  const std::string whole = bytes_of(dir / "whole.png");
  EXPECT_EQ(common::png_problem((dir / "whole.png").string()), "");
  std::ofstream(dir / "empty.png").flush();
  EXPECT_NE(common::png_problem((dir / "empty.png").string()).find("is empty"), std::string::npos);
  std::ofstream(dir / "cut.png", std::ios::binary) << whole.substr(0, whole.size() / 2);
  EXPECT_NE(common::png_problem((dir / "cut.png").string()).find("ends before its IEND chunk"), std::string::npos);
  std::ofstream(dir / "text.png", std::ios::binary) << std::string(100, 'x');
  EXPECT_NE(common::png_problem((dir / "text.png").string()).find("is not a PNG file"), std::string::npos);
  EXPECT_NE(common::png_problem((dir / "missing.png").string()).find("was not written"), std::string::npos);
}

// A full disk, as a file-size limit of 4 kB with SIGXFSZ ignored (tests/support/file_size_limit.hpp):
// gnuplot's write fails, gnuplot exits 0, and the PNG it leaves ends early. The earlier figure
// stays byte for byte, no temporary file is left, and the warning says why. Before, the cut PNG
// replaced it and the run reported success.
TEST(GnuplotRunner, AFigureCutShortByAFullDiskLeavesTheEarlierOne) {
  if (!common::gnuplot_available()) GTEST_SKIP() << "gnuplot is not installed";
  const fs::path dir = scratch_folder("gnuplot_full_disk");
  const std::string gp = (dir / "f.gp").string(), png = (dir / "f.png").string();
  ASSERT_EQ(common::run_gnuplot(figure_script(), gp, png), "");
  const std::string earlier = bytes_of(png);
  ASSERT_GT(earlier.size(), 8000u) << "the figure must be larger than the limit below";
  std::string warning;
  {
    const FileSizeLimit full_disk(4096);
    warning = common::run_gnuplot(figure_script(), gp, png);
  }
  EXPECT_NE(warning.find("'" + png + "'"), std::string::npos) << warning;
  EXPECT_NE(warning.find("is kept as it was"), std::string::npos) << warning;
  EXPECT_TRUE(bytes_of(png) == earlier) << "the earlier figure was replaced";
  EXPECT_EQ(everything_under(dir), (std::vector<std::string>{"f.gp", "f.png"}));
  // A figure written in its final place (acst_fit's cross-validation) and cut short is removed.
  std::ofstream(dir / "cut.png", std::ios::binary) << earlier.substr(0, 100);
  EXPECT_NE(common::keep_complete_png((dir / "cut.png").string(), (dir / "cut.png").string()).find("removed"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "cut.png"));
}

}  // namespace acst::test::gnuplot_runner_test
