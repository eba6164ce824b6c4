// acst_fit publishes its result set as a whole (issue 14, data integrity): a second fit into the
// same folder leaves the second set only, never files of both; a folder holding anything else
// is refused before any fitting, and left as it was.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "acst_calibration/cli.hpp"
#include "acst_common/result_folder.hpp"
#include "scratch.hpp"

namespace acst::test::fit_result_set_test {
namespace {

namespace fs = std::filesystem;

const std::string data = std::string(ACST_SOURCE_DIR) + "/data";

// A fit of one parameter to one curve with one iteration: a second or less.
std::string fit_description(const std::string& name, const std::string& id) {
  return "{\"name\": \"" + name + "\", \"material\": {\"file\": \"" + data + "/parameters/toyoura_acst_guide.json\"}," +
         " \"parameters\": {\"d1\": {\"start\": 0.5, \"bounds\": [0.1, 2.0]}}," +
         " \"experiments\": [{\"id\": \"" + id + "\", \"data\": \"" + data + "/lab/fukushima_tatsuoka_1984/ft84_fig5a_sc1p0.csv\"}]," +
         " \"optimizer\": {\"design_points\": 0, \"starts\": 1, \"max_iterations\": 1, \"threads\": 1}}";
}

struct Outcome {
  int rc;
  std::string err;
};

Outcome fit(const fs::path& description, const fs::path& out) {
  std::ostringstream o, e;
  const int rc = calibration::fit_cli({"--quiet", "--no-plot", "--output", out.string(), description.string()}, o, e);
  return {rc, e.str()};
}

}  // namespace

TEST(FitResultSet, ASecondFitReplacesTheWholeSet) {
  const fs::path dir = scratch_folder("fit_set");
  const fs::path out = dir / "out";
  std::ofstream(dir / "a.json") << fit_description("fit", "first");
  ASSERT_EQ(fit(dir / "a.json", out).rc, 0);
  ASSERT_TRUE(fs::exists(out / "curves" / "first.csv"));
  std::ofstream(dir / "b.json") << fit_description("fit", "second");
  const Outcome o = fit(dir / "b.json", out);
  ASSERT_EQ(o.rc, 0) << o.err;
  EXPECT_TRUE(fs::exists(out / "curves" / "second.csv"));
  EXPECT_FALSE(fs::exists(out / "curves" / "first.csv")) << "a curve of the earlier fit beside the new set";
  // nothing but the folder and the descriptions beside it: the staging folder is gone
  EXPECT_EQ(everything_under(dir, out), (std::vector<std::string>{"a.json", "b.json", "out"}));
  fs::remove_all(dir);
}

TEST(FitResultSet, AFolderWithOtherFilesIsRefusedBeforeFitting) {
  const fs::path dir = scratch_folder("fit_set_foreign");
  const fs::path out = dir / "out";
  fs::create_directories(out);
  std::ofstream(out / "notes.txt") << "mine";
  std::ofstream(dir / "a.json") << fit_description("fit", "first");
  const std::vector<std::string> before = everything_under(dir);
  Outcome o = fit(dir / "a.json", out);
  EXPECT_EQ(o.rc, 2);
  EXPECT_NE(o.err.find("holds 'notes.txt', which this tool does not write"), std::string::npos) << o.err;
  EXPECT_EQ(everything_under(dir), before);
  // another fit's results count as foreign too: replacing them would lose them
  fs::remove(out / "notes.txt");
  std::ofstream(out / "other_report.json") << "{}";
  o = fit(dir / "a.json", out);
  EXPECT_EQ(o.rc, 2);
  EXPECT_NE(o.err.find("holds 'other_report.json'"), std::string::npos) << o.err;
  EXPECT_TRUE(fs::exists(out / "other_report.json"));
  fs::remove_all(dir);
}

// The exchange itself: the folder holds the whole earlier set until the new one takes its place.
TEST(FitResultSet, PublishingSwapsWholeFolders) {
  const fs::path dir = scratch_folder("publish");
  const fs::path target = dir / "set";
  const std::string staging = common::staging_folder_for(target.string());
  EXPECT_EQ(fs::path(staging).parent_path(), dir);
  fs::create_directories(staging);
  std::ofstream(fs::path(staging) / "new.txt") << "new";
  common::publish_folder(staging, target.string());  // no earlier set: a rename
  EXPECT_TRUE(fs::exists(target / "new.txt"));
  fs::create_directories(staging);
  std::ofstream(fs::path(staging) / "newer.txt") << "newer";
  common::publish_folder(staging, target.string());
  EXPECT_TRUE(fs::exists(target / "newer.txt"));
  EXPECT_FALSE(fs::exists(target / "new.txt"));
  EXPECT_FALSE(fs::exists(staging));
  EXPECT_THROW(common::publish_folder(staging, target.string()), std::exception);  // nothing to publish
  EXPECT_TRUE(fs::exists(target / "newer.txt")) << "a failed publication leaves the earlier set";
  fs::remove_all(dir);
}

}  // namespace acst::test::fit_result_set_test
