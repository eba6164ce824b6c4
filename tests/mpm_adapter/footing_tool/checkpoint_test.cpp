// Checkpoints and determinism: a run resumed from a checkpoint continues bit for bit, and two
// runs with the same thread count agree exactly (ACST sand with fabric, footing, XPIC steps).
#include <gtest/gtest.h>

#include <cstdio>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <nlohmann/json.hpp>

#include "acst_common/files.hpp"
#include "acst_common/input_error.hpp"
#include "acst_footing_tool/build_simulation.hpp"
#include "acst_footing_tool/checkpoint.hpp"

using namespace acst::mpm;

namespace {

Scene small_footing(int threads, const std::string& output = "") {
  const std::string text = R"({"name": "small", "grid": {"cell_size": 0.15},
    "materials": {"sand": ")" + std::string(ACST_SOURCE_DIR) + R"(/data/parameters/toyoura_acst_calibrated.json"},
    "bodies": [{"material": "sand", "x_range": [0, 2.4], "y_range": [0, 1.2], "density": 1600,
                "relative_density_pct": 85.6, "bedding_angle_deg": 30}],
    "gravity": 9.8, "initial_stress": {"type": "geostatic", "K0": 0.4}, "surcharge_kPa": 1,
    "footing": {"width": 0.3, "centre_x": 1.2, "speed": 0.5, "inclination_deg": 10},
    "solver": {"xpic_every": 7, "threads": )" + std::to_string(threads) + R"(}, "stop": {"steps": 80})" + output + "}";
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
  state.vtk_times = {0.0, 0.5 * first.time(), first.time()};
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

// Every refusal is the user's bad input (InputError, exit 2), names the file and what is wrong,
// and leaves the simulation untouched.
void expect_refused(const std::string& file, const Scene& scene, const std::string& why) {
  Simulation target = build_simulation(scene);
  RunState st;
  try {
    read_checkpoint(file, scene, target, st);
    ADD_FAILURE() << "accepted a checkpoint that " << why;
  } catch (const acst::common::InputError& e) {
    EXPECT_NE(std::string(e.what()).find(why), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(file), std::string::npos) << e.what();
  }
  EXPECT_EQ(target.step_count(), 0) << "a failed read leaves the simulation untouched";
}

void put_bytes(const std::string& file, const std::string& bytes) { std::ofstream(file, std::ios::binary) << bytes; }

TEST(MpmCheckpoint, RejectsAnotherSceneAndTruncatedFiles) {
  const Scene scene = small_footing(1);
  Simulation sim = build_simulation(scene);
  sim.step();
  const std::string file = (std::filesystem::temp_directory_path() / "acst_mpm_checkpoint_bad.bin").string();
  write_checkpoint(file, scene, sim, RunState{});
  Scene other = small_footing(1);
  other.text += " ";
  expect_refused(file, other, "was written for a different scene");
  std::filesystem::resize_file(file, std::filesystem::file_size(file) / 2);
  expect_refused(file, scene, "is damaged");  // the checksum no longer covers what is there
  put_bytes(file, "ACSTMPM8");
  expect_refused(file, scene, "is truncated");
  put_bytes(file, "ACSTMPM7 and the rest of a checkpoint of an older version");
  expect_refused(file, scene, "was written by another version of acst_mpm");
  put_bytes(file, "not a checkpoint at all");
  expect_refused(file, scene, "is not an acst_mpm checkpoint");
  std::remove(file.c_str());
}

// One flipped byte anywhere (header, scene text, particle arrays, run record, the checksum
// itself) is refused; before checksums some were accepted (a negative step count reached the
// outputs) and some crashed --resume.
TEST(MpmCheckpoint, AnyFlippedByteIsRefused) {
  const Scene scene = small_footing(1);
  Simulation sim = build_simulation(scene);
  for (int k = 0; k < 3; ++k) sim.step();
  RunState state;
  state.history.push_back(LoadRecord{3, sim.time(), 0.001, 0.003, 2.0, 0.1, 0.0, 6.7, 0.0, 0.01, 0.5});
  const std::string file = (std::filesystem::temp_directory_path() / "acst_mpm_checkpoint_flip.bin").string();
  write_checkpoint(file, scene, sim, state);
  const std::string good = acst::common::read_input_file(file);
  const std::size_t positions = 64;
  for (std::size_t k = 0; k < positions; ++k) {
    std::string bad = good;
    const std::size_t at = 8 + k * (good.size() - 9) / (positions - 1);  // past the magic, up to the last byte
    bad[at] = static_cast<char>(bad[at] ^ (1 << (k % 8)));
    put_bytes(file, bad);
    SCOPED_TRACE("byte " + std::to_string(at) + " of " + std::to_string(good.size()));
    expect_refused(file, scene, "is damaged");
  }
  put_bytes(file, good);
  Simulation resumed = build_simulation(scene);
  RunState loaded;
  read_checkpoint(file, scene, resumed, loaded);  // the unflipped file still reads
  EXPECT_EQ(resumed.step_count(), 3);
  std::remove(file.c_str());
}

// The scene names its material file; a resume after the file was edited would go on with other
// parameters than the run began with, so the parameters are recorded and compared.
TEST(MpmCheckpoint, RefusesAResumeAfterTheMaterialChanged) {
  const Scene scene = small_footing(1);
  Simulation sim = build_simulation(scene);
  sim.step();
  const std::string file = (std::filesystem::temp_directory_path() / "acst_mpm_checkpoint_material.bin").string();
  write_checkpoint(file, scene, sim, RunState{});
  Scene edited = scene;
  nlohmann::json m = nlohmann::json::parse(edited.materials.at(0).json_text);
  m["parameters"]["G0"] = m["parameters"]["G0"].get<double>() * 1.01;
  edited.materials.at(0).json_text = m.dump();
  expect_refused(file, edited, "other parameters for material 'sand'");
  std::remove(file.c_str());
}

