// The lanes' update (include/acst/update_lanes.hpp). Its formulas are the model's own functions,
// the ones Material::update calls (the headers' ACST_INLINE forms, acst/inline.hpp), and so are
// the integrator's two steps, Heun's and one modified-Euler substep (integration/steps.hpp, which
// integration/explicit_substepping.hpp calls): what this file writes is the lanes' own part, which
// lanes take which route (the entry checks, the tests of the elastic and the plastic route, the
// flags of lanes that are left for Material::update), the loads and stores lane by lane, and the
// calls to pow and exp, once per lane outside the vector loops as the scalar code calls them.
// With no contraction into FMA and no reassociation (the flags of this file,
// materials/CMakeLists.txt) and with IEEE division and square root, a lane rounds exactly as the
// scalar code does: tests/materials/update_lanes_test.cpp compares the two bit for bit over states
// of every kind.
#include <cmath>
#include <limits>

#include "acst/acst_rates.hpp"
#include "acst/integration/steps.hpp"
#include "update_lanes_kernel.hpp"

#ifndef ACST_LANES_TARGET
#error "ACST_LANES_TARGET names the instruction set this copy of the kernel is built for"
#endif

// Every helper is forced inline into the vector loops (ACST_INLINE, as the model's functions are)
// and every loop over components unrolled, and conditions are joined with & and | rather than &&
// and || (no branch each): the loops over lanes vectorise only as one straight body.

