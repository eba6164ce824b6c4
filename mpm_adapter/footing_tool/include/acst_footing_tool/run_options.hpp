#pragma once
// What a run is asked to do besides its scene, and what it answers (runner.hpp).
#include <chrono>
#include <optional>
#include <string>
#include <vector>

namespace acst::mpm {

struct RunOptions {
  std::string output_dir;
  bool quiet = false, plot = true;
  std::string resume_from;  // checkpoint file
  // A wall-clock limit (a sweep's --budget): reached before the stop, the run writes its
  // checkpoint and returns with `interrupted`, its results unwritten, to be resumed later.
  std::optional<std::chrono::steady_clock::time_point> stop_at;
};

struct RunSummary {
  long long steps = 0;
  double wall_s = 0, particle_steps_per_s = 0;
  double Q_ult = 0, S_ult = 0, S_ult_over_B = 0, residual_V = 0;
  bool peak_reached = false;
  bool interrupted = false;  // stopped at RunOptions::stop_at; the checkpoint holds the run
  std::vector<std::string> warnings;
};

}  // namespace acst::mpm
