#pragma once
// Reading the "steps" array of a scene into blocks of steps with six control rows each.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "acst_driver/scene.hpp"

namespace acst::driver {

// `base_dir` resolves the file of a strain_path_csv step.
std::vector<Block> read_steps(const nlohmann::json& steps, const std::string& path, const std::string& base_dir);

// The preset names a step may use, for messages and --help.
const std::vector<std::string>& preset_names();

}  // namespace acst::driver
