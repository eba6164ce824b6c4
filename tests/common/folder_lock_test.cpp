// One run at a time in an output folder (common::FolderLock; issue 57, acst_sweep's folder): a
// second lock is refused at once, naming the folder and the holder's PID; the lock of a process
// that was killed is gone with it; a link planted at the lock file's name is not followed; a
// refused run's undo() leaves nothing it made.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "acst_common/files.hpp"
#include "acst_common/folder_lock.hpp"
#include "acst_common/input_error.hpp"
#include "lock_holder.hpp"
#include "scratch.hpp"

namespace acst::test::folder_lock_test {
namespace {

namespace fs = std::filesystem;

constexpr const char* lock_name = ".lock";

std::string refusal(const fs::path& dir) {
  try {
    common::FolderLock second(dir.string(), lock_name, "tool");
  } catch (const common::InputError& e) {
    return e.what();
  }
  return "taken";
}

}  // namespace

// Fork first: this test's process has started no threads yet.
TEST(FolderLock, ASecondRunIsRefusedNamingTheHolderAndAKilledHolderBlocksNothing) {
  const fs::path dir = scratch_folder("folder_lock") / "out";
  const pid_t holder = child_holding_lock(dir.string(), lock_name, "tool");
  const std::string refused = refusal(dir);
  EXPECT_NE(refused.find("the output folder '" + dir.string() + "' is in use by another tool (PID " +
                         std::to_string(holder) + ")"),
            std::string::npos)
      << refused;
  // In this process too: flock belongs to the open file, not to the process.
  {
    const common::FolderLock mine_elsewhere((dir.parent_path() / "other").string(), lock_name, "tool");
    EXPECT_NE(refusal(dir.parent_path() / "other").find("is in use"), std::string::npos);
  }
  ::kill(holder, SIGKILL);
  int status = 0;
  ::waitpid(holder, &status, 0);
  ASSERT_TRUE(WIFSIGNALED(status));
  // The kernel released the lock with the process; its file stays and is taken again.
  ASSERT_TRUE(fs::exists(dir / lock_name));
  EXPECT_EQ(refusal(dir), "taken");
  const common::FolderLock now(dir.string(), lock_name, "tool");
  EXPECT_EQ(common::read_input_file((dir / lock_name).string()), std::to_string(::getpid()) + "\n");
}

TEST(FolderLock, ALinkAtTheLockFilesNameIsRefusedNotFollowed) {
  const fs::path dir = scratch_folder("folder_lock_link");
  std::ofstream(dir / "victim.txt") << "mine";
  fs::create_symlink(dir / "victim.txt", dir / lock_name);
  EXPECT_NE(refusal(dir).find("cannot open its lock file '.lock'"), std::string::npos);
  EXPECT_EQ(common::read_input_file((dir / "victim.txt").string()), "mine");
}

TEST(FolderLock, UndoRemovesOnlyWhatTheLockMade) {
  const fs::path root = scratch_folder("folder_lock_undo");
  {
    common::FolderLock fresh((root / "new").string(), lock_name, "tool");
    fresh.undo();
  }
  EXPECT_FALSE(fs::exists(root / "new")) << "a folder the lock made, left empty";
  fs::create_directories(root / "earlier");
  std::ofstream(root / "earlier" / lock_name) << "123\n";
  {
    common::FolderLock earlier((root / "earlier").string(), lock_name, "tool");
    earlier.undo();
  }
  EXPECT_TRUE(fs::exists(root / "earlier" / lock_name)) << "an earlier run's lock file stays";
}

}  // namespace acst::test::folder_lock_test
