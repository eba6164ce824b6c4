#pragma once
// Pressure-dependent hypoelasticity, isotropic or cross-anisotropic from the fabric
// (docs/model.md section 2).
#include <Eigen/Core>
#include <cmath>

#include "acst/inline.hpp"
#include "acst/parameters.hpp"
#include "acst/tensor.hpp"

namespace acst {

// D_e : eps = P (D_iso : (P eps P)) P, with D_iso the isotropic stiffness of G and K and P = I
// unless the option elastic_anisotropy is on. A congruence of D_iso: symmetric and positive
// definite whenever D_iso is.
struct ElasticModuli {
  double G;  // shear modulus (of D_iso), kPa
  double K;  // bulk modulus (of D_iso), kPa
  bool anisotropic = false;
  Eigen::Matrix3d P{};  // read only when anisotropic ({} leaves it unset: the hot isotropic path)
  double P_max = 1.0;  // largest eigenvalue of P
};

// G = G0 pa (2.97 - e)^2 / (1 + e) sqrt(p/pa), evaluated at max(p, p_min) (2.97: void_ratio_limit).
ACST_INLINE double shear_modulus(double G0, double p_min, double e, double p) {
  const double pa = atmospheric_pressure;
  const double d = void_ratio_limit - e;
  return G0 * pa * d * d / (1.0 + e) * std::sqrt(normalised_pressure(p, p_min));
}

inline double shear_modulus(const Parameters& prm, double e, double p) { return shear_modulus(prm.G0, prm.p_min, e, p); }

// K = G 2(1 + nu) / (3(1 - 2nu)).
ACST_INLINE double bulk_modulus(double G, double nu) { return G * 2.0 * (1.0 + nu) / (3.0 * (1.0 - 2.0 * nu)); }

// P = exp(a sqrt(6)/12 F). For a fabric F = |F| (3 b b^T - I)/sqrt(6) the stiffness is Graham &
// Houlsby's (1983) cross-anisotropy about b, with Young's modulus along b exp(a |F|) times the
// one across it; det P = 1 (F is deviatoric), so a scales no volume. Sets P, P_max and
// anisotropic. Out of line (src/elasticity.cpp): the eigensolver is large code.
void set_fabric_stretch(ElasticModuli& mod, double a, const Sym& F);

// Sets the moduli at (e, p) and, with elastic_anisotropy, the fabric F, in place: a copy of the
// moduli would copy P, unset on the isotropic path (the plastic quantities set theirs this way).
inline void set_elastic_moduli(ElasticModuli& mod, const Parameters& prm, double e, double p, const Sym& F) {
  mod.G = shear_modulus(prm, e, p);
  mod.K = bulk_modulus(mod.G, prm.nu);
  if (prm.elastic_anisotropy != 0.0) set_fabric_stretch(mod, prm.elastic_anisotropy, F);
}

inline ElasticModuli elastic_moduli(const Parameters& prm, double e, double p, const Sym& F) {
  ElasticModuli mod;
  set_elastic_moduli(mod, prm, e, p, F);
  return mod;
}

// The isotropic moduli (no fabric at hand: nominal tangents).
inline ElasticModuli isotropic_elastic_moduli(const Parameters& prm, double e, double p) {
  const double G = shear_modulus(prm, e, p);
  return {G, bulk_modulus(G, prm.nu)};
}

// d sigma = 2G de_dev + K d eps_v I, into ds.
ACST_INLINE void isotropic_stress_increment(double G, double K, const double* deps, double* ds) {
  const double dev_v = trace(deps);
  deviator(deps, ds);
#pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) ds[i] = 2.0 * G * ds[i];
  ds[0] += K * dev_v;
  ds[1] += K * dev_v;
  ds[2] += K * dev_v;
}

inline Sym isotropic_stress_increment(double G, double K, const Sym& deps) {
  Sym ds;
  isotropic_stress_increment(G, K, deps.data(), ds.data());
  return ds;
}

// d sigma = D_e : d eps.
inline Sym elastic_stress_increment(const ElasticModuli& mod, const Sym& deps) {
  if (!mod.anisotropic) return isotropic_stress_increment(mod.G, mod.K, deps);
  const Eigen::Matrix3d& P = mod.P;
  const Sym inner = isotropic_stress_increment(mod.G, mod.K, from_matrix(P * to_matrix(deps) * P));
  return from_matrix(P * to_matrix(inner) * P);
}

// The elastic stiffness as a matrix acting on Voigt strain with tensor shear components.
inline Mat6 elastic_stiffness(const ElasticModuli& mod) {
  Mat6 D = Mat6::Zero();
  if (mod.anisotropic) {
    for (int j = 0; j < 6; ++j) D.col(j) = elastic_stress_increment(mod, Sym::Unit(j));
    return D;
  }
  const double lam = mod.K - 2.0 * mod.G / 3.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) D(i, j) = lam;
    D(i, i) += 2.0 * mod.G;
    D(i + 3, i + 3) = 2.0 * mod.G;
  }
  return D;
}

// The largest P-wave modulus over all directions, for explicit time steps: K + 4G/3 when
// isotropic; with P, (Pv)(x)(Pn) bounds the strain of a wave along n polarised along v, so
// (K + 4G/3) P_max^4 bounds it (nu >= 0), reached along P's major axis.
inline double constrained_modulus(const ElasticModuli& mod) {
  const double p2 = mod.P_max * mod.P_max;
  return (mod.K + 4.0 * mod.G / 3.0) * p2 * p2;
}

}  // namespace acst
