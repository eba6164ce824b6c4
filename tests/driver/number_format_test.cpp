// The CSV's fast number output gives the text of printf("%.10g") (10 significant digits),
// allowing only a one-unit difference in the 10th digit for values that lie within round-off of
// a halfway point (the fast path rounds the binary-scaled value once).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include "acst_driver/number_format.hpp"

namespace acst::test {
namespace {

std::string fast(double v) {
  std::string s;
  driver::append_number(s, v);
  return s;
}

std::string printf10(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

TEST(NumberFormat, MatchesPrintfOnRandomValuesOfEveryMagnitude) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> mantissa(1.0, 10.0), exponent(-8.0, 12.0);
  int differ = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double v = (i % 2 ? -1.0 : 1.0) * mantissa(rng) * std::pow(10.0, std::floor(exponent(rng)));
    const std::string a = fast(v), b = printf10(v);
    if (a != b) {
      ++differ;
      // Same number to one unit in the 10th significant digit.
      EXPECT_NEAR(std::strtod(a.c_str(), nullptr), std::strtod(b.c_str(), nullptr), 1.01e-9 * std::abs(v)) << a << " vs " << b;
    }
  }
  EXPECT_LT(differ, n / 10000) << "halfway cases should be rare";
}

TEST(NumberFormat, EdgeValues) {
  for (const double v : {0.0, 1.0, -1.0, 0.1, 1e-4, 9.9999999999e-5, 0.00099999999999, 9999999999.4, 9999999999.6, 1e10,
                         123.456, -0.5, 100.0, 1e-12, 5e20, 2.0 / 3.0, 99.99999999999})
    EXPECT_EQ(fast(v), printf10(v)) << v;
  EXPECT_EQ(fast(-0.0), "0");
  EXPECT_EQ(fast(std::nan("")).substr(0, 3), "nan");
}

}  // namespace
}  // namespace acst::test
