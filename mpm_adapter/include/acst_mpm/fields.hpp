#pragma once
// Particle fields people look at (VTK files and contour figures), derived from the particle
// arrays and the material's diagnostics. p and q are compression positive (geotechnical).
#include <string>
#include <vector>

#include "acst_mpm/simulation.hpp"

namespace acst::mpm {

struct ParticleFields {
  std::vector<double> p, q, shear_strain, displacement, void_ratio, fabric_norm, A, N;
  bool sand = false;  // void ratio and fabric fields are meaningful
};

// Maximum in-plane engineering shear strain sqrt((e_xx - e_yy)^2 + gamma_xy^2) of the
// accumulated strain.
double max_shear_strain(const double* strain);

ParticleFields particle_fields(const Simulation& sim);

}  // namespace acst::mpm
