#pragma once
// Reading parameters and integrator options from JSON, with errors that name the JSON path.
#include <nlohmann/json.hpp>
#include <string>

#include "acst/integration/options.hpp"
#include "acst/material.hpp"
#include "acst/parameters.hpp"
#include "acst/reference/drucker_prager.hpp"
#include "acst/reference/linear_elastic.hpp"
#include "acst/reference/von_mises.hpp"

namespace acst {

// {"G0": ..., ...}: every material constant required (the isotropic variant may omit or zero
// F0, e_A, k_f); guards p_min, h_min, R_tolerance optional; unknown keys rejected.
Parameters parameters_from_json(const nlohmann::json& j, Variant variant, const std::string& path);

// {"scheme": "ME", "stol": 1e-4, ...}; every key optional; unknown keys rejected.
integration::Options options_from_json(const nlohmann::json& j, const std::string& path);

// "ACST" or "isotropic".
Variant variant_from_json(const nlohmann::json& j, const std::string& path);

// {"E": kPa > 0, "nu": in (-1, 0.5)}; unknown keys rejected.
reference::LinearElastic linear_elastic_from_json(const nlohmann::json& j, const std::string& path);

// {"E", "nu", and exactly one of "yield_stress" (sigma_y) or "undrained_shear_strength" (s_u,
// sigma_y = sqrt(3) s_u)}, both kPa > 0; unknown keys rejected.
reference::VonMises von_mises_from_json(const nlohmann::json& j, const std::string& path);

// {"E", "nu", "friction_angle_deg" (phi in [0, 60)), "cohesion" (c, kPa >= 0, not both zero),
// "dilation_angle_deg" (psi in [0, phi], default phi: associated)}: the cone matched to
// Mohr-Coulomb in plane strain; unknown keys rejected.
reference::DruckerPrager drucker_prager_from_json(const nlohmann::json& j, const std::string& path);

// A material document {"model", "parameters", "integrator"} parsed and its keys checked
// (unknown keys rejected, "parameters" required); the values are each model kind's to read.
nlohmann::json model_document(const std::string& json_text);

// The ACST or isotropic material of such a document ("model" defaults to ACST).
Material material_from_document(const nlohmann::json& document);

}  // namespace acst
