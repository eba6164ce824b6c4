#pragma once
// The integrators' steps on plain arrays of N numbers, written once for the scalar integrator
// (explicit_substepping.hpp, every scheme) and the SIMD lanes (src/update_lanes_kernel.cpp: Heun's
// elastic step and one modified-Euler substep). Each is one sequence of IEEE operations in one
// order, so a lane rounds as the scalar update does (tests/materials/update_lanes_test.cpp);
// ACST_INLINE, as the model's formulas, for the lanes' kernel (acst/inline.hpp).
#include "acst/inline.hpp"
#include "acst/integration/embedded_runge_kutta.hpp"

namespace acst::integration {

// Heun's predictor, Euler's step over the fraction h: ys = y + h k1.
template <int N>
ACST_INLINE void euler_predictor(const double* __restrict y, const double* __restrict k1, double h,
                                 double* __restrict ys) {
#pragma GCC unroll 13
  for (int i = 0; i < N; ++i) ys[i] = y[i] + h * k1[i];
}

// Heun's two-stage secant step over the fraction h, from the rates k1 at y and k2 at the
// predictor: y_new = y + (h/2) (k1 + k2), and its error against Euler's step, (h/2) (k2 - k1).
template <int N>
ACST_INLINE void heun_combination(const double* __restrict y, const double* __restrict k1, const double* __restrict k2,
                                  double h, double* __restrict y_new, double* __restrict err) {
  const double half = 0.5 * h;
#pragma GCC unroll 13
  for (int i = 0; i < N; ++i) {
    y_new[i] = y[i] + half * (k1[i] + k2[i]);
    err[i] = half * (k2[i] - k1[i]);
  }
}

// The coefficients come as plain arrays (a tableau's rows, b and b_low): std::array's operator[]
// is an inline function of external linkage that a compiler may leave out of line, and the AVX2
// kernel must emit none (acst/inline.hpp); the kernel passes its own copies of them.

// Stage s's state of an embedded Runge-Kutta step of size h from y: ys = y + sum_{j<s} (h a_sj) k_j
// (a_s: the tableau's row s), summed in the order of j. k(j, i): number i of stage j's rate (a
// lane reads its own where it lies, with no copy: the kernel's loops over lanes vectorise only as
// one straight body).
template <int N, class Rates>
ACST_INLINE void stage_state(const double* a_s, int s, double h, const double* __restrict y, const Rates& k,
                             double* __restrict ys) {
#pragma GCC unroll 13
  for (int i = 0; i < N; ++i) ys[i] = y[i];
  for (int j = 0; j < s; ++j) {
    const double a = h * a_s[j];
#pragma GCC unroll 13
    for (int i = 0; i < N; ++i) ys[i] += a * k(j, i);
  }
}

// The step's solution y_new = y + sum_s (h b_s) k_s and its error estimate
// err = sum_s (h (b_s - b_low_s)) k_s (from 0), summed in the order of the stages. A caller that
// knows the count names it as `Stages` too (the lanes, and the scalar integrator for modified
// Euler): the loop over stages must unroll before the kernel's loops over lanes vectorise, and a
// count read from the tableau, or passed as an argument, came too late for that (the kernel 4 %
// larger); in the scalar integrator it saves 1 % of an update's instructions.
template <int N, int Stages = 0, class Rates>
ACST_INLINE void step_solution(int tableau_stages, const double* b_of, const double* b_low_of, double h,
                               const double* __restrict y, const Rates& k, double* __restrict y_new,
                               double* __restrict err) {
  const int stages = Stages > 0 ? Stages : tableau_stages;
#pragma GCC unroll 13
  for (int i = 0; i < N; ++i) {
    y_new[i] = y[i];
    err[i] = 0.0;
  }

  for (int s = 0; s < stages; ++s) {
    const double b = h * b_of[s], e = h * (b_of[s] - b_low_of[s]);
#pragma GCC unroll 13
    for (int i = 0; i < N; ++i) {
      y_new[i] += b * k(s, i);
      err[i] += e * k(s, i);
    }
  }
}

}  // namespace acst::integration
