#pragma once
// The one error type for bad input anywhere in the project (scenes, fit descriptions, material
// parameters, command lines): its message starts with where the problem is (a JSON path such as
// /steps/2/exit/q_above, a parameter or a file) and says what is allowed.
#include <stdexcept>

namespace acst::common {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace acst::common
