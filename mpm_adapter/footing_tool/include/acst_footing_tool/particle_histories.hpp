#pragma once
// Strain and stress histories of chosen particles (`output/particle_histories`, docs/mpm.md
// "Particle histories"), kept in each particle's material frame (acst_mpm/material_frame.hpp) so
// that the element driver can replay them as fixed-frame strain paths.
namespace acst::mpm {

class Simulation;

// One row of a particle's history, in the material frame (ABI convention: tension positive,
// Voigt xx yy zz xy xz yz; strain in tensor components).
struct TrackRecord {
  int track = 0;  // index into Scene::output.particle_histories
  long long step = 0;
  double time = 0, S_over_B = 0, x = 0, y = 0, rotation_rad = 0;
  double strain[3] = {0, 0, 0};  // xx yy xy
  double stress[6] = {0, 0, 0, 0, 0, 0};
  double fabric[6] = {0, 0, 0, 0, 0, 0};
  double void_ratio = 0, H = 0;
  double fabric_norm = 0, A = 0;  // |F| and A = F:n (the material's diagnostics); N = A/|F|
};

// The row of followed particle k now (its material is a sand: fabric, void ratio and H by name).
TrackRecord track_record(const Simulation& sim, int k, double S_over_B);

}  // namespace acst::mpm
