// Checkpoints and determinism: a run resumed from a checkpoint continues bit for bit, and two
// runs with the same thread count agree exactly (ACST sand with fabric, footing, XPIC steps).
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>

#include "acst_mpm/checkpoint.hpp"

using namespace acst::mpm;

namespace {

Scene small_footing(int threads) {
  const std::string text = R"({"name": "small", "grid": {"cell_size": 0.15},
    "materials": {"sand": ")" + std::string(ACST_SOURCE_DIR) + R"(/data/parameters/toyoura_acst_calibrated.json"},
    "bodies": [{"material": "sand", "x_range": [0, 2.4], "y_range": [0, 1.2], "density": 1600,
                "relative_density_pct": 85.6, "bedding_angle_deg": 30}],
    "gravity": 9.8, "initial_stress": {"type": "geostatic", "K0": 0.4}, "surcharge_kPa": 1,
    "footing": {"width": 0.3, "centre_x": 1.2, "speed": 0.5, "inclination_deg": 10},
    "solver": {"xpic_every": 7, "threads": )" + std::to_string(threads) + R"(}, "stop": {"steps": 80}})";
  return parse_scene(text);
}

void expect_identical(const Simulation& a, const Simulation& b) {
  ASSERT_EQ(a.step_count(), b.step_count());
  EXPECT_EQ(a.time(), b.time());
  EXPECT_EQ(a.particles().x, b.particles().x);
  EXPECT_EQ(a.particles().vy, b.particles().vy);
  EXPECT_EQ(a.particles().stress, b.particles().stress);
  EXPECT_EQ(a.particles().statev, b.particles().statev);
  EXPECT_EQ(a.reaction(reaction_footing).fy, b.reaction(reaction_footing).fy);
}

}  // namespace

TEST(MpmCheckpoint, ResumedRunContinuesBitForBit) {
  const Scene scene = small_footing(2);
  Simulation straight = build_simulation(scene);
  for (int k = 0; k < 80; ++k) straight.step();

  Simulation first = build_simulation(scene);
  for (int k = 0; k < 45; ++k) first.step();
  RunState state;
  state.vtk_frames = 3;
  state.history.push_back(LoadRecord{45, first.time(), 0.01, 0.02, 3.0, 0.5, 0.1, 10.0, 0.001, 1.0, 2.0});
  const std::string file = (std::filesystem::temp_directory_path() / "acst_mpm_checkpoint_test.bin").string();
  write_checkpoint(file, scene, first, state);

  Simulation resumed = build_simulation(scene);
  RunState loaded;
  read_checkpoint(file, scene, resumed, loaded);
  for (int k = 0; k < 35; ++k) resumed.step();
  expect_identical(straight, resumed);
  EXPECT_EQ(loaded.vtk_frames, 3);
  ASSERT_EQ(loaded.history.size(), 1u);
  EXPECT_EQ(loaded.history[0].V_kN_per_m, 3.0);
  std::remove(file.c_str());
}

TEST(MpmCheckpoint, RejectsAnotherSceneAndTruncatedFiles) {
  const Scene scene = small_footing(1);
  Simulation sim = build_simulation(scene);
  sim.step();
  const std::string file = (std::filesystem::temp_directory_path() / "acst_mpm_checkpoint_bad.bin").string();
  write_checkpoint(file, scene, sim, RunState{});
  Scene other = small_footing(1);
  other.text += " ";
  Simulation target = build_simulation(other);
  RunState st;
  EXPECT_THROW(read_checkpoint(file, other, target, st), SimulationError);
  std::filesystem::resize_file(file, std::filesystem::file_size(file) / 2);
  Simulation again = build_simulation(scene);
  try {
    read_checkpoint(file, scene, again, st);
    FAIL() << "a truncated checkpoint was accepted";
  } catch (const SimulationError& e) {
    EXPECT_NE(std::string(e.what()).find("truncated"), std::string::npos) << e.what();
  }
  EXPECT_EQ(again.step_count(), 0) << "a failed read leaves the simulation untouched";
  std::remove(file.c_str());
}

TEST(MpmDeterminism, SameThreadCountSameResult) {
  const Scene scene = small_footing(2);
  Simulation a = build_simulation(scene), b = build_simulation(scene);
  for (int k = 0; k < 60; ++k) a.step(), b.step();
  expect_identical(a, b);
  EXPECT_GT(-a.reaction(reaction_footing).fy, 0.0) << "the footing pushes on the sand";
}
