#pragma once
// Isotropic linear elasticity: a verification material with a closed-form update.
// Model convention (compression positive, tensor shear strain, kPa; docs/conventions.md).
#include "acst/elasticity.hpp"
#include "acst/tensor.hpp"

namespace acst::reference {

struct LinearElastic {
  double E;   // Young's modulus, kPa, > 0
  double nu;  // Poisson's ratio, in (-1, 0.5)
};

inline ElasticModuli moduli(const LinearElastic& m) {
  return {m.E / (2.0 * (1.0 + m.nu)), m.E / (3.0 * (1.0 - 2.0 * m.nu))};
}

inline Mat6 stiffness(const LinearElastic& m) { return elastic_stiffness(moduli(m)); }

inline Sym updated_stress(const LinearElastic& m, const Sym& stress, const Sym& strain_increment) {
  return stress + elastic_stress_increment(moduli(m), strain_increment);
}

}  // namespace acst::reference
