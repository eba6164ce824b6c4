#pragma once
// Perfectly plastic Drucker-Prager plasticity on linear elasticity: a frictional verification
// material with a closed-form update, matched to Mohr-Coulomb in plane strain so that the
// footing's limit load can be checked against Prandtl's c N_c + q N_q (docs/footing-study.md,
// "The discretisation's own error on a frictional soil"). Model convention (compression positive,
// tensor shear strain, kPa; docs/conventions.md).
//
// Yield f = sqrt(J2) - 3 alpha p - k, plastic potential g = sqrt(J2) - 3 beta p, with
// p = tr(sigma) / 3 and J2 = s:s / 2. The plane-strain match (Drucker & Prager 1952): alpha =
// tan(phi) / sqrt(9 + 12 tan^2 phi), k = 3 c / sqrt(9 + 12 tan^2 phi), and beta likewise from the
// dilation angle psi. With psi = phi (associated flow) a plane-strain body collapses under the
// loads of Mohr-Coulomb soil with friction angle phi and cohesion c.
#include <cmath>

#include "acst/reference/linear_elastic.hpp"

namespace acst::reference {

struct DruckerPrager {
  LinearElastic elastic;
  double alpha;  // friction coefficient of the cone, from phi
  double k;      // kPa, sqrt(J2) at p = 0, from c and phi
  double beta;   // dilation coefficient of the potential, from psi (beta = alpha: associated)
};

// The plane-strain match's coefficient of an angle: tan(a) / sqrt(9 + 12 tan^2 a).
inline double plane_strain_coefficient(double angle_deg) {
  const double t = std::tan(angle_deg * M_PI / 180.0);
  return t / std::sqrt(9.0 + 12.0 * t * t);
}

inline DruckerPrager drucker_prager_plane_strain(LinearElastic elastic, double friction_angle_deg, double cohesion,
                                                 double dilation_angle_deg) {
  const double t = std::tan(friction_angle_deg * M_PI / 180.0);
  return {elastic, plane_strain_coefficient(friction_angle_deg), 3.0 * cohesion / std::sqrt(9.0 + 12.0 * t * t),
          plane_strain_coefficient(dilation_angle_deg)};
}

struct DruckerPragerPoint {
  Sym stress;
  double equivalent_plastic_strain;  // sum of sqrt(2/3 d e_p : d e_p), e_p the plastic strain's deviator
};

inline double sqrt_J2(const Sym& stress) { return norm(deviator(stress)) / std::sqrt(2.0); }

inline double yield_value(const DruckerPrager& m, const Sym& stress) {
  return sqrt_J2(stress) - m.alpha * trace(stress) - m.k;
}

// Relative slack for stresses handed in from outside (initial states written with round-off).
inline constexpr double drucker_prager_tolerance = 1e-9;

inline bool within_yield_surface(const DruckerPrager& m, const Sym& stress) {
  return yield_value(m, stress) <= drucker_prager_tolerance * (m.k + m.alpha * std::abs(trace(stress)) + sqrt_J2(stress));
}

// Backward Euler, which needs no iteration for a cone on linear elasticity: the trial stress
// returns along the potential's gradient onto the cone, d lambda = f_trial / (G + 9 K alpha
// beta), sqrt(J2) falls by G d lambda and p rises by 3 K beta d lambda; where that would carry
// sqrt(J2) below zero the stress returns to the apex, p = -k / (3 alpha), s = 0. Returns whether
// the step yielded. `tangent` (optional) receives this algorithm's consistent tangent.
inline bool radial_return(const DruckerPrager& m, DruckerPragerPoint& point, const Sym& strain_increment, Mat6* tangent) {
  const ElasticModuli mod = moduli(m.elastic);
  const Sym trial = point.stress + elastic_stress_increment(mod, strain_increment);
  const Sym s_trial = deviator(trial);
  const double rho_trial = norm(s_trial) / std::sqrt(2.0);
  const double p_trial = trace(trial) / 3.0;
  const double f_trial = rho_trial - 3.0 * m.alpha * p_trial - m.k;
  if (f_trial <= 0.0) {
    point.stress = trial;
    if (tangent) *tangent = elastic_stiffness(mod);
    return false;
  }
  const Sym one = identity_tensor();
  const double A = mod.G + 9.0 * mod.K * m.alpha * m.beta;
  const double dlambda = f_trial / A;
  if (rho_trial - mod.G * dlambda <= 0.0) {
    // The apex (alpha > 0 there: a cone with alpha = 0 never leaves sqrt(J2) = k > 0).
    const double p_apex = -m.k / (3.0 * m.alpha);
    point.stress = p_apex * one;
    point.equivalent_plastic_strain += rho_trial / (std::sqrt(3.0) * mod.G);
    if (tangent) tangent->setZero();
    return true;
  }
  const double scale = 1.0 - mod.G * dlambda / rho_trial;
  point.stress = scale * s_trial + (p_trial + 3.0 * mod.K * m.beta * dlambda) * one;
  point.equivalent_plastic_strain += dlambda / std::sqrt(3.0);
  if (tangent) {
    // d sigma = [2G scale P_dev + 2G (1 - scale) n (x) n + K 1 (x) 1 - a (x) b / A] d eps, with
    // n the trial deviator's direction, a = sqrt2 G n - 3 K beta 1 (the return's direction) and
    // b = sqrt2 G n - 3 K alpha 1 (d f_trial / d eps).
    const Sym n = s_trial / norm(s_trial);
    const Mat6 volumetric = one * one.transpose() / 3.0;
    const Sym a = std::sqrt(2.0) * mod.G * n - 3.0 * mod.K * m.beta * one;
    const Sym b = std::sqrt(2.0) * mod.G * n - 3.0 * mod.K * m.alpha * one;
    *tangent = 3.0 * mod.K * volumetric + 2.0 * mod.G * scale * (Mat6::Identity() - volumetric) +
               2.0 * mod.G * (1.0 - scale) * n * contraction_row(n) - a * contraction_row(b) / A;
  }
  return true;
}

}  // namespace acst::reference
