// Lode angle measure and the Lode interpolation g(theta) of Li (2002), docs/model.md section 1.
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Geometry>

#include "acst/lode.hpp"
#include "acst/tensor.hpp"

namespace {

using acst::lode_interpolation;

// The formula exactly as the notes write it (not the rationalised form of the library):
// g = [sqrt((1+c^2)^2 + 4c(1-c^2)s) - (1+c^2)] / [2(1-c)s]; singular at s = 0 and c = 1.
double g_notes(double c, double s) {
  const double a = 1.0 + c * c;
  return (std::sqrt(a * a + 4.0 * c * (1.0 - c * c) * s) - a) / (2.0 * (1.0 - c) * s);
}

// Values of c = Me/Mc where g describes a convex deviatoric section (c >= about 0.7);
// Toyoura sand 0.75.
const double sand_c_values[] = {0.7, 0.75, 0.8, 0.9, 0.95};

TEST(LodeInterpolation, CheckValuesOfTheNotesForToyouraC) {
  const double c = 0.75;
  // 1e-15: these are closed-form values, the rationalised formula gives them to round-off.
  EXPECT_NEAR(lode_interpolation(c, -1.0).g, 1.0, 1e-15);   // triaxial compression
  EXPECT_NEAR(lode_interpolation(c, +1.0).g, 0.75, 1e-15);  // triaxial extension
  // At s = 0 the limit is c(1+c)/(1+c^2) = 1.3125/1.5625 = 0.84 exactly.
  EXPECT_NEAR(lode_interpolation(c, 0.0).g, 0.84, 1e-15);
  EXPECT_TRUE(std::isfinite(lode_interpolation(c, 0.0).dg_ds));
}

TEST(LodeInterpolation, CompressionExtensionAndZeroLodeValuesForSeveralC) {
  for (double c : sand_c_values) {
    SCOPED_TRACE(c);
    EXPECT_NEAR(lode_interpolation(c, -1.0).g, 1.0, 1e-14);
    EXPECT_NEAR(lode_interpolation(c, +1.0).g, c, 1e-14);
    EXPECT_NEAR(lode_interpolation(c, 0.0).g, c * (1.0 + c) / (1.0 + c * c), 1e-14);
    // Near s = 0 the value is smooth (no branch jump): g(+-1e-9) = g(0) +- 1e-9 g'(0) up to
    // a second-order term of ~1e-18 and a few ulps of round-off (1e-15).
    const double g0 = lode_interpolation(c, 0.0).g, dg0 = lode_interpolation(c, 0.0).dg_ds;
    EXPECT_NEAR(lode_interpolation(c, 1e-9).g, g0 + 1e-9 * dg0, 1e-15);
    EXPECT_NEAR(lode_interpolation(c, -1e-9).g, g0 - 1e-9 * dg0, 1e-15);
  }
}

TEST(LodeInterpolation, AgreesWithTheOriginalFormulaAwayFromZero) {
  for (double c : sand_c_values) {
    for (double s = -1.0; s <= 1.0 + 1e-12; s += 0.01) {
      if (std::abs(s) < 0.005) continue;  // the original is 0/0 there
      // The original loses about log10(1/|s|) digits to cancellation in its numerator:
      // at |s| >= 0.01 that is 2 digits of 16, so 1e-12 relative is ample.
      EXPECT_NEAR(lode_interpolation(c, s).g, g_notes(c, s), 1e-12 * g_notes(c, s)) << "c " << c << " s " << s;
    }
  }
}

TEST(LodeInterpolation, EqualCompressionAndExtensionStrengthGivesACircle) {
  // c = 1: Me = Mc, g = 1 for every Lode angle (the original formula is 0/0 here).
  for (double s = -1.0; s <= 1.0 + 1e-12; s += 0.125) {
    EXPECT_DOUBLE_EQ(lode_interpolation(1.0, s).g, 1.0);
    EXPECT_NEAR(lode_interpolation(1.0, s).dg_ds, 0.0, 1e-15);
  }
}

TEST(LodeInterpolation, DerivativeMatchesCentralDifferences) {
  const double h = 1e-6;
  for (double c : sand_c_values) {
    for (double s = -0.99; s <= 0.99 + 1e-12; s += 0.03) {
      const double fd = (lode_interpolation(c, s + h).g - lode_interpolation(c, s - h).g) / (2.0 * h);
      // Central differences: truncation h^2 g'''/6 ~ 1e-12, round-off 1e-16/h ~ 1e-10.
      EXPECT_NEAR(lode_interpolation(c, s).dg_ds, fd, 1e-8) << "c " << c << " s " << s;
    }
  }
}

TEST(LodeInterpolation, DecreasesMonotonicallyFromCompressionToExtension) {
  // g falls from 1 (compression) to c (extension): dg/ds < 0 on the whole range for c < 1.
  for (double c : sand_c_values)
    for (double s = -1.0; s <= 1.0 + 1e-12; s += 0.05) EXPECT_LT(lode_interpolation(c, s).dg_ds, 0.0);
}

// Unit deviator of a stress.
acst::Sym unit_deviator(const acst::Sym& sigma) {
  const acst::Sym d = acst::deviator(sigma);
  return d / acst::norm(d);
}

TEST(LodeAngle, TriaxialCompressionIsMinusOneAndExtensionPlusOne) {
  // Compression positive: sigma1 > sigma2 = sigma3 is triaxial compression.
  const acst::Sym compression = (acst::Sym() << 300, 100, 100, 0, 0, 0).finished();
  const acst::Sym extension = (acst::Sym() << 100, 300, 300, 0, 0, 0).finished();
  EXPECT_NEAR(acst::lode_sin3theta_unclamped(unit_deviator(compression)), -1.0, 1e-14);
  EXPECT_NEAR(acst::lode_sin3theta_unclamped(unit_deviator(extension)), 1.0, 1e-14);
  // The axis does not matter: compression along axis 3, extension along axis 2.
  const acst::Sym compression3 = (acst::Sym() << 80, 80, 200, 0, 0, 0).finished();
  const acst::Sym extension2 = (acst::Sym() << 150, 60, 150, 0, 0, 0).finished();
  EXPECT_NEAR(acst::lode_sin3theta_unclamped(unit_deviator(compression3)), -1.0, 1e-14);
  EXPECT_NEAR(acst::lode_sin3theta_unclamped(unit_deviator(extension2)), 1.0, 1e-14);
  // Pure shear (b = 0.5, sigma2 the mean of sigma1 and sigma3): s = 0.
  const acst::Sym shear = (acst::Sym() << 200, 150, 100, 0, 0, 0).finished();
  EXPECT_NEAR(acst::lode_sin3theta_unclamped(unit_deviator(shear)), 0.0, 1e-14);
}

TEST(LodeAngle, IndependentOfPrincipalFrame) {
  // A rotated triaxial compression state (shear components present) is still s = -1.
  const acst::Sym compression = (acst::Sym() << 300, 100, 100, 0, 0, 0).finished();
  const Eigen::Matrix3d Q =
      Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, 2.0, -0.5).normalized()).toRotationMatrix();
  EXPECT_NEAR(acst::lode_sin3theta_unclamped(unit_deviator(acst::rotate(compression, Q))), -1.0, 1e-13);
}

}  // namespace
