// The grid that follows the footing (docs/mpm.md, "The grid follows the footing"): the footing's
// base and the base wall stay on their node rows at every settlement and the grid's top does not
// sink; the rigid plate on a confined elastic layer still gives the closed form; Prandtl's load on
// weightless Tresca soil at h = B/10 comes within the tolerances below (with fixed rows: +14.7 %
// rough, +12.6 % smooth); the node-row footing no longer jumps where its base would have crossed
// a row; a run resumed from a checkpoint continues bit for bit; and the reader's checks of the key.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "acst_footing_tool/checkpoint.hpp"
#include "footing_runs.hpp"
#include "mpm_scenes.hpp"
#include "scratch.hpp"

using namespace acst::mpm;
using mpm_test::Period;
using mpm_test::run;
using mpm_test::tresca;

constexpr double pi = 3.14159265358979323846;

TEST(GridFollowsFooting, BaseAndBaseWallStayOnTheirRows) {
  Simulation s = mpm_test::build(tresca(0.1, "rough", 0.1, "penalty", true));
  const Grid built = s.grid();
  // Built with spacing h: the base wall (y = 0) three rows up, the footing's base (y = 2) on row 23.
  ASSERT_NEAR((0.0 - built.y0) / built.hy, 3.0, 1e-9);
  ASSERT_NEAR((2.0 - built.y0) / built.hy, 23.0, 1e-9);
  // Rows are added above so that the top never sinks below that of fixed rows: the soil's top
  // plus cells_above (6) cells.
  const double top = 2.0 + 6 * 0.1;
  EXPECT_GT(built.y0 + (built.ny - 1) * built.hy, top + 0.1) << "rows were added";
  double deepest = 0;
  while (s.footing().settlement() < 0.1) {
    const double base = s.footing().base_y();  // the grid of a step is laid out at its start
    s.step();
    const Grid& g = s.grid();
    ASSERT_NEAR((base - g.y0) / g.hy, 23.0, 1e-9) << "at S " << s.footing().settlement();
    ASSERT_NEAR((0.0 - g.y0) / g.hy, 3.0, 1e-9) << "at S " << s.footing().settlement();
    ASSERT_GE(g.y0 + (g.ny - 1) * g.hy, top - 1e-9) << "the grid's top sank at S " << s.footing().settlement();
    EXPECT_EQ(g.h, built.h) << "the columns do not move";
    EXPECT_EQ(g.x0, built.x0);
    deepest = 2.0 - base;
  }
  // 20 rows share the 2 m between the wall and the base: hy = (2 - S) / 20.
  EXPECT_NEAR(s.grid().hy, (2.0 - deepest) / 20.0, 1e-12);
  EXPECT_GT(deepest, 0.09);
}

TEST(GridFollowsFooting, RigidPlateOnConfinedElasticLayerGivesTheUniaxialStiffness) {
  // The plate spans the layer from wall to wall, the same test as with fixed rows
  // (mpm_footing_test): V = W M S / H with S the plate's travel less the contact's penetration.
  const double W = 1.0, H = 2.0, E = 1e4, nu = 0.3;
  std::string scene = mpm_test::elastic_block(
      W, H, 0.1, E, nu, 1000.0, R"("footing": {"width": 1.0, "centre_x": 0.5, "speed": 0.002}, "stop": {"time": 2.5})",
      R"({"grid_damping": 10, "particle_update": "FLIP"})");
  scene.replace(scene.find(R"("cell_size": )"), 0, R"("follow_footing": true, )");
  Simulation s = mpm_test::build(scene);
  const double M = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));  // kPa
  run(s, 20, [](const Simulation& x) { return x.time() >= 2.0; });
  const Period last = run(s, 20, [](const Simulation& x) { return x.time() >= 2.5; }).back();
  const double S = last.S - last.penetration, expected = W * M * S / H;  // kN/m
  EXPECT_NEAR(last.V, expected, 0.015 * expected) << "V " << last.V << " kN/m at S " << last.S << " m";
  EXPECT_LT(s.grid().hy, s.grid().h) << "the rows followed the plate";
}

// q = V/B over S/B 0.02-0.05 at h = B/10, 0.02 m/s, as the fixed-row test takes it. Measured
// (docs/mpm.md, "The grid follows the footing"): rough +7.8 %, smooth +4.0 % (fixed rows: +14.7 %,
// +12.6 %). Stated tolerances: never below Prandtl, at most +10 % rough and +6 % smooth.
TEST(GridFollowsFooting, PrandtlBearingCapacityAtATenthOfTheWidth) {
  const double prandtl = (2 + pi) * 10.0;  // kPa
  for (const std::string interface : {"rough", "smooth"}) {
    const double q = mpm_test::prandtl_q(0.1, interface, true);
    EXPECT_GT(q, prandtl) << interface << ": q " << q << " kPa";
    EXPECT_LT(q, (interface == "rough" ? 1.10 : 1.06) * prandtl)
        << interface << ": q " << q << " kPa at h = B/10, (2 + pi) s_u = " << prandtl;
  }
}

