#pragma once
// The ONE place where the C ABI's convention (tension positive, engineering shear strain,
// Voigt 11 22 33 12 13 23, row-major tangent) is converted to and from the model's
// (compression positive, tensor shear strain). Both acst_* functions and umat_ use it.
#include "acst/tensor.hpp"

namespace acst::abi {

// Entry i of an array, converted: the whole-tensor conversions below are these, entry by entry
// (also used alone for points laid out otherwise, as SIMD lanes).
inline double stress_entry_to_model(const double* s, int i) { return -s[i]; }
inline double stress_entry_from_model(double s) { return -s; }
inline double strain_entry_to_model(const double* e, int i) {
  return i < 3 ? -e[i] : -e[i] * 0.5;  // engineering gamma_ij = 2 eps_ij
}

inline Sym stress_to_model(const double* s) {
  Sym m;
  for (int i = 0; i < 6; ++i) m[i] = stress_entry_to_model(s, i);
  return m;
}

inline void stress_from_model(const Sym& s, double* out) {
  for (int i = 0; i < 6; ++i) out[i] = stress_entry_from_model(s[i]);
}

inline Sym strain_to_model(const double* e) {
  Sym m;
  for (int i = 0; i < 6; ++i) m[i] = strain_entry_to_model(e, i);
  return m;
}

// d(-sigma)/d(-gamma): the signs cancel; a shear column halves because eps_ij = gamma_ij / 2.
inline void tangent_from_model(const Mat6& D, double* out_row_major) {
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j) out_row_major[6 * i + j] = D(i, j) * (j < 3 ? 1.0 : 0.5);
}

}  // namespace acst::abi
