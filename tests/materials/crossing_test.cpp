// Elastic-plastic crossing inside one strain increment (docs/integration.md section 1,
// step 2): a start inside the cone that crosses the yield surface, and a start on the surface
// whose increment first unloads, then reloads on the far side of the cone. Each single big
// increment (ME, STOL 1e-4, the default) must agree with a reference made of many small
// increments along the same straight strain path (RK45, STOL 1e-10): for a rate-independent
// model the exact answer does not depend on how a straight path is cut into increments.
#include <gtest/gtest.h>

#include <cstdio>

#include "strain_path_replay.hpp"
#include "test_materials.hpp"

namespace acst::crossing_test {
namespace {

using integration::Report;
using integration::Status;

constexpr double kStol = 1e-4;
// Agreement asked of one big increment: 2 x STOL. ME's global error on the replayed paths of
// error_control_test stays below 0.6 x STOL; a crossing found to FTOL 1e-8 adds nothing visible.
constexpr double kTolerance = 2 * kStol;
constexpr int kReferencePieces = 2000;

// Yield value f = R/g - H of a state (negative inside the cone).
double yield_value(const Material& m, const State& s) {
  const Diagnostics d = m.diagnostics(s);
  return d.R / d.g - s.H;
}

// A reload of the loaded state (Crossing::lateral_shear_reload).
struct ReloadRun {
  double reload_at;  // where the fine reference first turns plastic (fraction of the increment)
  double error;      // of the one call against the fine reference
  Report report;     // of the one call
};

class Crossing : public ::testing::Test {
 protected:
  // Dense sand (e0 0.67) from 100 kPa, drained triaxial compression to 2 % axial strain in
  // increments of 1e-3 (driver, RK45 1e-10): a state on the yield surface after plastic loading.
  // Dense, because loose sand reloaded in extension against its compression fabric is so
  // contractive (D ~ 4 with the guide set) that any strain-controlled reversal collapses p to
  // the floor, where both runs are reset to the same p_min state and compare nothing.
  void SetUp() override {
    loaded_ = test::isotropic_sample(guide_, 100.0, 0.67);
    const std::vector<Sym> path = test::drained_triaxial_strain_path(guide_, loaded_, 1e-3, 20);
    loaded_ = test::replay(test::with_integrator(guide_, integration::Scheme::rk45, 1e-10), loaded_, path).states.back();
    loaded_.substep_hint = 1.0;
    drained_direction_ = path.back() / path.back()[0];  // per unit axial strain
  }

  // One call of the material under test against the fine reference; returns the relative error.
  double single_increment_error(const State& start, const Sym& deps, Report& report) const {
    State single = start, reference = start;
    report = guide_.update(single, deps);
    EXPECT_EQ(report.status, Status::ok) << integration::reason_text(report.reason);
    const Report ref = test::fine_increment_reference(guide_, reference, deps, kReferencePieces);
    EXPECT_EQ(ref.status, Status::ok) << integration::reason_text(ref.reason);
    return test::relative_stress_error(single, reference);
  }

  // The loaded state's reload by compression with a lateral shear (below); prints what it measured.
  ReloadRun lateral_shear_reload(double volumetric_part) const;

