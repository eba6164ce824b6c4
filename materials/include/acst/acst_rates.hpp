#pragma once
// The ACST model as the integrators see it: rates of (stress, fabric, void ratio) for a strain
// increment, yield value, error norm and drift correction (docs/model.md section 7).
#include <Eigen/Core>
#include <cmath>
#include <limits>

#include "acst/critical_state.hpp"
#include "acst/dilatancy.hpp"
#include "acst/elasticity.hpp"
#include "acst/fabric.hpp"
#include "acst/inline.hpp"
#include "acst/integration/report.hpp"
#include "acst/loading_index.hpp"
#include "acst/parameters.hpp"
#include "acst/plastic_modulus.hpp"
#include "acst/yield_function.hpp"

namespace acst {

// Every intermediate quantity of one constitutive evaluation.
struct PlasticQuantities {
  double p;
  StressRatioState ratio;
  ElasticModuli moduli;
  double psi;    // state parameter
  double A;      // fabric anisotropy variable F:n
  double zeta;   // dilatancy state parameter
  double D;      // dilatancy
  double h;      // hardening coefficient after its floor
  bool h_floored;
  double Kp;     // plastic modulus
  double n_r;    // n:r
};

// With the stress ratio state of sigma already at hand (see AcstRates::ratio_state).
// `void_ratio_offset`: a host's nonlocal void ratio minus the point's own (docs/model.md section
// 11): the state parameter, and through it the dilatancy and the peak, take it
// (nonlocal_state_parameter); the elasticity and the hardening keep e. 0 is the local model.
inline PlasticQuantities plastic_quantities(const Parameters& prm, const Sym& sigma, const Sym& F, double e,
                                            const StressRatioState& ratio, double void_ratio_offset = 0.0) {
  PlasticQuantities q;
  q.p = mean_stress(sigma);
  q.ratio = ratio;
  const double g = q.ratio.lode.g;
  set_elastic_moduli(q.moduli, prm, e, q.p, F);
  q.psi = nonlocal_state_parameter(state_parameter(prm, e, q.p), void_ratio_offset);
  q.A = fabric_anisotropy_variable(F, q.ratio.n);
  q.zeta = dilatancy_state_parameter(q.psi, prm.e_A, q.A);
  q.D = dilatancy(prm.d1, prm.m, q.zeta, q.ratio.R, prm.Mc, g);
  const FlooredHardening h = floored_hardening_coefficient(prm.h1, prm.h2, prm.h_min, e);
  q.h = h.h;
  q.h_floored = h.floored;
  const double n = peak_state_coefficient(prm.n, prm.peak_pressure_exponent, normalised_pressure(q.p, prm.p_min));
  q.Kp = plastic_modulus(q.moduli.G, q.h, prm.Mc, g, n, q.zeta, plastic_modulus_stress_ratio(q.ratio.R, prm.R_tolerance));
  q.n_r = contract(q.ratio.n, q.ratio.r);
  return q;
}

inline PlasticQuantities plastic_quantities(const Parameters& prm, const Sym& sigma, const Sym& F, double e,
                                            const Sym& strain_direction, double void_ratio_offset = 0.0) {
  return plastic_quantities(prm, sigma, F, e, stress_ratio_state(sigma, lode_shape(prm), prm.R_tolerance, strain_direction),
                            void_ratio_offset);
}

// The isotropic D_e : d eps^p / L = 2G n + sqrt(2/3) K D I, into a (n is deviatoric, so the
// deviatoric and volumetric parts separate without a deviator call).
ACST_INLINE void isotropic_plastic_stress_direction(double G, double K, double D, const double* n, double* a) {
#pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) a[i] = 2.0 * G * n[i];
  const double volumetric = std::sqrt(2.0 / 3.0) * K * D;
  a[0] += volumetric;
  a[1] += volumetric;
  a[2] += volumetric;
}

// D_e : d eps^p / L = D_e : (n + sqrt(2/27) D I): the stress relaxed per unit loading index.
inline Sym plastic_stress_direction(const PlasticQuantities& q) {
  if (q.moduli.anisotropic) return elastic_stress_increment(q.moduli, plastic_flow_direction(q.ratio.n, q.D));
  Sym a;
  isotropic_plastic_stress_direction(q.moduli.G, q.moduli.K, q.D, q.ratio.n.data(), a.data());
  return a;
}

// de = -(1 + e) d eps_v.
ACST_INLINE double void_ratio_rate(double e, const double* deps) { return -(1.0 + e) * trace(deps); }

// The rate of y = (stress, fabric, void ratio) with isotropic D_e and no plastic strain (the
// published model: no fabric read, no P built), into dy.
ACST_INLINE void isotropic_elastic_rate(double G0, double p_min, double nu, const double* y, const double* deps,
                                        double* dy) {
  const double e = y[12];
  const double G = shear_modulus(G0, p_min, e, mean_stress(y));
  isotropic_stress_increment(G, bulk_modulus(G, nu), deps, dy);
#pragma GCC unroll 13
  for (int i = 6; i < 12; ++i) dy[i] = 0.0;
  dy[12] = void_ratio_rate(e, deps);
}

// d sigma = D_e d eps - <L> D_e:(n + sqrt(2/27) D I), dF = <L> k_f (n - F), de = -(1 + e) d eps_v
// into dy, from D_e d eps, <L> and D_e:(n + sqrt(2/27) D I) (`elastic`, `load`, `relaxed`).
ACST_INLINE void plastic_rate_of(const double* elastic, double load, const double* relaxed, double k_f, const double* n,
                                 const double* F, double e, const double* deps, double* dy) {
  double dF[6];
  fabric_rate(k_f, n, F, dF);
#pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) {
    dy[i] = elastic[i] - load * relaxed[i];
    dy[6 + i] = load * dF[i];
  }
  dy[12] = void_ratio_rate(e, deps);
}

