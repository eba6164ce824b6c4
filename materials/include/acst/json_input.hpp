#pragma once
// Reading parameters and integrator options from JSON, with errors that name the JSON path.
#include <nlohmann/json.hpp>
#include <string>

#include "acst/integration/options.hpp"
#include "acst/parameters.hpp"

namespace acst {

// {"G0": ..., ...}: every material constant required (the isotropic variant may omit or zero
// F0, e_A, k_f); guards p_min, h_min, R_tolerance optional; unknown keys rejected.
Parameters parameters_from_json(const nlohmann::json& j, Variant variant, const std::string& path);

// {"scheme": "ME", "stol": 1e-4, ...}; every key optional; unknown keys rejected.
integration::Options options_from_json(const nlohmann::json& j, const std::string& path);

// "ACST" or "isotropic".
Variant variant_from_json(const nlohmann::json& j, const std::string& path);

}  // namespace acst