namespace acst::lanes::ACST_LANES_TARGET {
namespace {

constexpr int W = UpdateLanes::width;

// The plastic route's scheme: one substep of modified Euler, whose stages and solution the steps
// of the scalar integrator form (integration/steps.hpp). Its coefficients copied here at compile
// time, with internal linkage: a reference to the tableau would make this AVX2 object emit it
// and std::array's accessors (acst/inline.hpp; lanes_kernel_symbols).
constexpr int me_stages = integration::modified_euler_tableau.stages;
constexpr double me_a1[1] = {integration::modified_euler_tableau.a[1][0]};
constexpr double me_b[2] = {integration::modified_euler_tableau.b[0], integration::modified_euler_tableau.b[1]};
constexpr double me_b_low[2] = {integration::modified_euler_tableau.b_low[0],
                                integration::modified_euler_tableau.b_low[1]};
static_assert(me_stages == 2);

ACST_INLINE int finite(double x) { return std::abs(x) <= std::numeric_limits<double>::max(); }

// The Lode function of the unit deviator scale a (lode.hpp's lode_interpolation); `general` is
// set where Willam & Warnke's angle would need acos (not a lane's work).
template <bool WW>
ACST_INLINE LodeInterpolation lode(const Constants& k, double sin3theta, const double* a, double scale, int& general) {
  if constexpr (!WW) return lode_interpolation(k.p.c, sin3theta);
  if constexpr (WW) {
    general |= !plane_shear(a);
    return willam_warnke_at(k.p.c, cosine_from_principal_values(a, scale));
  }
}

// yield_function.hpp's yield_value; `unusable` is set below R_tolerance (g at s = 0) and where
// the Lode function is not a lane's.
template <bool WW>
ACST_INLINE double yield_value(const Constants& k, const double* sigma, double H, int& unusable) {
  double d[6];
  const YieldInvariants v = yield_invariants(sigma, d);
  unusable |= v.R < k.p.R_tolerance;
  return yield_function(v.R, lode<WW>(k, v.sin3theta, d, v.scale, unusable).g, H);
}

// yield_function.hpp's stress_ratio_state, for R >= R_tolerance (`unusable` set otherwise).
struct Ratio {
  double r[6], R, n[6];
  LoadingDirection direction;
};

template <bool WW>
ACST_INLINE Ratio ratio_state(const Constants& k, const double* sigma, int& unusable) {
  Ratio st;
  const double r_norm = stress_ratio(sigma, st.r);
  st.R = stress_ratio_invariant_of_norm(r_norm);
  unusable |= st.R < k.p.R_tolerance;
  st.direction = loading_direction(
      st.r, r_norm,
      [&](double s, const double* r_hat) __attribute__((always_inline)) { return lode<WW>(k, s, r_hat, 1.0, unusable); },
      st.n);
  return st;
}

// One lane's copy of a 13-component vector (stress, fabric, void ratio) of the integrator.
struct Vec {
  double v[13];
};

ACST_INLINE Vec load(const double (&a)[6][W], const double (&b)[6][W], const double (&e)[W], int l) {
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

ACST_INLINE Strain load(const double (&a)[6][W], int l) {
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
ACST_INLINE void quantities_before_pow(const Constants& k, const double* y, const Ratio& ratio, Stage& st, int l) {
  #pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) {
    st.r[i][l] = ratio.r[i];
    st.n[i][l] = ratio.n[i];
  }
  st.R[l] = ratio.R;
  st.g[l] = ratio.direction.lode.g;
  st.clamped[l] = ratio.direction.lode_clamped;
  const double p = mean_stress(y);
  const double G = shear_modulus(k.p.G0, k.p.p_min, y[12], p);
  st.G[l] = G;
  st.K[l] = bulk_modulus(G, k.p.nu);
  st.A[l] = fabric_anisotropy_variable(y + 6, ratio.n);
  st.pressure_ratio[l] = normalised_pressure(p, 0.0);
  st.peak_pressure_ratio[l] = normalised_pressure(p, k.p.p_min);
}

// plastic_quantities' pow and exp calls, one per lane (zeta and n with them).
// Lanes off the plastic route (`active` 0) skip the calls: a fifth of a footing's updates are
// elastic.
void transcendental(const Constants& k, const double (&e)[W], const double (&offset)[W], const int (&active)[W],
                    Stage& st) {
  for (int l = 0; l < W; ++l) {
    if (!active[l]) {
      st.exp_m_zeta[l] = st.exp_n_zeta[l] = 0.0;
      continue;
    }
    const double e_c = critical_void_ratio(k.p.e_Gamma, k.p.lambda_c, k.p.xi, st.pressure_ratio[l]);
    const double psi = nonlocal_state_parameter(state_parameter(e[l], e_c), offset[l]);
    const double zeta = dilatancy_state_parameter(psi, k.p.e_A, st.A[l]);
    st.exp_m_zeta[l] = dilatancy_exponential(k.p.m, zeta);
    st.exp_n_zeta[l] = peak_exponential(peak_state_coefficient(k.p.n, k.p.peak_pressure_exponent, st.peak_pressure_ratio[l]), zeta);
  }
}

// acst_rates.hpp plastic_rate after the pow and exp: dy at y for deps; `unusable` where the
// loading index's denominator is not positive or dy is not finite.
ACST_INLINE void rate_after_pow(const Constants& k, const double* y, const double* deps, const Stage& st, int l,
                                double* dy, int& unusable, int& h_floored) {
  double r[6], n[6];
  #pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) {
    r[i] = st.r[i][l];
    n[i] = st.n[i][l];
  }
  const double e = y[12], g = st.g[l], G = st.G[l], K = st.K[l];
  const double D = dilatancy_of_exponential(k.p.d1, st.exp_m_zeta[l], st.R[l], k.p.Mc, g);
  const FlooredHardening h = floored_hardening_coefficient(k.p.h1, k.p.h2, k.p.h_min, e);
  h_floored = h.floored;
  const double R = plastic_modulus_stress_ratio(st.R[l], k.p.R_tolerance);
  const double Kp = plastic_modulus_of_exponential(G, h.h, k.p.Mc, g, st.exp_n_zeta[l], R);
  const LoadingIndexTerms L = isotropic_loading_index_terms(G, K, Kp, D, n, contract(n, r), deps);
  unusable |= !(L.denominator > 0.0);
  double elastic[6], relaxed[6];
  isotropic_stress_increment(G, K, deps, elastic);
  isotropic_plastic_stress_direction(G, K, D, n, relaxed);
  plastic_rate_of(elastic, loading_index(L), relaxed, k.p.k_f, n, y + 6, e, deps, dy);
  bool all = true;
  #pragma GCC unroll 13
  for (int i = 0; i < 13; ++i) all = all & finite(dy[i]);
  unusable |= !all;
}

// acst_rates.hpp admissibility (none) and Material::update's physical(), on y.
ACST_INLINE int admissible(const Constants& k, const double* y) {
  const int void_ratio = void_ratio_admissible(y[12]);
  bool all = true;
  #pragma GCC unroll 13
  for (int i = 0; i < 13; ++i) all = all & finite(y[i]);
  return all & void_ratio & stress_within_limit(y) & (mean_stress(y) >= k.p.p_min);
}

template <bool WW>
void run(const Constants& k, UpdateLanes& L) {
  int ok[W], elastic_done[W];
  double k0[13][W];
  Stage start, end;
  const bool no_hint = !k.o.reuse_last_substep;
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
    entry = entry & void_ratio_admissible(y.v[12]) & stress_within_limit(y.v) &
            (std::abs(L.void_ratio_offset[l]) < void_ratio_limit);
    // Material::update takes a hint that is no step size as 1, and a hint of 1 or more
    // starts with the whole increment (the substep is clamped to 1).
    const double hint = L.substep_hint[l];
    const bool hint_usable = finite(hint) & (hint > 0.0);
    const bool whole_first_substep = no_hint | (hint >= 1.0) | !hint_usable;
    // The elastic rate k1, f0 and the unloading cosine (computed on the surface only).
    double k1[13];
    isotropic_elastic_rate(k.p.G0, k.p.p_min, k.p.nu, y.v, deps, k1);
    int f0_unusable = 0, ratio_unusable = 0;
    const double f0 = yield_value<WW>(k, y.v, L.H[l], f0_unusable);
    const bool on_surface = f0 >= -k.o.ftol;
    const Ratio ratio = ratio_state<WW>(k, y.v, ratio_unusable);
    const double p = mean_stress(y.v);
    double grad[6];
    yield_gradient(ratio.direction.dev_N_norm, ratio.n, ratio.r, p, grad);
    const bool loading = cosine_between(grad, k1) > k.o.ltol;
    // The plastic route up to its first rate (with plastic_rate's pressure guard).
    ok[l] = entry & whole_first_substep & on_surface & loading & (p >= k.p.p_min) & !f0_unusable & !ratio_unusable;
    quantities_before_pow(k, y.v, ratio, start, l);
    // The elastic route: inside the surface, or on it and not loading it; one Heun step
    // (heun_step) whose end stays inside and within STOL.
    const bool elastic = entry & !f0_unusable & ((!on_surface) | (!ratio_unusable & !loading));
    double y1[13], k2[13], y_el[13], err[13];
    integration::euler_predictor<13>(y.v, k1, 1.0, y1);
    isotropic_elastic_rate(k.p.G0, k.p.p_min, k.p.nu, y1, deps, k2);
    integration::heun_combination<13>(y.v, k1, k2, 1.0, y_el, err);
    const double error = relative_error(k.p.p_min, y_el, err);
    int trial_unusable = 0;
    const double f_trial = yield_value<WW>(k, y_el, L.H[l], trial_unusable);
    const bool elastic_lane = elastic & !trial_unusable & (f_trial <= k.o.ftol) & finite(error) &
                              !(max_of(error, 1e-16) > k.o.stol) & admissible(k, y_el) & (l < L.n);
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
  transcendental(k, L.void_ratio, L.void_ratio_offset, ok, start);
  double ys_e[W];
  // The first rate; the second stage's state y + k0 and its rate up to the pow.
  for (int l = 0; l < W; ++l) {
    const Vec y = load(L.stress, L.fabric, L.void_ratio, l);
    const Strain deps = load(L.strain_increment, l);
    int unusable = 0;
    double dy[13];
    rate_after_pow(k, y.v, deps, start, l, dy, unusable, start.h_floored[l]);
    #pragma GCC unroll 13
    for (int i = 0; i < 13; ++i) k0[i][l] = dy[i];
    Vec ys;
    integration::stage_state<13>(me_a1, 1, 1.0, y.v, [&](int, int i) __attribute__((always_inline)) { return dy[i]; },
                                 ys.v);
    unusable |= !(mean_stress(ys.v) >= k.p.p_min);
    quantities_before_pow(k, ys.v, ratio_state<WW>(k, ys.v, unusable), end, l);
    ys_e[l] = ys.v[12];
    ok[l] = ok[l] & !unusable;
  }
  transcendental(k, ys_e, L.void_ratio_offset, ok, end);
  // The second rate, the step and its error, the checks and the drift-free H.
  for (int l = 0; l < W; ++l) {
    const Vec y = load(L.stress, L.fabric, L.void_ratio, l);
    const Strain deps = load(L.strain_increment, l);
    int unusable = 0;
    double k1[13];
    // Stage j's rate: k0 (lane-minor) or k1.
    const auto rates = [&](int j, int i) __attribute__((always_inline)) { return j == 0 ? k0[i][l] : k1[i]; };
    Vec ys;
    integration::stage_state<13>(me_a1, 1, 1.0, y.v, rates, ys.v);
    rate_after_pow(k, ys.v, deps, end, l, k1, unusable, end.h_floored[l]);
    double y_new[13], err[13];
    integration::step_solution<13, me_stages>(me_stages, me_b, me_b_low, 1.0, y.v, rates, y_new, err);
    const double measured = relative_error(k.p.p_min, y_new, err);
    const bool accepted = admissible(k, y_new) & finite(measured) & !(max_of(measured, 1e-16) > k.o.stol);
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
