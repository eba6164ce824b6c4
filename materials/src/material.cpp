#include "acst/material.hpp"

#include "acst/acst_rates.hpp"
#include "acst/integration/explicit_substepping.hpp"

namespace acst {

using integration::Report;
using integration::Status;

Material::Material(const Parameters& parameters, const integration::Options& options)
    : parameters_(parameters), options_(options) {
  validate(parameters_);
  if (const std::string problem = integration::options_problem(options_); !problem.empty())
    throw InputError("integrator option " + problem);
}

State Material::initial_state(const Sym& stress, double void_ratio, const Eigen::Vector3d& deposition_direction) const {
  if (!stress.allFinite()) throw InputError("initial stress is not finite");
  if (!stress_within_limit(stress.data()))
    throw InputError("initial stress has a component beyond 1e100 kPa in size, where the model's arithmetic overflows");
  if (!(mean_stress(stress) >= parameters_.p_min))
    throw InputError("initial mean stress must be at least p_min = " + std::to_string(parameters_.p_min) + " kPa");
  if (!void_ratio_admissible(void_ratio)) throw InputError("initial void ratio must lie in (0, 2.97)");
  if (!usable_direction(deposition_direction))
    throw InputError("deposition direction must be a finite non-zero vector");
  State s;
  s.stress = stress;
  s.void_ratio = void_ratio;
  s.fabric = initial_fabric(parameters_.F0, deposition_direction);
  s.H = yield_value(stress, lode_shape(parameters_), parameters_.R_tolerance, 0.0);  // on the cone through the stress
  s.substep_hint = 1.0;
  return s;
}

namespace {

AcstRates::Vector pack(const State& s) {
  AcstRates::Vector y;
  y << s.stress, s.fabric, s.void_ratio;
  return y;
}

bool physical(const State& s) {
  return s.stress.allFinite() && stress_within_limit(s.stress.data()) && s.fabric.allFinite() && std::isfinite(s.H) &&
         void_ratio_admissible(s.void_ratio) && s.H >= 0.0;
}

}  // namespace

Report Material::update(State& state, const Sym& deps, Mat6* tangent_out, double void_ratio_offset) const {
  Report rep;
  if (!deps.allFinite() || !(std::abs(void_ratio_offset) < void_ratio_limit)) {
    rep.status = Status::invalid_input;
    rep.reason = integration::Reason::non_finite;
    return rep;
  }
  if (!physical(state)) {
    rep.status = Status::nonphysical_state;
    rep.reason = integration::Reason::non_finite;
    return rep;
  }
  const AcstRates model(parameters_, void_ratio_offset);
  AcstRates::Vector y = pack(state);
  // A hint that is no step size (NaN, zero, negative: a host's made-up state) means "none": the
  // update may end without a substep that rewrites it (a reset to the pressure floor), and OK
  // promises a finite state.
  double H = state.H, hint = std::isfinite(state.substep_hint) && state.substep_hint > 0.0 ? state.substep_hint : 1.0;
  rep = integration::ExplicitSubstepping<AcstRates>(model, options_).integrate(y, H, hint, deps);
  if (rep.status != Status::ok) return rep;
  State next = state;
  next.stress = AcstRates::stress(y);
  next.fabric = AcstRates::fabric(y);
  next.void_ratio = AcstRates::void_ratio(y);
  next.H = H;
  next.substep_hint = hint;
  next.pressure_floor_resets += rep.counters.pressure_floor_resets;
  // OK promises a finite, physical state and tangent (docs/c-abi.md): anything else asks for a
  // smaller increment and leaves the state as it came.
  Mat6 D;
  if (tangent_out) D = tangent(next, rep.plastic, deps, void_ratio_offset);
  if (!physical(next) || (tangent_out && !D.allFinite())) {
    rep.status = Status::step_reduction_requested;
    rep.reason = integration::Reason::non_finite;  // the integrator already held e and p in range
    rep.suggested_step_factor = 0.5;
    return rep;
  }
  state = next;
  if (tangent_out) *tangent_out = D;
  return rep;
}

// D_ep = D_e - (D_e : m) (x) (D_e : g) / [Kp + (D_e : g):m] (docs/model.md sections 6 and 7; with
// isotropic D_e, (2G n + sqrt(2/3) K D I) (x) (2G n - K (n:r) I) / [Kp + 2G - sqrt(2/3) K D (n:r)]).
Mat6 Material::tangent(const State& s, bool plastic, const Sym& strain_direction, double void_ratio_offset) const {
  const PlasticQuantities q =
      plastic_quantities(parameters_, s.stress, s.fabric, s.void_ratio, strain_direction, void_ratio_offset);
  Mat6 D = elastic_stiffness(q.moduli);
  if (!plastic) return D;
  const LoadingIndexTerms L = loading_index_terms(q.moduli, q.Kp, q.D, q.ratio.n, q.n_r, strain_direction);
  // Only a loading direction contributes; at a non-positive denominator keep the elastic part.
  if (L.denominator > 0.0 && L.numerator > 0.0) {
    const Sym b = loading_index_gradient(q.moduli, q.ratio.n, q.n_r);  // L = b:d_eps / denominator
    D -= plastic_stress_direction(q) * contraction_row(b) / L.denominator;
  }
  return D;
}

ElasticModuli Material::elastic_moduli(const State& s) const {
  return acst::elastic_moduli(parameters_, s.void_ratio, mean_stress(s.stress), s.fabric);
}

Diagnostics Material::diagnostics(const State& s, const Sym& strain_direction) const {
  const PlasticQuantities q = plastic_quantities(parameters_, s.stress, s.fabric, s.void_ratio, strain_direction);
  Diagnostics d;
  d.p = q.p;
  d.q = std::sqrt(1.5) * norm(deviator(s.stress));
  d.R = q.ratio.R;
  d.sin3theta = q.ratio.sin3theta;
  d.g = q.ratio.lode.g;
  d.psi = q.psi;
  d.zeta = q.zeta;
  d.A = q.A;
  d.fabric_norm = norm(s.fabric);
  d.critical_void_ratio = critical_void_ratio(parameters_, q.p);
  d.D = q.D;
  d.Kp = q.Kp;
  d.G = q.moduli.G;
  d.K = q.moduli.K;
  return d;
}

}  // namespace acst
