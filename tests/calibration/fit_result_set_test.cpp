// acst_fit publishes its result set as a whole (issue 14, data integrity): a second fit into the
// same folder leaves the second set only, never files of both; a folder holding anything else
// is refused before any fitting, and left as it was.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "acst_calibration/cli.hpp"
#include "acst_common/files.hpp"
#include "acst_common/result_folder.hpp"
#include "output_folder.hpp"
#include "scratch.hpp"
#include "unprivileged.hpp"

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
  const auto [dir, out] = used_output_folder("fit_set_foreign", {{"notes.txt", "mine"}});
  std::ofstream(dir / "a.json") << fit_description("fit", "first");
  const std::vector<std::string> before = everything_under(dir);
  Outcome o = fit(dir / "a.json", out);
  expect_foreign_file_refused(o.rc, o.err, "notes.txt", dir, before);
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

// A read-only output folder (issue 57): acst_fit said it could not write, yet the new set was in
// place and the earlier one sat in a hidden folder beside it. Now it is refused with exit 2 before
// fitting, and the folder and all beside it are left as they were. Run as the user nobody where
// the tests run as root, for whom the mode bits mean nothing (tests/support/unprivileged.hpp);
// both fits in children, so that this process never starts OpenMP's threads before a fork.
TEST(FitResultSet, AReadOnlyFolderIsRefusedBeforeFittingAndLeftAsItWas) {
  const std::string lab_file = data + "/lab/fukushima_tatsuoka_1984/ft84_fig5a_sc1p0.csv";
  if (!unprivileged_can_read(lab_file))
    GTEST_SKIP() << "the user nobody cannot read " << lab_file << " (a checkout under a folder only its owner may enter)";
  const fs::path dir = scratch_folder("fit_read_only"), messages = scratch_folder("fit_read_only_messages");
  const fs::path out = dir / "out";
  std::ofstream(dir / "a.json") << fit_description("fit", "first");
  hand_to_unprivileged(dir);
  hand_to_unprivileged(messages);
  const auto fit_as_user = [&] {
    return run_unprivileged([&] {
      std::ostringstream o, e;
      const int rc = calibration::fit_cli({"--quiet", "--no-plot", "--output", out.string(), (dir / "a.json").string()}, o, e);
      std::ofstream(messages / "err.txt") << e.str();
      return rc;
    });
  };
  ASSERT_EQ(fit_as_user(), 0);
  ASSERT_EQ(::chmod(out.c_str(), 0555), 0);
  const std::vector<std::string> before = everything_under(dir);
  const std::string parameters = common::read_input_file((out / "fit_parameters.json").string());
  EXPECT_EQ(fit_as_user(), 2);
  const std::string err = common::read_input_file((messages / "err.txt").string());
  EXPECT_NE(err.find("the output folder '" + out.string() + "' cannot be replaced by a new result set: the folder"), std::string::npos) << err;
  EXPECT_NE(err.find("cannot be written (Permission denied)"), std::string::npos) << err;
  EXPECT_EQ(everything_under(dir), before) << "nothing beside the folder, nothing changed in it";
  EXPECT_EQ(common::read_input_file((out / "fit_parameters.json").string()), parameters);
  ::chmod(out.c_str(), 0755);
}

// Where the earlier set cannot be removed once the new one is in place (its folder made read-only
// during the fit), publishing is no failure: the new set stands and the warning says where the
// earlier one was left. It threw, and acst_fit reported that it could not write.
TEST(FitResultSet, AnEarlierSetThatCannotBeRemovedIsAWarningNotAFailure) {
  const fs::path dir = scratch_folder("publish_read_only");
  const fs::path target = dir / "set";
  const std::string staging = common::staging_folder_for(target.string());
  fs::create_directories(target);
  fs::create_directories(staging);
  std::ofstream(target / "old.txt") << "old";
  std::ofstream(fs::path(staging) / "new.txt") << "new";
  hand_to_unprivileged(dir);
  ASSERT_EQ(::chmod(target.c_str(), 0555), 0);
  const int rc = run_unprivileged([&] {
    try {
      const std::string warning = common::publish_folder(staging, target.string());
      return warning.find("the new result set is in '" + target.string() + "'") != std::string::npos &&
                     warning.find("it is left in '" + staging + "'") != std::string::npos
                 ? 0
                 : 1;
    } catch (const std::exception&) {
      return 2;
    }
  });
  EXPECT_EQ(rc, 0) << "1: no or another warning, 2: it threw";
  EXPECT_TRUE(fs::exists(target / "new.txt"));
  EXPECT_TRUE(fs::exists(fs::path(staging) / "old.txt"));
  ::chmod(staging.c_str(), 0755);
}

}  // namespace acst::test::fit_result_set_test
