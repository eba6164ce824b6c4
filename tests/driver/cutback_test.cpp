// Cut-back: an increment that fails (material or Newton) is halved and retried, up to
// solver.max_halvings; the recovered result agrees with a finely incremented run. At the limit
// the run stops with a clear message and a one-increment reproducer scene that replays the
// failure (and passes once cut-back is allowed again). solver.max_cutbacks bounds the halvings of
// the whole run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "driver_scenes.hpp"

namespace acst::test {
namespace {

// Drained triaxial compression to 5 % in one increment, with an integrator limited to
// max_substeps per call: the full increment fails in the material and must be cut.
std::string one_big_increment(int max_substeps, const std::string& solver = "") {
  return scene_json("[{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 5, \"increments\": 1}]", 100.0, 0.7,
                    solver,
                    "{\"file\": \"" + parameter_file() + "\", \"integrator\": {\"max_substeps\": " + std::to_string(max_substeps) + "}}");
}

driver::Record fine_reference() {
  const auto r = run(scene_json("[{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 5, \"increments\": 500}]"));
  EXPECT_TRUE(r.ok) << r.message;
  return r.records.back();
}

void expect_close_to_fine(const driver::Record& got, const driver::Record& fine) {
  // The cut pieces are a coarser, uneven discretisation of the same path (each piece a
  // straight strain path); the driver error is first order in the piece size (~1e-3 strain):
  // 0.2 % on q and 0.02 % (absolute, in %) on e_v cover it; a wrong recovery is off by far more.
  EXPECT_NEAR(got.strain[0], fine.strain[0], 1e-12);
  EXPECT_NEAR(driver::signed_q(got.stress), driver::signed_q(fine.stress), 2e-3 * driver::signed_q(fine.stress));
  EXPECT_NEAR(driver::volumetric_strain_pct(got.strain), driver::volumetric_strain_pct(fine.strain), 0.02);
  // sigma_3 held to the Newton stress tolerance, 1e-8 max(p, pa) (p grows along this path).
  EXPECT_NEAR(got.stress[2], 100.0, 1e-8 * std::max(mean_stress(got.stress), atmospheric_pressure));
}

TEST(CutBack, RecoversFromAnOversizedIncrementTheMaterialRejects) {
  const auto r = run(one_big_increment(20));
  ASSERT_TRUE(r.ok) << r.message;
  ASSERT_EQ(r.records.size(), 2u);
  EXPECT_GT(r.records.back().cutbacks, 0);
  EXPECT_EQ(r.records.back().status, "cutback");
  expect_close_to_fine(r.records.back(), fine_reference());
}

TEST(CutBack, RecoversWhenNewtonNeedsMoreIterationsThanAllowed) {
  const auto r = run(scene_json("[{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 5, \"increments\": 1}]",
                                100.0, 0.7, ", \"solver\": {\"max_iterations\": 3}"));
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_GT(r.records.back().cutbacks, 0);
  expect_close_to_fine(r.records.back(), fine_reference());
}

TEST(CutBack, FinalFailureStopsWithAMessageAndAReproducerThatReplaysIt) {
  const auto r = run(one_big_increment(20, ", \"solver\": {\"max_halvings\": 2}"));
  ASSERT_FALSE(r.ok);
  EXPECT_NE(r.message.find("/steps/0 (drained_triaxial_compression), increment 1 of 1"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("more substeps than allowed"), std::string::npos) << r.message;
  EXPECT_EQ(r.records.size(), 1u);  // the initial row; nothing past the last converged state
  ASSERT_TRUE(r.reproducer.has_value());

  // Replaying the reproducer fails the same way, in its one increment...
  const driver::RunResult replay = run(r.reproducer->dump());
  ASSERT_FALSE(replay.ok);
  EXPECT_NE(replay.message.find("increment 1 of 1"), std::string::npos) << replay.message;
  EXPECT_NE(replay.message.find("more substeps than allowed"), std::string::npos) << replay.message;
  // ...from the same state and with the failing piece (a quarter of the 5 % after two halvings).
  const driver::ElementScene s = parse(r.reproducer->dump());
  EXPECT_EQ(s.initial.stress, r.records[0].stress);
  ASSERT_EQ(s.blocks.size(), 1u);
  const driver::Segment& g = s.blocks[0].steps[0].segments[0];
  EXPECT_EQ(g.increments, 1);
  EXPECT_NEAR(g.rows.value[0], 0.05 / 4.0, 1e-15);

  // With cut-back allowed again the same increment goes through.
  nlohmann::json again = *r.reproducer;
  again["solver"]["max_halvings"] = 12;
  const driver::RunResult fixed = run(again.dump());
  EXPECT_TRUE(fixed.ok) << fixed.message;
}

// The oversized increment above needs some halvings in all; a budget of that many lets the run
// through unchanged, one fewer stops it at the halving it refuses, naming the limit.
TEST(CutBack, MaxCutbacksBoundsTheHalvingsOfTheWholeRun) {
  const auto free_run = run(one_big_increment(20));
  ASSERT_TRUE(free_run.ok) << free_run.message;
  const long needed = free_run.cutbacks;
  ASSERT_GE(needed, 2);
  const auto within = run(one_big_increment(20, ", \"solver\": {\"max_cutbacks\": " + std::to_string(needed) + "}"));
  ASSERT_TRUE(within.ok) << within.message;
  EXPECT_EQ(within.cutbacks, needed);
  EXPECT_EQ(within.records.back().stress, free_run.records.back().stress) << "a budget not reached changes nothing";

  const auto over = run(one_big_increment(20, ", \"solver\": {\"max_cutbacks\": " + std::to_string(needed - 1) + "}"));
  ASSERT_FALSE(over.ok);
  EXPECT_EQ(over.cutbacks, 0) << "the increment did not complete";
  EXPECT_NE(over.message.find("after " + std::to_string(needed - 1) + " cut-backs in this run (solver/max_cutbacks)"),
            std::string::npos) << over.message;
  EXPECT_EQ(over.records.size(), 1u);
}

TEST(CutBack, MaxCutbacksOutOfRangeIsRefusedWithItsPath) {
  for (const char* bad : {"0", "-3", "2.5", "\"many\"", "2000000000"}) {
    SCOPED_TRACE(bad);
    try {
      parse(one_big_increment(20, std::string(", \"solver\": {\"max_cutbacks\": ") + bad + "}"));
      ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("/solver/max_cutbacks"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace acst::test
