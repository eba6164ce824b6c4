#include "acst_common/result_folder.hpp"

#include <fcntl.h>
#include <sys/stat.h>
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

namespace {

// Makes and removes a hidden folder in `folder`: what the result set's publishing needs there.
void probe_writable(const fs::path& folder, const std::string& dir, const std::string& role) {
  const fs::path probe = folder / (".acst_probe" + std::to_string(::getpid()));
  if (::mkdir(probe.c_str(), 0700) != 0 && errno != EEXIST)
    throw InputError("the output folder '" + dir + "' cannot be replaced by a new result set: " + role + " '" +
                     folder.string() + "' cannot be written (" + std::strerror(errno) + ")");
  ::rmdir(probe.c_str());
}

// Removes the earlier set; "" or where it was left and why.
std::string remove_earlier_set(const fs::path& earlier, const std::string& dir) {
  std::error_code ec;
  fs::remove_all(earlier, ec);
  if (!ec) return "";
  return "the new result set is in '" + dir + "', but the earlier one could not be removed (" + ec.message() +
         "): it is left in '" + earlier.string() + "'";
}

}  // namespace

void require_replaceable_folder(const std::string& dir) {
  fs::path root = fs::absolute(dir).lexically_normal();
  if (root.filename().empty()) root = root.parent_path();
  std::error_code ec;
  // The staging folder goes beside `dir`; folders still missing on the way there are made then.
  fs::path parent = root.parent_path();
  while (!fs::exists(parent, ec) && parent.has_relative_path()) parent = parent.parent_path();
  probe_writable(parent, dir, "its parent folder");
  if (!fs::is_directory(root, ec)) return;
  probe_writable(root, dir, "the folder");
  for (auto it = fs::recursive_directory_iterator(root, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
    if (it->is_directory() && !it->is_symlink()) probe_writable(it->path(), dir, "its folder");
}

std::string publish_folder(const std::string& staging, const std::string& dir) {
  std::error_code ec;
  if (!fs::exists(dir, ec)) {
    fs::rename(staging, dir);
    return "";
  }
  if (::renameat2(AT_FDCWD, staging.c_str(), AT_FDCWD, dir.c_str(), RENAME_EXCHANGE) != 0) {
    if (errno != EINVAL && errno != ENOSYS)
      throw std::runtime_error("cannot put '" + staging + "' in the place of '" + dir + "': " + std::strerror(errno));
    const std::string old = staging + ".old";
    fs::rename(dir, old);
    fs::rename(staging, dir);
    return remove_earlier_set(old, dir);
  }
  return remove_earlier_set(staging, dir);  // now the earlier set
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
