#pragma once
// A fresh folder per test under the system's temporary folder, and the list of everything in it,
// for the tests that check that a tool wrote nothing, or nothing outside its output folder.
// The folders a test program made are removed when it ends with every test passed, and kept
// (for a look at what went wrong) when one failed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

namespace acst::test {

namespace detail {

// Listens to the test program's end (GoogleTest owns and deletes it).
class ScratchCleaner : public ::testing::EmptyTestEventListener {
 public:
  void add(const std::filesystem::path& d) {
    const std::lock_guard<std::mutex> lock(mutex_);
    folders_.push_back(d);
  }
  void OnTestProgramEnd(const ::testing::UnitTest& unit) override {
    if (!unit.Passed()) return;
    std::error_code ignored;  // a folder already gone or busy is no reason to fail the program
    for (const auto& d : folders_) std::filesystem::remove_all(d, ignored);
  }

 private:
  std::mutex mutex_;
  std::vector<std::filesystem::path> folders_;
};

inline ScratchCleaner& scratch_cleaner() {
  static ScratchCleaner* const cleaner = [] {
    auto* c = new ScratchCleaner;
    ::testing::UnitTest::GetInstance()->listeners().Append(c);
    return c;
  }();
  return *cleaner;
}

}  // namespace detail

inline std::filesystem::path scratch_folder(const std::string& tag) {
  const auto d = std::filesystem::temp_directory_path() / ("acst_" + tag + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  detail::scratch_cleaner().add(d);
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
