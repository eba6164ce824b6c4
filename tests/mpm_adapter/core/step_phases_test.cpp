// The phases' wall times (Simulation::phase_seconds, summary.json's step_phase_seconds) account for
// the steps' time: none is negative, they add up to the steps' wall time measured around them
// (the laps cover all of step(); half is the bound a loaded machine keeps), and the
// material's phase, the costliest of a sand scene, has taken time.
#include <gtest/gtest.h>

#include <chrono>
#include <numeric>

#include "acst_mpm/simulation.hpp"
#include "mpm_scenes.hpp"

using namespace acst::mpm;

TEST(StepPhases, AddUpToTheStepsWallTime) {
  Simulation sim = mpm_test::build(mpm_test::small_sand_footing(""));
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < 60; ++k) sim.step();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const StepPhaseSeconds& s = sim.phase_seconds();
  for (std::size_t k = 0; k < step_phase_count; ++k) EXPECT_GE(s[k], 0.0) << step_phase_names[k];
  const double sum = std::accumulate(s.begin(), s.end(), 0.0);
  EXPECT_LE(sum, wall);
  EXPECT_GE(sum, 0.5 * wall);  // a preemption between two steps falls outside every lap
  EXPECT_GT(s[static_cast<std::size_t>(StepPhase::stress_update)], 0.0);
}
