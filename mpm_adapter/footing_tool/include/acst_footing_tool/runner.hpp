#pragma once
// Runs a scene to its stop: the step loop, the load record (every step, averaged over each
// XPIC period), VTK frames, contour figures, checkpoints, the summary and the progress line.
#include <string>
#include <vector>

#include "acst_footing_tool/scene.hpp"

namespace acst::mpm {

struct RunOptions {
  std::string output_dir;
  bool quiet = false, plot = true;
  std::string resume_from;  // checkpoint file
};

struct RunSummary {
  long long steps = 0;
  double wall_s = 0, particle_steps_per_s = 0;
  double Q_ult = 0, S_ult = 0, S_ult_over_B = 0, residual_V = 0;
  bool peak_reached = false;
  std::vector<std::string> warnings;
};

RunSummary run_scene(const Scene& scene, const RunOptions& options);

}  // namespace acst::mpm