// Prandtl's (2 + pi) s_u is the collapse load of a rigid-plastic soil under a footing on the
// undeformed surface; mpm_test::prandtl_q_rigid_plastic measures where the scene is that (E = 10^4
// s_u, the filter rare enough that the speed no longer matters). The issue's goal: within 3 % at h = B/10, closer at B/20,
// rough and smooth. Measured (docs/footing-study.md, "What Prandtl's load measures"): rough +2.1 % and
// +1.2 %, smooth -0.6 % and -0.2 %. Stated tolerances: the goal's.
TEST(GridFollowsFooting, PrandtlBearingCapacityOnTrescaSoilWithinThreePercentAtATenthOfTheWidth) {
  const double prandtl = (2 + pi) * 10.0;  // kPa
  for (const std::string interface : {"rough", "smooth"}) {
    const double coarse = mpm_test::prandtl_q_rigid_plastic(0.1, interface) / prandtl - 1;
    const double fine = mpm_test::prandtl_q_rigid_plastic(0.05, interface) / prandtl - 1;
    EXPECT_LT(std::fabs(coarse), 0.03) << interface << ": q / (2 + pi) s_u - 1 = " << coarse << " at h = B/10";
    EXPECT_LT(std::fabs(fine), std::fabs(coarse))
        << interface << ": q / (2 + pi) s_u - 1 = " << coarse << " at h = B/10, " << fine << " at B/20";
  }
}

// The measure of mpm_footing_test's NodeRowsJumpAtARowCrossingWhereContactDoesNot
// (mpm_test::largest_window_change; fixed rows: 6.5 %). Stated tolerance: 3 %.
TEST(GridFollowsFooting, NodeRowFootingNoLongerJumps) {
  Simulation s = mpm_test::build(tresca(0.1, "rough", 0.1, "node_rows", true));
  const double worst = mpm_test::largest_window_change(
      run(s, 20, [](const Simulation& x) { return x.footing().settlement() >= 0.075; }));
  EXPECT_LT(worst, 0.03) << "largest change " << 100 * worst << " %";
}

// The rows are laid out again from the footing's motion when a checkpoint comes back: the resumed
// run is the straight run bit for bit (ACST sand, inclined footing, XPIC steps).
TEST(GridFollowsFooting, ResumedRunContinuesBitForBit) {
  const Scene scene = parse_scene(R"({"name": "small", "grid": {"cell_size": 0.15, "follow_footing": true},
    "materials": {"sand": ")" + std::string(ACST_SOURCE_DIR) + R"(/data/parameters/toyoura_acst_calibrated.json"},
    "bodies": [{"material": "sand", "x_range": [0, 2.4], "y_range": [0, 1.2], "density": 1600,
                "relative_density_pct": 85.6, "bedding_angle_deg": 30}],
    "gravity": 9.8, "initial_stress": {"type": "geostatic", "K0": 0.4}, "surcharge_kPa": 1,
    "footing": {"width": 0.3, "centre_x": 1.2, "speed": 0.5, "inclination_deg": 10},
    "solver": {"xpic_every": 7, "threads": 2}, "stop": {"time": 0.5}})");
  // The checkpoint is taken past two thirds of a cell of settlement: rows laid out again from the
  // settled base instead of the starting one would be a row off.
  Simulation first = build_simulation(scene);
  while (first.footing().settlement() < 0.1) first.step();
  Simulation straight = build_simulation(scene);
  while (straight.step_count() < first.step_count() + 35) straight.step();
  const std::string file = (acst::test::scratch_folder("follow_checkpoint") / "checkpoint.bin").string();
  write_checkpoint(file, scene, first, RunState{});
  Simulation resumed = build_simulation(scene);
  RunState loaded;
  read_checkpoint(file, scene, resumed, loaded);
  for (int k = 0; k < 35; ++k) resumed.step();
  EXPECT_LT(straight.grid().hy, straight.grid().h) << "the rows followed the footing down";
  EXPECT_EQ(straight.grid().hy, resumed.grid().hy);
  EXPECT_EQ(straight.grid().y0, resumed.grid().y0);
  EXPECT_EQ(straight.particles().x, resumed.particles().x);
  EXPECT_EQ(straight.particles().vy, resumed.particles().vy);
  EXPECT_EQ(straight.particles().stress, resumed.particles().stress);
  EXPECT_EQ(straight.particles().statev, resumed.particles().statev);
  EXPECT_EQ(straight.reaction(reaction_footing).fy, resumed.reaction(reaction_footing).fy);
}

TEST(GridFollowsFooting, ReaderChecksTheKey) {
  const std::string no_footing = mpm_test::elastic_block(1.0, 1.0, 0.1, 1e4, 0.3, 1000.0, R"("stop": {"steps": 1})");
  std::string scene = no_footing;
  scene.replace(scene.find(R"("cell_size": )"), 0, R"("follow_footing": true, )");
  EXPECT_NE(mpm_test::parse_error(scene).find("/grid/follow_footing: needs a /footing"), std::string::npos)
      << mpm_test::parse_error(scene);
  scene = no_footing;
  scene.replace(scene.find(R"("cell_size": )"), 0, R"("follow_footing": 1, )");
  EXPECT_NE(mpm_test::parse_error(scene).find("/grid/follow_footing"), std::string::npos) << mpm_test::parse_error(scene);
}
