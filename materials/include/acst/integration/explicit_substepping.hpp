#pragma once
// Explicit substepping with error control (Sloan 1987; Sloan, Abbo & Sheng 2001), generic over
// the constitutive model. The scheme knows rates, yield values and error norms, nothing of sand.
//
// A Model provides:
//   using Vector;                                   integrated variables y
//   Reason plastic_rate(const Vector& y, const Sym& deps, Vector& dy, Counters&) const;
//   void   elastic_rate(const Vector& y, const Sym& deps, Vector& dy, Counters&) const;
//   double yield_value(const Vector& y, double H, const Sym& deps) const;
//   double unloading_cosine(const Vector& y, const Vector& elastic_dy, const Sym& deps) const;
//   double relative_error(const Vector& y_new, const Vector& error) const;
//   double hardening_memory(const Vector& y, const Sym& deps) const;   exact drift correction
//   Reason admissibility(const Vector& y) const;                   none where y may be taken
//   void   reset_to_pressure_floor(Vector& y, double& H) const;
// Rates are per unit pseudo-time T in [0, 1] for the whole strain increment deps.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "acst/integration/embedded_runge_kutta.hpp"
#include "acst/integration/options.hpp"
#include "acst/integration/report.hpp"
#include "acst/integration/steps.hpp"
#include "acst/tensor.hpp"

namespace acst::integration {

template <class Model>
class ExplicitSubstepping {
 public:
  using Vector = typename Model::Vector;
  static constexpr int size = Vector::RowsAtCompileTime;  // the steps (steps.hpp) work on its numbers

  ExplicitSubstepping(const Model& model, const Options& opt) : model_(model), opt_(opt) {}

  // Advances y and H over the strain increment deps. substep_hint carries the last accepted
  // substep size between calls (pseudo-time units).
  Report integrate(Vector& y, double& H, double& substep_hint, const Sym& deps) const {
    Report rep;
    Vector k1;
    model_.elastic_rate(y, deps, k1, rep.counters);
    const double f0 = model_.yield_value(y, H, deps);
    // A start on the surface loaded outwards is plastic from its start: the elastic trial would
    // only be thrown away. A neutral increment (cosine
    // within ltol of 0) is elastic if its trial stays on the surface.
    const bool on_surface = f0 >= -opt_.ftol;
    const double cosine = on_surface ? model_.unloading_cosine(y, k1, deps) : -1.0;
    if (cosine > opt_.ltol) return plastic(y, H, substep_hint, deps, rep);
    // Otherwise one Heun step decides elastic or not; only an elastic answer needs it within STOL.
    const ElasticStep trial = heun_step(y, k1, deps, 1.0, rep.counters);
    const double f_trial = model_.yield_value(trial.y, H, deps);
    if (f_trial <= opt_.ftol) {
      y = trial.error <= opt_.stol ? trial.y : elastic_update(y, deps, rep.counters);
      return finish(y, H, rep, Reason::none);
    }
    const double alpha = !on_surface           ? pegasus(y, H, deps, 0.0, f0, 1.0, f_trial, rep.counters)
                         : cosine >= -opt_.ltol ? 0.0
                                                : unload_reload_fraction(y, H, deps, f0, f_trial, rep.counters);
    if (alpha > 0.0) y = elastic_update(y, alpha * deps, rep.counters);
    return plastic(y, H, substep_hint, (1.0 - alpha) * deps, rep);
  }

 private:
  const Model& model_;
  const Options& opt_;

  struct ElasticStep {
    Vector y;
    double error;  // relative error estimate (Heun against Euler)
  };

  Report plastic(Vector& y, double& H, double& substep_hint, const Sym& deps, Report& rep) const {
    const Reason r = opt_.scheme == Scheme::forward_euler ? forward_euler(y, H, deps, rep)
                                                          : adaptive(y, H, substep_hint, deps, rep);
    return finish(y, H, rep, r);
  }

  // Heun's two-stage secant step over the fraction h of deps (pressure-dependent elasticity),
  // from the rate k1 at y (steps.hpp, as the lanes take it).
  ElasticStep heun_step(const Vector& y, const Vector& k1, const Sym& deps, double h, Counters& c) const {
    Vector ys, k2, y_new, err;
    euler_predictor<size>(y.data(), k1.data(), h, ys.data());
    model_.elastic_rate(ys, deps, k2, c);
    heun_combination<size>(y.data(), k1.data(), k2.data(), h, y_new.data(), err.data());
    const double error = model_.relative_error(y_new, err);
    // NaN would pass every "error > STOL" test: no estimate counts as too large an error.
    return {y_new, std::isfinite(error) ? std::max(error, 1e-16) : std::numeric_limits<double>::infinity()};
  }

