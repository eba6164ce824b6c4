#pragma once
// A process that holds an output folder's lock (common::FolderLock) until it is killed: the
// other run of the lock tests. Fork before the test starts threads.
#include <sys/types.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <string>

#include "acst_common/folder_lock.hpp"

namespace acst::test {

// The child's PID once it holds the lock on dir/`file` (as `tool`); the child pauses until killed.
inline pid_t child_holding_lock(const std::string& dir, const std::string& file, const std::string& tool) {
  int ready[2];
  EXPECT_EQ(::pipe(ready), 0);
  const pid_t child = ::fork();
  if (child == 0) {
    ::close(ready[0]);
    try {
      const common::FolderLock held(dir, file, tool);
      if (::write(ready[1], "1", 1) != 1) ::_exit(1);
      for (;;) ::pause();
    } catch (...) {
      ::_exit(1);
    }
  }
  ::close(ready[1]);
  char c = 0;
  EXPECT_EQ(::read(ready[0], &c, 1), 1) << "the child did not take the lock";
  ::close(ready[0]);
  return child;
}

}  // namespace acst::test
