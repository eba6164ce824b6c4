#pragma once
// The "material" entry of a scene or a fit description: either the material object itself
// {"model", "parameters", "integrator"} or {"file": NAME, "integrator": {...}}, a parameter file
// (relative to the describing file) whose integrator options the entry may override.
#include <nlohmann/json.hpp>
#include <string>

namespace acst::driver {

struct MaterialObject {
  nlohmann::json object;  // {model, parameters, integrator}, self-contained
  std::string source;     // "inline" or the file name as given
  std::string path;       // where errors inside `object` are reported: PATH or PATH/file (FILE)
};

// Reads the entry at JSON path `path`; checks the keys of both forms, not the values (the
// material library does). Throws common::InputError naming the path.
MaterialObject read_material_object(const nlohmann::json& j, const std::string& path, const std::string& base_dir);

}  // namespace acst::driver