  const Material guide_ = test::guide_material();  // ME, STOL 1e-4
  State loaded_;
  Sym drained_direction_;
};

TEST_F(Crossing, LoadedStateIsOnTheSurface) {
  // The set-up itself: |f| within FTOL-sized round-off of the surface after plastic loading.
  EXPECT_NEAR(yield_value(guide_, loaded_), 0.0, 1e-8);
  EXPECT_GT(guide_.diagnostics(loaded_).R, 0.5);  // well sheared
}

// Unload a little (elastic, ends inside), then reload with one increment 25x bigger than the
// unloading: most of it is plastic, the first part elastic up to the crossing found by Pegasus.
TEST_F(Crossing, BigIncrementFromInsideTheConeMatchesFineIncrements) {
  State inside = loaded_;
  const Report unload = guide_.update(inside, -2e-4 * drained_direction_);
  ASSERT_EQ(unload.status, Status::ok);
  EXPECT_FALSE(unload.plastic);
  EXPECT_EQ(unload.counters.substeps_accepted, 0);
  ASSERT_LT(yield_value(guide_, inside), -1e-3);  // clearly inside

  for (double axial : {1e-3, 5e-3, 2e-2}) {
    SCOPED_TRACE(axial);
    Report r;
    const double error = single_increment_error(inside, axial * drained_direction_, r);
    std::printf("inside start, reload of %.0e axial: error %.2e, crossing iterations %d, substeps %d/%d\n", axial,
                error, r.counters.crossing_iterations, r.counters.substeps_accepted, r.counters.substeps_rejected);
    EXPECT_LE(error, kTolerance);
    EXPECT_TRUE(r.plastic);
    // The comparison can tell a crossing from none: the same increment integrated as all
    // plastic (the start moved onto the surface by shrinking H to R/g) misses the reference by
    // far more than the tolerance.
    State all_plastic = inside, reference = inside;
    all_plastic.H = guide_.diagnostics(inside).R / guide_.diagnostics(inside).g;
    guide_.update(all_plastic, axial * drained_direction_);
    test::fine_increment_reference(guide_, reference, axial * drained_direction_, kReferencePieces);
    const double error_without_crossing = test::relative_stress_error(all_plastic, reference);
    std::printf("  the same as all plastic: error %.2e\n", error_without_crossing);
    EXPECT_GT(error_without_crossing, 10 * kTolerance);
    EXPECT_GT(r.counters.crossing_iterations, 0);  // the crossing was searched, not skipped
    EXPECT_EQ(r.counters.unload_reload, 0);        // a start inside is not an unload-reload case
    EXPECT_GE(r.counters.substeps_accepted, 1);
    EXPECT_GT(r.counters.rate_evaluations, 0);
  }
}

// Reversal: from the surface (triaxial compression), one isochoric increment of axial
// extension big enough to cross the whole cone: it unloads (elastic) through the hydrostatic
// axis and reloads on the extension side of the cone. The integrator must detect the
// unloading start (cosine test), bracket the far crossing and integrate only the rest
// plastically. Same tolerance as above. Isochoric on purpose: p stays constant in the elastic
// part, whose integration is then exact, so this isolates the crossing logic (reversals with
// volumetric strain are in hard_paths_test).
TEST_F(Crossing, UnloadThenReloadInOneIncrementMatchesFineIncrements) {
  for (double axial : {1e-2, 2e-2}) {  // the elastic part alone reaches the far side at ~8e-3
    SCOPED_TRACE(axial);
    const Sym reversal = (Sym() << -axial, 0.5 * axial, 0.5 * axial, 0, 0, 0).finished();
    Report r;
    const double error = single_increment_error(loaded_, reversal, r);
    std::printf("reversal of %.0e axial from the surface: error %.2e, unload_reload %d, crossing iterations %d, "
                "substeps %d/%d\n",
                axial, error, r.counters.unload_reload, r.counters.crossing_iterations, r.counters.substeps_accepted,
                r.counters.substeps_rejected);
    EXPECT_LE(error, kTolerance);
    EXPECT_GT(r.counters.unload_reload, 0);
    EXPECT_TRUE(r.plastic);
    EXPECT_GE(r.counters.substeps_accepted, 1);
    EXPECT_GT(r.counters.rate_evaluations, 0);
    // It really ended in extension on the far side: sin3theta > 0 (compression is -1).
    State end = loaded_;
    guide_.update(end, reversal);
    const Diagnostics d = guide_.diagnostics(end);
    EXPECT_GT(d.sin3theta, 0.5);
    EXPECT_EQ(r.counters.pressure_floor_resets, 0);
    EXPECT_GT(d.p, 100.0);
  }
}

// Where along a straight increment the fine reference first turns plastic (fraction of deps).
double reload_fraction(const Material& m, State s, const Sym& deps) {
  const Material fine = test::with_integrator(m, integration::Scheme::rk45, 1e-10);
  const int pieces = 1000;
  for (int i = 0; i < pieces; ++i)
    if (fine.update(s, deps / pieces).plastic) return double(i) / pieces;
  return 1.0;
}

// Unload-then-reload without a reversal: isotropic compression (R falls: unloading) with a shear
// strain eps_23 in the lateral plane, tangent to the cone at first (n:ds = 0), which carries the
// stress back out through the cone a little later. The unloading start must be detected (the
// cosine test) and the reload crossing bracketed by the scan over NSUB = 10 sub-intervals.
ReloadRun Crossing::lateral_shear_reload(double volumetric_part) const {
  const Sym deps = (Sym() << volumetric_part, volumetric_part, volumetric_part, 0, 0, 3e-3).finished();
  ReloadRun run{reload_fraction(guide_, loaded_, deps), 0.0, {}};
  run.error = single_increment_error(loaded_, deps, run.report);
  std::printf("compression + lateral shear, reload at %.3f of the increment: error %.2e, unload_reload %d, "
              "crossing iterations %d\n",
              run.reload_at, run.error, run.report.counters.unload_reload, run.report.counters.crossing_iterations);
  return run;
}

TEST_F(Crossing, ReloadThroughALodeAngleChangeMatchesFineIncrements) {
  const ReloadRun run = lateral_shear_reload(6e-4);
  ASSERT_GT(run.reload_at, 0.1);  // beyond the first scan interval (measured 0.11)
  EXPECT_LE(run.error, kTolerance);
  EXPECT_GT(run.report.counters.unload_reload, 0);
  EXPECT_GT(run.report.counters.crossing_iterations, 0);
  EXPECT_TRUE(run.report.plastic);
}

// The same with the reload inside the first scan sub-interval (at 7 % of the increment).
// Without refining the scan inside that first sub-interval (Sloan et al. 2001) the whole
// increment would be integrated as plastic and the drift correction H = R/g would shrink the
// cone during its unloading part (error 2.4e-3, 12x the tolerance).
TEST_F(Crossing, ReloadWithinTheFirstScanIntervalMatchesFineIncrements) {
  const ReloadRun run = lateral_shear_reload(4e-4);
  ASSERT_LT(run.reload_at, 0.1);  // inside the first scan interval (measured 0.07)
  EXPECT_LE(run.error, kTolerance);
  EXPECT_GT(run.report.counters.unload_reload, 0);
}

// A small reversal that stays inside the cone is elastic: no substeps, no unload-reload count,
// no crossing, and the stress change is the elastic one (isochoric at constant p: exact).
TEST_F(Crossing, SmallReversalStaysElastic) {
  const double axial = 2e-4;
  const Sym reversal = (Sym() << -axial, 0.5 * axial, 0.5 * axial, 0, 0, 0).finished();
  State s = loaded_;
  const Report r = guide_.update(s, reversal);
  ASSERT_EQ(r.status, Status::ok);
  EXPECT_FALSE(r.plastic);
  EXPECT_EQ(r.counters.substeps_accepted, 0);
  EXPECT_EQ(r.counters.unload_reload, 0);
  EXPECT_GT(r.counters.rate_evaluations, 0);  // the elastic trial is two rate evaluations
  // Isochoric: p does not change, so G is constant and d sigma = 2 G de exactly (relative 1e-12).
  const double G = guide_.diagnostics(loaded_).G;
  const Sym expected = loaded_.stress + 2.0 * G * reversal;
  EXPECT_LE(norm(s.stress - expected) / norm(expected), 1e-12);
}


// Continued loading from the surface is plastic from its start, so it skips the elastic trial
// (docs/integration.md section 1, step 1): FE-1 then evaluates one elastic rate (the loading
// test) and one plastic rate, where the trial would add a second elastic rate. The answer is the
// trial path's: the same start moved a hair inside the cone (H raised by 2 FTOL) takes the trial,
// finds the crossing at once and must end at the same stress to round-off (the crossing moves
// the start by ~FTOL, a relative change of ~1e-8).
TEST_F(Crossing, LoadingFromTheSurfaceSkipsTheTrialAndAgreesWithIt) {
  const Material fe1 = test::with_integrator(guide_, integration::Scheme::forward_euler, 1e-4);
  const Sym deps = 1e-4 * drained_direction_;
  State direct = loaded_;
  const Report r = fe1.update(direct, deps);
  ASSERT_EQ(r.status, Status::ok);
  EXPECT_TRUE(r.plastic);
  EXPECT_EQ(r.counters.rate_evaluations, 2);
  EXPECT_EQ(r.counters.crossing_iterations, 0);

  State via_trial = loaded_;
  via_trial.H += 2e-8;
  const Report t = fe1.update(via_trial, deps);
  ASSERT_EQ(t.status, Status::ok);
  EXPECT_TRUE(t.plastic);
  EXPECT_GE(t.counters.rate_evaluations, 4);  // the trial's two elastic rates and the crossing
  EXPECT_LE(norm(direct.stress - via_trial.stress) / norm(direct.stress), 1e-6);
}

}  // namespace
}  // namespace acst::crossing_test
