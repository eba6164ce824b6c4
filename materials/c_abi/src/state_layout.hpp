#pragma once
// The sand kinds' state-variable array (ACST and isotropic), shared by their ABI kind and umat_.
#include <Eigen/Core>

#include "acst/state.hpp"
#include "model_kind.hpp"

namespace acst::abi {

// Where each state variable lives in STATEV: the one table the names, the size, the rotation
// and the copies to and from acst::State below derive from.
enum SandSlot : int { slot_fabric = 0, slot_void_ratio = 6, slot_H, slot_substep_hint, slot_floor_resets, state_size };
inline constexpr const char* state_names[state_size] = {
    "F11", "F22", "F33", "F12", "F13", "F23", "void_ratio", "H", "substep_hint", "pressure_floor_resets"};
inline constexpr int fabric_offset[] = {slot_fabric};  // the fabric tensor is the only tensorial entry
inline constexpr StateLayout sand_state_layout{state_names, state_size, fabric_offset, 1};
static_assert(state_size == ACST_NSTATV, "ACST_NSTATV is the sand state size");
static_assert(slot_void_ratio == slot_fabric + 6, "the fabric takes six Voigt slots");

// The floor-reset count as a State holds it. A counter only: an unusable value restarts it
// rather than making the state non-physical.
inline int floor_resets_of(const double* statev) {
  const double resets = statev[slot_floor_resets];
  return (resets >= 0.0 && resets < 2e9) ? static_cast<int>(resets) : 0;
}

inline void fill_state(State& s, const double* statev) {
  for (int i = 0; i < 6; ++i) s.fabric[i] = statev[slot_fabric + i];
  s.void_ratio = statev[slot_void_ratio];
  s.H = statev[slot_H];
  s.substep_hint = statev[slot_substep_hint];
  s.pressure_floor_resets = floor_resets_of(statev);
}

inline void store_state(const State& s, double* statev) {
  for (int i = 0; i < 6; ++i) statev[slot_fabric + i] = s.fabric[i];
  statev[slot_void_ratio] = s.void_ratio;
  statev[slot_H] = s.H;
  statev[slot_substep_hint] = s.substep_hint;
  statev[slot_floor_resets] = s.pressure_floor_resets;
}

// Turns every tensorial entry of a layout with the material (T -> Q T Q^T).
inline void rotate_tensorial_state(double* statev, const StateLayout& layout, const Eigen::Matrix3d& Q) {
  for (int k = 0; k < layout.tensors; ++k) {
    Eigen::Map<Sym> tensor(statev + layout.tensor_offsets[k]);
    tensor = rotate(tensor, Q);
  }
}

}  // namespace acst::abi
