#pragma once
// Yield surface f = R/g(theta) - H and its loading direction n (docs/model.md section 5).
#include <algorithm>
#include <cmath>

#include "acst/lode.hpp"
#include "acst/tensor.hpp"

namespace acst {

// R = sqrt(3/2 r:r) of the stress-ratio tensor r = s/p (equals q/p in triaxial tests).
inline double stress_ratio_invariant(const Sym& r) { return std::sqrt(1.5 * contract(r, r)); }

inline double mean_stress(const Sym& sigma) { return trace(sigma) / 3.0; }

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
inline double yield_function(double R, double g, double H) { return R / g - H; }

// f = R/g(theta) - H from the stress alone, without the loading direction (the cheap check of
// every elastic trial). With d = dev(sigma): R = sqrt(3/2) |d|/|p| and r_hat = sign(p) d/|d|, so
// sin 3theta = sign(p) (-3 sqrt(6) det(d) / |d|^3) needs no tensor division (bench/RESULTS.md 1).
inline double yield_value(const Sym& sigma, const LodeShape& c, double R_tolerance, double H) {
  const double p = mean_stress(sigma);
  const Sym d = deviator(sigma);
  const double d_norm = norm(d);
  const double R = std::sqrt(1.5) * d_norm / std::abs(p);
  if (R < R_tolerance) return yield_function(R, lode_interpolation(c, 0.0).g, H);
  const double inv_norm = 1.0 / d_norm;
  const double s_raw = std::copysign(1.0, p) * (-3.0 * std::sqrt(6.0)) * determinant(d) * (inv_norm * inv_norm * inv_norm);
  return yield_function(R, lode_g(c, std::clamp(s_raw, -1.0, 1.0), d, std::copysign(inv_norm, p)), H);
}

// n = dev(N)/|dev(N)| with dev(N) = [sqrt(3/2)(g + 3 s g') r_hat + 9 g' (r_hat^2 - I/3)] / g^2,
// N = d(R/g)/dr, s = sin 3theta. Below R_tolerance, n is the unit deviatoric part of
// `fallback_direction` (the strain increment) and g is g(s = 0); n = 0 if that is zero too.
inline StressRatioState stress_ratio_state(const Sym& sigma, const LodeShape& c, double R_tolerance,
                                           const Sym& fallback_direction) {
  // Reciprocals computed once and multiplied: a tensor divided by a scalar is six divisions in a
  // serial chain of them, the cost of this function (bench/RESULTS.md section 1, proposal 4).
  StressRatioState st;
  st.r = deviator(sigma) * (1.0 / mean_stress(sigma));
  const double r_norm = norm(st.r);
  st.R = std::sqrt(1.5) * r_norm;
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
  const Sym r_hat = st.r * (1.0 / r_norm);
  const double s_raw = lode_sin3theta_unclamped(r_hat);
  st.lode_clamped = std::abs(s_raw) > 1.0 + 1e-10;
  st.sin3theta = std::clamp(s_raw, -1.0, 1.0);
  st.lode = lode_interpolation(c, st.sin3theta, r_hat, 1.0);
  const double g = st.lode.g, dg = st.lode.dg_ds;
  Sym devN = std::sqrt(1.5) * (g + 3.0 * st.sin3theta * dg) * r_hat + 9.0 * dg * deviator(square(r_hat));
  devN *= 1.0 / (g * g);
  st.dev_N_norm = norm(devN);
  st.n = devN * (1.0 / st.dev_N_norm);
  return st;
}

// df/dsigma = (|dev N| / p)(n - (n:r) I/3).
inline Sym yield_gradient(const StressRatioState& st, double p) {
  return st.dev_N_norm / p * (st.n - contract(st.n, st.r) / 3.0 * identity_tensor());
}

}  // namespace acst