// max(|d sigma_err| / |sigma|, |dF_err| / max(|F|, 0.01), |de_err| / (1 + e)) of y's 13 numbers.
ACST_INLINE double relative_error(double p_min, const double* y_new, const double* err) {
  const double es = norm(err) / max_of(norm(y_new), p_min);
  const double ef = norm(err + 6) / max_of(norm(y_new + 6), 1e-2);
  const double ee = std::abs(err[12]) / (1.0 + y_new[12]);
  return max_of(es, max_of(ef, ee));
}

class AcstRates {
 public:
  static constexpr int size = 13;  // stress (6), fabric (6), void ratio
  using Vector = Eigen::Matrix<double, size, 1>;
  using Reason = integration::Reason;
  using Counters = integration::Counters;

  // One object per update (never shared between threads): it keeps the last stress ratio state.
  // `void_ratio_offset`: the host's nonlocal offset of the update (plastic_quantities).
  explicit AcstRates(const Parameters& prm, double void_ratio_offset = 0.0)
      : prm_(prm), void_ratio_offset_(void_ratio_offset) {}

  static Sym stress(const Vector& y) { return y.template head<6>(); }
  static Sym fabric(const Vector& y) { return y.template segment<6>(6); }
  static double void_ratio(const Vector& y) { return y[12]; }

  void elastic_rate(const Vector& y, const Sym& deps, Vector& dy, Counters& c) const {
    ++c.rate_evaluations;
    if (prm_.elastic_anisotropy == 0.0) {
      isotropic_elastic_rate(prm_.G0, prm_.p_min, prm_.nu, y.data(), deps.data(), dy.data());
      return;
    }
    const double e = void_ratio(y);
    dy.template head<6>() = elastic_stress_increment(elastic_moduli(prm_, e, mean_stress(stress(y)), fabric(y)), deps);
    dy.template segment<6>(6).setZero();
    dy[12] = void_ratio_rate(e, deps.data());
  }

