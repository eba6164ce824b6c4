// The sand's regularisation as a whole (docs/mpm.md, "Nonlocal regularisation"): where the field
// is homogeneous the averaged void ratio is the particle's own, and every bundled element scene
// run with the offset a homogeneous patch of particles gets gives its local result; an internal
// length of 0 is the local model to the bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include "acst_driver/runner.hpp"
#include "acst_driver/scene.hpp"
#include "acst_footing_tool/scene_size.hpp"
#include "acst_mpm/nonlocal_average.hpp"
#include "mpm_scenes.hpp"

namespace mpm_regularisation_test {

using namespace acst::mpm;
namespace fs = std::filesystem;

// The largest offset a lattice of particles of one void ratio gets from the average (a patch of
// 0.5 x 0.5 m at 0.01 m, l = 0.05: its middle and its edges, where the sums are truncated).
double homogeneous_offset(double e, NonlocalKernel kernel) {
  Particles P;
  const int side = 50;
  P.resize(side * side, 0);
  for (int j = 0; j < side; ++j)
    for (int i = 0; i < side; ++i) {
      const std::size_t p = static_cast<std::size_t>(j * side + i);
      P.x[p] = 0.005 + 0.01 * i;
      P.y[p] = 0.005 + 0.01 * j;
      P.volume_initial[p] = 1e-4;
    }
  std::vector<double> value(P.n, e), mean(P.n);
  NonlocalAverage(0.05, kernel, std::vector<int>(P.n, 1), std::nullopt).average(P, value.data(), mean.data(), 1);
  double worst = 0.0;
  for (double m : mean) worst = std::max(worst, std::fabs(m - e));
  return worst;
}

TEST(Regularisation, AHomogeneousFieldGivesTheLocalResultInEveryBundledElementScene) {
  int scenes = 0;
  for (const auto& entry : fs::directory_iterator(fs::path(ACST_SOURCE_DIR) / "data/scenes/element")) {
    if (entry.path().extension() != ".json") continue;
    SCOPED_TRACE(entry.path().string());
    const acst::driver::ElementScene local = acst::driver::read_scene(entry.path().string());
    acst::driver::ElementScene nonlocal = local;
    const double e0 = local.initial.void_ratio;
    nonlocal.initial.void_ratio_offset = homogeneous_offset(e0, NonlocalKernel::galavi_schweiger);
    // The average of one value is that value, to the rounding of a sum of a few hundred terms.
    ASSERT_LE(nonlocal.initial.void_ratio_offset, 1e-13 * e0);
    if (nonlocal.initial.void_ratio_offset == 0.0) nonlocal.initial.void_ratio_offset = 1e-15;  // a rounding's worth
    const acst::driver::RunResult a = acst::driver::run_scene(local), b = acst::driver::run_scene(nonlocal);
    ASSERT_EQ(a.ok, b.ok) << b.message;
    ASSERT_EQ(a.records.size(), b.records.size());
    double scale = 0.0, worst = 0.0;
    for (const auto& r : a.records) scale = std::max(scale, acst::norm(r.stress));
    for (std::size_t k = 0; k < a.records.size(); ++k) {
      worst = std::max(worst, acst::norm(a.records[k].stress - b.records[k].stress) / scale);
      worst = std::max(worst, std::fabs(a.records[k].void_ratio - b.records[k].void_ratio));
    }
    EXPECT_LT(worst, 1e-12);
    ++scenes;
  }
  EXPECT_GE(scenes, 30);
}

// A small dense-sand footing run 300 steps with "internal_length_m": 0 against the same scene
// without the key: the same particles, to the bit.
TEST(Regularisation, AnInternalLengthOfZeroIsTheLocalModel) {
  const auto scene = mpm_test::small_sand_footing;
  mpm_test::expect_identical_runs(scene(""), scene(R"(, "regularisation": {"internal_length_m": 0})"), 300);
  // And with a length the same scene's particles carry offsets (the averaging ran).
  EXPECT_GT(mpm_test::spread_after(scene(R"(, "regularisation": {"internal_length_m": 0.2})"), 300,
                                   [](const Simulation& s) -> const auto& { return s.regulariser().state().offset; }),
            1e-7);
}

// A row of dense sand between smooth walls, a smooth base and a smooth platen over its whole
// width, compressed in 600 steps: every particle strains alike, so the averaged void ratio is
// each particle's own and the regularised run, averaging every step, is the local one within
// 1e-12 (stress, void ratio, fabric and every other state variable).
TEST(Regularisation, AHomogeneouslyCompressedBlockGivesTheLocalResult) {
  const auto scene = mpm_test::compressed_sand_row;
  Simulation local = mpm_test::build(scene("")),
             nonlocal = mpm_test::build(scene(R"(, "regularisation": {"internal_length_m": 0.2, "every_steps": 1})"));
  const std::vector<double> state0 = local.particles().statev, averaged0 = nonlocal.regulariser().state().averaged;
  for (int k = 0; k < 600; ++k) local.step(), nonlocal.step();
  const Particles &a = local.particles(), &b = nonlocal.particles();
  ASSERT_EQ(a.n, 12u);
  const mpm_test::ParticleGap gap = mpm_test::particle_gap(a, b);
  EXPECT_LT(gap.stress, 1e-12);
  EXPECT_LT(gap.state, 1e-12);
  const Regulariser::ParticleState& averaging = nonlocal.regulariser().state();
  for (double d : averaging.offset) EXPECT_LT(std::fabs(d), 1e-13);
  EXPECT_GT(std::fabs(averaging.averaged[0] - averaged0[0]), 1e-3) << "the averaging followed the void ratio";
  // The compression was real and homogeneous: every particle shortened alike, by at least 2 % and
  // by no more than the platen moved (its penalty contact takes a little of it), and the state moved.
  const double platen = local.footing().settlement() / 0.1;
  for (std::size_t p = 0; p < a.n; ++p) {
    EXPECT_NEAR(a.F[4 * p + 3], a.F[3], 1e-12) << "particle " << p;
    EXPECT_NEAR(a.F[4 * p], 1.0, 1e-12) << "particle " << p;
  }
  EXPECT_LT(a.F[3], 0.98);
  EXPECT_GT(a.F[3], 1.0 - platen);
  double moved = 0.0;
  for (std::size_t k = 0; k < a.statev.size(); ++k) moved = std::max(moved, std::fabs(a.statev[k] - state0[k]));
  EXPECT_GT(moved, 1e-3);
}

}  // namespace mpm_regularisation_test

