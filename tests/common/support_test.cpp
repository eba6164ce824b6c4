// The support layer (common/): JSON field readers name the JSON path, files are written whole
// or not at all (at once or streamed), paths resolve against the naming file's folder, durations read as people write
// them, and the parallel loop visits every index exactly once and passes exceptions on.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>
#include <vector>

#include "acst_common/atomic_file.hpp"
#include "acst_common/duration.hpp"
#include "acst_common/files.hpp"
#include "acst_common/interpolate.hpp"
#include "acst_common/json_fields.hpp"
#include "acst_common/parallel_for.hpp"
#include "acst_common/plain_stem.hpp"
#include "acst_common/result_folder.hpp"
#include "scratch.hpp"

namespace fs = std::filesystem;
namespace f = acst::common::fields;
using acst::common::InputError;
using nlohmann::json;

namespace {

std::string message_of(const std::function<void()>& fn) {
  try {
    fn();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(CommonFields, MessagesStartWithThePathAndSayWhatIsAllowed) {
  const json j = json::parse(R"({"a": -1, "b": "x", "c": 1.5, "d": [1, 2]})");
  EXPECT_EQ(message_of([&] { f::number(j["a"], "/a", f::positive(), "kPa"); }).rfind("/a: -1 is out of range; allowed: (0, inf) kPa", 0), 0u);
  EXPECT_EQ(message_of([&] { f::number(j["b"], "/b"); }).rfind("/b: expected a number", 0), 0u);
  EXPECT_EQ(message_of([&] { f::integer(j["c"], "/c", 0, 9); }).rfind("/c: expected an integer in [0, 9]", 0), 0u);
  EXPECT_EQ(message_of([&] { f::numbers(j["d"], "/d", 3, "x y z"); }).rfind("/d: expected an array of 3 numbers", 0), 0u);
  EXPECT_EQ(message_of([&] { f::allow_keys(j, {"a", "b"}, ""); }).rfind("/c: unknown key (allowed here: a, b)", 0), 0u);
  EXPECT_EQ(message_of([&] { f::parse("{\"x\": 1e999}", "", "the scene"); }).rfind("/: the scene is not valid JSON", 0), 0u);
  EXPECT_EQ(message_of([&] { f::parse("{", "/file", "the file"); }).rfind("/file: the file is not valid JSON", 0), 0u);
  EXPECT_EQ(f::number(j["c"], "/c", f::positive()), 1.5);
}

TEST(CommonFiles, AtomicWriteReplacesWholeOrLeavesTheOldFile) {
  const fs::path dir = fs::temp_directory_path() / ("acst_common_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string file = (dir / "result.csv").string();
  acst::common::write_file_atomically(file, "old\n");
  acst::common::write_file_atomically(file, "new\n");
  EXPECT_EQ(acst::common::read_input_file(file), "new\n");
  // A target that cannot be replaced (a non-empty folder of that name): the write fails, no
  // temporary file is left behind and the folder is untouched.
  fs::create_directories(dir / "taken" / "inside");
  EXPECT_THROW(acst::common::write_file_atomically((dir / "taken").string(), "x"), std::runtime_error);
  EXPECT_TRUE(fs::is_directory(dir / "taken" / "inside"));
  int entries = 0;
  for (const auto& e : fs::directory_iterator(dir)) entries += e.path().filename().string()[0] == '.';
  EXPECT_EQ(entries, 0) << "a temporary file was left";
  EXPECT_THROW(acst::common::read_input_file((dir / "none").string()), InputError);
  fs::remove_all(dir);
}

// A folder of an earlier run is emptied into previous/ (which the next run replaces); a move
// interrupted half way is finished by the next call, so no file is lost or left beside a new run.
TEST(CommonFiles, AnEarlierRunIsSetAsideWholeEvenAfterAnInterruption) {
  using acst::common::set_aside_earlier_run;
  const fs::path dir = fs::temp_directory_path() / ("acst_common_aside_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const auto own = [](const std::string& name) { return name.rfind("run_", 0) == 0 || acst::common::is_temporary_name(name); };
  EXPECT_EQ(set_aside_earlier_run(dir.string(), own), 0u);  // created, nothing to move
  EXPECT_TRUE(fs::is_directory(dir));
  for (const char* f : {"run_a.csv", "run_b.vtp", ".run_c.csv.tmp123"}) std::ofstream(dir / f) << f;
  EXPECT_EQ(set_aside_earlier_run(dir.string(), own), 3u);
  EXPECT_TRUE(fs::exists(dir / "previous" / "run_b.vtp"));
  // interrupted: one file already in previous.new, one still in the folder
  fs::create_directories(dir / "previous.new");
  std::ofstream(dir / "previous.new" / "run_d.csv") << "d";
  std::ofstream(dir / "run_e.csv") << "e";
  EXPECT_EQ(set_aside_earlier_run(dir.string(), own), 1u);
  EXPECT_FALSE(fs::exists(dir / "previous.new"));
  EXPECT_TRUE(fs::exists(dir / "previous" / "run_d.csv"));
  EXPECT_TRUE(fs::exists(dir / "previous" / "run_e.csv"));
  EXPECT_FALSE(fs::exists(dir / "previous" / "run_b.vtp")) << "the older run is replaced";
  // anything the tool does not write is refused, and nothing moves
  std::ofstream(dir / "run_f.csv") << "f";
  fs::create_directories(dir / "run_folder");
  EXPECT_THROW(set_aside_earlier_run(dir.string(), own), InputError);
  EXPECT_TRUE(fs::exists(dir / "run_f.csv"));
  EXPECT_FALSE(acst::common::is_temporary_name(".tmp1"));
  EXPECT_FALSE(acst::common::is_temporary_name(".a.tmp"));
  EXPECT_FALSE(acst::common::is_temporary_name("a.tmp12"));
  fs::remove_all(dir);
}

TEST(CommonFiles, StreamedWriteAppearsWholeAtCommitAndNotAtAllWhenDropped) {
  const fs::path dir = acst::test::scratch_folder("common_stream");
  const std::string file = (dir / "result.csv").string();
  acst::common::write_file_atomically(file, "old\n");
  auto hidden = [&] {
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir)) n += e.path().filename().string()[0] == '.';
    return n;
  };
  {
    acst::common::AtomicFileWriter w(file);
    w.write("new ");
    w.write("rows\n");
    EXPECT_EQ(w.size(), 9u);
    EXPECT_EQ(acst::common::read_input_file(file), "old\n");  // not before the commit
    EXPECT_EQ(hidden(), 1);
  }  // dropped: the old file stays, the temporary file goes
  EXPECT_EQ(acst::common::read_input_file(file), "old\n");
  EXPECT_EQ(hidden(), 0);
  // A second writer takes a range of the first's text (a header put in front of written rows).
  acst::common::AtomicFileWriter rows(file);
  rows.write("0123456789");
  acst::common::AtomicFileWriter other((dir / "other.csv").string());
  other.write("head,");
  other.copy_from(rows, 3, 7);
  other.commit();
  rows.commit();
  EXPECT_EQ(acst::common::read_input_file((dir / "other.csv").string()), "head,3456");
  EXPECT_EQ(acst::common::read_input_file(file), "0123456789");
  EXPECT_EQ(hidden(), 0);
  EXPECT_THROW(acst::common::AtomicFileWriter((dir / "no" / "such" / "folder.csv").string()), std::runtime_error);
  fs::remove_all(dir);
}

TEST(CommonFiles, ResolveIsRelativeToTheNamingFilesFolder) {
  EXPECT_EQ(acst::common::resolve("/data/scenes", "../lab/x.csv"), "/data/scenes/../lab/x.csv");
  EXPECT_EQ(acst::common::resolve("/data/scenes", "/abs/x.csv"), "/abs/x.csv");
  EXPECT_EQ(acst::common::resolve("", "x.csv"), "x.csv");
}

TEST(CommonDuration, ReadsAsPeopleWriteIt) {
  EXPECT_EQ(acst::common::duration_text(12.34), "12.3 s");
  EXPECT_EQ(acst::common::duration_text(245.0), "4 min 05 s");
  EXPECT_EQ(acst::common::duration_text(7380.0), "2 h 03 min");
  EXPECT_EQ(acst::common::duration_text(-1.0), "?");
}

TEST(CommonParallelFor, EveryIndexOnceForAnyThreadCountAndSchedule) {
  for (int threads : {1, 2, 3})
    for (auto schedule : {acst::common::Schedule::static_chunks, acst::common::Schedule::dynamic}) {
      std::vector<std::atomic<int>> hits(1001);
      acst::common::parallel_for(threads, hits.size(), [&](int, std::size_t i) { ++hits[i]; }, schedule);
      for (std::size_t i = 0; i < hits.size(); ++i) ASSERT_EQ(hits[i].load(), 1) << i << " threads " << threads;
    }
}

TEST(CommonParallelFor, StaticChunksGiveEachIndexAFixedThread) {
  std::vector<int> first(100, -1), second(100, -2);
  acst::common::parallel_for(2, first.size(), [&](int t, std::size_t i) { first[i] = t; });
  acst::common::parallel_for(2, second.size(), [&](int t, std::size_t i) { second[i] = t; });
  EXPECT_EQ(first, second);
}

TEST(CommonParallelFor, AnExceptionFromTheBodyIsRethrown) {
  EXPECT_THROW(acst::common::parallel_for(2, 50, [](int, std::size_t i) {
                 if (i == 17) throw std::runtime_error("17");
               }),
               std::runtime_error);
}

TEST(CommonPlainStem, OnlyNamesThatStayInTheirFolder) {
  for (const char* good : {"kimura_V85.6_alpha0", "a", "x-1"}) EXPECT_TRUE(acst::common::is_plain_stem(good)) << good;
  for (const char* bad : {"", ".", "..", ".hidden", "a/b", "../x", "a b", "q'uote", "semi;colon", "new\nline"})
    EXPECT_FALSE(acst::common::is_plain_stem(bad)) << bad;
  EXPECT_FALSE(acst::common::is_plain_stem(std::string(101, 'a')));
  EXPECT_EQ(message_of([] { acst::common::require_plain_stem("..", "/name"); }).rfind("/name: '..' is not a plain file stem", 0), 0u);
}

TEST(CommonInterpolate, LinearInsideNaNOutsideFirstOfRepeats) {
  const std::vector<double> x{0.0, 1.0, 1.0, 3.0}, y{0.0, 2.0, 5.0, 9.0};
  EXPECT_DOUBLE_EQ(acst::common::interpolate(x, y, 0.5), 1.0);
  EXPECT_DOUBLE_EQ(acst::common::interpolate(x, y, 1.0), 2.0);  // the first of the repeated x
  EXPECT_DOUBLE_EQ(acst::common::interpolate(x, y, 2.0), 7.0);  // between the last repeat and 3
  EXPECT_TRUE(std::isnan(acst::common::interpolate(x, y, -0.1)));
  EXPECT_TRUE(std::isnan(acst::common::interpolate(x, y, 3.1)));
  EXPECT_TRUE(std::isnan(acst::common::interpolate({}, {}, 0.0)));
  const auto [fx, fy] = acst::common::finite_samples({0.0, 1.0, NAN, 3.0}, {1.0, NAN, 4.0, 7.0});
  EXPECT_EQ(fx, (std::vector<double>{0.0, 3.0}));
  EXPECT_EQ(fy, (std::vector<double>{1.0, 7.0}));
}
