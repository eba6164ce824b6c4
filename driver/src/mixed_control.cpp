#include "acst_driver/mixed_control.hpp"

#include <Eigen/LU>
#include <algorithm>

#include "acst/yield_function.hpp"

namespace acst::driver {

namespace {

bool converged_residual(const LinearControl& ctl, const Sym& r, double stress_scale, const NewtonOptions& o) {
  for (int i = 0; i < 6; ++i) {
    const bool stress_row = ctl.A.row(i).cwiseAbs().maxCoeff() > 0.0;
    const double tol = stress_row ? o.stress_tolerance * stress_scale : o.strain_tolerance;
    if (!(std::abs(r[i]) <= tol)) return false;
  }
  return true;
}

// Partial pivoting is about three times cheaper than full pivoting on 6 x 6; with the rows
// scaled to a largest entry of 1, a pivot below 1e-12 of the largest one counts as singular.
bool singular(const Eigen::PartialPivLU<Mat6>& lu) {
  const auto d = lu.matrixLU().diagonal().cwiseAbs();
  return !d.allFinite() || !(d.minCoeff() > 1e-12 * d.maxCoeff());
}

}  // namespace

const char* failure_text(IncrementFailure f) {
  switch (f) {
    case IncrementFailure::none: return "converged";
    case IncrementFailure::material: return "the material update failed";
    case IncrementFailure::singular_jacobian:
      return "singular Newton matrix A D + B (the control leaves a component free at this state)";
    case IncrementFailure::not_converged: return "Newton iteration did not converge";
    case IncrementFailure::non_finite: return "Newton iterate became non-finite";
  }
  return "?";
}

IncrementResult solve_increment(const Material& material, State& state, const LinearControl& ctl, const Sym& guess,
                                const NewtonOptions& o, double void_ratio_offset) {
  IncrementResult res;
  res.failure = IncrementFailure::not_converged;
  Sym deps = guess;
  const double stress_scale = std::max(mean_stress(state.stress), atmospheric_pressure);
  integration::Counters work;
  for (int it = 1; it <= o.max_iterations; ++it) {
    res.iterations = it;
    State trial = state;
    Mat6 D;
    res.material = material.update(trial, deps, &D, void_ratio_offset);
    work += res.material.counters;
    if (res.material.status != integration::Status::ok) {
      res.failure = IncrementFailure::material;
      break;
    }
    const Sym r = ctl.A * (trial.stress - state.stress) + ctl.B * deps - ctl.c;
    // Rows scaled by their largest entry, so that stress rows (~ stiffness) and strain rows (~1) weigh alike.
    Mat6 J = ctl.A * D + ctl.B;
    Sym rs = r;
    for (int i = 0; i < 6; ++i) {
      const double m = J.row(i).cwiseAbs().maxCoeff();
      if (m > 0.0) {
        J.row(i) /= m;
        rs[i] /= m;
      }
    }
    const Eigen::PartialPivLU<Mat6> lu(J);
    if (singular(lu)) {  // a component is left free: the control is singular
      res.failure = IncrementFailure::singular_jacobian;
      break;
    }
    const Sym correction = -lu.solve(rs);
    const bool small_correction = correction.cwiseAbs().maxCoeff() <= o.strain_tolerance + 1e-8 * deps.cwiseAbs().maxCoeff();
    if (converged_residual(ctl, r, stress_scale, o) && small_correction) {
      state = trial;
      res.converged = true;
      res.failure = IncrementFailure::none;
      res.strain_increment = deps;
      res.tangent = D;
      break;
    }
    deps += correction;
    if (!deps.allFinite()) {
      res.failure = IncrementFailure::non_finite;
      break;
    }
  }
  res.material.counters = work;
  return res;
}

LinearControl drained_triaxial(double de_axial) {
  LinearControl c;
  c.B(0, 0) = 1.0;
  c.c[0] = de_axial;
  for (int i = 1; i < 6; ++i) c.A(i, i) = 1.0;  // lateral and shear stresses held
  return c;
}

LinearControl undrained_triaxial(double de_axial) {
  LinearControl c;
  c.B(0, 0) = 1.0;
  c.c[0] = de_axial;
  c.B.row(1) << 1, 1, 1, 0, 0, 0;  // eps_v = 0
  c.A(2, 1) = 1.0;                 // sigma_2 - sigma_3 = 0
  c.A(2, 2) = -1.0;
  for (int i = 3; i < 6; ++i) c.A(i, i) = 1.0;
  return c;
}

}  // namespace acst::driver
