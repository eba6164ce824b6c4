#pragma once
// The material frame of a followed particle (output/particle_histories, docs/mpm.md "Particle
// histories"): the frame it had at the start, turned with it.
//
// The core turns each particle's stress and fabric with its spin before every material update
// (Hughes-Winget, in-plane). The material answers the same to a rotated state and strain
// increment as to the unrotated ones, so a history is kept in the material frame: there the
// state never rotates and the strain is the sum of the increments the material saw, turned back.
namespace acst::mpm {

// Per followed particle in Particles::track_frame: cos and sin of its accumulated rotation, then
// its strain in the material frame (xx yy xy, tensor).
inline constexpr int material_frame_size = 5;

// Turns a frame over a half step with velocity gradient L (row-major, L_ij = dv_i/dx_j) by the
// material update's own rotation (hughes_winget_rotation) and adds the strain increment, turned
// back into it.
void turn_material_frame(double* frame, const double* L, double dt);

// In-plane tensor T (xx, yy, xy) of the current axes in the material frame: R^T T R with
// R = [[c, s], [-s, c]] the accumulated rotation (the state now is R T_material R^T).
void to_material_frame(double c, double s, double xx, double yy, double xy, double* out);

}  // namespace acst::mpm
