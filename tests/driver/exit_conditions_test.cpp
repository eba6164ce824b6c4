// Exit conditions end a step where they should: at the increment where the watched quantity
// crosses its threshold, located inside that increment to within 1e-9 of the quantity's change
// over it (Illinois false position), never before the crossing; repeat blocks run their cycles
// with reversal targets and stop early on their own exit condition.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "driver_scenes.hpp"

namespace acst::test {
namespace {

// Located to 1e-9 of the change over one increment (below 1 kPa here): 1e-6 is a margin of 1e3.
constexpr double located = 1e-6;

double q_of(const driver::Record& r) { return driver::signed_q(r.stress); }

TEST(ExitConditions, QAboveStopsDrainedShearWhereQReachesTheThreshold) {
  const auto r = run(scene_json(
      "[{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 20, \"increments\": 2000,"
      " \"exit\": {\"q_above\": 150}}]"));
  ASSERT_TRUE(r.ok) << r.message;
  const driver::Record& last = r.records.back();
  EXPECT_EQ(last.status, "exit:q_above");
  EXPECT_GE(q_of(last), 150.0);  // met, not short of it
  EXPECT_NEAR(q_of(last), 150.0, located);
  // The previous row had not reached it, and the step stopped long before its 20 %.
  EXPECT_LT(q_of(r.records[r.records.size() - 2]), 150.0);
  EXPECT_LT(last.strain[0], 0.05);
  // The time column counts the fraction of the step done.
  EXPECT_NEAR(last.time, last.strain[0] / 0.20, 1e-9);
}

TEST(ExitConditions, AxialStrainAndStressRatioExits) {
  const auto r = run(scene_json(
      "[{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 20, \"increments\": 200,"
      " \"exit\": {\"axial_strain_pct_above\": 3.333}},"
      " {\"preset\": \"drained_triaxial_extension\", \"axial_strain_pct\": 20, \"increments\": 200,"
      " \"exit\": {\"stress_ratio_below\": 0.5}}]"));
  ASSERT_TRUE(r.ok) << r.message;
  int found = 0;
  for (const auto& rec : r.records) {
    if (rec.status == "exit:axial_strain_pct_above") {
      ++found;
      EXPECT_NEAR(100.0 * rec.strain[0], 3.333, located);
    }
    if (rec.status == "exit:stress_ratio_below") {
      ++found;
      EXPECT_NEAR(driver::stress_ratio_of(rec.stress), 0.5, located);
      EXPECT_LE(driver::stress_ratio_of(rec.stress), 0.5);
    }
  }
  EXPECT_EQ(found, 2);
}

TEST(ExitConditions, PBelowEndsUndrainedShearOfLooseSand) {
  const auto r = run(scene_json(
      "[{\"preset\": \"undrained_triaxial_compression\", \"axial_strain_pct\": 10, \"increments\": 1000,"
      " \"exit\": {\"p_below\": 120}}]",
      200.0, 0.9));
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.records.back().status, "exit:p_below");
  EXPECT_NEAR(mean_stress(r.records.back().stress), 120.0, located);
}

TEST(ExitConditions, RepeatBlockRunsItsCyclesBetweenReversalTargets) {
  const auto r = run(scene_json(
      "[{\"repeat\": {\"cycles\": 3, \"steps\": ["
      "  {\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 5, \"increments\": 500, \"exit\": {\"q_above\": 60}},"
      "  {\"preset\": \"drained_triaxial_extension\", \"axial_strain_pct\": 5, \"increments\": 500, \"exit\": {\"q_below\": -20}}]}}]"));
  ASSERT_TRUE(r.ok) << r.message;
  int tops = 0, bottoms = 0;
  for (const auto& rec : r.records) {
    if (rec.status == "exit:q_above") {
      EXPECT_NEAR(q_of(rec), 60.0, located);
      EXPECT_EQ(rec.stage, 0);
      EXPECT_EQ(rec.cycle, tops + 1);
      ++tops;
    }
    if (rec.status == "exit:q_below") {
      EXPECT_NEAR(q_of(rec), -20.0, located);
      EXPECT_EQ(rec.stage, 1);
      ++bottoms;
    }
  }
  EXPECT_EQ(tops, 3);
  EXPECT_EQ(bottoms, 3);
  EXPECT_EQ(r.records.back().cycle, 3);
}

TEST(ExitConditions, BlockExitEndsTheCyclesEarly) {
  // Loose sand under undrained cyclic loading: p' falls below 60 kPa in the first extension
  // (the cone model keeps later cycles elastic); the block stops there, not after 100 cycles.
  const auto r = run(scene_json(
      "[{\"repeat\": {\"cycles\": 100, \"exit\": {\"p_below\": 60}, \"steps\": ["
      "  {\"preset\": \"undrained_triaxial_compression\", \"axial_strain_pct\": 5, \"increments\": 5000, \"exit\": {\"q_above\": 30}},"
      "  {\"preset\": \"undrained_triaxial_extension\", \"axial_strain_pct\": 5, \"increments\": 5000, \"exit\": {\"q_below\": -30}}]}},"
      " {\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 0.1, \"increments\": 10}]",
      100.0, 0.85));
  ASSERT_TRUE(r.ok) << r.message;
  int block_exit = -1;
  for (std::size_t k = 0; k < r.records.size(); ++k)
    if (r.records[k].status == "exit:p_below") block_exit = static_cast<int>(k);
  ASSERT_GE(block_exit, 0);
  EXPECT_NEAR(mean_stress(r.records[block_exit].stress), 60.0, located);
  EXPECT_LT(r.records[block_exit].cycle, 100);
  // The next step then ran: the rows after the block belong to step 1.
  EXPECT_EQ(r.records.back().step, 1);
  EXPECT_EQ(static_cast<int>(r.records.size()) - 1 - block_exit, 10);
}

TEST(ExitConditions, TheEarliestOfTwoCrossingsInOneIncrementEndsTheStep) {
  // Two 5 % increments: the first crosses q = 100 kPa (near 0.1 % strain) and eps_a = 4 %; the
  // step must end at the q crossing, located inside that coarse increment.
  const auto r = run(scene_json(
      "[{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 10, \"increments\": 2,"
      " \"exit\": {\"axial_strain_pct_above\": 4, \"q_above\": 100}}]"));
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.records.back().status, "exit:q_above");
  EXPECT_NEAR(q_of(r.records.back()), 100.0, located);
  EXPECT_LT(100.0 * r.records.back().strain[0], 1.0);
}

TEST(ExitConditions, AConditionMetAtTheStartSkipsTheStep) {
  const auto r = run(scene_json(
      "[{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 5, \"increments\": 50, \"exit\": {\"p_above\": 50}}]"));
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_EQ(r.records.size(), 1u);  // the initial row only
  EXPECT_EQ(r.increments, 0);
}

}  // namespace
}  // namespace acst::test
