#pragma once
// For the calibration tests: the bundled fit descriptions' folder, and what an invalid
// description is refused with.
#include <nlohmann/json.hpp>
#include <string>

#include "acst_calibration/fit_spec.hpp"

namespace acst::test {

inline const std::string calibration_dir = std::string(ACST_SOURCE_DIR) + "/data/calibration";

// The error message of a description (relative paths against calibration_dir); "" if valid.
inline std::string fit_spec_error(const nlohmann::json& description) {
  try {
    calibration::parse_fit_spec(description.dump(), calibration_dir, "t");
  } catch (const common::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace acst::test
