#pragma once
// A fresh folder per test under the system's temporary folder, and the list of everything in it,
// for the tests that check that a tool wrote nothing, or nothing outside its output folder.
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace acst::test {

inline std::filesystem::path scratch_folder(const std::string& tag) {
  const auto d = std::filesystem::temp_directory_path() / ("acst_" + tag + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

// Every file and folder under `root` (relative paths, sorted); `except` (a folder under root) is
// listed but not entered.
inline std::vector<std::string> everything_under(const std::filesystem::path& root, const std::filesystem::path& except = {}) {
  std::vector<std::string> names;
  for (auto it = std::filesystem::recursive_directory_iterator(root); it != std::filesystem::recursive_directory_iterator(); ++it) {
    names.push_back(std::filesystem::relative(it->path(), root).string());
    if (!except.empty() && it->path() == except) it.disable_recursion_pending();
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace acst::test
