// Stress-controlled, strain-controlled and mixed runs of the same elastic-range path agree.
// A sample is sheared to q/p = 0.6 and unloaded to q/p = 0.3, so that it sits inside its
// yield cone; then a random six-component strain path of small increments is run under strain
// control. Its stresses, fed back as stress targets (all six components, or a random mix of
// stress and strain components per increment), must give back the same strains and stresses.
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <string>

#include "driver_scenes.hpp"

namespace acst::test {
namespace {

std::string num(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

const char* names[] = {"11", "22", "33", "12", "13", "23"};

// Shear to q/p 0.6, unload to q/p 0.3: inside the cone, the response is elastic.
const std::string base_steps =
    "{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 5, \"increments\": 500,"
    " \"exit\": {\"stress_ratio_above\": 0.6}},"
    "{\"preset\": \"drained_triaxial_extension\", \"axial_strain_pct\": 1, \"increments\": 100,"
    " \"exit\": {\"stress_ratio_below\": 0.3}}";

// Scene value of a strain component: percent, engineering shear.
double strain_pct(const Sym& eps, int i) { return (i < 3 ? 100.0 : 200.0) * eps[i]; }

class ControlEquivalence : public ::testing::TestWithParam<unsigned> {};

TEST_P(ControlEquivalence, StressAndMixedTargetsReproduceTheStrainControlledPath) {
  std::mt19937 rng(GetParam());
  std::uniform_real_distribution<double> step(-0.002, 0.002);  // percent per increment
  const int n = 25;
  std::string strain_steps;
  for (int k = 0; k < n; ++k) {
    strain_steps += ", {\"control\": {";
    for (int i = 0; i < 6; ++i)
      strain_steps += std::string(i ? ", " : "") + "\"" + names[i] + "\": {\"strain_pct\": " + num(step(rng)) + "}";
    strain_steps += "}, \"increments\": 1}";
  }
  const driver::RunResult base = run(scene_json("[" + base_steps + "]"));
  const driver::RunResult strain_run = run(scene_json("[" + base_steps + strain_steps + "]"));
  ASSERT_TRUE(base.ok) << base.message;
  ASSERT_TRUE(strain_run.ok) << strain_run.message;
  const std::size_t n0 = base.records.size();
  ASSERT_EQ(strain_run.records.size(), n0 + n);
  // Precondition: the random path stayed elastic (the fabric only evolves in plastic loading).
  for (std::size_t k = n0; k < strain_run.records.size(); ++k)
    ASSERT_EQ(strain_run.records[k].fabric_norm, base.records.back().fabric_norm) << "path left the cone at " << k;

  std::bernoulli_distribution stress_component(0.5);
  for (const bool mixed : {false, true}) {
    std::string target_steps;
    for (int k = 0; k < n; ++k) {
      const driver::Record& r = strain_run.records[n0 + k];
      target_steps += ", {\"control\": {";
      for (int i = 0; i < 6; ++i) {
        const bool by_stress = !mixed || stress_component(rng);
        target_steps += std::string(i ? ", " : "") + "\"" + names[i] + "\": {" +
                        (by_stress ? "\"stress_to\": " + num(r.stress[i]) : "\"strain_to_pct\": " + num(strain_pct(r.strain, i))) + "}";
      }
      target_steps += "}, \"increments\": 1}";
    }
    const driver::RunResult target_run = run(scene_json("[" + base_steps + target_steps + "]"));
    ASSERT_TRUE(target_run.ok) << target_run.message;
    ASSERT_EQ(target_run.records.size(), n0 + n);
    // Stress targets are met to 1e-8 max(p, pa) ~ 1e-6 kPa (Newton stress tolerance); over a
    // stiffness above 3e4 kPa that is ~3e-11 strain per increment, and targets are absolute so
    // the errors do not add up: 1e-9 on strains and 1e-5 kPa on stresses leave a wide margin.
    for (int k = 0; k < n; ++k) {
      const driver::Record& a = strain_run.records[n0 + k];
      const driver::Record& b = target_run.records[n0 + k];
      for (int i = 0; i < 6; ++i) {
        EXPECT_NEAR(b.strain[i], a.strain[i], 1e-9) << (mixed ? "mixed" : "stress") << " run, increment " << k << ", component " << names[i];
        EXPECT_NEAR(b.stress[i], a.stress[i], 1e-5) << (mixed ? "mixed" : "stress") << " run, increment " << k << ", component " << names[i];
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(RandomPaths, ControlEquivalence, ::testing::Values(1u, 2u, 3u, 4u));

}  // namespace
}  // namespace acst::test
