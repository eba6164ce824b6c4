#pragma once
// Perfectly plastic, associated von Mises plasticity on linear elasticity: a verification
// material with a closed-form update. Model convention (compression positive, tensor shear
// strain, kPa; docs/conventions.md).
#include <cmath>

#include "acst/reference/linear_elastic.hpp"

namespace acst::reference {

struct VonMises {
  LinearElastic elastic;
  double yield_stress;  // sigma_y, kPa: q at yield (sqrt(3) s_u gives max shear s_u in plane strain)
};

struct VonMisesPoint {
  Sym stress;
  double equivalent_plastic_strain;  // sum of sqrt(2/3 d eps_p : d eps_p)
};

// q = sqrt(3/2 s:s).
inline double equivalent_stress(const Sym& stress) { return std::sqrt(1.5) * norm(deviator(stress)); }

// Relative slack for stresses handed in from outside (initial states written with round-off).
inline constexpr double yield_tolerance = 1e-9;

inline bool within_yield_surface(const VonMises& m, const Sym& stress) {
  return equivalent_stress(stress) <= m.yield_stress * (1.0 + yield_tolerance);
}

// Backward Euler (radial return), which needs no iteration here: the trial deviator is scaled back
// onto q = sigma_y and the equivalent plastic strain grows by (q_trial - sigma_y) / 3G. It is the
// exact solution for increments that keep the deviatoric direction; otherwise first-order in the
// increment. Returns whether the step yielded. `tangent` (optional) receives the consistent
// tangent d sigma / d eps of this algorithm.
inline bool radial_return(const VonMises& m, VonMisesPoint& point, const Sym& strain_increment, Mat6* tangent) {
  const ElasticModuli mod = moduli(m.elastic);
  const Sym trial = point.stress + elastic_stress_increment(mod, strain_increment);
  const Sym s_trial = deviator(trial);
  const double q_trial = std::sqrt(1.5) * norm(s_trial);
  if (q_trial <= m.yield_stress) {
    point.stress = trial;
    if (tangent) *tangent = elastic_stiffness(mod);
    return false;
  }
  const double scale = m.yield_stress / q_trial;
  point.stress = trial - (1.0 - scale) * s_trial;
  point.equivalent_plastic_strain += (q_trial - m.yield_stress) / (3.0 * mod.G);
  if (tangent) {
    // Deviatoric stiffness 2G scale, less the radial direction n: moving the trial stress
    // outwards along n returns to the same point.
    const Sym n = s_trial / norm(s_trial);
    const Sym one = identity_tensor();
    const Mat6 volumetric = one * one.transpose() / 3.0;
    *tangent = 3.0 * mod.K * volumetric +
               2.0 * mod.G * scale * (Mat6::Identity() - volumetric - n * contraction_row(n));
  }
  return true;
}

}  // namespace acst::reference
