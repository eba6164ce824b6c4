#include "acst/update_lanes.hpp"

#include "update_lanes_kernel.hpp"

namespace acst {

#if !defined(ACST_LANES_OFF)
namespace {

lanes::Constants constants_of(const Material& material) {
  const Parameters& p = material.parameters();
  return {p, material.options(), lode_shape(p).form == LodeForm::willam_warnke};
}

}  // namespace
#endif

void put_lane(UpdateLanes& lanes, int l, const State& state, const Sym& strain_increment, double void_ratio_offset) {
  for (int i = 0; i < 6; ++i) {
    lanes.stress[i][l] = state.stress[i];
    lanes.fabric[i][l] = state.fabric[i];
    lanes.strain_increment[i][l] = strain_increment[i];
  }
  lanes.void_ratio[l] = state.void_ratio;
  lanes.H[l] = state.H;
  lanes.substep_hint[l] = state.substep_hint;
  lanes.void_ratio_offset[l] = void_ratio_offset;
}

void take_lane(const UpdateLanes& lanes, int l, State& state) {
  for (int i = 0; i < 6; ++i) {
    state.stress[i] = lanes.stress[i][l];
    state.fabric[i] = lanes.fabric[i][l];
  }
  state.void_ratio = lanes.void_ratio[l];
  state.H = lanes.H[l];
  state.substep_hint = lanes.substep_hint[l];
}

bool lanes_apply(const Material& material) {
#if defined(ACST_LANES_OFF)
  (void)material;
  return false;
#else
  return material.options().scheme == integration::Scheme::modified_euler &&
         material.parameters().elastic_anisotropy == 0.0 && material.options().max_substeps >= 1;
#endif
}

void update_lanes(const Material& material, UpdateLanes& lanes, LaneBuild build) {
  const int n = lanes.n;
  for (int l = 0; l < UpdateLanes::width; ++l) lanes.done[l] = 0;
  if (n <= 0 || n > UpdateLanes::width || !lanes_apply(material)) return;
  // The unused lanes repeat lane 0, so that they compute on numbers (and are never done).
  for (int l = n; l < UpdateLanes::width; ++l) {
    for (int i = 0; i < 6; ++i) {
      lanes.stress[i][l] = lanes.stress[i][0];
      lanes.fabric[i][l] = lanes.fabric[i][0];
      lanes.strain_increment[i][l] = lanes.strain_increment[i][0];
    }
    lanes.void_ratio[l] = lanes.void_ratio[0];
    lanes.void_ratio_offset[l] = lanes.void_ratio_offset[0];
    lanes.H[l] = lanes.H[0];
    lanes.substep_hint[l] = lanes.substep_hint[0];
  }
#if !defined(ACST_LANES_OFF)
  const lanes::Constants k = constants_of(material);
  // The x86-64-v3 copy (AVX2 and FMA, built without contraction: the same numbers) where the CPU
  // has it: a vector holds four lanes there, two in the generic copy.
  if (build == LaneBuild::best && __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma"))
    return lanes::x86_64_v3::update(k, lanes);
  lanes::generic::update(k, lanes);
#else
  (void)build;
#endif
}

}  // namespace acst