  // d sigma = D_e d eps - <L> D_e:(n + sqrt(2/27) D I);  dF = <L> k_f (n - F).
  Reason plastic_rate(const Vector& y, const Sym& deps, Vector& dy, Counters& c) const {
    ++c.rate_evaluations;
    const Sym sigma = stress(y), F = fabric(y);
    const double e = void_ratio(y);
    if (!(mean_stress(sigma) >= prm_.p_min)) {
      ++c.guard_pressure_floor;
      return Reason::pressure_floor;
    }
    const PlasticQuantities q = plastic_quantities(prm_, sigma, F, e, ratio_state(sigma, deps), void_ratio_offset_);
    count_guards(q, c);
    const LoadingIndexTerms L = loading_index_terms(q.moduli, q.Kp, q.D, q.ratio.n, q.n_r, deps);
    if (!(L.denominator > 0.0)) {
      ++c.guard_uniqueness;
      return Reason::loss_of_uniqueness;
    }
    const Sym elastic = elastic_stress_increment(q.moduli, deps), relaxed = plastic_stress_direction(q);
    plastic_rate_of(elastic.data(), loading_index(L), relaxed.data(), prm_.k_f, q.ratio.n.data(), F.data(), e, deps.data(),
                    dy.data());
    return Reason::none;
  }

  double yield_value(const Vector& y, double H, const Sym&) const {
    return acst::yield_value(stress(y), lode_shape(prm_), prm_.R_tolerance, H);
  }

  // Cosine between df/dsigma at y and the elastic trial stress increment; 0 (neutral) on the
  // cone's axis, R below R_tolerance, where df/dsigma is not defined and n is only a guess.
  double unloading_cosine(const Vector& y, const Vector& elastic_dy, const Sym& deps) const {
    const Sym sigma = stress(y);
    const StressRatioState& ratio = ratio_state(sigma, deps);
    if (ratio.small_R) return 0.0;
    return cosine_between(yield_gradient(ratio, mean_stress(sigma)).data(), elastic_dy.data());
  }

  // The error norm of a substep (acst::relative_error).
  double relative_error(const Vector& y_new, const Vector& err) const {
    return acst::relative_error(prm_.p_min, y_new.data(), err.data());
  }

  // H = R/g(theta): exact drift correction after a plastic substep.
  double hardening_memory(const Vector& y, const Sym&) const {
    return acst::yield_value(stress(y), lode_shape(prm_), prm_.R_tolerance, 0.0);
  }

  // Why y cannot be taken (none: it can): p below the floor, a void ratio out of its range, or
  // something non-finite. Only the first is reset to the floor (a free surface, tension,
  // liquefaction); the others fail the integration: before, all three counted as "below the
  // floor", and a 60 % compression came back as an isotropic p_min state with e < 0 (issue 14).
  Reason admissibility(const Vector& y) const {
    if (!y.allFinite()) return Reason::non_finite;
    if (!void_ratio_admissible(y[12])) return Reason::void_ratio_range;
    return mean_stress(stress(y)) >= prm_.p_min ? Reason::none : Reason::pressure_floor;
  }

  void reset_to_pressure_floor(Vector& y, double& H) const {
    y.template head<6>() = prm_.p_min * identity_tensor();
    H = 0.0;
  }

  const Parameters& parameters() const { return prm_; }

 private:
  const Parameters& prm_;
  double void_ratio_offset_;
  // The start state's stress ratio state is wanted twice in a plastic update, by the unloading
  // test of the elastic fraction and by the first rate:
  // the last one is kept with the stress and strain direction it was computed for.
  mutable StressRatioState last_ratio_{};
  mutable Sym last_sigma_ = Sym::Constant(std::numeric_limits<double>::quiet_NaN());  // NaN: equal to nothing
  mutable Sym last_direction_ = Sym::Zero();

  const StressRatioState& ratio_state(const Sym& sigma, const Sym& strain_direction) const {
    if (sigma != last_sigma_ || strain_direction != last_direction_) {
      last_ratio_ = stress_ratio_state(sigma, lode_shape(prm_), prm_.R_tolerance, strain_direction);
      last_sigma_ = sigma;
      last_direction_ = strain_direction;
    }
    return last_ratio_;
  }

  static void count_guards(const PlasticQuantities& q, Counters& c) {
    c.guard_small_R += q.ratio.small_R;
    c.guard_lode_clamp += q.ratio.lode_clamped;
    c.guard_h_floor += q.h_floored;
  }
};

}  // namespace acst