  ElasticStep heun_step(const Vector& y, const Sym& deps, double h, Counters& c) const {
    Vector k1;
    model_.elastic_rate(y, deps, k1, c);
    return heun_step(y, k1, deps, h, c);
  }

  // The elastic law over deps within STOL, by Heun substeps (one for ordinary increments). The
  // error falls with the cube of the substep, so 1e-3 of the increment is always enough; the
  // floor keeps an unreachable STOL from costing a million substeps.
  Vector elastic_update(const Vector& y0, const Sym& deps, Counters& c) const {
    const double smallest = std::max(opt_.min_substep, 1e-3);
    Vector y = y0;
    double T = 0.0, dT = 1.0;
    while (T < 1.0) {
      const double h = std::min(dT, 1.0 - T);
      const ElasticStep step = heun_step(y, deps, h, c);
      const double factor = 0.9 * std::sqrt(opt_.stol / step.error);
      if (step.error > opt_.stol && h > smallest) {
        dT = std::max(h * std::max(factor, 0.1), smallest);
        continue;
      }
      y = step.y;
      T = h >= 1.0 - T ? 1.0 : T + h;
      dT = std::max(h * std::min(factor, 2.0), smallest);
    }
    return y;
  }

  // The yield value after the elastic fraction alpha of deps (one Heun step where that is
  // within STOL, as for ordinary increments).
  double yield_at(const Vector& y, double H, const Sym& deps, double alpha, Counters& c) const {
    const Sym part = alpha * deps;
    const ElasticStep step = heun_step(y, part, 1.0, c);
    return model_.yield_value(step.error <= opt_.stol ? step.y : elastic_update(y, part, c), H, deps);
  }

  // Fraction of deps that is elastic for an increment that starts on the surface, unloads and
  // ends outside it (f1 > 0): where the path crosses the surface again.
  double unload_reload_fraction(const Vector& y, double H, const Sym& deps, double f0, double f1, Counters& c) const {
    ++c.unload_reload;
    // Scan [lo, hi] in n steps for the first point outside; if the very first step is already
    // outside, the path's inside stretch is shorter than one step: scan that step again, finer.
    const int n = std::max(opt_.unload_scan_intervals, 2);
    double lo = 0.0, hi = 1.0;
    for (int level = 0; level < 4; ++level) {
      double a = lo, fa = f0;
      for (int j = 1; j <= n; ++j) {
        const double b = lo + (hi - lo) * j / n;
        const double fb = b == 1.0 ? f1 : yield_at(y, H, deps, b, c);
        if (fb > opt_.ftol) {
          if (fa < -opt_.ftol) return pegasus(y, H, deps, a, fa, b, fb, c);
          if (j > 1) return a;
          hi = b;
          break;
        }
        a = b;
        fa = fb;
      }
    }
    return 0.0;
  }

  // Pegasus regula falsi between fa < 0 and fb > 0.
  double pegasus(const Vector& y, double H, const Sym& deps, double a, double fa, double b, double fb,
                 Counters& c) const {
    double x = b;
    for (int it = 0; it < opt_.crossing_max_iterations; ++it) {
      ++c.crossing_iterations;
      x = b - fb * (b - a) / (fb - fa);
      const double fx = yield_at(y, H, deps, x, c);
      if (std::abs(fx) <= opt_.ftol) return x;
      if (fx * fb < 0.0) {
        a = b;
        fa = fb;
      } else {
        fa = fa * fb / (fb + fx);
      }
      b = x;
      fb = fx;
    }
    return x;
  }

  Reason rate(const Vector& y, const Sym& deps, Vector& k, Counters& c) const {
    const Reason r = model_.plastic_rate(y, deps, k, c);
    if (r != Reason::none) return r;
    return k.allFinite() ? Reason::none : Reason::non_finite;
  }

  Reason forward_euler(Vector& y, double& H, const Sym& deps, Report& rep) const {
    const int n = std::max(opt_.fe_substeps, 1);
    Vector k;
    for (int i = 0; i < n; ++i) {
      const Reason r = rate(y, deps, k, rep.counters);
      if (r != Reason::none) return r;
      y += k / n;
      if (const Reason bad = model_.admissibility(y); bad != Reason::none) return bad;
      H = model_.hardening_memory(y, deps);
      ++rep.counters.substeps_accepted;
      rep.plastic = true;
    }
    return Reason::none;
  }

