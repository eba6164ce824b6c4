#pragma once
#include <stdexcept>

namespace acst::driver {

// Thrown for any invalid scene or input description (element tests, fits, MPM scenes); the
// message starts with the JSON path (e.g. /steps/2/exit/q_above).
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace acst::driver
