// The MPM's nonlocal average (core/include/acst_mpm/nonlocal_average.hpp): the kernels as
// defined; every particle's mean the normalised sum over every pair within reach, found again
// after the particles move past the lists' skin; a constant field kept; a half domain with its
// mirror image giving the whole domain's means; the same bits for any thread count.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "acst_mpm/nonlocal_average.hpp"

namespace mpm_nonlocal_average_test {

using namespace acst::mpm;

Particles cloud(std::size_t n, double width, double height, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Particles P;
  P.resize(n, 0);
  for (std::size_t p = 0; p < n; ++p) {
    P.x[p] = width * u(rng);
    P.y[p] = height * u(rng);
    P.volume_initial[p] = 0.5 + u(rng);
    P.F[4 * p] = 1.0 + 0.1 * (u(rng) - 0.5);  // volumes change with F
  }
  return P;
}

// The mean by the definition: every pair, no lists, the kernel as the averaging reads it.
std::vector<double> brute_force(const Particles& P, const std::vector<double>& v, NonlocalKernel k, double l,
                                const double* mirror_x = nullptr) {
  const KernelTable w_of(k);
  std::vector<double> mean(P.n);
  for (std::size_t p = 0; p < P.n; ++p) {
    double s = 0.0, w = 0.0;
    for (std::size_t q = 0; q < P.n; ++q) {
      double wq = w_of(std::hypot(P.x[q] - P.x[p], P.y[q] - P.y[p]) / l);
      if (mirror_x) wq += w_of(std::hypot(2.0 * *mirror_x - P.x[q] - P.x[p], P.y[q] - P.y[p]) / l);
      s += wq * P.volume(q) * v[q];
      w += wq * P.volume(q);
    }
    mean[p] = s / w;
  }
  return mean;
}

TEST(NonlocalAverage, KernelsAsDefined) {
  const double l = 0.2;
  EXPECT_EQ(nonlocal_weight(NonlocalKernel::gauss, 0.0, l), 1.0);
  EXPECT_NEAR(nonlocal_weight(NonlocalKernel::gauss, l, l), std::exp(-1.0), 1e-15);
  EXPECT_EQ(nonlocal_weight(NonlocalKernel::galavi_schweiger, 0.0, l), 0.0) << "nothing from the point itself";
  EXPECT_NEAR(nonlocal_weight(NonlocalKernel::galavi_schweiger, 0.5 * l, l), 0.5 * std::exp(-0.25), 1e-15);
  for (NonlocalKernel k : {NonlocalKernel::gauss, NonlocalKernel::galavi_schweiger}) {
    EXPECT_EQ(nonlocal_weight(k, 1.0001 * nonlocal_reach * l, l), 0.0);
    // The table the averaging reads: within 2e-7 of the kernel (whose largest value is 1 or 0.43).
    const KernelTable table(k);
    double worst = 0.0;
    for (int i = 0; i <= 100000; ++i) {
      const double s = nonlocal_reach * i / 100000.0;
      worst = std::max(worst, std::fabs(table(s) - nonlocal_weight(k, s, 1.0)));
    }
    EXPECT_LT(worst, 2e-7);
    EXPECT_EQ(table(1.0001 * nonlocal_reach), 0.0);
  }
}

TEST(NonlocalAverage, IsTheNormalisedSumOverEveryPairAlsoAfterTheParticlesMove) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (NonlocalKernel k : {NonlocalKernel::gauss, NonlocalKernel::galavi_schweiger}) {
    Particles P = cloud(700, 2.0, 1.0, rng);
    std::vector<double> v(P.n), mean(P.n);
    for (double& x : v) x = u(rng);
    const double l = 0.1;
    NonlocalAverage avg(l, k, std::vector<int>(P.n, 1), std::nullopt);
    avg.average(P, v.data(), mean.data(), 2);
    std::vector<double> ref = brute_force(P, v, k, l);
    for (std::size_t p = 0; p < P.n; ++p) ASSERT_NEAR(mean[p], ref[p], 1e-13) << p;
    EXPECT_EQ(avg.builds(), 1);
    // Moved a little (at most 0.07 l, within half the skin, 0.125 l): the same lists; then past
    // it: found again.
    for (double step : {0.05 * l, 0.5 * l}) {
      for (std::size_t p = 0; p < P.n; ++p) P.x[p] += step * u(rng), P.y[p] += step * u(rng);
      avg.average(P, v.data(), mean.data(), 2);
      ref = brute_force(P, v, k, l);
      for (std::size_t p = 0; p < P.n; ++p) ASSERT_NEAR(mean[p], ref[p], 1e-13) << p << " after " << step;
    }
    EXPECT_EQ(avg.builds(), 2) << "found again once, when they had moved past the skin";
  }
}