  Reason adaptive(Vector& y, double& H, double& substep_hint, const Sym& deps, Report& rep) const {
    const Tableau& tb = tableau_of(opt_.scheme);
    const double exponent = 1.0 / (tb.error_order + 1.0);
    // Where STOL/R exceeds (1.1/0.9)^(q+1), the step factor 0.9 (STOL/R)^(1/(q+1)) exceeds the
    // growth cap of 1.1 below, and the cap is all that is used of it: such a substep skips the pow
    // and gives the same numbers (the 1 % margin keeps pow's round-off from deciding). Most MPM
    // updates, with their small strain increments, are such substeps.
    double capped_ratio = 1.01;
    for (int i = 0; i <= tb.error_order; ++i) capped_ratio *= 1.1 / 0.9;
    std::array<Vector, 7> k;
    const auto stage_rates = [&k](int s, int i) { return k[s][i]; };  // for the steps (steps.hpp)
    Counters& c = rep.counters;
    double T = 0.0;
    // dT_next: the natural substep size; h: the one tried (cut to reach T = 1 exactly).
    // A hint below the smallest substep (a host's stale or made-up state) would fail every call
    // before it tried a substep: it counts as the smallest.
    double dT_next = (opt_.reuse_last_substep && substep_hint > 0.0) ? std::clamp(substep_hint, opt_.min_substep, 1.0) : 1.0;
    bool k0_valid = false, last_rejected = false;
    Reason last_failure = Reason::none;
    while (T < 1.0) {
      const bool truncated = dT_next >= 1.0 - T;
      const double h = truncated ? 1.0 - T : dT_next;
      if (dT_next < opt_.min_substep)
        return last_failure == Reason::none ? Reason::substep_too_small : last_failure;
      if (c.substeps_accepted + c.substeps_rejected >= opt_.max_substeps) return Reason::too_many_substeps;
      Reason r = Reason::none;
      if (!k0_valid) {
        r = rate(y, deps, k[0], c);
        if (r != Reason::none) return r;  // fails at the start state: a smaller substep cannot help
        k0_valid = true;
      }
      for (int s = 1; s < tb.stages && r == Reason::none; ++s) {
        Vector ys;
        stage_state<size>(tb.a[s].data(), s, h, y.data(), stage_rates, ys.data());
        r = rate(ys, deps, k[s], c);
      }
      Vector y_new, err;
      if (r == Reason::none) {
        // A two-stage scheme's count (modified Euler, the default) as a constant (steps.hpp).
        if (tb.stages == modified_euler_tableau.stages)
          step_solution<size, modified_euler_tableau.stages>(tb.stages, tb.b.data(), tb.b_low.data(), h, y.data(),
                                                             stage_rates, y_new.data(), err.data());
        else
          step_solution<size>(tb.stages, tb.b.data(), tb.b_low.data(), h, y.data(), stage_rates, y_new.data(),
                              err.data());
        r = model_.admissibility(y_new);
      }
      if (r != Reason::none) {  // a stage left the admissible region: shrink hard
        last_failure = r;
        ++c.substeps_rejected;
        dT_next = 0.1 * h;
        last_rejected = true;
        continue;
      }
      const double measured = model_.relative_error(y_new, err);
      if (!std::isfinite(measured)) {  // no error estimate (a stage's rate overflowed): shrink hard
        last_failure = Reason::non_finite;
        ++c.substeps_rejected;
        dT_next = 0.1 * h;
        last_rejected = true;
        continue;
      }
      const double R = std::max(measured, 1e-16);
      // pow, not sqrt, for ME's exponent 1/2: the two differ in the last bit at times, and the
      // calibration follows that to another set.
      const double factor = R * capped_ratio <= opt_.stol ? 1.1 : 0.9 * std::pow(opt_.stol / R, exponent);
      if (R > opt_.stol) {
        ++c.substeps_rejected;
        dT_next = h * std::max(factor, 0.1);
        last_rejected = true;
        continue;
      }
      y = y_new;
      T = truncated ? 1.0 : T + h;
      H = model_.hardening_memory(y, deps);
      ++c.substeps_accepted;
      rep.plastic = true;
      if (tb.first_same_as_last)
        k[0] = k[tb.stages - 1];
      else
        k0_valid = false;
      const double grown = h * (last_rejected ? std::min(factor, 1.0) : std::min(factor, 1.1));
      dT_next = truncated ? std::max(dT_next, grown) : grown;
      last_rejected = false;
      last_failure = Reason::none;
    }
    substep_hint = std::min(dT_next, 1.0);
    return Reason::none;
  }

  // A pressure-floor failure is reset (where the policy says so) only when p is all that is wrong:
  // the model's admissibility names a void ratio out of range or a non-finite value otherwise.
  Report finish(Vector& y, double& H, Report& rep, Reason r) const {
    if (r == Reason::none) r = model_.admissibility(y);
    if (r == Reason::pressure_floor && opt_.pressure_floor == PressureFloorPolicy::reset) {
      model_.reset_to_pressure_floor(y, H);
      ++rep.counters.pressure_floor_resets;
      r = Reason::none;
    }
    rep.reason = r;
    if (r != Reason::none) {
      rep.status = Status::step_reduction_requested;
      rep.suggested_step_factor = r == Reason::loss_of_uniqueness ? 0.25 : 0.5;
    }
    return rep;
  }
};

}  // namespace acst::integration
