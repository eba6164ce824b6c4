// The one reader of JSON input files (common/json_file.hpp): every way a file can fail to be a
// JSON document is worded "<what> '<path>': <reason>", a syntax error with its line and column.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "acst_common/files.hpp"
#include "acst_common/input_error.hpp"
#include "acst_common/json_file.hpp"
#include "scratch.hpp"

namespace acst::test::json_file_test {
namespace {

namespace fs = std::filesystem;

std::string error_of(const fs::path& file, const std::string& what = "the scene file", const std::string& named_at = "") {
  try {
    common::fields::read_json_file(file.string(), what, named_at);
  } catch (const common::InputError& e) {
    return e.what();
  }
  return "read";
}

TEST(JsonFile, AValidFileIsItsDocument) {
  const fs::path dir = scratch_folder("json_file_valid");
  std::ofstream(dir / "s.json") << "{\"steps\": [1, 2.5, \"x\"], \"on\": true}\n";
  EXPECT_EQ(common::fields::read_json_file((dir / "s.json").string(), "the scene file"),
            nlohmann::json::parse("{\"steps\": [1, 2.5, \"x\"], \"on\": true}"));
}

TEST(JsonFile, EveryFailureNamesWhatTheFileIsAndWhere) {
  const fs::path dir = scratch_folder("json_file_bad");
  const std::string missing = (dir / "none.json").string();
  EXPECT_EQ(error_of(missing), "the scene file '" + missing + "': cannot open: No such file or directory");
  EXPECT_EQ(error_of(dir), "the scene file '" + dir.string() + "': a directory, not a regular file");

  // Above the cap, refused before it is read (the file is sparse: nothing is written to disk).
  const fs::path big = dir / "big.json";
  std::ofstream(big).close();
  fs::resize_file(big, common::max_input_bytes + 1);
  EXPECT_EQ(error_of(big), "the scene file '" + big.string() + "': larger than the 64 MiB an input file may have");

  std::ofstream(dir / "broken.json") << "{\n  \"steps\": [1, 2],\n  \"on\": tru\n}\n";
  const std::string broken = (dir / "broken.json").string();
  EXPECT_EQ(error_of(broken).rfind("the scene file '" + broken + "': not valid JSON: at /on: parse error at line 4, column 0: ", 0), 0u)
      << error_of(broken);
  std::ofstream(dir / "overflow.json") << "{\"parameters\": {\"G0\": 1e999}}";
  EXPECT_EQ(error_of(dir / "overflow.json"), "the scene file '" + (dir / "overflow.json").string() +
                                                 "': not valid JSON: at /parameters/G0: number overflow parsing '1e999'");
}

// A file that an input names (a material file) is read with that input's JSON path in front.
TEST(JsonFile, AFileNamedInsideAnInputStartsWithItsPath) {
  const fs::path dir = scratch_folder("json_file_named");
  const std::string missing = (dir / "m.json").string();
  EXPECT_EQ(error_of(missing, "the material file", "/material/file"),
            "/material/file: the material file '" + missing + "': cannot open: No such file or directory");
}

}  // namespace
}  // namespace acst::test::json_file_test
