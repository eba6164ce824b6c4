#pragma once
// Scenes for the driver tests: JSON text around a list of steps, parsed and run through the
// library API (acst::driver). Paths are absolute, so the scenes do not depend on the directory.
#include <string>

#include "acst_driver/runner.hpp"
#include "acst_driver/scene.hpp"

namespace acst::test {

inline std::string parameter_file(const std::string& name = "toyoura_acst_guide.json") {
  return std::string(ACST_SOURCE_DIR) + "/data/parameters/" + name;
}

// A scene with the guide set, an isotropic start at p0 and e0 (bedding angle 0), the given
// steps (a JSON array text) and optional extra top-level members (",\"solver\": {...}").
inline std::string scene_json(const std::string& steps, double p0 = 100.0, double e0 = 0.7,
                              const std::string& extra = "", const std::string& material = "") {
  const std::string m = material.empty() ? "{\"file\": \"" + parameter_file() + "\"}" : material;
  return "{\"material\": " + m + ", \"initial_state\": {\"confining_pressure\": " + std::to_string(p0) +
         ", \"void_ratio\": " + std::to_string(e0) + ", \"bedding_angle_deg\": 0}, \"steps\": " + steps + extra + "}";
}

inline driver::ElementScene parse(const std::string& json) { return driver::parse_scene(json, "", "test"); }

inline driver::RunResult run(const std::string& json) { return driver::run_scene(parse(json)); }

}  // namespace acst::test
