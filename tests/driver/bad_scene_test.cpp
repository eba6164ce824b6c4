// Every kind of bad scene gets its own clear error, naming the JSON path, and a non-zero exit
// with nothing written. Run through the command line (acst::driver::element_cli) with the
// scene in a fresh temporary directory and an output directory that must not appear.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <utility>
#include <vector>

#include "acst_driver/cli.hpp"
#include "driver_scenes.hpp"

namespace acst::test::driver_bad_scene_test {
namespace {

namespace fs = std::filesystem;

struct Case {
  const char* name;
  std::string scene;          // JSON text
  std::vector<std::string> expected;  // substrings of the error message (path first)
};

const std::string material = "{\"file\": \"" + parameter_file() + "\"}";
const std::string state = "{\"confining_pressure\": 100, \"void_ratio\": 0.7, \"bedding_angle_deg\": 0}";
const std::string tc = "{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 1, \"increments\": 10}";

std::string with(const std::string& steps, const std::string& extra = "", const std::string& st = state,
                 const std::string& mat = material) {
  return "{\"material\": " + mat + ", \"initial_state\": " + st + ", \"steps\": " + steps + extra + "}";
}

std::string six(const std::string& row) {  // six copies of a constraint row
  std::string s = "[";
  for (int i = 0; i < 6; ++i) s += (i ? ", " : "") + row;
  return s + "]";
}

std::vector<Case> cases() {
  const std::string inline_material =
      "{\"model\": \"ACST\", \"parameters\": {\"G0\": -125, \"nu\": 0.1, \"Mc\": 1.25, \"c\": 0.75, \"e_Gamma\": 0.934,"
      " \"lambda_c\": 0.019, \"xi\": 0.7, \"d1\": 0.48, \"m\": 10, \"h1\": 0.44, \"h2\": 0, \"n\": 2.3, \"e_A\": 0.16,"
      " \"F0\": 0.43, \"k_f\": 9, \"e_max\": 0.977, \"e_min\": 0.597}}";
  return {
      {"syntax", "{\"material\": ", {"not valid JSON", "line 1"}},
      {"not_object", "[1, 2]", {"/: expected a JSON object"}},
      {"unknown_top_key", with("[" + tc + "]", ", \"outputs\": {}"), {"/outputs: unknown key", "allowed here"}},
      {"missing_steps", "{\"material\": " + material + ", \"initial_state\": " + state + "}", {"/steps: required"}},
      {"material_file_missing", with("[" + tc + "]", "", state, "{\"file\": \"no/such/file.json\"}"),
       {"/material/file: the material file '", "no/such/file.json': cannot open: "}},
      {"bad_parameter", with("[" + tc + "]", "", state, inline_material), {"/material/parameters", "G0"}},
      {"bad_scheme", with("[" + tc + "]", "", state, "{\"file\": \"" + parameter_file() + "\", \"integrator\": {\"scheme\": \"RK4\"}}"),
       {"/material/integrator/scheme", "RK45"}},
      {"both_stress_forms", with("[" + tc + "]", "", "{\"stress\": [100,100,100,0,0,0], \"confining_pressure\": 100, \"void_ratio\": 0.7, \"bedding_angle_deg\": 0}"),
       {"/initial_state/confining_pressure: give only one of stress, confining_pressure"}},
      {"stress_size", with("[" + tc + "]", "", "{\"stress\": [100,100,100,0,0], \"void_ratio\": 0.7, \"bedding_angle_deg\": 0}"),
       {"/initial_state/stress: expected an array of 6 numbers"}},
      {"tension", with("[" + tc + "]", "", "{\"stress\": [-100,-100,-100,0,0,0], \"void_ratio\": 0.7, \"bedding_angle_deg\": 0}"),
       {"/initial_state/stress", "below p_min"}},
      {"void_ratio_range", with("[" + tc + "]", "", "{\"confining_pressure\": 100, \"void_ratio\": 3.5, \"bedding_angle_deg\": 0}"),
       {"/initial_state/void_ratio: 3.5 is out of range", "(0, 2.97)"}},
      {"no_fabric_direction", with("[" + tc + "]", "", "{\"confining_pressure\": 100, \"void_ratio\": 0.7}"),
       {"/initial_state: one of bedding_angle_deg, deposition_direction is required"}},
      {"empty_steps", with("[]"), {"/steps: expected a non-empty array"}},
      {"unknown_preset", with("[{\"preset\": \"triaxial\", \"increments\": 10}]"), {"/steps/0/preset: unknown preset 'triaxial'", "drained_triaxial_compression"}},
      {"preset_argument_missing", with("[{\"preset\": \"plane_strain_compression\", \"increments\": 10}]"),
       {"/steps/0/axial_strain_pct: required by preset plane_strain_compression"}},
      {"preset_unknown_argument", with("[{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 1, \"b\": 0.5, \"increments\": 10}]"),
       {"/steps/0/b: unknown key for preset drained_triaxial_compression"}},
      {"increments_missing", with("[{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 1}]"), {"/steps/0/increments: required"}},
      {"increments_zero", with("[{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 1, \"increments\": 0}]"),
       {"/steps/0/increments: 0 is out of range"}},
      {"increments_fraction", with("[{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 1, \"increments\": 2.5}]"),
       {"/steps/0/increments: expected an integer"}},
      {"strain_out_of_range", with("[{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": -3, \"increments\": 10}]"),
       {"/steps/0/axial_strain_pct: -3 is out of range", "(0, 100]"}},
      {"free_component", with("[{\"control\": {\"axial\": {\"strain_pct\": 1}, \"lateral\": {\"stress\": 0}, \"12\": {\"stress\": 0}, \"13\": {\"stress\": 0}}, \"increments\": 10}]"),
       {"/steps/0/control: component 23 is not controlled", "nothing defaults to sigma = 0"}},
      {"doubly_controlled", with("[{\"control\": {\"axial\": {\"strain_pct\": 1}, \"11\": {\"stress\": 0}, \"lateral\": {\"stress\": 0}, \"shear\": {\"stress\": 0}}, \"increments\": 10}]"),
       {"/steps/0/control/11: component 11 is already controlled by 'axial'"}},
      {"control_two_kinds", with("[{\"control\": {\"axial\": {\"strain_pct\": 1, \"stress\": 5}, \"lateral\": {\"stress\": 0}, \"shear\": {\"stress\": 0}}, \"increments\": 10}]"),
       {"/steps/0/control/axial/strain_pct: give only one of"}},
      {"constraints_count", with("[{\"constraints\": [{\"stress\": [1,0,0,0,0,0], \"change\": 0}], \"increments\": 10}]"),
       {"/steps/0/constraints: expected an array of exactly 6 constraints"}},
      {"constraints_singular", with("[{\"constraints\": " + six("{\"stress\": [1,0,0,0,0,0], \"change\": 0}") + ", \"increments\": 10}]"),
       {"/steps/0: the control leaves the strain component", "rank 1 of 6"}},
      {"constraints_zero_row", with("[{\"constraints\": " + six("{\"change\": 0}") + ", \"increments\": 10}]"),
       {"/steps/0/constraints/0: a constraint needs a non-zero"}},
      {"exit_unknown", with("[{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 1, \"increments\": 10, \"exit\": {\"q_abov\": 5}}]"),
       {"/steps/0/exit/q_abov: unknown key", "q_above"}},
      {"exit_not_number", with("[{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 1, \"increments\": 10, \"exit\": {\"q_above\": \"high\"}}]"),
       {"/steps/0/exit/q_above: expected a number"}},
      {"repeat_cycles", with("[{\"repeat\": {\"cycles\": 0, \"steps\": [" + tc + "]}}]"), {"/steps/0/repeat/cycles: 0 is out of range"}},
      {"repeat_nested", with("[{\"repeat\": {\"cycles\": 2, \"steps\": [{\"repeat\": {\"cycles\": 2, \"steps\": [" + tc + "]}}]}}]"),
       {"/steps/0/repeat/steps/0/repeat: repeat blocks cannot be nested"}},
      {"strain_path_file_missing", with("[{\"preset\": \"strain_path_csv\", \"file\": \"missing.csv\"}]"),
       {"/steps/0/file", "cannot open"}},
      {"solver_range", with("[" + tc + "]", ", \"solver\": {\"max_halvings\": 99}"), {"/solver/max_halvings: 99 is out of range"}},
      {"output_name", with("[" + tc + "]", ", \"output\": {\"name\": \"../escape\"}"), {"/output/name", "not a plain file stem"}},
      {"lab_data_missing", with("[" + tc + "]", ", \"lab_data\": \"missing.csv\""), {"/lab_data", "cannot open"}},
  };
}

class BadScene : public ::testing::TestWithParam<Case> {};

fs::path fresh_directory(const std::string& name) {
  const fs::path d = fs::temp_directory_path() / ("acst_bad_scene_" + std::to_string(::getpid()) + "_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

struct Refusal {
  int rc;           // acst_element's exit status
  std::string err;  // what it said
  bool out_made;    // whether its output directory appeared
};

// acst_element run once on `scenes` (file name, JSON text), written into a fresh directory named
// after `tag`, with `options` and an output directory in that directory.
Refusal run_scenes(const std::string& tag, std::vector<std::string> options,
                   const std::vector<std::pair<std::string, std::string>>& scenes) {
  const fs::path dir = fresh_directory(tag);
  const fs::path out = dir / "out";
  options.insert(options.end(), {"--output", out.string()});
  for (const auto& [name, text] : scenes) {
    std::ofstream(dir / name) << text;
    options.push_back((dir / name).string());
  }
  std::ostringstream o, e;
  const int rc = driver::element_cli(options, o, e);
  const Refusal r{rc, e.str(), fs::exists(out)};
  fs::remove_all(dir);
  return r;
}

TEST_P(BadScene, IsRejectedWithItsJsonPathAndNothingIsWritten) {
  const Case& c = GetParam();
  const Refusal r = run_scenes(c.name, {"--quiet"}, {{"scene.json", c.scene}});
  EXPECT_EQ(r.rc, 2);
  for (const auto& s : c.expected) EXPECT_NE(r.err.find(s), std::string::npos) << "expected '" << s << "' in: " << r.err;
  EXPECT_NE(r.err.find("nothing was run or written"), std::string::npos);
  EXPECT_FALSE(r.out_made) << "the output directory was created";
}

INSTANTIATE_TEST_SUITE_P(Kinds, BadScene, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& i) { return std::string(i.param.name); });

TEST(BadScene, OneBadSceneInABatchStopsTheWholeBatch) {
  const Refusal r =
      run_scenes("batch", {}, {{"good.json", with("[" + tc + "]")}, {"bad.json", with("[" + tc + "]", ", \"lab_data\": 5")}});
  EXPECT_EQ(r.rc, 2);
  EXPECT_NE(r.err.find("bad.json: /lab_data: expected a file name or an array of file names"), std::string::npos) << r.err;
  EXPECT_FALSE(r.out_made);
}

TEST(BadScene, TwoScenesWritingTheSameFilesAreRejected) {
  const std::string named_x = with("[" + tc + "]", ", \"output\": {\"name\": \"x\"}");
  const Refusal r = run_scenes("same_name", {}, {{"a.json", named_x}, {"b.json", named_x}});
  EXPECT_EQ(r.rc, 2);
  EXPECT_NE(r.err.find("/output/name: writes to"), std::string::npos) << r.err;
  EXPECT_FALSE(r.out_made);
}

TEST(BadScene, CommandLineErrors) {
  std::ostringstream o, e;
  EXPECT_EQ(driver::element_cli({}, o, e), 2);
  EXPECT_NE(e.str().find("no scene file given"), std::string::npos);
  EXPECT_EQ(driver::element_cli({"--frobnicate", "x.json"}, o, e), 2);
  EXPECT_NE(e.str().find("unknown option '--frobnicate'"), std::string::npos);
  EXPECT_EQ(driver::element_cli({"/no/such/scene.json"}, o, e), 2);
  EXPECT_NE(e.str().find("the scene file '/no/such/scene.json': cannot open: "), std::string::npos) << e.str();
  std::ostringstream help;
  EXPECT_EQ(driver::element_cli({"--help"}, help, e), 0);
  EXPECT_NE(help.str().find("Usage: acst_element"), std::string::npos);
}

}  // namespace
}  // namespace acst::test::driver_bad_scene_test
