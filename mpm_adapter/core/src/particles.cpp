#include "acst_mpm/particles.hpp"

namespace acst::mpm {

void Particles::resize(std::size_t count, int nstate) {
  n = count;
  state_size = nstate;
  for (auto* v : {&x, &y, &x_initial, &y_initial, &vx, &vy, &mass, &weight_mass, &volume_initial, &density,
                  &surcharge_length, &side_length, &wave_speed})
    v->assign(n, 0.0);
  F.assign(4 * n, 0.0);
  for (std::size_t p = 0; p < n; ++p) F[4 * p] = F[4 * p + 3] = 1.0;
  stress.assign(6 * n, 0.0);
  strain.assign(3 * n, 0.0);
  statev.assign(static_cast<std::size_t>(nstate) * n, 0.0);
  material.assign(n, 0);
  stress_free.assign(n, 0);
}

double Particles::volume(std::size_t p) const {
  const double* f = &F[4 * p];
  return volume_initial[p] * (f[0] * f[3] - f[1] * f[2]);
}

}  // namespace acst::mpm
