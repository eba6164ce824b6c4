#include "acst_footing_tool/fields.hpp"

#include <algorithm>
#include <cmath>

#include "acst.h"

namespace acst::mpm {

double max_shear_strain(const double* e) { return std::hypot(e[0] - e[1], 2.0 * e[2]); }

ParticleFields particle_fields(const Simulation& sim) {
  const Particles& P = sim.particles();
  ParticleFields f;
  for (auto* v : {&f.p, &f.q, &f.shear_strain, &f.displacement, &f.void_ratio, &f.fabric_norm, &f.A, &f.N})
    v->assign(P.n, 0.0);
  std::vector<int> e_index;
  for (const auto& m : sim.materials()) {
    e_index.push_back(m->state_index("void_ratio"));
    f.sand = f.sand || m->is_sand();
  }
  for (std::size_t i = 0; i < P.n; ++i) {
    const AbiMaterial& m = *sim.materials()[P.material[i]];
    const double* s = &P.stress[6 * i];
    const double* q = P.statev.data() + P.state_size * i;
    double d[ACST_NDIAGNOSTICS];
    m.diagnostics(d, s, q);
    f.p[i] = d[0];
    f.q[i] = d[1];
    f.shear_strain[i] = max_shear_strain(&P.strain[3 * i]);
    f.displacement[i] = std::hypot(P.x[i] - P.x_initial[i], P.y[i] - P.y_initial[i]);
    if (m.is_sand()) {
      f.void_ratio[i] = e_index[P.material[i]] >= 0 ? q[e_index[P.material[i]]] : 0.0;
      f.A[i] = d[6];
      f.fabric_norm[i] = d[7];
      f.N[i] = d[7] > 0.0 ? d[6] / d[7] : 0.0;  // relative fabric-loading orientation
    }
  }
  return f;
}

SideMeasures side_measures(const Particles& P, const std::vector<double>& y_now, const std::vector<double>& shear_strain,
                           double centre_x, bool mirror) {
  SideMeasures m;
  for (std::size_t i = 0; i < P.n && i < y_now.size() && i < shear_strain.size(); ++i) {
    const bool left = P.x_initial[i] < centre_x;
    const double sheared = shear_strain[i] > sheared_area_gamma ? P.volume_initial[i] : 0.0;
    const double heave = std::max(0.0, y_now[i] - P.y_initial[i]);
    (left ? m.sheared_area_left : m.sheared_area_right) += sheared;
    double& h = left ? m.heave_left : m.heave_right;
    h = std::max(h, heave);
  }
  if (mirror) {
    m.sheared_area_left = m.sheared_area_right;
    m.heave_left = m.heave_right;
  }
  return m;
}

}  // namespace acst::mpm
