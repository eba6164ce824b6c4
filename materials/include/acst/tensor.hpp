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

namespace acst {

using Sym = Eigen::Matrix<double, 6, 1>;
using Mat6 = Eigen::Matrix<double, 6, 6>;

inline Sym identity_tensor() { return (Sym() << 1, 1, 1, 0, 0, 0).finished(); }

inline double trace(const Sym& a) { return a[0] + a[1] + a[2]; }

inline Sym deviator(const Sym& a) {
  Sym d = a;
  const double m = trace(a) / 3.0;
  d[0] -= m;
  d[1] -= m;
  d[2] -= m;
  return d;
}

// a:b, the double contraction of two symmetric tensors.
inline double contract(const Sym& a, const Sym& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + 2.0 * (a[3] * b[3] + a[4] * b[4] + a[5] * b[5]);
}

inline double norm(const Sym& a) { return std::sqrt(contract(a, a)); }

inline double determinant(const Sym& a) {
  return a[0] * (a[1] * a[2] - a[5] * a[5]) - a[3] * (a[3] * a[2] - a[5] * a[4]) +
         a[4] * (a[3] * a[5] - a[1] * a[4]);
}

// a.a (matrix square of a symmetric tensor), again symmetric.
inline Sym square(const Sym& a) {
  Sym s;
  s[0] = a[0] * a[0] + a[3] * a[3] + a[4] * a[4];
  s[1] = a[3] * a[3] + a[1] * a[1] + a[5] * a[5];
  s[2] = a[4] * a[4] + a[5] * a[5] + a[2] * a[2];
  s[3] = a[0] * a[3] + a[3] * a[1] + a[4] * a[5];
  s[4] = a[0] * a[4] + a[3] * a[5] + a[4] * a[2];
  s[5] = a[3] * a[4] + a[1] * a[5] + a[5] * a[2];
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

// Q a Q^T for a rotation Q (objective rotation of stress and fabric).
inline Sym rotate(const Sym& a, const Eigen::Matrix3d& Q) { return from_matrix(Q * to_matrix(a) * Q.transpose()); }

// Row vector b such that b * eps_voigt = b_tensor : eps (shear slots doubled), for tangents.
inline Eigen::Matrix<double, 1, 6> contraction_row(const Sym& b) {
  Eigen::Matrix<double, 1, 6> row;
  row << b[0], b[1], b[2], 2.0 * b[3], 2.0 * b[4], 2.0 * b[5];
  return row;
}

}  // namespace acst