// A file with a good checksum can still hold what no run writes (made by hand, or by a bug):
// each such value is refused by name instead of being carried into the run.
TEST(MpmCheckpoint, RefusesImpossibleValuesUnderAGoodChecksum) {
  const Scene scene = small_footing(1);
  const std::string file = (std::filesystem::temp_directory_path() / "acst_mpm_checkpoint_values.bin").string();
  auto written = [&](auto&& spoil) {
    Simulation sim = build_simulation(scene);
    sim.step();
    RunState st;
    st.contours_done.assign(scene.output.contours_at_S_over_B.size(), 0);
    spoil(sim, st);
    write_checkpoint(file, scene, sim, st);
  };
  written([](Simulation& sim, RunState&) { sim.restore(sim.particles(), sim.feature_state(), Clock{-5, 0.0, 0.0}, sim.footing().motion(), sim.footing().friction()); });
  expect_refused(file, scene, "impossible clock");
  written([](Simulation& sim, RunState&) { sim.particles().material[7] = 3; });
  expect_refused(file, scene, "particle 7 a material index out of range");
  written([](Simulation& sim, RunState&) { sim.particles().statev[11] = std::nan(""); });
  expect_refused(file, scene, "non-finite particle value");
  written([](Simulation& sim, RunState&) { sim.particles().y[2] = 1e9; });
  expect_refused(file, scene, "puts particle 2 off the grid");
  written([](Simulation& sim, RunState&) { sim.particles().mass[4] = -1.0; });
  expect_refused(file, scene, "particle 4 a mass, density or volume that is not positive");
  written([](Simulation&, RunState& st) { st.vtk_frames = 2; });
  expect_refused(file, scene, "impossible frame count");
  written([](Simulation&, RunState& st) { st.contours_done.push_back(0); });
  expect_refused(file, scene, "contour list of the wrong length");
  written([](Simulation&, RunState& st) { st.peak.x.assign(3, 0.0); });
  expect_refused(file, scene, "peak snapshot of the wrong size");
  written([](Simulation&, RunState& st) { st.history.push_back(LoadRecord{-1}); });
  expect_refused(file, scene, "impossible load record");
  // The largest step counts (issue 57): the next step would overflow a signed integer. Every
  // count a run goes on from is held to max_checkpoint_steps; the bound itself is taken.
  const long long largest = std::numeric_limits<long long>::max();
  written([&](Simulation& sim, RunState&) { sim.restore(sim.particles(), sim.feature_state(), Clock{largest, 1.0, 1e-4}, sim.footing().motion(), sim.footing().friction()); });
  expect_refused(file, scene, "impossible clock (step 9223372036854775807");
  written([&](Simulation& sim, RunState&) { sim.restore(sim.particles(), sim.feature_state(), Clock{max_checkpoint_steps + 1, 1.0, 1e-4}, sim.footing().motion(), sim.footing().friction()); });
  expect_refused(file, scene, "impossible clock");
  written([&](Simulation&, RunState& st) { st.period_steps = largest; });
  expect_refused(file, scene, "impossible running sum");
  written([&](Simulation&, RunState& st) { st.history.push_back(LoadRecord{largest}); });
  expect_refused(file, scene, "impossible load record");
  written([&](Simulation& sim, RunState&) { sim.restore(sim.particles(), sim.feature_state(), Clock{max_checkpoint_steps, 1.0, 1e-4}, sim.footing().motion(), sim.footing().friction()); });
  {
    Simulation sim = build_simulation(scene);
    RunState st;
    read_checkpoint(file, scene, sim, st);
    EXPECT_EQ(sim.step_count(), max_checkpoint_steps);
  }
  std::remove(file.c_str());
}

TEST(MpmDeterminism, SameThreadCountSameResult) {
  const Scene scene = small_footing(2);
  Simulation a = build_simulation(scene), b = build_simulation(scene);
  for (int k = 0; k < 60; ++k) a.step(), b.step();
  expect_identical(a, b);
  EXPECT_GT(-a.reaction(reaction_footing).fy, 0.0) << "the footing pushes on the sand";
}

// A followed particle's frame (the cosine and sine of its turn, and its strain) under a good
// checksum: 1e300 gave a run that ended with OK and non-finite history values. Refused by name;
// a frame as a run writes it is taken.
TEST(MpmCheckpoint, RefusesAnImpossibleParticleHistoryFrame) {
  const Scene scene = small_footing(1, R"(, "output": {"particle_histories": [{"name": "P", "at": [1.275, 1.125]}]})");
  const std::string file = (std::filesystem::temp_directory_path() / "acst_mpm_checkpoint_frame.bin").string();
  for (const int slot : {-1, 0, 1, 2, 4}) {
    Simulation sim = build_simulation(scene);
    sim.step();
    ASSERT_EQ(sim.particles().track_frame.size(), 5u);
    if (slot >= 0) sim.particles().track_frame[static_cast<std::size_t>(slot)] = 1e300;
    RunState st;
    st.contours_done.assign(scene.output.contours_at_S_over_B.size(), 0);
    write_checkpoint(file, scene, sim, st);
    if (slot < 0) {
      Simulation again = build_simulation(scene);
      RunState back;
      EXPECT_NO_THROW(read_checkpoint(file, scene, again, back));
    } else {
      expect_refused(file, scene, "impossible particle-history frame (followed particle 0)");
    }
  }
  std::remove(file.c_str());
}
