#include "acst_driver/axial_symmetry.hpp"

#include <Eigen/QR>
#include <algorithm>

namespace acst::driver {

Sym mirrored_23(const Sym& a) {
  Sym m = a;
  std::swap(m[1], m[2]);
  std::swap(m[3], m[4]);
  return m;
}

Sym symmetrized_23(const Sym& a) { return 0.5 * (a + mirrored_23(a)); }

bool symmetric_23(const Sym& a) { return a[1] == a[2] && a[3] == a[4]; }

bool symmetric_23(const State& s) { return symmetric_23(s.stress) && symmetric_23(s.fabric); }

namespace {

using Row = Eigen::Matrix<double, 1, 12>;

// Each mirrored row is one of the rows or its negative, with the same value (or its negative):
// the common case (triaxial, oedometric, strain rows), without a factorisation.
bool rows_map_onto_rows(const Eigen::Matrix<double, 6, 12>& rows, const Eigen::Matrix<double, 6, 12>& mirrored, const Sym& c) {
  for (int i = 0; i < 6; ++i) {
    bool found = false;
    for (int j = 0; j < 6 && !found; ++j)
      for (const double s : {1.0, -1.0})
        found = found || (Row(mirrored.row(i)) == s * Row(rows.row(j)) && c[i] == s * c[j]);
    if (!found) return false;
  }
  return true;
}

}  // namespace

bool symmetric_23(const LinearControl& c) {
  Eigen::Matrix<double, 6, 12> rows, mirrored;
  rows << c.A, c.B;
  for (int i = 0; i < 6; ++i) mirrored.row(i) << mirrored_23(c.A.row(i).transpose()).transpose(),
                                 mirrored_23(c.B.row(i).transpose()).transpose();
  if (rows_map_onto_rows(rows, mirrored, c.c)) return true;
  // Otherwise the mirrored constraints must lie in the span of the rows (isotropic and p-q steps:
  // sigma_11 - sigma_22 mirrors to a sum of two rows). T combines the rows into the mirrored
  // ones; 1e-12 on the O(1) coefficients, and on c relative to its largest value, since c
  // carries the state's round-off.
  const Eigen::Matrix<double, 6, 6> T =
      rows.transpose().completeOrthogonalDecomposition().solve(mirrored.transpose()).transpose();
  const double scale = std::max(1.0, c.c.cwiseAbs().maxCoeff());
  return (mirrored - T * rows).cwiseAbs().maxCoeff() <= 1e-12 && (T * c.c - c.c).cwiseAbs().maxCoeff() <= 1e-12 * scale;
}

}  // namespace acst::driver
