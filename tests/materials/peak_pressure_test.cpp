// The option peak_pressure_exponent beta (docs/model.md section 6): the peak-state coefficient is
// n (p/pa)^beta, so the peak stress ratio R = Mc g exp(-n (p/pa)^beta zeta) depends on the pressure
// beyond what zeta carries. beta = 0 is the published model. Guide set, drained triaxial
// compression, compression positive.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "acst/acst_rates.hpp"
#include "acst_driver/record.hpp"
#include "driver_scenes.hpp"
#include "test_materials.hpp"

namespace acst::test {
namespace {

constexpr double beta = 0.4;

std::string guide_with_beta(double b) {
  nlohmann::json m = nlohmann::json::parse(read_text("data/parameters/toyoura_acst_guide.json"));
  m["parameters"]["peak_pressure_exponent"] = b;
  return m.dump();
}

// Drained triaxial compression to 12 % axial strain in steps of 0.02 %.
std::vector<driver::Record> triaxial(double b, double p0, double e0) {
  const auto r = run(scene_json("[{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 12, \"increments\": 600}]",
                                p0, e0, "", guide_with_beta(b)));
  EXPECT_TRUE(r.ok) << r.message;
  return r.records;
}

driver::Record triaxial_peak(double b, double p0, double e0) {
  const auto records = triaxial(b, p0, e0);
  return *std::max_element(records.begin(), records.end(), [](const auto& a, const auto& c) {
    return driver::stress_ratio_of(a.stress) < driver::stress_ratio_of(c.stress);
  });
}

// The peak is where the plastic modulus vanishes: on R = Mc exp(-n (p/pa)^beta zeta) in triaxial
// compression (g = 1), at the peak's own p and zeta; dense sand at 20 and 400 kPa, where the
// coefficient is 0.53 and 1.9 times n. 0.5 %: the record is the increment nearest the peak, and p
// still moves there. Off that surface by more than 5 % is the published one, R = Mc exp(-n zeta).
TEST(PeakPressureExponent, DensePeaksSitOnThePressureDependentPeakSurface) {
  const Parameters prm = guide_material().parameters();
  for (double p0 : {20.0, 400.0}) {
    SCOPED_TRACE("p0 = " + std::to_string(p0));
    const driver::Record peak = triaxial_peak(beta, p0, 0.66);
    const double p = mean_stress(peak.stress), R = driver::stress_ratio_of(peak.stress);
    ASSERT_LT(peak.zeta, -0.05) << "a dense state";
    const double n_p = prm.n * std::pow(p / atmospheric_pressure, beta);
    EXPECT_NEAR(R / (prm.Mc * std::exp(-n_p * peak.zeta)), 1.0, 0.005);
    EXPECT_GT(std::abs(R / (prm.Mc * std::exp(-prm.n * peak.zeta)) - 1.0), 0.05);
  }
}

// What the option is for: with beta > 0 the state parameter counts less at low pressure, so a
// dense specimen at 20 kPa peaks lower than with the published constant n, and at 400 kPa higher.
// A loose one at 20 kPa has no peak (it hardens towards Mc, where zeta is 0 and n does not act),
// but its bound Mc exp(-n zeta) is nearer Mc, so its stress ratio rises faster: higher at 2 %.
TEST(PeakPressureExponent, APositiveExponentFlattensThePeaksPressureDependence) {
  const auto change = [](double p0, double e0) {
    return driver::stress_ratio_of(triaxial_peak(beta, p0, e0).stress) / driver::stress_ratio_of(triaxial_peak(0.0, p0, e0).stress) - 1.0;
  };
  EXPECT_LT(change(20.0, 0.66), -0.05) << "dense, 20 kPa";
  EXPECT_GT(change(400.0, 0.66), 0.05) << "dense, 400 kPa";
  const auto at_two_pct = [](double b) { return driver::stress_ratio_of(triaxial(b, 20.0, 0.95)[100].stress); };
  EXPECT_GT(at_two_pct(beta) / at_two_pct(0.0) - 1.0, 0.01) << "loose, 20 kPa, 2 % axial strain";
}

// The plastic modulus at a state: at p = pa beta changes nothing (to round-off); elsewhere it is
// G h (Mc g exp(-n (p/pa)^beta zeta)/R - 1) with the state's own G, h, g, zeta and R; below
// p_min the coefficient is that of p_min, like the moduli.
TEST(PeakPressureExponent, PlasticModulusFollowsTheClosedForm) {
  Parameters with = guide_material().parameters();
  with.peak_pressure_exponent = beta;
  const Parameters without = guide_material().parameters();
  const Sym F = initial_fabric(without.F0, Eigen::Vector3d(0, 0, 1));
  const Sym dir = deviator((Sym() << 1.0, -0.5, -0.5, 0.2, 0.0, 0.1).finished());
  const auto Kp_at = [&](const Parameters& prm, double p) {
    const Sym s = p * (Sym() << 1.6, 0.8, 0.6, 0.1, 0.0, 0.05).finished();
    return plastic_quantities(prm, s, F, 0.7, dir);
  };
  const double pa = atmospheric_pressure;
  EXPECT_NEAR(Kp_at(with, pa).Kp, Kp_at(without, pa).Kp, 1e-12 * std::abs(Kp_at(without, pa).Kp));
  for (double p : {0.2, 5.0, 50.0, 300.0}) {
    SCOPED_TRACE("p = " + std::to_string(p));
    const PlasticQuantities q = Kp_at(with, p);
    const double g = q.ratio.lode.g, pp = std::max(p, with.p_min);
    const double expected = q.moduli.G * q.h * (with.Mc * g * std::exp(-with.n * std::pow(pp / pa, beta) * q.zeta) / q.ratio.R - 1.0);
    EXPECT_NEAR(q.Kp, expected, 1e-12 * std::abs(expected));
    EXPECT_GT(std::abs(q.Kp - Kp_at(without, p).Kp), 1e-3 * std::abs(expected)) << "the option acts away from pa";
  }
}

std::string input_error_of(const nlohmann::json& material) {
  try {
    Material::from_json(material.dump());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Out of range is refused by name and range; the isotropic reduction may use it (it has no fabric).
TEST(PeakPressureExponent, OutOfRangeIsRefusedByNameAndTheIsotropicModelTakesIt) {
  nlohmann::json j = nlohmann::json::parse(guide_with_beta(1.5));
  const std::string range = input_error_of(j);
  EXPECT_NE(range.find("/parameters/peak_pressure_exponent"), std::string::npos) << range;
  EXPECT_NE(range.find("[-1, 1]"), std::string::npos) << range;
  nlohmann::json iso = nlohmann::json::parse(read_text("data/parameters/toyoura_isotropic_literature.json"));
  iso["parameters"]["peak_pressure_exponent"] = -0.3;
  EXPECT_EQ(input_error_of(iso), "");
}

}  // namespace
}  // namespace acst::test
