#pragma once
// Yield surface f = R/g(theta) - H and its loading direction n (docs/model.md section 5).
#include <cmath>

#include "acst/inline.hpp"
#include "acst/lode.hpp"
#include "acst/tensor.hpp"

namespace acst {

// R = sqrt(3/2 r:r) of the stress-ratio tensor r = s/p (equals q/p in triaxial tests).
inline double stress_ratio_invariant(const Sym& r) { return std::sqrt(1.5 * contract(r, r)); }

ACST_INLINE double mean_stress(const double* sigma) { return trace(sigma) / 3.0; }

inline double mean_stress(const Sym& sigma) { return mean_stress(sigma.data()); }

// r = s / p.
inline Sym stress_ratio_tensor(const Sym& sigma) { return deviator(sigma) / mean_stress(sigma); }

// Everything the yield function gives about the current stress ratio.
struct StressRatioState {
  Sym r;            // stress-ratio tensor s/p
  double R;         // sqrt(3/2 r:r)
  double sin3theta; // clamped to [-1, 1]
  LodeInterpolation lode;
  Sym n;            // unit deviatoric loading direction
  double dev_N_norm;  // |dev(d(R/g)/dr)|, scales df/dsigma
  bool small_R;       // R below tolerance: n taken from the strain increment
  bool lode_clamped;  // |sin3theta| exceeded 1 by more than round-off before clamping
};

// f = R/g - H.
ACST_INLINE double yield_function(double R, double g, double H) { return R / g - H; }

// The stress's part of the yield value, without the loading direction (the cheap check of every
// elastic trial): with d = dev(sigma) (into d), R = sqrt(3/2) |d|/|p| and r_hat = sign(p) d/|d|,
// so sin 3theta = sign(p) (-3 sqrt(6) det(d) / |d|^3) needs no tensor division;
// `scale` = sign(p)/|d| makes r_hat of d for the Lode function. sin3theta (clamped to
// [-1, 1]) and scale mean something only where R is not below R_tolerance.
struct YieldInvariants {
  double R, sin3theta, scale;
};

ACST_INLINE YieldInvariants yield_invariants(const double* sigma, double* d) {
  const double p = mean_stress(sigma);
  deviator(sigma, d);
  const double d_norm = norm(d);
  const double inv_norm = 1.0 / d_norm;
  const double s_raw = std::copysign(1.0, p) * (-3.0 * std::sqrt(6.0)) * determinant(d) * (inv_norm * inv_norm * inv_norm);
  return {std::sqrt(1.5) * d_norm / std::abs(p), clamp_of(s_raw, -1.0, 1.0), std::copysign(inv_norm, p)};
}

// f = R/g(theta) - H from the stress alone; below R_tolerance g is g(s = 0).
inline double yield_value(const Sym& sigma, const LodeShape& c, double R_tolerance, double H) {
  Sym d;
  const YieldInvariants v = yield_invariants(sigma.data(), d.data());
  const double g = v.R < R_tolerance ? lode_interpolation(c, 0.0).g : lode_g(c, v.sin3theta, d.data(), v.scale);
  return yield_function(v.R, g, H);
}

// r = s/p into r, by p's reciprocal: a tensor divided by a scalar is six divisions in a serial
// chain of them, which was the cost of the ratio state.
// Returns |r|.
ACST_INLINE double stress_ratio(const double* sigma, double* r) {
  deviator(sigma, r);
  scaled(r, 1.0 / mean_stress(sigma), r);
  return norm(r);
}

// R = sqrt(3/2) |r|.
ACST_INLINE double stress_ratio_invariant_of_norm(double r_norm) { return std::sqrt(1.5) * r_norm; }

// The Lode angle and the loading direction of the stress ratio r (|r| = r_norm, R not below
// R_tolerance): the state's sin3theta, lode_clamped, lode and dev_N_norm, and n (into n).
struct LoadingDirection {
  double sin3theta;
  int lode_clamped;  // 0 or 1 (an int: acst/inline.hpp)
  LodeInterpolation lode;
  double dev_N_norm;
};

// n = dev(N)/|dev(N)| with dev(N) = [sqrt(3/2)(g + 3 s g') r_hat + 9 g' (r_hat^2 - I/3)] / g^2,
// N = d(R/g)/dr, s = sin 3theta, r_hat = r/|r|; g and g' from lode(s, r_hat), the caller's Lode
// function.
template <class Lode>
ACST_INLINE LoadingDirection loading_direction(const double* r, double r_norm, Lode&& lode, double* n) {
  LoadingDirection dir;
  double r_hat[6];
  scaled(r, 1.0 / r_norm, r_hat);
  const double s_raw = lode_sin3theta_unclamped(r_hat);
  dir.lode_clamped = std::abs(s_raw) > 1.0 + 1e-10;
  dir.sin3theta = clamp_of(s_raw, -1.0, 1.0);
  dir.lode = lode(dir.sin3theta, r_hat);
  const double g = dir.lode.g, dg = dir.lode.dg_ds;
  double r_hat2[6], dev_r_hat2[6], devN[6];
  square(r_hat, r_hat2);
  deviator(r_hat2, dev_r_hat2);
  const double a = std::sqrt(1.5) * (g + 3.0 * dir.sin3theta * dg), b = 9.0 * dg, scale = 1.0 / (g * g);
#pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) devN[i] = (a * r_hat[i] + b * dev_r_hat2[i]) * scale;
  dir.dev_N_norm = norm(devN);
  scaled(devN, 1.0 / dir.dev_N_norm, n);
  return dir;
}

// The stress ratio state of sigma. Below R_tolerance, n is the unit deviatoric part of
// `fallback_direction` (the strain increment) and g is g(s = 0); n = 0 if that is zero too.
inline StressRatioState stress_ratio_state(const Sym& sigma, const LodeShape& c, double R_tolerance,
                                           const Sym& fallback_direction) {
  StressRatioState st;
  const double r_norm = stress_ratio(sigma.data(), st.r.data());
  st.R = stress_ratio_invariant_of_norm(r_norm);
  st.small_R = st.R < R_tolerance;
  st.lode_clamped = false;
  if (st.small_R) {
    st.sin3theta = 0.0;
    st.lode = lode_interpolation(c, 0.0);
    const Sym d = deviator(fallback_direction);
    const double dn = norm(d);
    st.n = dn > 0.0 ? Sym(d / dn) : Sym(Sym::Zero());
    st.dev_N_norm = std::sqrt(1.5) / st.lode.g;
    return st;
  }
  const LoadingDirection dir = loading_direction(
      st.r.data(), r_norm, [&c](double s, const double* r_hat) { return lode_interpolation(c, s, r_hat, 1.0); },
      st.n.data());
  st.sin3theta = dir.sin3theta;
  st.lode_clamped = dir.lode_clamped;
  st.lode = dir.lode;
  st.dev_N_norm = dir.dev_N_norm;
  return st;
}

// df/dsigma = (|dev N| / p)(n - (n:r) I/3) into grad.
ACST_INLINE void yield_gradient(double dev_N_norm, const double* n, const double* r, double p, double* grad) {
  const double scale = dev_N_norm / p, n_r3 = contract(n, r) / 3.0;
#pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) grad[i] = scale * (n[i] - n_r3 * (i < 3 ? 1.0 : 0.0));
}

inline Sym yield_gradient(const StressRatioState& st, double p) {
  Sym grad;
  yield_gradient(st.dev_N_norm, st.n.data(), st.r.data(), p, grad.data());
  return grad;
}

}  // namespace acst
