// The bundled element-test scenes (data/scenes/element/*.json) are valid, cover the reference
// study's tests and every element-test curve in data/lab/, and a lab scene runs to its strain.
#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "acst_driver/lab_data.hpp"
#include "driver_scenes.hpp"

namespace acst::test {
namespace {

namespace fs = std::filesystem;
const fs::path root(ACST_SOURCE_DIR);

std::vector<fs::path> scene_files() {
  std::vector<fs::path> v;
  for (const auto& e : fs::directory_iterator(root / "data/scenes/element"))
    if (e.path().extension() == ".json") v.push_back(e.path());
  std::sort(v.begin(), v.end());
  return v;
}

TEST(BundledScenes, AllParseAndCoverEveryLabCurve) {
  std::set<std::string> named_lab_files, names;
  for (const auto& f : scene_files()) {
    SCOPED_TRACE(f.string());
    const driver::ElementScene s = driver::read_scene(f.string());
    names.insert(s.output.name);
    for (const auto& lab : s.lab_data) named_lab_files.insert(fs::canonical(lab).string());
  }
  // Every element-test curve (a file with a usable strain range) has a scene overlaying it.
  int curves = 0;
  for (const auto& e : fs::recursive_directory_iterator(root / "data/lab")) {
    if (e.path().extension() != ".csv") continue;
    const driver::LabCurve c = driver::read_commented_csv(e.path().string(), true);
    if (c.text("strain_range_pct").empty()) continue;
    ++curves;
    EXPECT_TRUE(named_lab_files.count(fs::canonical(e.path()).string())) << "no scene for " << e.path();
  }
  EXPECT_GE(curves, 20);
  // The reference study: PSC at 50/200 kPa, bedding 0/90, ACST and isotropic; TC dense and loose 50-400 kPa.
  for (const char* n : {"ref_psc_dense_s050_a00_acst", "ref_psc_dense_s050_a90_acst", "ref_psc_dense_s200_a00_acst",
                        "ref_psc_dense_s200_a90_acst", "ref_psc_dense_s050_isotropic", "ref_psc_dense_s200_isotropic",
                        "ref_tc_dense_s050_acst", "ref_tc_dense_s400_acst", "ref_tc_loose_s050_acst", "ref_tc_loose_s400_acst"})
    EXPECT_TRUE(names.count(n)) << n;
}

TEST(BundledScenes, ALabSceneRunsToItsStrainAtTheFilesConditions) {
  const driver::ElementScene s = driver::read_scene((root / "data/scenes/element/lab_wang33_HKU_TMD1.json").string());
  const driver::LabCurve lab = driver::read_lab_curve(s.lab_data.at(0));
  EXPECT_DOUBLE_EQ(mean_stress(s.initial.stress), lab.number("sigma3_kPa"));
  EXPECT_DOUBLE_EQ(s.initial.void_ratio, lab.number("e0"));
  const driver::RunResult r = driver::run_scene(s);
  ASSERT_TRUE(r.ok) << r.message;
  EXPECT_GE(100.0 * r.records.back().strain[0], 3.3);  // past the end of the usable data (3.3 %)
}

TEST(LabData, EmptyCellsAreMissingValuesNotZeros) {
  const driver::LabCurve c = driver::read_lab_curve((root / "data/lab/fukushima_tatsuoka_1984/ft84_fig5a_sc1p0.csv").string());
  EXPECT_DOUBLE_EQ(c.number("sigma3_kPa"), 98.0);
  const auto q = c.column("q_kPa"), ev = c.column("eps_v_pct");
  ASSERT_EQ(q.size(), ev.size());
  int q_only = 0, ev_only = 0;
  for (std::size_t i = 0; i < q.size(); ++i) {
    q_only += !std::isnan(q[i]) && std::isnan(ev[i]);
    ev_only += std::isnan(q[i]) && !std::isnan(ev[i]);
  }
  EXPECT_GT(q_only, 10);  // the two traces were read at different strains
  EXPECT_GT(ev_only, 10);
}

}  // namespace
}  // namespace acst::test
