#pragma once
// Element-test runs shared by the physics tests: drained or undrained triaxial compression with
// the mixed-control driver, recording the quantities the tests judge (model convention:
// compression positive, axis 1 = axial).
#include <Eigen/Core>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "acst/material.hpp"
#include "acst_driver/mixed_control.hpp"

namespace acst::test {

struct TriaxialPoint {
  double axial_strain;       // eps_1
  double volumetric_strain;  // eps_v, positive = contraction
  double p, q, R;            // mean stress, deviator stress, R = q/p in triaxial
  double void_ratio;
  double A;            // F:n with n at the current stress (strain direction = last increment)
  double fabric_norm;  // |F|
};

enum class Drainage { drained, undrained };

// Isotropic start at p0 and e0 with deposition direction b, then `steps` axial increments of
// `de_axial`. Throws if an increment does not converge: a test must never judge a run the
// driver could not follow.
inline std::vector<TriaxialPoint> triaxial_compression(const Material& mat, double p0, double e0,
                                                       const Eigen::Vector3d& b, Drainage drainage,
                                                       double de_axial, int steps) {
  State state = mat.initial_state(p0 * identity_tensor(), e0, b);
  std::vector<TriaxialPoint> path;
  path.reserve(steps + 1);
  Sym strain = Sym::Zero();
  Sym guess = Sym::Zero();
  guess[0] = de_axial;
  auto record = [&](const Sym& direction) {
    const Diagnostics d = mat.diagnostics(state, direction);
    path.push_back({strain[0], strain[0] + strain[1] + strain[2], d.p, d.q, d.R, state.void_ratio, d.A,
                    d.fabric_norm});
  };
  record(guess);
  const driver::LinearControl control = drainage == Drainage::drained ? driver::drained_triaxial(de_axial)
                                                                      : driver::undrained_triaxial(de_axial);
  for (int i = 0; i < steps; ++i) {
    const driver::IncrementResult res = driver::solve_increment(mat, state, control, guess);
    if (!res.converged) throw std::runtime_error("triaxial increment " + std::to_string(i) + " did not converge");
    strain += res.strain_increment;
    guess = res.strain_increment;
    record(res.strain_increment);
  }
  return path;
}

}  // namespace acst::test
