// Each preset keeps what it holds, at every increment and deep into plastic loading:
// drained triaxial keeps sigma_3 (and sigma_2), undrained triaxial keeps e_v = 0, plane strain
// keeps eps_2 = 0, constant-p shear keeps p, true triaxial keeps b. Tolerances are the solver's:
// a stress row is met to stress_tolerance * max(p, pa) = 1e-8 max(p, pa) at the start of the
// increment (targets are absolute along the step, so the error never accumulates); a strain row
// to strain_tolerance = 1e-12.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "driver_scenes.hpp"

namespace acst::test {
namespace {

double stress_tolerance(const driver::RunResult& r) {
  double p_max = 0.0;
  for (const auto& rec : r.records) p_max = std::max(p_max, mean_stress(rec.stress));
  return 1e-8 * std::max(p_max, atmospheric_pressure);
}

driver::RunResult run_preset(const std::string& preset_and_args, double p0, double e0, int increments) {
  const driver::RunResult r =
      run(scene_json("[{\"preset\": " + preset_and_args + ", \"increments\": " + std::to_string(increments) + "}]", p0, e0));
  EXPECT_TRUE(r.ok) << r.message;
  EXPECT_EQ(static_cast<int>(r.records.size()), increments + 1);
  return r;
}

TEST(PresetConstraints, DrainedTriaxialHoldsTheLateralStressesAndNoShear) {
  const auto r = run_preset("\"drained_triaxial_compression\", \"axial_strain_pct\": 10", 100.0, 0.7, 400);
  const double tol = stress_tolerance(r);
  for (const auto& rec : r.records) {
    EXPECT_NEAR(rec.stress[1], 100.0, tol);
    EXPECT_NEAR(rec.stress[2], 100.0, tol);
    for (int i = 3; i < 6; ++i) EXPECT_NEAR(rec.stress[i], 0.0, tol);
  }
  // It did load the sample: the axial strain is the requested 10 % and q rose well past yield.
  EXPECT_NEAR(r.records.back().strain[0], 0.10, 1e-12);
  EXPECT_GT(driver::signed_q(r.records.back().stress), 100.0);
}

TEST(PresetConstraints, UndrainedTriaxialKeepsTheVolumeAndReportsThePorePressure) {
  const auto r = run_preset("\"undrained_triaxial_compression\", \"axial_strain_pct\": 5", 200.0, 0.85, 250);
  const double tol = stress_tolerance(r);
  for (const auto& rec : r.records) {
    EXPECT_NEAR(trace(rec.strain), 0.0, 1e-12);
    EXPECT_NEAR(rec.stress[1], rec.stress[2], tol);
    // With the total lateral stress (cell pressure) held, u = sigma3'_0 - sigma3', which is
    // also the change of total minus effective mean stress, dq/3 - dp'.
    EXPECT_NEAR(rec.u_excess, 200.0 - 0.5 * (rec.stress[1] + rec.stress[2]), 1e-9 * 200.0);
    EXPECT_NEAR(rec.u_excess, (rec.stress[0] - rec.stress[2]) / 3.0 - (mean_stress(rec.stress) - 200.0), 1e-6);
  }
  // Loose sand contracts: under undrained shear p' falls and u rises.
  EXPECT_LT(mean_stress(r.records.back().stress), 200.0);
  EXPECT_GT(r.records.back().u_excess, 10.0);
}

TEST(PresetConstraints, PlaneStrainKeepsTheIntermediateStrainZero) {
  const auto r = run_preset("\"plane_strain_compression\", \"axial_strain_pct\": 8", 50.0, 0.66, 400);
  const double tol = stress_tolerance(r);
  for (const auto& rec : r.records) {
    EXPECT_NEAR(rec.strain[1], 0.0, 1e-12);
    EXPECT_NEAR(rec.stress[2], 50.0, tol);
  }
  // The intermediate stress built up between the two others, as plane strain does.
  const Sym& s = r.records.back().stress;
  EXPECT_GT(s[1], s[2] + 1.0);
  EXPECT_LT(s[1], s[0]);
}

TEST(PresetConstraints, ConstantPShearKeepsP) {
  for (const double e : {4.0, -4.0}) {  // compression and extension
    const auto r = run_preset("\"constant_p_shear\", \"axial_strain_pct\": " + std::to_string(e), 150.0, 0.75, 200);
    const double tol = stress_tolerance(r);
    for (const auto& rec : r.records) EXPECT_NEAR(mean_stress(rec.stress), 150.0, tol);
    EXPECT_GT(std::abs(driver::signed_q(r.records.back().stress)), 50.0);
    EXPECT_EQ(driver::signed_q(r.records.back().stress) > 0.0, e > 0.0);
  }
}

TEST(PresetConstraints, TrueTriaxialKeepsBAndTheMinorStress) {
  const auto r = run_preset("\"true_triaxial\", \"b\": 0.5, \"axial_strain_pct\": 4", 100.0, 0.7, 200);
  const double tol = stress_tolerance(r);
  for (std::size_t k = 1; k < r.records.size(); ++k) {
    const Sym& s = r.records[k].stress;
    EXPECT_NEAR(s[2], 100.0, tol);
    // (sigma_2 - sigma_3) - b (sigma_1 - sigma_3) = 0 from the isotropic start.
    EXPECT_NEAR((s[1] - s[2]) - 0.5 * (s[0] - s[2]), 0.0, 3.0 * tol);
  }
}

}  // namespace
}  // namespace acst::test
