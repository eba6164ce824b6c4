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

}  // namespace

IncrementResult solve_increment(const Material& material, State& state, const LinearControl& ctl, const Sym& guess,
                                const NewtonOptions& o) {
  IncrementResult res;
  Sym deps = guess;
  const double stress_scale = std::max(mean_stress(state.stress), atmospheric_pressure);
  integration::Counters work;
  for (int it = 1; it <= o.max_iterations; ++it) {
    res.iterations = it;
    State trial = state;
    Mat6 D;
    res.material = material.update(trial, deps, &D);
    work += res.material.counters;
    if (res.material.status != integration::Status::ok) break;
    const Sym r = ctl.A * (trial.stress - state.stress) + ctl.B * deps - ctl.c;
    const Mat6 J = ctl.A * D + ctl.B;
    const Eigen::FullPivLU<Mat6> lu(J);
    if (!lu.isInvertible()) break;  // a component is left free: the control is singular
    const Sym correction = -lu.solve(r);
    const bool small_correction = correction.cwiseAbs().maxCoeff() <= o.strain_tolerance + 1e-8 * deps.cwiseAbs().maxCoeff();
    if (converged_residual(ctl, r, stress_scale, o) && small_correction) {
      state = trial;
      res.converged = true;
      res.strain_increment = deps;
      break;
    }
    deps += correction;
    if (!deps.allFinite()) break;
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

LinearControl strain_controlled(const Sym& de) {
  LinearControl c;
  c.B.setIdentity();
  c.c = de;
  return c;
}

}  // namespace acst::driver
