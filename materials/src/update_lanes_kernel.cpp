// The lanes' update (include/acst/update_lanes.hpp). Every expression below is the one of the
// scalar code it names, written out for one lane with its operands in the same order: with no
// contraction into FMA and no reassociation (the flags of this file, materials/CMakeLists.txt) and
// with IEEE division and square root, a lane rounds exactly as the scalar code does. pow and exp
// are called once per lane, outside the vector loops, as the scalar code calls them. A change of
// a formula in the model's headers must be made here too: tests/materials/update_lanes_test.cpp compares
// the two bit for bit over states of every kind.
#include <cmath>
#include <limits>

#include "acst/parameters.hpp"
#include "update_lanes_kernel.hpp"

#ifndef ACST_LANES_TARGET
#error "ACST_LANES_TARGET names the instruction set this copy of the kernel is built for"
#endif

// Every helper is inlined into the vector loops and every loop over components unrolled, and
// conditions are joined with & and | rather than && and || (no branch each): the loops over lanes
// vectorise only as one straight body.
#define ACST_LANE inline __attribute__((always_inline))

namespace acst::lanes::ACST_LANES_TARGET {
namespace {

constexpr int W = UpdateLanes::width;

// std::min, std::max and std::clamp as the standard defines them (which operand wins a tie or a
// NaN matters for the bits).
ACST_LANE double min_of(double a, double b) { return b < a ? b : a; }
ACST_LANE double max_of(double a, double b) { return a < b ? b : a; }
ACST_LANE double clamp_of(double v, double lo, double hi) { return v < lo ? lo : (hi < v ? hi : v); }
ACST_LANE int finite(double x) { return std::abs(x) <= std::numeric_limits<double>::max(); }

// tensor.hpp
ACST_LANE double trace(const double* a) { return a[0] + a[1] + a[2]; }
ACST_LANE double contract(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2.0 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}
ACST_LANE double norm(const double* a) { return std::sqrt(contract(a, a)); }
ACST_LANE void deviator(const double* a, double* d) {
  const double m = trace(a) / 3.0;
  d[0] = a[0] - m;
  d[1] = a[1] - m;
  d[2] = a[2] - m;
  d[3] = a[3];
  d[4] = a[4];
  d[5] = a[5];
}
ACST_LANE double determinant(const double* a) {
  return a[0] * (a[1] * a[2] - a[5] * a[5]) - a[3] * (a[3] * a[2] - a[5] * a[4]) + a[4] * (a[3] * a[5] - a[1] * a[4]);
}
ACST_LANE void square(const double* a, double* s) {
  s[0] = a[0] * a[0] + a[3] * a[3] + a[4] * a[4];
  s[1] = a[3] * a[3] + a[1] * a[1] + a[5] * a[5];
  s[2] = a[4] * a[4] + a[5] * a[5] + a[2] * a[2];
  s[3] = a[0] * a[3] + a[3] * a[1] + a[4] * a[5];
  s[4] = a[0] * a[4] + a[3] * a[5] + a[4] * a[2];
  s[5] = a[3] * a[4] + a[1] * a[5] + a[5] * a[2];
}
ACST_LANE double mean_stress(const double* s) { return trace(s) / 3.0; }

struct Lode {
  double g, dg;
};

// lode.hpp, Li's form.
ACST_LANE Lode li_interpolation(double c, double s) {
  const double a = 1.0 + c * c;
  const double b = 4.0 * c * (1.0 - c * c);
  const double root = std::sqrt(max_of(a * a + b * s, 1e-300));
  const double g = 2.0 * c * (1.0 + c) / (a + root);
  const double dg_ds = -g * b / (2.0 * root * (a + root));
  return {g, dg_ds};
}

// lode.cpp: cosine_from_principal_values; the caller has checked a[3] != 0, a[4] = a[5] = 0.
ACST_LANE double ww_cosine(const double* a, double scale) {
  const double m = 0.5 * (a[0] + a[1]), d = 0.5 * (a[0] - a[1]);
  const double radius = std::sqrt(d * d + a[3] * a[3]);
  const double lowest = scale > 0.0 ? min_of(a[2], m - radius) : max_of(a[2], m + radius);
  return clamp_of(-std::sqrt(1.5) * scale * lowest, 0.5, 1.0);
}

// lode.cpp: willam_warnke_quotient and willam_warnke_at.
ACST_LANE Lode ww_at(double c, double x, bool with_derivative) {
  const double a = 1.0 - c * c, b = 2.0 * c - 1.0;
  const double root = std::sqrt(max_of(4.0 * a * x * x + 5.0 * c * c - 4.0 * c, 0.0));
  const double num = 2.0 * a * x + b * root, den = 4.0 * a * x * x + b * b;
  const double g = num / den;
  if (!with_derivative) return {g, 0.0};
  const double delta = x - 0.5;
  const double b2 = b * b;
  const double near = -a / (3.0 * b2) + delta * a * (2.0 - c) * (2.0 - c) / (3.0 * b2 * b2);
  const double dnum = 2.0 * a + (root > 0.0 ? b * 4.0 * a * x / root : 0.0), dden = 8.0 * a * x;
  const double dg_dx = (dnum * den - num * dden) / (den * den);
  const double far = dg_dx / (12.0 * delta * (x + 0.5));
  return {g, delta < 1e-6 ? near : far};
}

ACST_LANE bool plane_shear(const double* a) { return (a[3] != 0.0) & (a[4] == 0.0) & (a[5] == 0.0); }

// The Lode function of the unit deviator scale a (lode.hpp's lode_interpolation and lode_g);
// `general` is set where Willam & Warnke's angle would need acos (not a lane's work).
template <bool WW>
ACST_LANE Lode lode(const Constants& k, double s, const double* a, double scale, bool with_derivative, int& general) {
  if constexpr (!WW) return li_interpolation(k.c, s);
  if constexpr (WW) {
    general |= !plane_shear(a);
    return ww_at(k.c, ww_cosine(a, scale), with_derivative);
  }
}

// yield_function.hpp: yield_value. `unusable` is set below R_tolerance (g at s = 0) and where
// the Lode function is not a lane's.
template <bool WW>
ACST_LANE double yield_value(const Constants& k, const double* sigma, double H, int& unusable) {
  const double p = mean_stress(sigma);
  double d[6];
  deviator(sigma, d);
  const double d_norm = norm(d);
  const double R = std::sqrt(1.5) * d_norm / std::abs(p);
  unusable |= R < k.R_tolerance;
  const double inv_norm = 1.0 / d_norm;
  const double s_raw = std::copysign(1.0, p) * (-3.0 * std::sqrt(6.0)) * determinant(d) * (inv_norm * inv_norm * inv_norm);
  const double g = lode<WW>(k, clamp_of(s_raw, -1.0, 1.0), d, std::copysign(inv_norm, p), false, unusable).g;
  return R / g - H;
}

// yield_function.hpp: stress_ratio_state, for R >= R_tolerance (`unusable` set otherwise).
struct Ratio {
  double r[6], R, s, g, dg_ds, n[6], dev_N_norm;
  int clamped;
};

template <bool WW>
ACST_LANE Ratio ratio_state(const Constants& k, const double* sigma, int& unusable) {
  Ratio st;
  double d[6];
  deviator(sigma, d);
  const double ip = 1.0 / mean_stress(sigma);
  #pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) st.r[i] = d[i] * ip;
  const double r_norm = norm(st.r);
  st.R = std::sqrt(1.5) * r_norm;
  unusable |= st.R < k.R_tolerance;
  double r_hat[6];
  const double inv = 1.0 / r_norm;
  #pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) r_hat[i] = st.r[i] * inv;
  const double s_raw = -std::sqrt(6.0) * 3.0 * determinant(r_hat);
  st.clamped = std::abs(s_raw) > 1.0 + 1e-10;
  st.s = clamp_of(s_raw, -1.0, 1.0);
  const Lode l = lode<WW>(k, st.s, r_hat, 1.0, true, unusable);
  st.g = l.g;
  st.dg_ds = l.dg;
  double sq[6], dsq[6];
  square(r_hat, sq);
  deviator(sq, dsq);
  const double a = std::sqrt(1.5) * (st.g + 3.0 * st.s * st.dg_ds), b = 9.0 * st.dg_ds;
  const double scale = 1.0 / (st.g * st.g);
  double devN[6];
  #pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) devN[i] = (a * r_hat[i] + b * dsq[i]) * scale;
  st.dev_N_norm = norm(devN);
  const double inv_N = 1.0 / st.dev_N_norm;
  #pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) st.n[i] = devN[i] * inv_N;
  return st;
}

// elasticity.hpp: shear_modulus and bulk_modulus.
ACST_LANE double shear_modulus(const Constants& k, double e, double p) {
  const double pa = atmospheric_pressure;
  const double d = void_ratio_limit - e;
  return k.G0 * pa * d * d / (1.0 + e) * std::sqrt(max_of(p, k.p_min) / pa);
}
ACST_LANE double bulk_modulus(double G, double nu) { return G * 2.0 * (1.0 + nu) / (3.0 * (1.0 - 2.0 * nu)); }

// elasticity.hpp: isotropic_stress_increment.
ACST_LANE void isotropic_stress_increment(double G, double K, const double* deps, double* ds) {
  const double dev_v = trace(deps);
  double d[6];
  deviator(deps, d);
  #pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) ds[i] = 2.0 * G * d[i];
  ds[0] += K * dev_v;
  ds[1] += K * dev_v;
  ds[2] += K * dev_v;
}

// One lane's copy of a 13-component vector (stress, fabric, void ratio) of the integrator.
struct Vec {
  double v[13];
};

ACST_LANE Vec load(const double (&a)[6][W], const double (&b)[6][W], const double (&e)[W], int l) {
  Vec y;
  #pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) y.v[i] = a[i][l];
  #pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) y.v[6 + i] = b[i][l];
  y.v[12] = e[l];
  return y;
}

struct Strain {
  double v[6];
  operator const double*() const { return v; }  // NOLINT(google-explicit-constructor): read as an array
};

ACST_LANE Strain load(const double (&a)[6][W], int l) {
  Strain d;
  #pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) d.v[i] = a[i][l];
  return d;
}

// Per lane, what a rate evaluation needs across the pow and exp calls, lane-minor as the vector
// loops read and write it.
struct Stage {
  double r[6][W], R[W], g[W], n[6][W];
  int clamped[W];
  double G[W], K[W], A[W], pressure_ratio[W], peak_pressure_ratio[W];
  double exp_m_zeta[W], exp_n_zeta[W];
  int h_floored[W];
};

// acst_rates.hpp plastic_quantities up to its pow (p, the moduli, A), with the ratio state at y.
ACST_LANE void quantities_before_pow(const Constants& k, const double* y, const Ratio& ratio, Stage& st, int l) {
  #pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) {
    st.r[i][l] = ratio.r[i];
    st.n[i][l] = ratio.n[i];
  }
  st.R[l] = ratio.R;
  st.g[l] = ratio.g;
  st.clamped[l] = ratio.clamped;
  const double p = mean_stress(y);
  const double e = y[12];
  const double G = shear_modulus(k, e, p);
  st.G[l] = G;
  st.K[l] = bulk_modulus(G, k.nu);
  st.A[l] = contract(y + 6, ratio.n);
  st.pressure_ratio[l] = max_of(p, 0.0) / atmospheric_pressure;
  st.peak_pressure_ratio[l] = max_of(p, k.p_min) / atmospheric_pressure;
}

// The calls to pow and exp, one per lane, as critical_state.hpp, dilatancy.hpp and
// plastic_modulus.hpp make them.
// Lanes off the plastic route (`active` 0) skip the calls: a fifth of a footing's updates are
// elastic.
void transcendental(const Constants& k, const double (&e)[W], const int (&active)[W], Stage& st) {
  for (int l = 0; l < W; ++l) {
    if (!active[l]) {
      st.exp_m_zeta[l] = st.exp_n_zeta[l] = 0.0;
      continue;
    }
    const double psi = e[l] - (k.e_Gamma - k.lambda_c * std::pow(st.pressure_ratio[l], k.xi));
    const double zeta = psi - k.e_A * (st.A[l] - 1.0);
    const double n = k.beta == 0.0 ? k.n : k.n * std::pow(st.peak_pressure_ratio[l], k.beta);
    st.exp_m_zeta[l] = std::exp(k.m * zeta);
    st.exp_n_zeta[l] = std::exp(-n * zeta);
  }
}

// acst_rates.hpp plastic_rate after the pow and exp: dy at y for deps; `unusable` where the
// loading index's denominator is not positive or dy is not finite.
ACST_LANE void rate_after_pow(const Constants& k, const double* y, const double* deps, const Stage& st, int l, double* dy,
                           int& unusable, int& h_floored) {
  double r[6], n[6];
  #pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) {
    r[i] = st.r[i][l];
    n[i] = st.n[i][l];
  }
  const double e = y[12];
  const double g = st.g[l];
  const double R = max_of(st.R[l], k.R_tolerance);
  const double D = k.d1 * (st.exp_m_zeta[l] - st.R[l] / (k.Mc * g));
  const double h_raw = k.h1 - k.h2 * e;
  h_floored = h_raw < k.h_min;
  const double h = h_floored ? k.h_min : h_raw;
  const double G = st.G[l], K = st.K[l];
  const double Kp = G * h * (k.Mc * g * st.exp_n_zeta[l] / R - 1.0);
  const double n_r = contract(n, r);
  const double numerator = 2.0 * G * contract(n, deps) - K * n_r * trace(deps);
  const double denominator = Kp + 2.0 * G - std::sqrt(2.0 / 3.0) * K * D * n_r;
  unusable |= !(denominator > 0.0);
  const double load_index = numerator > 0.0 ? numerator / denominator : 0.0;
  double dsig[6], a[6];
  isotropic_stress_increment(G, K, deps, dsig);
  #pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) a[i] = 2.0 * G * n[i];
  const double volumetric = std::sqrt(2.0 / 3.0) * K * D;
  a[0] += volumetric;
  a[1] += volumetric;
  a[2] += volumetric;
  #pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) dy[i] = dsig[i] - load_index * a[i];
  #pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) dy[6 + i] = load_index * (k.k_f * (n[i] - y[6 + i]));
  dy[12] = -(1.0 + e) * trace(deps);
  bool all = true;
  #pragma GCC unroll 13
  for (int i = 0; i < 13; ++i) all = all & finite(dy[i]);
  unusable |= !all;
}

