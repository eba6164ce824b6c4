// Error control of the stress-point integrators (docs/integration.md sections 1-3).
// Drained triaxial compression of dense (e0 0.67) and loose (e0 0.9) sand from 100 kPa, guide
// set, ten axial strain increments of 1e-2 (to 10 % axial strain). The strain path is computed
// once with the driver at a fine tolerance and then replayed as pure strain increments, so every
// scheme integrates the identical path. Error = max over the path of
// |sigma - sigma_ref| / max(|sigma_ref|, pa); reference = RK45 at STOL 1e-12.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "strain_path_replay.hpp"
#include "test_materials.hpp"

namespace acst {
namespace {

using integration::Scheme;

constexpr double kInitialPressure = 100.0;  // kPa
constexpr double kAxialIncrement = 1e-2;
constexpr int kIncrements = 10;  // to 10 % axial strain

struct SandCase {
  const char* name;
  double void_ratio;
};

class ErrorControl : public ::testing::TestWithParam<SandCase> {
 protected:
  void SetUp() override {
    start_ = test::isotropic_sample(guide_, kInitialPressure, GetParam().void_ratio);
    path_ = test::drained_triaxial_strain_path(guide_, start_, kAxialIncrement, kIncrements);
    const test::Replay ref = test::replay(test::with_integrator(guide_, Scheme::rk45, 1e-12), start_, path_);
    ASSERT_TRUE(ref.ok) << integration::reason_text(ref.reason);
    reference_ = ref.states;
  }

  // Max stress error of one scheme over the whole path; fails the test if the run fails.
  double path_error(const Material& m, const State& start, size_t first_increment = 0) const {
    const std::vector<Sym> tail(path_.begin() + first_increment, path_.end());
    const std::vector<State> ref_tail(reference_.begin() + first_increment, reference_.end());
    const test::Replay run = test::replay(m, start, tail);
    EXPECT_TRUE(run.ok) << integration::reason_text(run.reason);
    return run.ok ? test::max_stress_error(run.states, ref_tail) : INFINITY;
  }

