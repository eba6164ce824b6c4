#include "acst_common/result_folder.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include "acst_common/input_error.hpp"

namespace acst::common {
namespace fs = std::filesystem;

namespace {

[[noreturn]] void refuse_entry(const std::string& dir, const std::string& name) {
  throw InputError("the output folder '" + dir + "' holds '" + name +
                   "', which this tool does not write: choose an empty folder or one of an earlier run");
}

void require_folder_or_nothing(const fs::path& root, const std::string& dir) {
  std::error_code ec;
  if (fs::exists(root, ec) && !fs::is_directory(root, ec))
    throw InputError("the output folder '" + dir + "' exists and is not a folder");
}

}  // namespace

void require_own_folder(const std::string& dir, const std::function<bool(const std::string&)>& is_own) {
  const fs::path root(dir);
  require_folder_or_nothing(root, dir);
  std::error_code ec;
  if (!fs::exists(root, ec)) return;
  for (const fs::directory_entry& e : fs::directory_iterator(root)) {
    const std::string name = e.path().filename().string();
    if (!is_own(name)) refuse_entry(dir, name);
  }
}

std::string staging_folder_for(const std::string& dir) {
  fs::path p = fs::absolute(dir).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();  // "a/b/" and "a/b/." name the folder b
  return (p.parent_path() / ("." + p.filename().string() + ".new" + std::to_string(::getpid()))).string();
}

void publish_folder(const std::string& staging, const std::string& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) {
    fs::rename(staging, dir);
    return;
  }
  if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, dir.c_str(), RENAME_EXCHANGE) != 0) {
    if (errno != EINVAL && errno != ENOSYS)
      throw std::runtime_error("cannot put '" + staging + "' in the place of '" + dir + "': " + std::strerror(errno));
    const std::string old = staging + ".old";
    fs::rename(dir, old);
    fs::rename(staging, dir);
    fs::remove_all(old);
    return;
  }
  fs::remove_all(staging);  // now the earlier set
}

std::size_t set_aside_earlier_run(const std::string& dir, const std::function<bool(const std::string&)>& is_own) {
  const fs::path root(dir);
  require_folder_or_nothing(root, dir);
  fs::create_directories(root);
  const std::string previous = previous_run_folder, staging = previous + ".new";
  std::vector<fs::path> earlier;
  for (const fs::directory_entry& e : fs::directory_iterator(root)) {
    const std::string name = e.path().filename().string();
    if (name == previous || name == staging) continue;
    if (!is_own(name) || !e.is_regular_file()) refuse_entry(dir, name);
    earlier.push_back(e.path());
  }
  if (earlier.empty() && !fs::exists(root / staging)) return 0;
  fs::create_directories(root / staging);
  for (const fs::path& f : earlier) fs::rename(f, root / staging / f.filename());
  fs::remove_all(root / previous);
  fs::rename(root / staging, root / previous);
  return earlier.size();
}

}  // namespace acst::common
