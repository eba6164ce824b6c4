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
inline PlasticQuantities plastic_quantities(const Parameters& prm, const Sym& sigma, const Sym& F, double e,
                                            const StressRatioState& ratio) {
  PlasticQuantities q;
  q.p = mean_stress(sigma);
  q.ratio = ratio;
  const double g = q.ratio.lode.g;
  set_elastic_moduli(q.moduli, prm, e, q.p, F);
  q.psi = state_parameter(prm, e, q.p);
  q.A = fabric_anisotropy_variable(F, q.ratio.n);
  q.zeta = dilatancy_state_parameter(q.psi, prm.e_A, q.A);
  const double R = std::max(q.ratio.R, prm.R_tolerance);
  q.D = dilatancy(prm.d1, prm.m, q.zeta, q.ratio.R, prm.Mc, g);
  const double h = hardening_coefficient(prm.h1, prm.h2, e);
  q.h_floored = h < prm.h_min;
  q.h = q.h_floored ? prm.h_min : h;
  const double n = peak_state_coefficient(prm.n, prm.peak_pressure_exponent, q.p, prm.p_min, atmospheric_pressure);
  q.Kp = plastic_modulus(q.moduli.G, q.h, prm.Mc, g, n, q.zeta, R);
  q.n_r = contract(q.ratio.n, q.ratio.r);
  return q;
}

inline PlasticQuantities plastic_quantities(const Parameters& prm, const Sym& sigma, const Sym& F, double e,
                                            const Sym& strain_direction) {
  return plastic_quantities(prm, sigma, F, e, stress_ratio_state(sigma, lode_shape(prm), prm.R_tolerance, strain_direction));
}

// D_e : d eps^p / L = D_e : (n + sqrt(2/27) D I), isotropic 2G n + sqrt(2/3) K D I: the stress
// relaxed per unit loading index
// (n is deviatoric, so the deviatoric and volumetric parts separate without a deviator call.)
inline Sym plastic_stress_direction(const PlasticQuantities& q) {
  if (q.moduli.anisotropic) return elastic_stress_increment(q.moduli, plastic_flow_direction(q.ratio.n, q.D));
  Sym a = 2.0 * q.moduli.G * q.ratio.n;
  const double volumetric = std::sqrt(2.0 / 3.0) * q.moduli.K * q.D;
  a[0] += volumetric;
  a[1] += volumetric;
  a[2] += volumetric;
  return a;
}

class AcstRates {
 public:
  static constexpr int size = 13;  // stress (6), fabric (6), void ratio
  using Vector = Eigen::Matrix<double, size, 1>;
  using Reason = integration::Reason;
  using Counters = integration::Counters;

  // One object per update (never shared between threads): it keeps the last stress ratio state.
  explicit AcstRates(const Parameters& prm) : prm_(prm) {}

  static Sym stress(const Vector& y) { return y.template head<6>(); }
  static Sym fabric(const Vector& y) { return y.template segment<6>(6); }
  static double void_ratio(const Vector& y) { return y[12]; }

  void elastic_rate(const Vector& y, const Sym& deps, Vector& dy, Counters& c) const {
    ++c.rate_evaluations;
    const double e = void_ratio(y);
    const double p = mean_stress(stress(y));
    if (prm_.elastic_anisotropy == 0.0) {  // the published model: no fabric read, no P built
      const double G = shear_modulus(prm_, e, p);
      dy.template head<6>() = isotropic_stress_increment(G, bulk_modulus(G, prm_.nu), deps);
    } else {
      dy.template head<6>() = elastic_stress_increment(elastic_moduli(prm_, e, p, fabric(y)), deps);
    }
    dy.template segment<6>(6).setZero();
    dy[12] = -(1.0 + e) * trace(deps);  // de = -(1 + e) d eps_v
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
    const PlasticQuantities q = plastic_quantities(prm_, sigma, F, e, ratio_state(sigma, deps));
    count_guards(q, c);
    const LoadingIndexTerms L = loading_index_terms(q.moduli, q.Kp, q.D, q.ratio.n, q.n_r, deps);
    if (!(L.denominator > 0.0)) {
      ++c.guard_uniqueness;
      return Reason::loss_of_uniqueness;
    }
    const double load = L.numerator > 0.0 ? L.numerator / L.denominator : 0.0;
    Sym dsig = elastic_stress_increment(q.moduli, deps);
    dsig -= load * plastic_stress_direction(q);
    dy.template head<6>() = dsig;
    dy.template segment<6>(6) = load * fabric_rate(prm_.k_f, q.ratio.n, F);
    dy[12] = -(1.0 + e) * trace(deps);
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
    const Sym grad = yield_gradient(ratio, mean_stress(sigma));
    const Sym dsig = elastic_dy.template head<6>();
    const double den = norm(grad) * norm(dsig);
    return den > 0.0 ? contract(grad, dsig) / den : 0.0;
  }

  // max(|d sigma_err| / |sigma|, |dF_err| / max(|F|, 0.01), |de_err| / (1 + e)).
  double relative_error(const Vector& y_new, const Vector& err) const {
    const double es = norm(stress(err)) / std::max(norm(stress(y_new)), prm_.p_min);
    const double ef = norm(fabric(err)) / std::max(norm(fabric(y_new)), 1e-2);
    const double ee = std::abs(err[12]) / (1.0 + y_new[12]);
    return std::max(es, std::max(ef, ee));
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
  // The start state's stress ratio state is wanted twice in a plastic update, by the unloading
  // test of the elastic fraction and by the first rate (bench/RESULTS.md section 1, proposal 2):
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
