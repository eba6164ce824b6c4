#pragma once
// Strain and stress histories of chosen particles, written so that the element driver can replay
// them (`output/particle_histories`, docs/mpm.md "Particle histories").
//
// The MPM turns each particle's stress and fabric with its spin before every material update
// (Hughes-Winget, in-plane). The material answers the same to a rotated state and strain
// increment as to the unrotated ones, so the history is kept in the particle's material frame:
// the frame it had at the start, turned with it. There the state never rotates and the strain
// is the sum of the increments the material saw, turned back: a fixed-frame strain path that
// acst_element replays as it stands.
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

// Per tracked particle in Particles::track_frame: cos and sin of its accumulated rotation, then
// its strain in the material frame (xx yy xy, tensor).
inline constexpr int track_frame_size = 5;

// Follows one tracked particle over a half step with velocity gradient L (row-major, L_ij =
// dv_i/dx_j), turning its frame by the material update's rotation (hughes_winget_rotation).
void follow_track(double* frame, const double* L, double dt);

// The row of tracked particle k now (its material is a sand: fabric, void ratio and H by name).
TrackRecord track_record(const Simulation& sim, int k, double S_over_B);

}  // namespace acst::mpm