TEST(NonlocalAverage, KeepsAConstantFieldAndLeavesOutWhatTakesNoPart) {
  std::mt19937_64 rng(4);
  Particles P = cloud(500, 1.0, 1.0, rng);
  std::vector<int> part(P.n, 1);
  std::vector<double> v(P.n, 0.6523), mean(P.n, -1.0);
  for (std::size_t p = 0; p < P.n; p += 7) part[p] = 0, v[p] = 1e6;  // another material
  NonlocalAverage avg(0.08, NonlocalKernel::gauss, part, std::nullopt);
  avg.average(P, v.data(), mean.data(), 1);
  for (std::size_t p = 0; p < P.n; ++p) {
    if (part[p])
      EXPECT_NEAR(mean[p], 0.6523, 1e-15) << p;
    else
      EXPECT_EQ(mean[p], -1.0) << "left as it was";
  }
}

// A cloud symmetric about x = 1 with a symmetric field, and its right half with the line as a
// mirror: the same means at the same particles.
TEST(NonlocalAverage, AHalfDomainGivesTheWholeDomainsMeans) {
  std::mt19937_64 rng(6);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const std::size_t half = 300;
  Particles right = cloud(half, 1.0, 1.0, rng), whole;
  whole.resize(2 * half, 0);
  std::vector<double> v_right(half), v_whole(2 * half);
  for (std::size_t p = 0; p < half; ++p) {
    right.x[p] += 1.0;
    v_right[p] = u(rng);
    for (std::size_t k : {p, p + half}) {
      whole.x[k] = k == p ? right.x[p] : 2.0 - right.x[p];
      whole.y[k] = right.y[p];
      whole.volume_initial[k] = right.volume_initial[p];
      whole.F[4 * k] = right.F[4 * p];
      v_whole[k] = v_right[p];
    }
  }
  const double mirror = 1.0;
  for (NonlocalKernel k : {NonlocalKernel::gauss, NonlocalKernel::galavi_schweiger}) {
    std::vector<double> m_right(half), m_whole(2 * half);
    NonlocalAverage(0.15, k, std::vector<int>(half, 1), mirror).average(right, v_right.data(), m_right.data(), 2);
    NonlocalAverage(0.15, k, std::vector<int>(2 * half, 1), std::nullopt).average(whole, v_whole.data(), m_whole.data(), 2);
    for (std::size_t p = 0; p < half; ++p) ASSERT_NEAR(m_right[p], m_whole[p], 1e-13) << p;
    const std::vector<double> ref = brute_force(right, v_right, k, 0.15, &mirror);
    for (std::size_t p = 0; p < half; ++p) ASSERT_NEAR(m_right[p], ref[p], 1e-13) << p;
  }
}

TEST(NonlocalAverage, TheSameBitsOnAnyThreadCount) {
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Particles P = cloud(2000, 3.0, 1.5, rng);
  std::vector<double> v(P.n), one(P.n), two(P.n), four(P.n);
  for (double& x : v) x = u(rng);
  for (auto [threads, out] : {std::pair{1, &one}, std::pair{2, &two}, std::pair{4, &four}})
    NonlocalAverage(0.1, NonlocalKernel::gauss, std::vector<int>(P.n, 1), std::nullopt)
        .average(P, v.data(), out->data(), threads);
  EXPECT_EQ(one, two);
  EXPECT_EQ(one, four);
}

}  // namespace mpm_nonlocal_average_test
