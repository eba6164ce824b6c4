// The MPM's maps stay true to its code: every source file of the core and the tools is named in
// the README's code map, and every call of Simulation::step() in the manual's phase list
// (docs/mpm.md, "One step"), so that a new file or phase cannot land undocumented.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

namespace acst::test::code_map_test {
namespace fs = std::filesystem;

const fs::path source = fs::path(ACST_SOURCE_DIR);

std::string text_of(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// The text from the line that starts with `heading` to the next heading of its level or above.
std::string section(const std::string& text, const std::string& heading) {
  const std::size_t at = text.find("\n" + heading);
  if (at == std::string::npos) return "";
  const std::string level = heading.substr(0, heading.find(' ') + 1);  // "## "
  std::size_t end = at + 1;
  while ((end = text.find("\n#", end + 1)) != std::string::npos) {
    const std::size_t hashes = text.find_first_not_of('#', end + 1) - (end + 1);
    if (hashes <= level.size() - 1) break;
  }
  return text.substr(at, end == std::string::npos ? std::string::npos : end - at);
}

TEST(CodeMap, EverySourceFileOfTheMpmIsInTheReadmesCodeMap) {
  const std::string map = section(text_of(source / "README.md"), "## Code map");
  ASSERT_FALSE(map.empty()) << "README.md has no '## Code map'";
  int files = 0;
  for (const char* part : {"core", "footing_tool", "sweep_tool"})
    for (const auto& e : fs::recursive_directory_iterator(source / "mpm_adapter" / part)) {
      const std::string ext = e.path().extension().string();
      if (!e.is_regular_file() || (ext != ".hpp" && ext != ".cpp")) continue;
      ++files;
      const std::string stem = e.path().stem().string();
      const std::regex named("\\b" + stem + "\\.(hpp|cpp)\\b");
      EXPECT_TRUE(std::regex_search(map, named)) << e.path() << " is not in the README's code map";
    }
  EXPECT_GT(files, 40);
}

TEST(CodeMap, EveryCallOfStepIsInTheManualsPhaseList) {
  const std::string code = text_of(source / "mpm_adapter/core/src/simulation.cpp");
  const std::size_t begin = code.find("void Simulation::step() {");
  ASSERT_NE(begin, std::string::npos);
  const std::string body = code.substr(begin, code.find("\n}\n", begin) - begin);
  const std::string phases = section(text_of(source / "docs/mpm.md"), "## One step");
  ASSERT_FALSE(phases.empty()) << "docs/mpm.md has no '## One step'";
  // Calls, less the language's words and the arguments' accessors.
  const std::set<std::string> not_phases = {"step", "if", "fail_at", "data", "threads", "static_cast", "phase", "lap"};
  const std::regex call(R"((\w+)\()");
  int calls = 0;
  for (std::sregex_iterator it(body.begin(), body.end(), call), end; it != end; ++it) {
    const std::string name = (*it)[1];
    if (not_phases.count(name)) continue;
    ++calls;
    const std::regex listed("`[^`\n]*\\b" + name + "\\b[^`\n]*`");
    EXPECT_TRUE(std::regex_search(phases, listed)) << "step() calls " << name << ", which docs/mpm.md's phase list does not name";
  }
  EXPECT_GT(calls, 10);
}

}  // namespace acst::test::code_map_test
