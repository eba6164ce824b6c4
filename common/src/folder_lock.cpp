#include "acst_common/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "acst_common/input_error.hpp"

namespace acst::common {
namespace fs = std::filesystem;

namespace {

// What the holder wrote into the lock file: its PID, or "" while it has not yet.
std::string holder_of(int fd) {
  char text[32] = {};
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  std::string pid = n > 0 ? std::string(text, static_cast<std::size_t>(n)) : "";
  while (!pid.empty() && (pid.back() == '\n' || pid.back() == ' ')) pid.pop_back();
  return pid.find_first_not_of("0123456789") == std::string::npos ? pid : "";
}

}  // namespace

FolderLock::FolderLock(const std::string& dir, const std::string& file_name, const std::string& tool)
    : dir_(dir), file_((fs::path(dir) / file_name).string()) {
  std::error_code ec;
  made_dir_ = !fs::exists(dir_, ec);
  fs::create_directories(dir_);
  // O_EXCL first, to know whether this run made the file; O_NOFOLLOW: a link planted at the
  // name is refused, never followed.
  fd_ = ::open(file_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  made_file_ = fd_ >= 0;
  if (fd_ < 0 && errno == EEXIST) fd_ = ::open(file_.c_str(), O_RDWR | O_NOFOLLOW | O_CLOEXEC);
  if (fd_ < 0)
    throw InputError("the output folder '" + dir_ + "': cannot open its lock file '" + file_name + "': " +
                     std::strerror(errno));
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    const std::string pid = holder_of(fd_);
    ::close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK)
      throw InputError("the output folder '" + dir_ + "' is in use by another " + tool +
                       (pid.empty() ? std::string() : " (PID " + pid + ")") +
                       ": two runs in one folder would mix their files; wait for it to end or choose another folder");
    throw InputError("the output folder '" + dir_ + "': cannot lock '" + file_name + "': " + std::strerror(error));
  }
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, pid.data(), pid.size(), 0) < 0) {
    // The PID is only for the message of a run refused meanwhile; the lock holds without it.
  }
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) ::close(fd_);
}

void FolderLock::undo() {
  // Still held while the file goes: a run arriving now is refused, or makes a file of its own.
  if (made_file_) ::unlink(file_.c_str());
  if (made_dir_) ::rmdir(dir_.c_str());  // only when empty: another run may have started in it
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
}

}  // namespace acst::common
