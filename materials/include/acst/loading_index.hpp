#pragma once
// Loading index in strain-driven form (docs/model.md section 6).
#include <cmath>

#include "acst/elasticity.hpp"
#include "acst/inline.hpp"
#include "acst/tensor.hpp"

namespace acst {

struct LoadingIndexTerms {
  double numerator;    // (D_e : g):d eps; isotropic: 2G n:de - K (n:r) d eps_v
  double denominator;  // Kp + (D_e : g):m; isotropic: Kp + 2G - sqrt(2/3) K D (n:r); must be > 0 (uniqueness)
};

// m = n + sqrt(2/27) D I: the plastic strain per unit loading index (docs/model.md section 6).
inline Sym plastic_flow_direction(const Sym& n, double D) { return n + std::sqrt(2.0 / 27.0) * D * identity_tensor(); }

// D_e : g with g = n - (n:r)/3 I, the direction of df/dsigma: L = (D_e : g):d eps / denominator.
inline Sym loading_index_gradient(const ElasticModuli& mod, const Sym& n, double n_r) {
  if (!mod.anisotropic) return 2.0 * mod.G * n - mod.K * n_r * identity_tensor();
  return elastic_stress_increment(mod, n - n_r / 3.0 * identity_tensor());
}

// The terms with isotropic D_e: [2G n:de_dev - K (n:r) d eps_v] and [Kp + 2G - sqrt(2/3) K D (n:r)].
ACST_INLINE LoadingIndexTerms isotropic_loading_index_terms(double G, double K, double Kp, double D, const double* n,
                                                            double n_r, const double* deps) {
  return {2.0 * G * contract(n, deps) - K * n_r * trace(deps), Kp + 2.0 * G - std::sqrt(2.0 / 3.0) * K * D * n_r};
}

// L = [2G n:de_dev - K (n:r) d eps_v] / [Kp + 2G - sqrt(2/3) K D (n:r)] with isotropic D_e;
// in general (D_e : g):d eps / [Kp + (D_e : g):m] (D_e is symmetric).
inline LoadingIndexTerms loading_index_terms(const ElasticModuli& mod, double Kp, double D, const Sym& n, double n_r,
                                             const Sym& deps) {
  if (!mod.anisotropic) return isotropic_loading_index_terms(mod.G, mod.K, Kp, D, n.data(), n_r, deps.data());
  const Sym b = loading_index_gradient(mod, n, n_r);
  return {contract(b, deps), Kp + contract(b, plastic_flow_direction(n, D))};
}

// <L>: the loading index where it loads, 0 where it unloads (the denominator is positive).
ACST_INLINE double loading_index(const LoadingIndexTerms& L) { return L.numerator > 0.0 ? L.numerator / L.denominator : 0.0; }

}  // namespace acst
