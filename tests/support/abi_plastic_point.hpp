#pragma once
// A stress point of a plastic kind behind the C ABI whose one state variable is the equivalent
// plastic strain (von_mises, drucker_prager), its updates, and the check of its consistent tangent
// against central differences (tension positive, engineering shear, kPa).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "abi_model.hpp"
#include "acst.h"

namespace acst::test {

struct PlasticPoint {
  Voigt stress;
  double eps_p = 0.0;
};

// The point acst_initial_state makes of `stress0`, which it must accept.
inline PlasticPoint plastic_start(const acst_model* m, const Voigt& stress0) {
  PlasticPoint p;
  const acst_status st = acst_initial_state(&p.eps_p, p.stress.data(), m, stress0.data(), 0.0, nullptr);
  EXPECT_EQ(st.code, ACST_OK) << st.message;
  return p;
}

// One acst_update of `p`, which must succeed, with the consistent tangent where one is asked;
// returns whether it yielded.
inline bool plastic_step(const acst_model* m, PlasticPoint& p, const Voigt& dstrain, Tangent* tangent = nullptr) {
  acst_counters counters;
  const acst_status st =
      acst_update(p.stress.data(), &p.eps_p, tangent ? tangent->data() : nullptr, &counters, m, dstrain.data());
  EXPECT_EQ(st.code, ACST_OK) << st.message;
  return counters.plastic == 1;
}

// The consistent tangent of an increment that turns the deviatoric direction, from a state on the
// yield surface (isotropic 100 kPa, then 50 increments that yield), checked against central
// differences of the update with respect to each strain component, the increment and each of its
// perturbations yielding. h = 1e-7: truncation (~ h^2 G^3 / sigma_y^2) and cancellation
// (~ 1e-16 sigma / h) both stay below 1e-9 of G; the tolerance is 1e-5 of the largest entry.
// The tangent is left in `D`; call it in ASSERT_NO_FATAL_FAILURE (an update that does not yield stops
// the check).
inline void check_yielding_tangent(const acst_model* m, Tangent& D) {
  PlasticPoint on_surface = plastic_start(m, {-100, -100, -100, 0, 0, 0});
  for (int k = 0; k < 50; ++k) plastic_step(m, on_surface, {-4e-4, 1e-4, 1.5e-4, 2e-4, 0, -1e-4});
  const Voigt d{-1e-4, 2e-5, 3e-5, 1e-4, -6e-5, 4e-5};
  PlasticPoint p = on_surface;
  ASSERT_TRUE(plastic_step(m, p, d, &D));
  double scale = 0.0;
  for (double v : D) scale = std::max(scale, std::abs(v));
  const double h = 1e-7;
  for (int j = 0; j < 6; ++j) {
    Voigt up = d, down = d;
    up[j] += h;
    down[j] -= h;
    PlasticPoint pu = on_surface, pd = on_surface;
    ASSERT_TRUE(plastic_step(m, pu, up));
    ASSERT_TRUE(plastic_step(m, pd, down));
    for (int i = 0; i < 6; ++i)
      EXPECT_NEAR(D[6 * i + j], (pu.stress[i] - pd.stress[i]) / (2.0 * h), 1e-5 * scale) << "i " << i << " j " << j;
  }
}

}  // namespace acst::test
