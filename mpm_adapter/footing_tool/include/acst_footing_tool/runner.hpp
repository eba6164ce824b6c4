#pragma once
// Runs a scene to its stop: the step loop, the load record (every step, averaged over each
// XPIC period), VTK frames, contour figures, checkpoints, the summary and the progress line.
#include "acst_footing_tool/run_options.hpp"
#include "acst_footing_tool/scene.hpp"

namespace acst::mpm {

RunSummary run_scene(const Scene& scene, const RunOptions& options);

}  // namespace acst::mpm
