#pragma once
// The adapter between the MPM core and the material library: it reaches the material ONLY
// through the C ABI (acst.h). Per particle it turns the velocity gradient into a strain
// increment and an incremental rotation, and turns stress and fabric objectively (Hughes-Winget)
// and updates them in one call, acst_update_rotated. The MPM core stores stress in the ABI's
// convention (tension positive, Voigt xx yy zz xy xz yz, kPa): no conversion happens here.
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "acst.h"

namespace acst::mpm {

struct MaterialError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The incremental rotation of a half step, Q = (I - W/2)^-1 (I + W/2) of the in-plane spin
// W = skew(L) dt (Hughes-Winget), as cos and sin of its angle: Q = [[c, s, 0], [-s, c, 0], [0, 0, 1]]
// (L row-major, L_ij = dv_i/dx_j). The one formula for the material update and the particles'
// followed frames (material_frame.hpp), which must turn alike.
struct PlaneRotation {
  double c, s;
};
inline PlaneRotation hughes_winget_rotation(const double* L, double dt) {
  const double w = 0.5 * (L[1] - L[2]) * dt, d = 1.0 + 0.25 * w * w;
  return {(1.0 - 0.25 * w * w) / d, w / d};
}

// One material: an owning handle plus what the core needs to know about it.
class AbiMaterial {
 public:
  static constexpr int max_state_size = 64;

  // json_text: {"model": ..., "parameters": ...} as acst_model_create reads it; `name` is used
  // in messages. Throws MaterialError with the library's message.
  AbiMaterial(const std::string& name, const std::string& json_text);

  const std::string& name() const { return name_; }
  std::string kind() const;
  int state_size() const { return state_size_; }
  std::vector<std::string> state_names() const;
  const acst_model* handle() const { return model_.get(); }
  bool is_sand() const;

  // Initial state from a stress (ABI convention), void ratio and deposition direction.
  void initial_state(double* statev, double* stress, double void_ratio, const double* deposition) const;
  double void_ratio_from_relative_density(double Dr) const;
  double wave_speed(const double* stress, const double* statev, double density) const;
  // acst_diagnostics: p, q, R, sin3theta, psi, zeta, A, fabric_norm, e_c, D, Kp, G, K.
  void diagnostics(double* out, const double* stress, const double* statev) const;
  // Index of a state variable by name, -1 if the material has none.
  int state_index(const std::string& name) const;

  // Plane-strain update over dt from the velocity gradient L (row-major 2x2, L_ij = dv_i/dx_j):
  // rotates, then integrates the strain increment, retrying in up to 64 sub-increments when the
  // integrator asks for a smaller one. Returns ACST_OK or the failing status (stress and state
  // then keep their last good values, rotated); on a failure `reproducer`, when given, receives
  // the element-test scene that replays the failing increment (acst_reproducer; "" for the
  // verification kinds, which the element driver cannot run). `stress_free` is set when the
  // update ended at the material's pressure floor (the library reset the point to an isotropic
  // p_min: soil in tension or at a free surface, without stiffness; never for the verification
  // kinds, which have no floor).
  // `offset`: the nonlocal regularisation's offsets of the point (nonlocal_size() doubles: its
  // averaged quantities minus its own; acst.h, "Nonlocal regularisation"), or null for the local
  // model.
  acst_status update(double* stress, double* statev, const double* L, double dt, bool& stress_free,
                     std::string* reproducer = nullptr, const double* offset = nullptr) const;

  // update() of n <= batch_size particles at once, their stress, state and L 6, state_size and 4
  // doubles apart: one acst_update_rotated_batch call (the library updates points of the common
  // kind together in SIMD registers, with the same numbers), then update()'s retries for the
  // particles it failed. The same numbers as n calls of update(). stress_free: n flags. Returns
  // the first failing particle's index (n if none), its status in `failure` and, where asked,
  // its reproducer. `offset`: nonlocal_size() doubles a point, or null.
  static constexpr std::size_t batch_size = 16;
  std::size_t update_batch(std::size_t n, double* stress, double* statev, const double* L, double dt, int* stress_free,
                           acst_status& failure, std::string* reproducer = nullptr,
                           const double* offset = nullptr) const;

  // The quantities the material takes nonlocally (0 for the verification kinds, 1 for the sand:
  // its void ratio) and a point's local values of them.
  int nonlocal_size() const { return nonlocal_size_; }
  void nonlocal_local(double* out, const double* stress, const double* statev) const;

 private:
  // What update() does after acst_update_rotated failed: turn, update, subdivide.
  acst_status retry(double* stress, double* statev, const double* Q, const double* de, bool& stress_free,
                    std::string* reproducer, const double* offset) const;

  std::string name_;
  std::unique_ptr<acst_model, void (*)(acst_model*)> model_;
  int state_size_ = 0, nonlocal_size_ = 0;
};

}  // namespace acst::mpm
