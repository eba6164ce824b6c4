// Bad MPM scenes: each error names the JSON path and what is allowed.
#include <gtest/gtest.h>

#include "acst_footing_tool/build_simulation.hpp"

using namespace acst::mpm;

namespace {

const std::string good = R"({"name": "s", "grid": {"cell_size": 0.5},
  "materials": {"soil": {"model": "linear_elastic", "parameters": {"E": 1000, "nu": 0.3}}},
  "bodies": [{"material": "soil", "x_range": [0, 2], "y_range": [0, 1], "density": 1000}],
  "footing": {"width": 0.5, "centre_x": 1, "speed": 0.01}, "stop": {"S_over_B": 0.1}})";

std::string replaced(const std::string& from, const std::string& to) {
  std::string s = good;
  const auto at = s.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return s.replace(at, from.size(), to);
}

void expect_error(const std::string& text, const std::string& path, const std::string& words) {
  try {
    parse_scene(text);
    FAIL() << "accepted a scene that should fail at " << path;
  } catch (const acst::common::InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.rfind(path, 0), 0u) << m;
    EXPECT_NE(m.find(words), std::string::npos) << m;
  }
}

}  // namespace

TEST(MpmScene, TheGoodSceneParses) {
  const Scene s = parse_scene(good);
  EXPECT_EQ(s.bodies.size(), 1u);
  EXPECT_TRUE(s.footing.has_value());
  EXPECT_EQ(*s.stop.S_over_B, 0.1);
}

TEST(MpmScene, ErrorsNameThePath) {
  expect_error(replaced(R"("name": "s",)", R"("name": "s", "colour": 1,)"), "/colour", "unknown key");
  expect_error(replaced(R"("cell_size": 0.5)", R"("cell_size": -1)"), "/grid/cell_size", "out of range");
  expect_error(replaced(R"("density": 1000)", R"("density": "heavy")"), "/bodies/0/density", "expected a number");
  expect_error(replaced(R"("x_range": [0, 2])", R"("x_range": [0, 2.2])"), "/bodies/0", "grid lines");
  expect_error(replaced(R"("material": "soil")", R"("material": "rock")"), "/bodies/0/material", "not defined");
  expect_error(replaced(R"("nu": 0.3)", R"("nu": 0.7)"), "/materials/soil", "nu");
  expect_error(replaced(R"("speed": 0.01)", R"("speed": 0)"), "/footing/speed", "out of range");
  expect_error(replaced(R"("stop": {"S_over_B": 0.1})", R"("stop": {})"), "/stop", "one of");
  expect_error(replaced(R"("footing": {"width": 0.5, "centre_x": 1, "speed": 0.01}, )", ""), "/stop/S_over_B",
               "needs a /footing");
  expect_error(replaced(R"({"name": "s",)", R"({"name": "s", "solver": {"particle_update": "APIC"},)"),
               "/solver/particle_update", "FLIP, PIC, XPIC");
  expect_error(replaced(R"({"name": "s",)", R"({"name": "s", "solver": {"stress_update": "middle"},)"),
               "/solver/stress_update", "average, first, last");
  expect_error(replaced(R"({"name": "s",)", R"({"name": "s", "solver": {"volumetric_averaging": "node"},)"),
               "/solver/volumetric_averaging", "none, cell");
  expect_error(replaced(R"("materials": {"soil": {"model": "linear_elastic", "parameters": {"E": 1000, "nu": 0.3}}})",
                        R"("materials": {"soil": "no/such/file.json"})"),
               "/materials/soil", "cannot open");
  expect_error(replaced(R"({"name": "s",)", R"({"name": "s", "output": {"contour_fields": ["N", "stress"]},)"),
               "/output/contour_fields/1", "shear_strain, displacement, fabric_norm, N, void_ratio");
  expect_error(replaced(R"({"name": "s",)", R"({"name": "s", "output": {"contour_fields": ["N", "N"]},)"),
               "/output/contour_fields/1", "named twice");
  expect_error("{not json", "/", "not valid JSON");
}

TEST(MpmScene, FootingContactChoicesAreChecked) {
  const std::string f = R"("speed": 0.01)";
  expect_error(replaced(f, R"("speed": 0.01, "contact": "glue")"), "/footing/contact", "penalty, node_rows");
  expect_error(replaced(f, R"("speed": 0.01, "interface": "sticky")"), "/footing/interface", "rough, smooth, coulomb");
  expect_error(replaced(f, R"("speed": 0.01, "interface": "coulomb")"), "/footing", "friction_coefficient");
  expect_error(replaced(f, R"("speed": 0.01, "interface": "coulomb", "friction_coefficient": -0.1)"),
               "/footing/friction_coefficient", "out of range");
  expect_error(replaced(f, R"("speed": 0.01, "friction_coefficient": 0.3)"), "/footing/friction_coefficient",
               "only with interface 'coulomb'");
  expect_error(replaced(f, R"("speed": 0.01, "contact": "node_rows", "interface": "coulomb", "friction_coefficient": 0.3)"),
               "/footing/interface", "needs contact 'penalty'");
  expect_error(replaced(f, R"("speed": 0.01, "contact": "node_rows", "penalty_factor": 2)"), "/footing/penalty_factor",
               "only with contact 'penalty'");
  expect_error(replaced(f, R"("speed": 0.01, "penalty_factor": 0)"), "/footing/penalty_factor", "out of range");
  expect_error(replaced(f, R"("speed": 0.01, "unload_at_S_over_B": 0)"), "/footing/unload_at_S_over_B", "out of range");
  expect_error(replaced(f, R"("speed": 0.01, "unload_at_S_over_B": 0.05)"), "/stop/S_over_B", "stops by time or steps");
  const Scene s = parse_scene(replaced(f, R"("speed": 0.01, "interface": "coulomb", "friction_coefficient": 0.4)"));
  EXPECT_EQ(s.footing->interface, FootingInterface::coulomb);
  EXPECT_EQ(s.footing->friction_coefficient, 0.4);
  EXPECT_EQ(s.footing->contact, FootingContact::penalty);
}

TEST(MpmScene, SandNeedsAVoidRatio) {
  const std::string sand = R"({"name": "s", "grid": {"cell_size": 0.5},
    "materials": {"sand": ")" + std::string(ACST_SOURCE_DIR) + R"(/data/parameters/toyoura_acst_calibrated.json"},
    "bodies": [{"material": "sand", "x_range": [0, 2], "y_range": [0, 1], "density": 1600}], "stop": {"steps": 1}})";
  try {
    build_simulation(parse_scene(sand));
    FAIL() << "a sand body without void ratio was accepted";
  } catch (const acst::common::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/bodies/0"), std::string::npos) << e.what();
  }
}

TEST(MpmScene, MissingSceneFileIsAnError) {
  EXPECT_THROW(read_scene("/no/such/scene.json"), acst::common::InputError);
}

// The scene name becomes the output folder and reaches gnuplot scripts: a plain stem only.
TEST(MpmScene, NameIsAPlainFileStem) {
  for (const char* bad : {"..", ".", "../up", "a/b", "two words", "quote'd", "line\\nbreak", ""})
    expect_error(replaced(R"("name": "s")", std::string("\"name\": \"") + bad + "\""), "/name", "plain file stem");
  EXPECT_EQ(parse_scene(replaced(R"("name": "s")", R"("name": "V85.6_alpha-0")")).name, "V85.6_alpha-0");
}
