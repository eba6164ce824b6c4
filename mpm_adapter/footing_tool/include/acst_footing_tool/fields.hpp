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

// How the soil left of the footing's centre line fared against the soil right of it (by where
// each particle started): the area that has sheared more than `gamma_limit` (initial particle
// areas, m^2 per metre) and the largest heave (upward displacement, m). On a symmetric half
// domain the left side is the mirror image of the right.
struct SideMeasures {
  double sheared_area_left = 0, sheared_area_right = 0, heave_left = 0, heave_right = 0;
};
inline constexpr double sheared_area_gamma = 0.05;
SideMeasures side_measures(const Particles& P, const std::vector<double>& y_now, const std::vector<double>& shear_strain,
                           double centre_x, bool mirror);

}  // namespace acst::mpm
