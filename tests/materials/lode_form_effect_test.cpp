// What the Lode form changes in element tests (docs/model.md section 1): with the same parameters,
// lode_form 1 (Willam & Warnke) leaves triaxial compression as it is (g = 1 on the compression
// meridian for both forms) and lowers the plane-strain peak, which stays on its form's peak
// surface R = Mc g exp(-n zeta). Guide set, drained, compression positive.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "acst/lode.hpp"
#include "driver_scenes.hpp"
#include "test_materials.hpp"

namespace acst::test {
namespace {

std::string material_with_lode_form(int form) {
  nlohmann::json m = nlohmann::json::parse(read_text("data/parameters/toyoura_acst_guide.json"));
  m["parameters"]["lode_form"] = form;
  return m.dump();
}

driver::RunResult run_with(int form, const std::string& preset, double p0, double e0) {
  const auto r = run(scene_json("[{\"preset\": " + preset + ", \"increments\": 400}]", p0, e0, "", material_with_lode_form(form)));
  EXPECT_TRUE(r.ok) << r.message;
  return r;
}

TEST(LodeFormEffect, TriaxialCompressionIsTheSameForBothForms) {
  const auto li = run_with(0, "\"drained_triaxial_compression\", \"axial_strain_pct\": 10", 100.0, 0.7);
  const auto ww = run_with(1, "\"drained_triaxial_compression\", \"axial_strain_pct\": 10", 100.0, 0.7);
  ASSERT_EQ(li.records.size(), ww.records.size());
  for (std::size_t i = 0; i < li.records.size(); ++i) {
    // Only round-off and the integrator's tolerance separate them: the stress stays on the
    // compression meridian, where both g are 1 and the derivatives enter through r_hat only.
    EXPECT_NEAR(ww.records[i].stress[0], li.records[i].stress[0], 1e-6 * li.records[i].stress[0]) << "increment " << i;
    EXPECT_NEAR(ww.records[i].void_ratio, li.records[i].void_ratio, 1e-9) << "increment " << i;
  }
}

TEST(LodeFormEffect, PlaneStrainPeakIsLowerAndSitsOnEachFormsPeakSurface) {
  const auto li = run_with(0, "\"plane_strain_compression\", \"axial_strain_pct\": 8", 100.0, 0.66);
  const auto ww = run_with(1, "\"plane_strain_compression\", \"axial_strain_pct\": 8", 100.0, 0.66);
  const auto R = [](const Sym& s) { return std::sqrt(1.5) * norm(deviator(s)) / mean_stress(s); };
  const auto peak = [&](const driver::RunResult& r) {
    return *std::max_element(r.records.begin(), r.records.end(),
                             [&](const auto& a, const auto& b) { return R(a.stress) < R(b.stress); });
  };
  const driver::Record li_peak = peak(li), ww_peak = peak(ww);
  // The peak stress ratio is where the plastic modulus vanishes: R = Mc g(theta) exp(-n zeta),
  // each form with its own g at its own Lode angle (0.5 %: the record is the increment nearest
  // the peak, and p still moves there).
  const Parameters prm = guide_material().parameters();
  const auto on_peak_surface = [&](const driver::Record& rec, const LodeShape& shape) {
    const Sym d = deviator(rec.stress);
    const double g = lode_interpolation(shape, lode_sin3theta_unclamped(d / norm(d))).g;
    return R(rec.stress) / (prm.Mc * g * std::exp(-prm.n * rec.zeta));
  };
  EXPECT_NEAR(on_peak_surface(li_peak, LodeShape(prm.c)), 1.0, 0.005);
  EXPECT_NEAR(on_peak_surface(ww_peak, LodeShape(prm.c, LodeForm::willam_warnke)), 1.0, 0.005);
  // The elliptic g is lower between the meridians, so the plane-strain peak falls (by 1.2 % with
  // the guide set's c = 0.75: g itself is 1.7 % lower at the peak's Lode angle, which moves a
  // little towards compression).
  EXPECT_LT(R(ww_peak.stress), 0.995 * R(li_peak.stress));
}

}  // namespace
}  // namespace acst::test