// acst_rates.hpp admissibility (none) and Material::update's physical(), on y.
ACST_LANE int admissible(const Constants& k, const double* y) {
  bool all = true;
  #pragma GCC unroll 13
  for (int i = 0; i < 13; ++i) all = all & finite(y[i]);
  return all & (y[12] > 0.0) & (y[12] < void_ratio_limit) & (mean_stress(y) >= k.p_min);
}

// acst_rates.hpp relative_error.
ACST_LANE double relative_error(const Constants& k, const double* y_new, const double* err) {
  const double es = norm(err) / max_of(norm(y_new), k.p_min);
  const double ef = norm(err + 6) / max_of(norm(y_new + 6), 1e-2);
  const double ee = std::abs(err[12]) / (1.0 + y_new[12]);
  return max_of(es, max_of(ef, ee));
}

template <bool WW>
void run(const Constants& k, UpdateLanes& L) {
  int ok[W], elastic_done[W];
  double k0[13][W];
  Stage start, end;
  const bool no_hint = !k.reuse_last_substep;
  // The elastic test of ExplicitSubstepping::integrate and its elastic route, and the plastic
  // route's first rate up to its pow.
  for (int l = 0; l < W; ++l) {
    const Vec y = load(L.stress, L.fabric, L.void_ratio, l);
    const Strain deps = load(L.strain_increment, l);
    // Material::update's entry checks and hint; a hint below 1 starts with a short substep.
    bool entry = finite(L.H[l]) & (L.H[l] >= 0.0);
    #pragma GCC unroll 13
    for (int i = 0; i < 13; ++i) entry = entry & finite(y.v[i]);
    #pragma GCC unroll 13
    for (int i = 0; i < 6; ++i) entry = entry & finite(deps[i]);
    entry = entry & (y.v[12] > 0.0) & (y.v[12] < void_ratio_limit);
    // Material::update takes a hint that is no step size as 1, and a hint of 1 or more
    // starts with the whole increment (the substep is clamped to 1).
    const double hint = L.substep_hint[l];
    const bool hint_usable = finite(hint) & (hint > 0.0);
    const bool whole_first_substep = no_hint | (hint >= 1.0) | !hint_usable;
    // The elastic rate k1, f0 and the unloading cosine (computed on the surface only).
    const double p = mean_stress(y.v);
    const double G = shear_modulus(k, y.v[12], p);
    double k1[13];
    isotropic_stress_increment(G, bulk_modulus(G, k.nu), deps, k1);
    #pragma GCC unroll 13
    for (int i = 6; i < 12; ++i) k1[i] = 0.0;
    k1[12] = -(1.0 + y.v[12]) * trace(deps);
    int f0_unusable = 0, ratio_unusable = 0;
    const double f0 = yield_value<WW>(k, y.v, L.H[l], f0_unusable);
    const bool on_surface = f0 >= -k.ftol;
    const Ratio ratio = ratio_state<WW>(k, y.v, ratio_unusable);
    double grad[6];
    const double scale = ratio.dev_N_norm / p, n_r3 = contract(ratio.n, ratio.r) / 3.0;
    #pragma GCC unroll 13
    for (int i = 0; i < 6; ++i) grad[i] = scale * (ratio.n[i] - n_r3 * (i < 3 ? 1.0 : 0.0));
    const double den = norm(grad) * norm(k1);
    const double cosine = den > 0.0 ? contract(grad, k1) / den : 0.0;
    const bool loading = cosine > k.ltol;
    // The plastic route up to its first rate (with plastic_rate's pressure guard).
    ok[l] = entry & whole_first_substep & on_surface & loading & (p >= k.p_min) & !f0_unusable & !ratio_unusable;
    quantities_before_pow(k, y.v, ratio, start, l);
    // The elastic route: inside the surface, or on it and not loading it; one Heun step
    // (heun_step) whose end stays inside and within STOL.
    const bool elastic = entry & !f0_unusable & ((!on_surface) | (!ratio_unusable & !loading));
    double y1[13], k2[13], y_el[13], err[13];
    #pragma GCC unroll 13
    for (int i = 0; i < 13; ++i) y1[i] = y.v[i] + 1.0 * k1[i];
    const double G1 = shear_modulus(k, y1[12], mean_stress(y1));
    isotropic_stress_increment(G1, bulk_modulus(G1, k.nu), deps, k2);
    #pragma GCC unroll 13
    for (int i = 6; i < 12; ++i) k2[i] = 0.0;
    k2[12] = -(1.0 + y1[12]) * trace(deps);
    #pragma GCC unroll 13
    for (int i = 0; i < 13; ++i) {
      y_el[i] = y.v[i] + 0.5 * (k1[i] + k2[i]);
      err[i] = 0.5 * (k2[i] - k1[i]);
    }
    const double error = relative_error(k, y_el, err);
    int trial_unusable = 0;
    const double f_trial = yield_value<WW>(k, y_el, L.H[l], trial_unusable);
    const bool elastic_lane = elastic & !trial_unusable & (f_trial <= k.ftol) & finite(error) &
                              !(max_of(error, 1e-16) > k.stol) & admissible(k, y_el) & (l < L.n);
    elastic_done[l] = elastic_lane;
    #pragma GCC unroll 13
    for (int i = 0; i < 6; ++i) L.stress[i][l] = elastic_lane ? y_el[i] : L.stress[i][l];
    #pragma GCC unroll 13
    for (int i = 0; i < 6; ++i) L.fabric[i][l] = elastic_lane ? y_el[6 + i] : L.fabric[i][l];
    L.void_ratio[l] = elastic_lane ? y_el[12] : L.void_ratio[l];
    L.substep_hint[l] = (elastic_lane & !hint_usable) ? 1.0 : hint;
  }
  int plastic_lanes = 0;
  for (int l = 0; l < W; ++l) plastic_lanes += ok[l];
  if (plastic_lanes == 0) {  // elastic lanes only (or none): the rest is the plastic route's
    for (int l = 0; l < W; ++l) {
      L.done[l] = elastic_done[l];
      L.plastic[l] = L.guard_lode_clamp[l] = L.guard_h_floor[l] = 0;
    }
    return;
  }
  transcendental(k, L.void_ratio, ok, start);
  double ys_e[W];
  // The first rate; the second stage's state y + k0 and its rate up to the pow.
  for (int l = 0; l < W; ++l) {
    const Vec y = load(L.stress, L.fabric, L.void_ratio, l);
    const Strain deps = load(L.strain_increment, l);
    int unusable = 0;
    double dy[13];
    rate_after_pow(k, y.v, deps, start, l, dy, unusable, start.h_floored[l]);
    Vec ys;
    #pragma GCC unroll 13
    for (int i = 0; i < 13; ++i) {
      k0[i][l] = dy[i];
      ys.v[i] = y.v[i] + 1.0 * dy[i];
    }
    unusable |= !(mean_stress(ys.v) >= k.p_min);
    quantities_before_pow(k, ys.v, ratio_state<WW>(k, ys.v, unusable), end, l);
    ys_e[l] = ys.v[12];
    ok[l] = ok[l] & !unusable;
  }
  transcendental(k, ys_e, ok, end);
  // The second rate, the step and its error, the checks and the drift-free H.
  for (int l = 0; l < W; ++l) {
    const Vec y = load(L.stress, L.fabric, L.void_ratio, l);
    const Strain deps = load(L.strain_increment, l);
    int unusable = 0;
    Vec ys;
    #pragma GCC unroll 13
    for (int i = 0; i < 13; ++i) ys.v[i] = y.v[i] + 1.0 * k0[i][l];
    double k1[13];
    rate_after_pow(k, ys.v, deps, end, l, k1, unusable, end.h_floored[l]);
    double y_new[13], err[13];
    #pragma GCC unroll 13
    for (int i = 0; i < 13; ++i) {
      y_new[i] = (y.v[i] + 0.5 * k0[i][l]) + 0.5 * k1[i];
      err[i] = (0.0 + -0.5 * k0[i][l]) + 0.5 * k1[i];
    }
    const double measured = relative_error(k, y_new, err);
    const bool accepted = admissible(k, y_new) & finite(measured) & !(max_of(measured, 1e-16) > k.stol);
    const double H = yield_value<WW>(k, y_new, 0.0, unusable);
    const bool done = ok[l] & accepted & !unusable & finite(H) & (H >= 0.0) & (l < L.n);
    L.done[l] = done | elastic_done[l];
    L.plastic[l] = done;
    L.guard_lode_clamp[l] = start.clamped[l] + end.clamped[l];
    L.guard_h_floor[l] = start.h_floored[l] + end.h_floored[l];
    // Written back only where done (a select: each lane owns its slots).
    #pragma GCC unroll 13
    for (int i = 0; i < 6; ++i) L.stress[i][l] = done ? y_new[i] : L.stress[i][l];
    #pragma GCC unroll 13
    for (int i = 0; i < 6; ++i) L.fabric[i][l] = done ? y_new[6 + i] : L.fabric[i][l];
    L.void_ratio[l] = done ? y_new[12] : L.void_ratio[l];
    L.H[l] = done ? H : L.H[l];
    L.substep_hint[l] = done ? 1.0 : L.substep_hint[l];
  }
}

}  // namespace

void update(const Constants& k, UpdateLanes& lanes) {
  if (k.willam_warnke)
    run<true>(k, lanes);
  else
    run<false>(k, lanes);
}

}  // namespace acst::lanes::ACST_LANES_TARGET
