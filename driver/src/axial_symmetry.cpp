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

bool symmetric_23(const LinearControl& c) {
  // The mirrored constraints [A P, B P | c] must lie in the row space of [A, B | c]: solve for
  // the combination T of the rows that gives them and check both sides (1e-12 on the O(1)
  // coefficients; on c relative to its largest value, since c carries the state's round-off).
  Eigen::Matrix<double, 6, 12> rows, mirrored;
  rows << c.A, c.B;
  for (int i = 0; i < 6; ++i) mirrored.row(i) << mirrored_23(c.A.row(i).transpose()).transpose(),
                                 mirrored_23(c.B.row(i).transpose()).transpose();
  const Eigen::Matrix<double, 6, 6> T =
      rows.transpose().completeOrthogonalDecomposition().solve(mirrored.transpose()).transpose();
  const double scale = std::max(1.0, c.c.cwiseAbs().maxCoeff());
  return (mirrored - T * rows).cwiseAbs().maxCoeff() <= 1e-12 && (T * c.c - c.c).cwiseAbs().maxCoeff() <= 1e-12 * scale;
}

}  // namespace acst::driver
