#include "acst_footing_tool/particle_histories.hpp"

#include <cmath>
#include <utility>

#include "acst.h"
#include "acst_mpm/material_frame.hpp"
#include "acst_mpm/simulation.hpp"

namespace acst::mpm {

TrackRecord track_record(const Simulation& sim, int k, double S_over_B) {
  const Particles& P = sim.particles();
  const std::size_t p = static_cast<std::size_t>(P.tracked[static_cast<std::size_t>(k)]);
  const double* frame = &P.track_frame[static_cast<std::size_t>(material_frame_size * k)];
  const double c = frame[0], s = frame[1];
  const AbiMaterial& m = *sim.materials()[static_cast<std::size_t>(P.material[p])];
  const double* sig = &P.stress[6 * p];
  const double* q = P.statev.data() + P.state_size * p;
  const double* F = q + m.state_index("F11");
  TrackRecord r;
  r.track = k;
  r.step = sim.step_count();
  r.time = sim.time();
  r.S_over_B = S_over_B;
  r.x = P.x[p];
  r.y = P.y[p];
  r.rotation_rad = std::atan2(-s, c);  // R = [[c, s], [-s, c]] turns clockwise by atan2(s, c)
  for (int i = 0; i < 3; ++i) r.strain[i] = frame[2 + i];
  // In-plane parts turned back; zz stays; the out-of-plane shears (xz, yz) turn as a vector.
  for (auto [tensor, out] : {std::pair{sig, r.stress}, std::pair{F, r.fabric}}) {
    double in_plane[3];
    to_material_frame(c, s, tensor[0], tensor[1], tensor[3], in_plane);
    out[0] = in_plane[0];
    out[1] = in_plane[1];
    out[2] = tensor[2];
    out[3] = in_plane[2];
    out[4] = c * tensor[4] - s * tensor[5];
    out[5] = s * tensor[4] + c * tensor[5];
  }
  double d[ACST_NDIAGNOSTICS];
  m.diagnostics(d, sig, q);
  r.A = d[6];
  r.fabric_norm = d[7];
  r.void_ratio = q[m.state_index("void_ratio")];
  r.H = q[m.state_index("H")];
  return r;
}

}  // namespace acst::mpm