// A length the averaging cannot use is refused by the reader with its JSON path, the value and the
// allowed range, before anything is written: the documented defaults at 1 g (2.8 mm on 0.1 m
// cells) used to fail at the first step blaming the soil's extent, 1e-300 m overflowed the bins'
// count (undefined behaviour), and a derived length had no cap.
TEST(Regularisation, ALengthTheAveragingCannotUseIsRefusedWithItsPath) {
  const auto scene = mpm_test::small_sand_footing;
  const std::string defaults = mpm_test::parse_error(scene(R"(, "regularisation": {})"));
  EXPECT_NE(defaults.find("/regularisation: the length derived from the grains, 0.00283"), std::string::npos) << defaults;
  EXPECT_NE(defaults.find("allowed: at least 0.1 m"), std::string::npos) << defaults;
  for (const char* tiny : {"1e-300", "5e-324", "0.05"}) {
    const std::string m = mpm_test::parse_error(scene(std::string(R"(, "regularisation": {"internal_length_m": )") + tiny + "}"));
    EXPECT_NE(m.find("/regularisation/internal_length_m"), std::string::npos) << m;
    EXPECT_NE(m.find("shorter than the particles' spacing (0.1 m"), std::string::npos) << m;
  }
  const std::string huge = mpm_test::parse_error(scene(R"(, "regularisation": {"d50_mm": 100, "acceleration_level": 1000})"));
  EXPECT_NE(huge.find("/regularisation: the length derived from d50_mm 100 and acceleration_level 1000"), std::string::npos)
      << huge;
  EXPECT_EQ(mpm_test::parse_error(scene(R"(, "regularisation": {"internal_length_m": 0.1})")), "accepted");
  EXPECT_EQ(mpm_test::parse_error(scene(R"(, "regularisation": {"acceleration_level": 40})")), "accepted");  // 0.113 m
}

// The neighbour lists count in the scene's memory estimate: a length that reaches every particle
// costs 4 bytes a pair, which the estimate left out (20 MB against 1.3 GB on 12 800 particles).
TEST(Regularisation, TheNeighbourListsCountInTheMemoryEstimate) {
  const auto scene = [](const std::string& regularisation) {
    return mpm_test::delivered_sand_scene(R"("bodies": [{"material": "sand", "x_range": [0, 16], "y_range": [0, 8],
        "density": 1600, "relative_density_pct": 85, "bedding_angle_deg": 0}], "stop": {"steps": 10})" + regularisation);
  };
  const acst::mpm::SceneSize local = acst::mpm::scene_size(acst::mpm::parse_scene(scene("")), 0.0);
  const acst::mpm::SceneSize wide =
      acst::mpm::scene_size(acst::mpm::parse_scene(scene(R"(, "regularisation": {"internal_length_m": 100})")), 0.0);
  ASSERT_EQ(wide.particles, 12800.0);
  EXPECT_GE(wide.bytes() - local.bytes(), 4.0 * wide.particles * wide.particles);
}
