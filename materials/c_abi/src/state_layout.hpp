#pragma once
// The sand kinds' state-variable array (ACST and isotropic), shared by their ABI kind and umat_.
#include <Eigen/Core>

#include "acst/state.hpp"
#include "model_kind.hpp"

namespace acst::abi {

inline constexpr int state_size = 10;
inline constexpr const char* state_names[state_size] = {
    "F11", "F22", "F33", "F12", "F13", "F23", "void_ratio", "H", "substep_hint", "pressure_floor_resets"};
inline constexpr int fabric_offset[] = {0};  // the fabric tensor is the only tensorial entry
inline constexpr StateLayout sand_state_layout{state_names, state_size, fabric_offset, 1};
static_assert(state_size == ACST_NSTATV, "ACST_NSTATV is the sand state size");

inline void fill_state(State& s, const double* statev) {
  for (int i = 0; i < 6; ++i) s.fabric[i] = statev[i];
  s.void_ratio = statev[6];
  s.H = statev[7];
  s.substep_hint = statev[8];
  // A counter only: an unusable value restarts it rather than making the state non-physical.
  const double resets = statev[9];
  s.pressure_floor_resets = (resets >= 0.0 && resets < 2e9) ? static_cast<int>(resets) : 0;
}

inline void store_state(const State& s, double* statev) {
  for (int i = 0; i < 6; ++i) statev[i] = s.fabric[i];
  statev[6] = s.void_ratio;
  statev[7] = s.H;
  statev[8] = s.substep_hint;
  statev[9] = s.pressure_floor_resets;
}

// Turns every tensorial entry of a layout with the material (T -> Q T Q^T).
inline void rotate_tensorial_state(double* statev, const StateLayout& layout, const Eigen::Matrix3d& Q) {
  for (int k = 0; k < layout.tensors; ++k) {
    Eigen::Map<Sym> tensor(statev + layout.tensor_offsets[k]);
    tensor = rotate(tensor, Q);
  }
}

}  // namespace acst::abi
