#pragma once
// Layout of the state-variable arrays of each model kind, shared by the acst_* functions and umat_.
#include <Eigen/Core>

#include "acst/state.hpp"

namespace acst::abi {

inline constexpr int state_size = 10;
inline constexpr const char* state_names[state_size] = {
    "F11", "F22", "F33", "F12", "F13", "F23", "void_ratio", "H", "substep_hint", "pressure_floor_resets"};

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

// The fabric tensor is the only tensorial entry: it turns with the material (F -> Q F Q^T).
inline void rotate_tensorial_state(double* statev, const Eigen::Matrix3d& Q) {
  Eigen::Map<Sym> fabric(statev);
  fabric = rotate(fabric, Q);
}

// linear_elastic has no state; von_mises one scalar.
inline constexpr int von_mises_state_size = 1;
inline constexpr const char* von_mises_state_names[von_mises_state_size] = {"equivalent_plastic_strain"};

}  // namespace acst::abi
