// Reading inputs (common/): only regular files of bounded size are read (a directory, /dev/zero
// or a FIFO is refused at once, not read forever), and JSON is parsed with a depth cap and an
// error that says where inside the document it is (issue 14: crashes and hangs).
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <chrono>
#include <fstream>
#include <string>

#include "acst_common/files.hpp"
#include "acst_common/json_fields.hpp"
#include "scratch.hpp"

namespace {

namespace fs = std::filesystem;
namespace f = acst::common::fields;
using acst::common::InputError;

std::string read_error(const std::string& path, std::uintmax_t cap = acst::common::max_input_bytes) {
  try {
    acst::common::read_input_file(path, cap);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string parse_error(const std::string& text) {
  try {
    f::parse(text, "/material/file", "the material file");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(InputFiles, ARegularFileIsReadWhole) {
  const fs::path dir = acst::test::scratch_folder("input_files_regular");
  std::ofstream(dir / "a.json") << "{\"x\": 1}\n";
  EXPECT_EQ(acst::common::read_input_file((dir / "a.json").string()), "{\"x\": 1}\n");
  fs::remove_all(dir);
}

TEST(InputFiles, NonRegularFilesAreRefusedWithWhatTheyAre) {
  const fs::path dir = acst::test::scratch_folder("input_files_special");
  EXPECT_EQ(read_error(dir.string()), "'" + dir.string() + "': a directory, not a regular file");
  EXPECT_EQ(read_error("/dev/zero"), "'/dev/zero': a character device, not a regular file");
  // A FIFO without a writer: opening it must not wait for one.
  const fs::path fifo = dir / "pipe.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_EQ(read_error(fifo.string()), "'" + fifo.string() + "': a FIFO, not a regular file");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 1.0);
  EXPECT_EQ(read_error((dir / "none.json").string()), "'" + (dir / "none.json").string() + "': cannot open: No such file or directory");
  fs::remove_all(dir);
}

TEST(InputFiles, AFileAboveTheCapIsRefused) {
  const fs::path dir = acst::test::scratch_folder("input_files_cap");
  std::ofstream(dir / "big.csv") << std::string(1000, 'x');
  EXPECT_NE(read_error((dir / "big.csv").string(), 999).find("big.csv': larger than the"), std::string::npos);
  EXPECT_EQ(read_error((dir / "big.csv").string(), 1000), "");
  EXPECT_EQ(acst::common::max_input_bytes, 64u << 20);
  fs::remove_all(dir);
}

TEST(JsonDepth, TwoMegabytesOfOpeningBracketsAreRefusedNotAStackOverflow) {
  const std::string e = parse_error(std::string(2 << 20, '['));
  EXPECT_EQ(e.rfind("/material/file: the material file is not valid JSON: at /0/0/0", 0), 0u) << e;
  EXPECT_NE(e.find("nested deeper than 100 levels"), std::string::npos) << e;
}

TEST(JsonDepth, TheCapIsOneHundredLevels) {
  const auto nested = [](int levels) { return std::string(levels, '[') + std::string(levels, ']'); };
  EXPECT_EQ(parse_error(nested(100)), "");
  EXPECT_NE(parse_error(nested(101)).find("nested deeper than 100 levels"), std::string::npos);
}

TEST(JsonNumbers, ANumberBeyondADoubleNamesItsPathInsideTheDocument) {
  const std::string e = parse_error(R"({"parameters": {"G0": 1e999}})");
  EXPECT_EQ(e, "/material/file: the material file is not valid JSON: at /parameters/G0: number overflow parsing '1e999'");
  EXPECT_NE(parse_error(R"({"a": [1, 2, -1e400]})").find("at /a/2: number overflow"), std::string::npos);
}

TEST(JsonNumbers, TheParsedDocumentIsTheLibrarysOwn) {
  const std::string text = R"({"a": [1, {"b": 2.5, "c": [true, null, "s\n"]}], "a2": -3, "d": {}, "e": []})";
  EXPECT_EQ(f::parse(text, "", "x"), nlohmann::json::parse(text));
}

}  // namespace
