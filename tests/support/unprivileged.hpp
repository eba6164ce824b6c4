#pragma once
// Permissions as a user has them, also where the tests run as root (CI does), for whom a folder's
// mode bits mean nothing: `body` runs in a child process that first becomes the user nobody
// (65534) when this process is root. Its exit status is the child's return value; 125 when the
// user could not be changed. Fork before the test starts threads (an OpenMP pool): a child of a
// threaded process may only call what is safe after fork.
#include <grp.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <functional>

namespace acst::test {

inline constexpr uid_t unprivileged_id = 65534;

// Makes `path` and everything under it the unprivileged user's, so that the child can use it.
inline void hand_to_unprivileged(const std::filesystem::path& path) {
  if (::geteuid() != 0) return;
  if (::chown(path.c_str(), unprivileged_id, unprivileged_id) != 0) return;
  for (const auto& e : std::filesystem::recursive_directory_iterator(path))
    if (::lchown(e.path().c_str(), unprivileged_id, unprivileged_id) != 0) return;
}

inline int run_unprivileged(const std::function<int()>& body) {
  const pid_t child = ::fork();
  if (child == 0) {
    if (::geteuid() == 0 && (::setgroups(0, nullptr) != 0 || ::setresgid(unprivileged_id, unprivileged_id, unprivileged_id) != 0 ||
                             ::setresuid(unprivileged_id, unprivileged_id, unprivileged_id) != 0))
      ::_exit(125);
    ::_exit(body());
  }
  int status = 0;
  if (child < 0 || ::waitpid(child, &status, 0) != child) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

// Whether the unprivileged user can read `path` (a test that runs a tool as that user on the
// checkout's data cannot run where the checkout lies under a folder only its owner may enter).
inline bool unprivileged_can_read(const std::filesystem::path& path) {
  return run_unprivileged([&] { return ::access(path.c_str(), R_OK) == 0 ? 0 : 1; }) == 0;
}

}  // namespace acst::test
