#pragma once
// The ONE place where the C ABI's convention (tension positive, engineering shear strain,
// Voigt 11 22 33 12 13 23, row-major tangent) is converted to and from the model's
// (compression positive, tensor shear strain). Both acst_* functions and umat_ use it.
#include "acst/tensor.hpp"

namespace acst::abi {

inline Sym stress_to_model(const double* s) { return -Eigen::Map<const Sym>(s); }

inline void stress_from_model(const Sym& s, double* out) {
  Eigen::Map<Sym> o(out);
  o = -s;
}

inline Sym strain_to_model(const double* e) {
  Sym m = -Eigen::Map<const Sym>(e);
  m.tail<3>() *= 0.5;  // engineering gamma_ij = 2 eps_ij
  return m;
}

// d(-sigma)/d(-gamma): the signs cancel; a shear column halves because eps_ij = gamma_ij / 2.
inline void tangent_from_model(const Mat6& D, double* out_row_major) {
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) out_row_major[6 * i + j] = D(i, j) * (j < 3 ? 1.0 : 0.5);
}

}  // namespace acst::abi
