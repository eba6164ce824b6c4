#pragma once
// Symmetric second-order tensors in Voigt storage.
//
// Convention (stated once for the whole library, see docs/conventions.md):
//   order 11, 22, 33, 12, 13, 23;
//   every component is the TENSOR component (strain: eps_12, not gamma_12 = 2 eps_12);
//   compression positive for stress and strain inside the model.
// The double contraction a:b therefore weights the three shear slots twice.
#include <Eigen/Core>
#include <cmath>

#include "acst/inline.hpp"

namespace acst {

using Sym = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

inline Sym identity_tensor() { return (Sym() << 1, 1, 1, 0, 0, 0).finished(); }

// The tensor algebra on six numbers in Voigt order, the forms the lanes' kernel shares
// (acst/inline.hpp); the Sym forms below call them.
ACST_INLINE double trace(const double* a) { return a[0] + a[1] + a[2]; }

// d = dev(a); d may be a.
ACST_INLINE void deviator(const double* a, double* d) {
  const double m = trace(a) / 3.0;
  d[0] = a[0] - m;
  d[1] = a[1] - m;
  d[2] = a[2] - m;
  d[3] = a[3];
  d[4] = a[4];
  d[5] = a[5];
}

// a:b, the double contraction of two symmetric tensors.
ACST_INLINE double contract(const double* a, const double* b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2.0 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}

ACST_INLINE double norm(const double* a) { return std::sqrt(contract(a, a)); }

ACST_INLINE double determinant(const double* a) {
  return a[0] * (a[1] * a[2] - a[5] * a[5]) - a[3] * (a[3] * a[2] - a[5] * a[4]) +
         a[4] * (a[3] * a[5] - a[1] * a[4]);
}

// s = a.a (matrix square of a symmetric tensor), again symmetric; s may not be a.
ACST_INLINE void square(const double* a, double* s) {
  s[0] = a[0] * a[0] + a[3] * a[3] + a[4] * a[4];
  s[1] = a[3] * a[3] + a[1] * a[1] + a[5] * a[5];
  s[2] = a[4] * a[4] + a[5] * a[5] + a[2] * a[2];
  s[3] = a[0] * a[3] + a[3] * a[1] + a[4] * a[5];
  s[4] = a[0] * a[4] + a[3] * a[5] + a[4] * a[2];
  s[5] = a[3] * a[4] + a[1] * a[5] + a[5] * a[2];
}

// out = a s, component by component; out may be a.
ACST_INLINE void scaled(const double* a, double s, double* out) {
#pragma GCC unroll 13
  for (int i = 0; i < 6; ++i) out[i] = a[i] * s;
}

// The cosine of the angle between a and b, a:b / (|a| |b|); 0 where either is zero.
ACST_INLINE double cosine_between(const double* a, const double* b) {
  const double den = norm(a) * norm(b);
  return den > 0.0 ? contract(a, b) / den : 0.0;
}

inline double trace(const Sym& a) { return trace(a.data()); }

inline Sym deviator(const Sym& a) {
  Sym d;
  deviator(a.data(), d.data());
  return d;
}

inline double contract(const Sym& a, const Sym& b) { return contract(a.data(), b.data()); }

inline double norm(const Sym& a) { return norm(a.data()); }

inline double determinant(const Sym& a) { return determinant(a.data()); }

inline Sym square(const Sym& a) {
  Sym s;
  square(a.data(), s.data());
  return s;
}

inline Eigen::Matrix3d to_matrix(const Sym& a) {
  Eigen::Matrix3d m;
  m << a[0], a[3], a[4], a[3], a[1], a[5], a[4], a[5], a[2];
  return m;
}

inline Sym from_matrix(const Eigen::Matrix3d& m) {
  return (Sym() << m(0, 0), m(1, 1), m(2, 2), 0.5 * (m(0, 1) + m(1, 0)), 0.5 * (m(0, 2) + m(2, 0)),
          0.5 * (m(1, 2) + m(2, 1)))
      .finished();
}

// Q a Q^T as 3 x 3 matrices, for any rotation Q.
inline Sym rotate_general(const Sym& a, const Eigen::Matrix3d& Q) { return from_matrix(Q * to_matrix(a) * Q.transpose()); }

// Whether Q turns about axis 3 only (its third row and column are those of the identity), as
// the rotations of plane-strain hosts do.
inline bool turns_about_axis3(const Eigen::Matrix3d& Q) {
  return Q(0, 2) == 0.0 && Q(1, 2) == 0.0 && Q(2, 0) == 0.0 && Q(2, 1) == 0.0 && Q(2, 2) == 1.0;
}

// Whether a row-major rotation r turns about axis 3 only (turns_about_axis3 of the matrix).
inline bool turns_about_axis3(const double* r) {
  return r[2] == 0.0 && r[5] == 0.0 && r[6] == 0.0 && r[7] == 0.0 && r[8] == 1.0;
}

// rotate_general(a, Q) for such a Q, given its in-plane entries q00 q01 q10 q11, into out (6
// entries, not a): the same products and sums, less the terms that are exact zeros, so the same
// result (tests/materials/objectivity_test.cpp) for a fraction of the work.
inline void rotate_about_axis3(const double* a, double q00, double q01, double q10, double q11, double* out) {
  const double t00 = q00 * a[0] + q01 * a[3], t01 = q00 * a[3] + q01 * a[1];  // (Q a), rows 1 and 2
  const double t10 = q10 * a[0] + q11 * a[3], t11 = q10 * a[3] + q11 * a[1];
  const double r01 = t00 * q10 + t01 * q11, r10 = t10 * q00 + t11 * q01;
  const double r02 = q00 * a[4] + q01 * a[5], r20 = a[4] * q00 + a[5] * q01;
  const double r12 = q10 * a[4] + q11 * a[5], r21 = a[4] * q10 + a[5] * q11;
  out[0] = t00 * q00 + t01 * q01;
  out[1] = t10 * q10 + t11 * q11;
  out[2] = a[2];
  out[3] = 0.5 * (r01 + r10);
  out[4] = 0.5 * (r02 + r20);
  out[5] = 0.5 * (r12 + r21);
}

inline Sym rotate_about_axis3(const Sym& a, const Eigen::Matrix3d& Q) {
  Sym out;
  rotate_about_axis3(a.data(), Q(0, 0), Q(0, 1), Q(1, 0), Q(1, 1), out.data());
  return out;
}

// Q a Q^T for a rotation Q (objective rotation of stress and fabric).
inline Sym rotate(const Sym& a, const Eigen::Matrix3d& Q) {
  return turns_about_axis3(Q) ? rotate_about_axis3(a, Q) : rotate_general(a, Q);
}

// Row vector b such that b * eps_voigt = b_tensor : eps (shear slots doubled), for tangents.
inline Eigen::Matrix<double, 1, 6> contraction_row(const Sym& b) {
  Eigen::Matrix<double, 1, 6> row;
  row << b[0], b[1], b[2], 2.0 * b[3], 2.0 * b[4], 2.0 * b[5];
  return row;
}

}  // namespace acst
