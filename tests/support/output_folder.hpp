#pragma once
// Output folders that a tool finds already in use, for the tests of what the tools do with them:
// a folder `out` in a fresh scratch folder, holding files before the tool runs (an earlier run's,
// or someone else's), and the check that a tool refused such a folder and left it as it was.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "scratch.hpp"

namespace acst::test {

struct UsedOutputFolder {
  std::filesystem::path dir;  // the scratch folder (scratch_folder(tag))
  std::filesystem::path out;  // dir/out, the folder given to the tool
};

// A fresh scratch folder with the folder `out` in it, holding `files` (name, text) already.
inline UsedOutputFolder used_output_folder(const std::string& tag,
                                           const std::vector<std::pair<std::string, std::string>>& files) {
  UsedOutputFolder f{scratch_folder(tag), {}};
  f.out = f.dir / "out";
  std::filesystem::create_directories(f.out);
  for (const auto& [name, text] : files) std::ofstream(f.out / name) << text;
  return f;
}

// A tool refused an output folder that holds `foreign`, a file it does not write: exit 2, a
// message that names the file, and everything under `root` as `before` lists it (everything_under).
inline void expect_foreign_file_refused(int rc, const std::string& err, const std::string& foreign,
                                        const std::filesystem::path& root, const std::vector<std::string>& before) {
  EXPECT_EQ(rc, 2);
  EXPECT_NE(err.find("holds '" + foreign + "', which this tool does not write"), std::string::npos) << err;
  EXPECT_EQ(everything_under(root), before);
}

}  // namespace acst::test