  const Material guide_ = test::guide_material();
  State start_;
  std::vector<Sym> path_;
  std::vector<State> reference_;
};

// The reference must be far more accurate than anything compared with it: the smallest error
// measured below (STOL 1e-6) is a few 1e-7, so a reference good to 1e-9 perturbs it by < 1 %.
TEST_P(ErrorControl, ReferenceIsConverged) {
  const double vs_looser = path_error(test::with_integrator(guide_, Scheme::rk45, 1e-11), start_);
  const double vs_fresh_substeps = path_error(test::with_integrator(guide_, Scheme::rk45, 1e-12, 1, false), start_);
  std::printf("%s: reference RK45 1e-12 vs RK45 1e-11: %.3g, vs RK45 1e-12 without substep reuse: %.3g\n",
              GetParam().name, vs_looser, vs_fresh_substeps);
  EXPECT_LT(vs_looser, 1e-9);
  EXPECT_LT(vs_fresh_substeps, 1e-9);
}

// A well-behaved adaptive scheme shows its error tracking STOL (section 3). Over STOL 1e-2..1e-6:
// - the error falls by at least 3x per decade on the whole (81x over the four decades), and the
//   least-squares slope of log(error) against log(STOL) lies in [0.6, 1.4] (1 = proportional;
//   measured 0.8 to 1.2);
// - the error stays within 10x of STOL. ME meets this over the whole range (measured 0.05 to
//   0.6 x STOL). RK23 and RK45 are held to it for STOL <= 1e-3 only (measured up to 7x): at
//   STOL 1e-2 they take one or two substeps across the stiff elastic-to-plastic knee of the
//   first increment from the isotropic state (Kp ~ 1/R at R = 0), where the embedded error
//   estimate is not asymptotic; loose RK23 then lands at 25x STOL. That point still enters the
//   slope fit, and it must not be wild: error below 50x STOL.
TEST_P(ErrorControl, AdaptiveErrorTracksTolerance) {
  const std::vector<double> stols = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
  for (Scheme scheme : {Scheme::modified_euler, Scheme::rk23, Scheme::rk45}) {
    SCOPED_TRACE(integration::scheme_name(scheme));
    std::vector<double> errors;
    for (double stol : stols) {
      const double e = path_error(test::with_integrator(guide_, scheme, stol), start_);
      std::printf("%s %-4s STOL %.0e  error %.3e  (%.2f x STOL)\n", GetParam().name,
                  integration::scheme_name(scheme), stol, e, e / stol);
      errors.push_back(e);
      const bool held_to_10x = scheme == Scheme::modified_euler || stol <= 1e-3;
      EXPECT_LE(e, (held_to_10x ? 10.0 : 50.0) * stol) << "STOL " << stol;
    }
    EXPECT_LE(errors.back(), errors.front() / 81.0);
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double k = stols.size();
    for (size_t i = 0; i < stols.size(); ++i) {
      const double x = std::log10(stols[i]), y = std::log10(errors[i]);
      sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    const double slope = (k * sxy - sx * sy) / (k * sxx - sx * sx);
    std::printf("%s %-4s slope of log(error) vs log(STOL): %.2f\n", GetParam().name, integration::scheme_name(scheme),
                slope);
    EXPECT_GE(slope, 0.6);
    EXPECT_LE(slope, 1.4);
  }
}

// FE-N has no error control and converges at first order: doubling N halves the error.
// Measured from the state at 1 % axial strain (reference state, on the yield surface), over the
// remaining nine increments: observed order log2(e_N / e_2N) in [0.8, 1.2] for N = 4..64
// (measured 1.00 to 1.03).
TEST_P(ErrorControl, ForwardEulerConvergesAtFirstOrderFromAShearedState) {
  const State sheared = reference_.front();
  double previous = 0.0;
  for (int n = 4; n <= 64; n *= 2) {
    const double e = path_error(test::with_integrator(guide_, Scheme::forward_euler, 1.0, n), sheared, 1);
    if (n > 4) {
      const double order = std::log2(previous / e);
      std::printf("%s FE-%d -> FE-%d from 1 %% axial strain: error %.3e, order %.3f\n", GetParam().name, n / 2, n, e,
                  order);
      EXPECT_GE(order, 0.8) << "N " << n;
      EXPECT_LE(order, 1.2) << "N " << n;
    }
    previous = e;
  }
}

// The same over the whole path, first increment included: the knee of the first 1e-2 increment
// from the isotropic state is resolved only once the substep is small against it, so for
// N = 4..64 the error falls faster than first order (measured orders 3.0 down to 1.25: coarse
// FE overshoots the knee). Asserted: the pre-asymptotic fall is at least first order (error
// falls >= 16x from N = 4 to 64), and the doublings from N = 128 to 1024 have an order in
// [0.8, 1.2] (measured 1.01 to 1.06).
TEST_P(ErrorControl, ForwardEulerConvergesAtFirstOrderOverTheWholePath) {
  std::vector<double> errors;
  std::vector<int> ns;
  for (int n = 4; n <= 1024; n *= 2) {
    ns.push_back(n);
    errors.push_back(path_error(test::with_integrator(guide_, Scheme::forward_euler, 1.0, n), start_));
  }
  for (size_t i = 1; i < ns.size(); ++i) {
    const double order = std::log2(errors[i - 1] / errors[i]);
    std::printf("%s whole path FE-%d: error %.3e, order %.3f\n", GetParam().name, ns[i], errors[i], order);
    if (ns[i] > 128) {
      EXPECT_GE(order, 0.8) << "N " << ns[i];
      EXPECT_LE(order, 1.2) << "N " << ns[i];
    }
  }
  EXPECT_LE(errors[4], errors[0] / 16.0);  // N = 64 against N = 4
}

INSTANTIATE_TEST_SUITE_P(DrainedTriaxial100kPa, ErrorControl,
                         ::testing::Values(SandCase{"dense", 0.67}, SandCase{"loose", 0.9}),
                         [](const ::testing::TestParamInfo<SandCase>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace acst
