// Isotropic reduction, docs/model.md section 8: F0 = e_A = k_f = 0 gives A = 0 and
// zeta = psi, the isotropic critical-state model through the same code path; the reduction
// must be exact, bit for bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "acst_driver/mixed_control.hpp"
#include "test_materials.hpp"
#include "triaxial_run.hpp"

namespace {

using acst::Sym;
using nlohmann::json;

const std::string isotropic_file = "data/parameters/toyoura_isotropic_literature.json";

acst::Material isotropic_variant() { return acst::Material::from_json(acst::test::read_text(isotropic_file)); }

// The same constants declared as the anisotropic model with its fabric switched off.
acst::Material acst_without_fabric() {
  json j = json::parse(acst::test::read_text(isotropic_file));
  j["model"] = "ACST";
  j["parameters"]["F0"] = 0.0;
  j["parameters"]["e_A"] = 0.0;
  j["parameters"]["k_f"] = 0.0;
  return acst::Material::from_json(j.dump());
}

// A strain-controlled path with rotating principal axes, shear, loading and unloading, so that
// every branch of the update (elastic, crossing, plastic, unload-reload) is exercised.
std::vector<Sym> mixed_strain_path() {
  std::vector<Sym> path;
  for (int i = 0; i < 400; ++i) {
    const double t = i / 400.0 * 2.0 * 3.14159265358979;
    const double sign = i < 300 ? 1.0 : -0.5;
    path.push_back(sign * 1e-4 *
                   (Sym() << 1.0, -0.3 + 0.2 * std::sin(t), -0.3, 0.4 * std::cos(t), 0.2 * std::sin(2 * t), 0.1)
                       .finished());
  }
  return path;
}

std::vector<acst::State> run(const acst::Material& mat, const std::vector<Sym>& path) {
  acst::State s = mat.initial_state((Sym() << 120, 100, 100, 0, 0, 0).finished(), 0.72, Eigen::Vector3d(0, 1, 0));
  std::vector<acst::State> states{s};
  for (const Sym& deps : path) {
    EXPECT_EQ(mat.update(s, deps).status, acst::integration::Status::ok);
    states.push_back(s);
  }
  return states;
}

TEST(IsotropicReduction, AcstWithoutFabricEqualsIsotropicVariantBitForBit) {
  const auto path = mixed_strain_path();
  const auto iso = run(isotropic_variant(), path);
  const auto red = run(acst_without_fabric(), path);
  ASSERT_EQ(iso.size(), red.size());
  for (std::size_t i = 0; i < iso.size(); ++i) {
    for (int k = 0; k < 6; ++k) ASSERT_EQ(iso[i].stress[k], red[i].stress[k]) << "step " << i << " slot " << k;
    ASSERT_EQ(iso[i].void_ratio, red[i].void_ratio) << "step " << i;
    ASSERT_EQ(iso[i].H, red[i].H) << "step " << i;
    ASSERT_EQ(red[i].fabric, Sym::Zero()) << "step " << i;  // F stays 0: dF = L k_f (n - F) = 0
  }
}

TEST(IsotropicReduction, DrainedTriaxialPathsAreBitIdentical) {
  const auto iso = acst::test::triaxial_compression(isotropic_variant(), 100.0, 0.7, Eigen::Vector3d(1, 0, 0),
                                                    acst::test::Drainage::drained, 1e-4, 1000);
  const auto red = acst::test::triaxial_compression(acst_without_fabric(), 100.0, 0.7, Eigen::Vector3d(1, 0, 0),
                                                    acst::test::Drainage::drained, 1e-4, 1000);
  for (std::size_t i = 0; i < iso.size(); ++i) {
    ASSERT_EQ(iso[i].p, red[i].p) << "step " << i;
    ASSERT_EQ(iso[i].q, red[i].q) << "step " << i;
    ASSERT_EQ(iso[i].volumetric_strain, red[i].volumetric_strain) << "step " << i;
    ASSERT_EQ(red[i].A, 0.0);
  }
}

TEST(IsotropicReduction, FabricChangesTheResponse) {
  // The anisotropic literature set has the same constants plus F0 = 0.5, e_A = 0.1, k_f = 5:
  // the two must differ by far more than round-off (here: more than 2 % in q somewhere), or
  // the bit-identity above would prove nothing.
  const auto iso = acst::test::triaxial_compression(isotropic_variant(), 100.0, 0.7, Eigen::Vector3d(1, 0, 0),
                                                    acst::test::Drainage::drained, 1e-4, 1000);
  const auto ani = acst::test::triaxial_compression(acst::test::literature_material(), 100.0, 0.7,
                                                    Eigen::Vector3d(1, 0, 0), acst::test::Drainage::drained, 1e-4,
                                                    1000);
  double max_relative = 0.0;
  for (std::size_t i = 1; i < iso.size(); ++i)
    max_relative = std::max(max_relative, std::abs(ani[i].q - iso[i].q) / iso[i].q);
  EXPECT_GT(max_relative, 0.02);
}

TEST(IsotropicReduction, IsotropicModelWithFabricParametersIsRejected) {
  for (const char* key : {"F0", "e_A", "k_f"}) {
    json j = json::parse(acst::test::read_text(isotropic_file));
    j["parameters"][key] = 0.3;
    try {
      acst::Material::from_json(j.dump());
      ADD_FAILURE() << "accepted isotropic model with " << key << " = 0.3";
    } catch (const acst::InputError& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
  // Explicit zeros are accepted.
  json j = json::parse(acst::test::read_text(isotropic_file));
  j["parameters"]["F0"] = 0.0;
  EXPECT_NO_THROW(acst::Material::from_json(j.dump()));
}

}  // namespace
