#pragma once
// The material's phase of the step (docs/mpm.md, "One step"): every particle's deformation
// gradient, strain and stress over dt from its velocity gradient, the material called through the
// C ABI in runs of one material, the regularisation's offsets handed with each call, and the
// followed particles' material frames turned.
#include <memory>
#include <string>
#include <vector>

#include "acst_mpm/grid.hpp"
#include "acst_mpm/material_adapter.hpp"
#include "acst_mpm/particles.hpp"
#include "acst_mpm/regulariser.hpp"
#include "acst_mpm/step_scratch.hpp"

namespace acst::mpm {

// The first refused update (in thread order): its particle (-1: none), the material's message and
// the scene acst_element replays.
struct MaterialFailure {
  long long particle = -1;
  std::string message, reproducer;
};

// `cell_averaged`: each dilation rate the mean over its cell's particles (docs/mpm.md,
// "Volumetric locking"); vx, vy the nodal velocities. On a failure the followed particles' frames
// are left as they were.
MaterialFailure update_material_points(Particles& P, const std::vector<std::shared_ptr<const AbiMaterial>>& materials,
                                       const Regulariser& regulariser, const Grid& grid, bool cell_averaged,
                                       StepScratch& w, const double* vx, const double* vy, double dt);

}  // namespace acst::mpm
