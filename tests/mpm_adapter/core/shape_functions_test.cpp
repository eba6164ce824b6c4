// B2GIMP shape functions: the design note's check values, partition of unity, gradient sums,
// continuity across the piecewise ranges and derivatives against finite differences.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "acst_mpm/shape_functions.hpp"

using namespace acst::mpm;

TEST(B2gimpShapeFunctions, CheckValuesForQuarterCellDomains) {
  // (xi, S, dS/dxi) for l = 0.25 from the closed form of the averaged quadratic B-spline.
  const double table[][3] = {{0, 35.0 / 48, 0},       {0.25, 2.0 / 3, -0.5},   {0.5, 95.0 / 192, -0.8125},
                             {0.75, 7.0 / 24, -0.75}, {1, 13.0 / 96, -0.5},    {1.25, 1.0 / 24, -0.25},
                             {1.5, 1.0 / 192, -0.0625}};
  for (const auto& r : table) {
    EXPECT_NEAR(b2gimp_weight(r[0], 0.25), r[1], 1e-14) << "xi = " << r[0];
    EXPECT_NEAR(b2gimp_slope(r[0], 0.25), r[2], 1e-14) << "xi = " << r[0];
    EXPECT_NEAR(b2gimp_weight(-r[0], 0.25), r[1], 1e-14) << "symmetric at xi = " << -r[0];
    EXPECT_NEAR(b2gimp_slope(-r[0], 0.25), -r[2], 1e-14) << "antisymmetric at xi = " << -r[0];
  }
  EXPECT_EQ(b2gimp_weight(1.75, 0.25), 0.0);
  EXPECT_EQ(b2gimp_weight(2.5, 0.5), 0.0);
}

TEST(B2gimpShapeFunctions, HalfCellDomainsAverageTheBSplineOverTheCell) {
  // l = 0.5: S(xi) is the integral of the B-spline N over [xi - 1/2, xi + 1/2], done by hand:
  // S(0) = 2/3, S(1/2) = 23/48, S(1) = 1/6, S(2) = 0.
  EXPECT_NEAR(b2gimp_weight(0.0, 0.5), 2.0 / 3.0, 1e-14);
  EXPECT_NEAR(b2gimp_weight(1.0, 0.5), 1.0 / 6.0, 1e-14);
  EXPECT_NEAR(b2gimp_weight(2.0, 0.5), 0.0, 1e-14);
  EXPECT_NEAR(b2gimp_weight(0.5, 0.5), 23.0 / 48.0, 1e-14);
}

TEST(B2gimpShapeFunctions, PartitionOfUnityAndZeroGradientSum) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(2.0, 9.0);
  for (double l : {0.5, 0.25, 1.0 / 6.0, 0.125}) {
    for (int k = 0; k < 2000; ++k) {
      const AxisWeights a = axis_weights(u(rng), l);
      double s = 0, ds = 0;
      for (int i = 0; i < 4; ++i) s += a.w[i], ds += a.dw[i];
      ASSERT_NEAR(s, 1.0, 1e-14) << "l = " << l;
      ASSERT_NEAR(ds, 0.0, 1e-13) << "l = " << l;
    }
  }
}

TEST(B2gimpShapeFunctions, ReproducesLinearFieldsAndTheirSlope) {
  // sum_i S_i x_i = X and sum_i dS_i x_i = 1 (linear completeness of the quadratic B-splines).
  for (double l : {0.5, 0.25}) {
    for (double X = 3.0; X < 4.0; X += 0.0137) {
      const AxisWeights a = axis_weights(X, l);
      double x = 0, slope = 0;
      for (int i = 0; i < 4; ++i) x += a.w[i] * (a.first + i), slope += a.dw[i] * (a.first + i);
      ASSERT_NEAR(x, X, 1e-13);
      ASSERT_NEAR(slope, 1.0, 1e-13);
    }
  }
}

TEST(B2gimpShapeFunctions, ContinuousWithFiniteDifferenceSlopesInEveryRange) {
  for (double l : {0.5, 0.25, 0.125}) {
    const double edges[] = {0.5 - l, 0.5 + l, 1.5 - l, 1.5 + l};
    for (double e : edges) {  // value continuous at each range boundary
      EXPECT_NEAR(b2gimp_weight(e - 1e-10, l), b2gimp_weight(e + 1e-10, l), 1e-9) << "l " << l << " edge " << e;
      EXPECT_NEAR(b2gimp_slope(e - 1e-10, l), b2gimp_slope(e + 1e-10, l), 1e-8) << "l " << l << " edge " << e;
    }
    for (double xi = -1.97; xi < 1.97; xi += 0.01) {
      const double d = 1e-6;
      const double fd = (b2gimp_weight(xi + d, l) - b2gimp_weight(xi - d, l)) / (2 * d);
      ASSERT_NEAR(b2gimp_slope(xi, l), fd, 1e-7) << "l " << l << " xi " << xi;
    }
  }
}

// The weights as the ranges are written, one scalar operation at a time: the loops' form (the
// terms of l worked out once, divisions in pairs) must give these numbers bit for bit, since the
// footing's results are compared bit for bit across builds.
TEST(B2gimpShapeFunctions, PairedDivisionsGiveThePlainFormulasNumbers) {
  const auto plain = [](double xi, double l) {
    const double a = std::fabs(xi), inv_l = 1.0 / l;
    double w = 0.0, d = 0.0;
    if (a < 0.5 - l) {
      w = 0.75 - a * a - l * l / 3.0;
      d = -2.0 * a;
    } else if (a < 0.5 + l) {
      const double b = a - l, c = 1.5 - a - l;
      w = (0.5 - 0.75 * b + b * b * b / 3.0 - c * c * c / 6.0) * (0.5 * inv_l);
      d = (0.5 * c * c - (0.75 - b * b)) * (0.5 * inv_l);
    } else if (a <= 1.5 - l) {
      w = 0.5 * (1.5 - a) * (1.5 - a) + l * l / 6.0;
      d = a - 1.5;
    } else if (a < 1.5 + l) {
      const double c = 1.5 + l - a;
      w = c * c * c * (inv_l / 12.0);
      d = -c * c * (0.25 * inv_l);
    }
    return B2gimpValue{w, xi < 0.0 ? -d : d};
  };
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2.2, 2.2);
  for (double l : {0.5, 0.25, 1.0 / 6.0, 0.125}) {
    const B2gimpDomain domain(l);
    for (int k = 0; k < 20000; ++k) {
      const double xi = u(rng);
      const B2gimpValue got = b2gimp(xi, domain), want = plain(xi, l);
      ASSERT_EQ(got.w, want.w) << "l " << l << " xi " << xi;
      ASSERT_EQ(got.dw, want.dw) << "l " << l << " xi " << xi;
    }
  }
}
