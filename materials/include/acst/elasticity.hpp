#pragma once
// Pressure-dependent hypoelasticity (docs/model.md section 2).
#include <algorithm>
#include <cmath>

#include "acst/parameters.hpp"
#include "acst/tensor.hpp"

namespace acst {

struct ElasticModuli {
  double G;  // shear modulus, kPa
  double K;  // bulk modulus, kPa
};

// G = G0 pa (2.97 - e)^2 / (1 + e) sqrt(p/pa), evaluated at max(p, p_min) (2.97: void_ratio_limit).
inline double shear_modulus(const Parameters& prm, double e, double p) {
  const double pa = atmospheric_pressure;
  const double d = void_ratio_limit - e;
  return prm.G0 * pa * d * d / (1.0 + e) * std::sqrt(std::max(p, prm.p_min) / pa);
}

// K = G 2(1 + nu) / (3(1 - 2nu)).
inline double bulk_modulus(double G, double nu) { return G * 2.0 * (1.0 + nu) / (3.0 * (1.0 - 2.0 * nu)); }

inline ElasticModuli elastic_moduli(const Parameters& prm, double e, double p) {
  const double G = shear_modulus(prm, e, p);
  return {G, bulk_modulus(G, prm.nu)};
}

// d sigma = 2G de_dev + K d eps_v I.
inline Sym elastic_stress_increment(const ElasticModuli& mod, const Sym& deps) {
  const double dev_v = trace(deps);
  Sym ds = 2.0 * mod.G * deviator(deps);
  ds[0] += mod.K * dev_v;
  ds[1] += mod.K * dev_v;
  ds[2] += mod.K * dev_v;
  return ds;
}

// The elastic stiffness as a matrix acting on Voigt strain with tensor shear components.
inline Mat6 elastic_stiffness(const ElasticModuli& mod) {
  Mat6 D = Mat6::Zero();
  const double lam = mod.K - 2.0 * mod.G / 3.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) D(i, j) = lam;
    D(i, i) += 2.0 * mod.G;
    D(i + 3, i + 3) = 2.0 * mod.G;
  }
  return D;
}

// Constrained (P-wave) modulus K + 4G/3, for explicit time steps.
inline double constrained_modulus(const ElasticModuli& mod) { return mod.K + 4.0 * mod.G / 3.0; }

}  // namespace acst
