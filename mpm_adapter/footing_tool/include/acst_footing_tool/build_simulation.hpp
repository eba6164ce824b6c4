#pragma once
// A scene turned into a ready simulation (docs/mpm.md, "Scenes").
#include "acst_footing_tool/scene.hpp"
#include "acst_mpm/simulation.hpp"

namespace acst::mpm {

// Builds the grid, walls, particles (initial stress and state through the material ABI) and the
// boundaries; throws common::InputError naming the JSON path where the scene cannot be built.
Simulation build_simulation(const Scene& scene);

}  // namespace acst::mpm
