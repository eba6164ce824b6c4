// Inputs that are not what they claim (issue 14: crashes and hangs), in the three tools: a
// directory, /dev/zero or a FIFO where a file is named, a JSON document nested two megabytes
// deep, a number beyond the range of a double. Each is refused at once with exit 2, a message
// that names the file or the JSON path, and nothing written.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <chrono>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "acst_calibration/cli.hpp"
#include "acst_common/files.hpp"
#include "acst_driver/cli.hpp"
#include "acst_footing_tool/cli.hpp"
#include "driver_scenes.hpp"
#include "scratch.hpp"

namespace acst::test::hostile_files_test {
namespace {

namespace fs = std::filesystem;
using Cli = int (*)(const std::vector<std::string>&, std::ostream&, std::ostream&);

const std::string data = std::string(ACST_SOURCE_DIR) + "/data";

void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

// Runs the tool on `args` (output into dir/out); expects exit 2 within a second, every piece of
// `says` in the message, and the scratch folder as it was.
void expect_refused(Cli cli, const fs::path& dir, std::vector<std::string> args, const std::vector<std::string>& says) {
  const std::vector<std::string> before = everything_under(dir);
  args.insert(args.begin(), {"--quiet", "--no-plot", "--output", (dir / "out").string()});
  std::ostringstream out, err;
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_EQ(cli(args, out, err), 2) << err.str();
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 2.0);
  for (const std::string& s : says) EXPECT_NE(err.str().find(s), std::string::npos) << "missing '" << s << "' in: " << err.str();
  EXPECT_EQ(everything_under(dir), before);
}

// A folder with a FIFO, a directory and a file of 2 MB of '[' to name as inputs.
struct Specials {
  fs::path dir, fifo, folder, deep;
  explicit Specials(const std::string& tag) : dir(scratch_folder(tag)), fifo(dir / "fifo.json"), folder(dir / "folder.json"), deep(dir / "deep.json") {
    EXPECT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    fs::create_directories(folder);
    write(deep, std::string(2 << 20, '['));
  }
  ~Specials() { fs::remove_all(dir); }
};

const std::string shear =
    "[{\"control\": {\"11\": {\"strain_pct\": 0.05}, \"22\": {\"stress\": 0}, \"33\": {\"stress\": 0},"
    " \"12\": {\"strain_pct\": 0.2}, \"13\": {\"stress\": 0}, \"23\": {\"stress\": 0}}, \"increments\": 5}]";

TEST(HostileFiles, ElementTool) {
  const Specials s("files_element");
  const Cli cli = driver::element_cli;
  expect_refused(cli, s.dir, {"/dev/zero"}, {"the scene file '/dev/zero': a character device, not a regular file"});
  expect_refused(cli, s.dir, {s.fifo.string()}, {"the scene file '" + s.fifo.string() + "': a FIFO, not a regular file"});
  expect_refused(cli, s.dir, {s.folder.string()}, {"the scene file '" + s.folder.string() + "': a directory, not a regular file"});
  expect_refused(cli, s.dir, {s.deep.string()},
                 {"the scene file '" + s.deep.string() + "': not valid JSON: at /0/0/0", "nested deeper than 100 levels"});
  write(s.dir / "material.json", "{\"parameters\": {\"G0\": 1e999}}");
  write(s.dir / "t.json", scene_json(shear, 100.0, 0.7, "", "{\"file\": \"/dev/zero\"}"));
  expect_refused(cli, s.dir, {(s.dir / "t.json").string()}, {"/material/file: the material file '/dev/zero': a character device"});
  write(s.dir / "t.json", scene_json(shear, 100.0, 0.7, "", "{\"file\": \"material.json\"}"));
  expect_refused(cli, s.dir, {(s.dir / "t.json").string()}, {"/material/file: the material file", "at /parameters/G0: number overflow parsing '1e999'"});
  write(s.dir / "t.json", scene_json(shear, 100.0, 0.7, ", \"lab_data\": [\"fifo.json\"]"));
  expect_refused(cli, s.dir, {(s.dir / "t.json").string()}, {"/lab_data/0: ", "fifo.json': a FIFO, not a regular file"});
  write(s.dir / "t.json", scene_json(shear, 100.0, 0.7, ", \"output\": {\"every\": 1e999}"));
  expect_refused(cli, s.dir, {(s.dir / "t.json").string()}, {"at /output/every: number overflow parsing '1e999'"});
}

std::string fit_description(const std::string& material, const std::string& lab, const std::string& extra = "") {
  return "{\"material\": {\"file\": \"" + material + "\"}, \"parameters\": {\"d1\": {\"start\": 0.5, \"bounds\": [0.1, 2.0]}}," +
         " \"experiments\": [{\"data\": \"" + lab + "\"" + extra + "}]}";
}

TEST(HostileFiles, FitTool) {
  const Specials s("files_fit");
  const Cli cli = calibration::fit_cli;
  const std::string material = data + "/parameters/toyoura_acst_guide.json";
  const std::string lab = data + "/lab/fukushima_tatsuoka_1984/ft84_fig5a_sc1p0.csv";
  expect_refused(cli, s.dir, {"/dev/zero"}, {"the fit description '/dev/zero': a character device, not a regular file"});
  expect_refused(cli, s.dir, {s.fifo.string()}, {"the fit description '" + s.fifo.string() + "': a FIFO, not a regular file"});
  expect_refused(cli, s.dir, {s.folder.string()}, {"the fit description '" + s.folder.string() + "': a directory, not a regular file"});
  expect_refused(cli, s.dir, {s.deep.string()},
                 {"the fit description '" + s.deep.string() + "': not valid JSON: at /0/0/0", "nested deeper than 100 levels"});
  write(s.dir / "fit.json", fit_description("/dev/zero", lab));
  expect_refused(cli, s.dir, {(s.dir / "fit.json").string()}, {"/material/file: the material file '/dev/zero': a character device"});
  write(s.dir / "fit.json", fit_description(material, s.fifo.string()));
  expect_refused(cli, s.dir, {(s.dir / "fit.json").string()}, {"/experiments/0/data: ", "fifo.json': a FIFO, not a regular file"});
  write(s.dir / "fit.json", fit_description(material, "/dev/zero"));
  expect_refused(cli, s.dir, {(s.dir / "fit.json").string()}, {"/experiments/0/data: ", "'/dev/zero': a character device"});
  // The number that made acst_fit abort, in the description and in the material file it names.
  write(s.dir / "fit.json", fit_description(material, lab, ", \"weight\": 1e999"));
  expect_refused(cli, s.dir, {(s.dir / "fit.json").string()}, {"at /experiments/0/weight: number overflow parsing '1e999'"});
  // In a lab file's header the number reads as infinity: held to the description's range.
  std::string header_inf = common::read_input_file(lab);
  header_inf.replace(header_inf.find("# sigma3_kPa: 98.0"), 18, "# sigma3_kPa: 1e999");
  write(s.dir / "lab.csv", header_inf);
  write(s.dir / "fit.json", fit_description(material, (s.dir / "lab.csv").string()));
  expect_refused(cli, s.dir, {(s.dir / "fit.json").string()}, {"/experiments/0: the lab file", "has 'sigma3_kPa: 1e999', out of range; allowed: (0, inf); give sigma3_kPa"});
  write(s.dir / "material.json", "{\"parameters\": {\"G0\": -1e999}}");
  write(s.dir / "fit.json", fit_description((s.dir / "material.json").string(), lab));
  expect_refused(cli, s.dir, {(s.dir / "fit.json").string()}, {"/material/file: the material file", "at /parameters/G0: number overflow parsing '-1e999'"});
}

std::string mpm_scene(const std::string& material, const std::string& output = "") {
  return "{\"name\": \"s\", \"grid\": {\"cell_size\": 0.5}, \"materials\": {\"soil\": " + material + "}," +
         " \"bodies\": [{\"material\": \"soil\", \"x_range\": [0, 2], \"y_range\": [0, 1], \"density\": 1000}]," +
         " \"stop\": {\"steps\": 3}" + output + "}";
}

TEST(HostileFiles, MpmTool) {
  const Specials s("files_mpm");
  const Cli cli = mpm::mpm_cli;
  const std::string elastic = "{\"model\": \"linear_elastic\", \"parameters\": {\"E\": 1000, \"nu\": 0.3}}";
  expect_refused(cli, s.dir, {"/dev/zero"}, {"the scene file '/dev/zero': a character device, not a regular file"});
  expect_refused(cli, s.dir, {s.fifo.string()}, {"the scene file '" + s.fifo.string() + "': a FIFO, not a regular file"});
  expect_refused(cli, s.dir, {s.folder.string()}, {"the scene file '" + s.folder.string() + "': a directory, not a regular file"});
  expect_refused(cli, s.dir, {s.deep.string()},
                 {"the scene file '" + s.deep.string() + "': not valid JSON: at /0/0/0", "nested deeper than 100 levels"});
  write(s.dir / "s.json", mpm_scene("\"/dev/zero\""));
  expect_refused(cli, s.dir, {(s.dir / "s.json").string()}, {"/materials/soil: '/dev/zero': a character device"});
  write(s.dir / "s.json", mpm_scene("\"fifo.json\""));
  expect_refused(cli, s.dir, {(s.dir / "s.json").string()}, {"/materials/soil: ", "fifo.json': a FIFO"});
  write(s.dir / "s.json", mpm_scene(elastic, ", \"output\": {\"lab_curve\": \"folder.json\"}"));
  expect_refused(cli, s.dir, {(s.dir / "s.json").string()}, {"/output/lab_curve: ", "folder.json': a directory"});
  write(s.dir / "s.json", mpm_scene("{\"model\": \"linear_elastic\", \"parameters\": {\"E\": 1e999, \"nu\": 0.3}}"));
  expect_refused(cli, s.dir, {(s.dir / "s.json").string()}, {"at /materials/soil/parameters/E: number overflow parsing '1e999'"});
  // A checkpoint to resume from must be a regular file as well.
  write(s.dir / "s.json", mpm_scene(elastic));
  expect_refused(cli, s.dir, {"--resume", "/dev/zero", (s.dir / "s.json").string()}, {"--resume: the checkpoint '/dev/zero': a character device"});
}

}  // namespace
}  // namespace acst::test::hostile_files_test
