// The MPM's three parts keep their floors (mpm_adapter/CMakeLists.txt, docs/mpm.md): the core
// includes nothing of the tools and of the material but acst.h, the footing tool nothing of the
// sweep tool, and inside each part no module (a header and the sources that implement it)
// reaches back up to one that reaches it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <algorithm>
#include <functional>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace acst::test::mpm_layers_test {
namespace fs = std::filesystem;

const fs::path root = fs::path(ACST_SOURCE_DIR) / "mpm_adapter";

std::vector<std::string> project_includes(const fs::path& file) {
  std::ifstream in(file);
  const std::regex include(R"re(^\s*#\s*include\s*"([^"]+)")re");
  std::vector<std::string> out;
  std::smatch m;
  for (std::string line; std::getline(in, line);)
    if (std::regex_search(line, m, include)) out.push_back(m[1]);
  return out;
}

std::vector<fs::path> sources_of(const std::string& part) {
  std::vector<fs::path> files;
  for (const auto& e : fs::recursive_directory_iterator(root / part))
    if (e.is_regular_file() && (e.path().extension() == ".hpp" || e.path().extension() == ".cpp"))
      files.push_back(e.path());
  return files;
}

TEST(MpmLayers, EachPartIncludesOnlyWhatLiesBelowIt) {
  const std::map<std::string, std::vector<std::string>> allowed = {
      {"core", {"acst_mpm/", "acst_common/", "acst.h"}},
      {"footing_tool", {"acst_footing_tool/", "acst_mpm/", "acst_common/", "acst.h"}},
      {"sweep_tool", {"acst_sweep/", "acst_footing_tool/", "acst_mpm/", "acst_common/", "sweep_mpi.hpp"}}};
  for (const auto& [part, prefixes] : allowed) {
    const std::vector<fs::path> files = sources_of(part);
    ASSERT_GT(files.size(), 3u) << part;
    for (const fs::path& f : files)
      for (const std::string& inc : project_includes(f)) {
        bool ok = false;
        for (const std::string& p : prefixes) ok = ok || inc.rfind(p, 0) == 0;
        EXPECT_TRUE(ok) << f << " includes \"" << inc << "\", which is not below " << part;
      }
  }
}

// A module is a stem: a header and the source of the same name (a source without a header of its
// own, like main.cpp, is a module nothing includes).
TEST(MpmLayers, NoModuleReachesBackUpInsideAPart) {
  const std::map<std::string, std::string> own_prefix = {
      {"core", "acst_mpm/"}, {"footing_tool", "acst_footing_tool/"}, {"sweep_tool", "acst_sweep/"}};
  for (const auto& entry : own_prefix) {
    // Named copies, not structured bindings: a lambda below captures the part's name, and
    // C++17 (clang) does not let a lambda capture a structured binding.
    const std::string part = entry.first;
    const std::string prefix = entry.second;
    const std::vector<fs::path> files = sources_of(part);
    std::map<std::string, std::set<std::string>> uses;
    for (const fs::path& f : files) {
      std::vector<std::string> own;  // the modules of this part it includes
      for (const std::string& inc : project_includes(f))
        if (inc.rfind(prefix, 0) == 0 || inc.find('/') == std::string::npos) own.push_back(fs::path(inc).stem().string());
      const std::string module = f.stem().string();
      for (const std::string& used : own)
        if (used != module) uses[module].insert(used);
    }
    // Depth-first search for a cycle, naming it.
    std::map<std::string, int> mark;  // 1 on the path, 2 done
    std::vector<std::string> path;
    std::function<void(const std::string&)> visit = [&](const std::string& m) {
      mark[m] = 1;
      path.push_back(m);
      for (const std::string& n : uses[m]) {
        if (mark[n] == 1) {
          std::string cycle;
          for (auto it = std::find(path.begin(), path.end(), n); it != path.end(); ++it) cycle += *it + " -> ";
          ADD_FAILURE() << part << ": " << cycle << n;
        } else if (mark[n] == 0) {
          visit(n);
        }
      }
      path.pop_back();
      mark[m] = 2;
    };
    for (const auto& [m, used] : uses)
      if (mark[m] == 0) visit(m);
  }
}

}  // namespace acst::test::mpm_layers_test
