#include "acst/elasticity.hpp"

#include <Eigen/Eigenvalues>

namespace acst {

void set_fabric_stretch(ElasticModuli& mod, double a, const Sym& F) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
  eig.computeDirect(to_matrix(F));
  const Eigen::Vector3d stretch = (a * std::sqrt(6.0) / 12.0 * eig.eigenvalues()).array().exp();
  mod.P = eig.eigenvectors() * stretch.asDiagonal() * eig.eigenvectors().transpose();
  mod.P_max = stretch.maxCoeff();
  mod.anisotropic = true;
}

}  // namespace acst
