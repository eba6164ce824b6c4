#pragma once
// One run at a time in an output folder: an exclusive advisory lock (flock) on a lock file in
// it, held while the run writes there. The kernel releases it when the process ends in any way,
// so a run that crashed or was killed never blocks the next one.
#include <string>

namespace acst::common {

class FolderLock {
 public:
  // Makes `dir` when it is missing, and takes the lock on dir/`file_name` without waiting;
  // throws InputError naming the folder and, where it is known, the holder's PID when another
  // process holds it, and InputError naming the file when it cannot be made or is a link.
  FolderLock(const std::string& dir, const std::string& file_name, const std::string& tool);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

  // For a run refused after taking the lock (nothing else written): removes the lock file and
  // the folder where this lock made them, so that a refusal leaves nothing behind.
  void undo();

 private:
  std::string dir_, file_;
  int fd_ = -1;
  bool made_dir_ = false, made_file_ = false;
};

}  // namespace acst::common
