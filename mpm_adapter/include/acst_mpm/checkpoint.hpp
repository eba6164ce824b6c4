#pragma once
// Checkpoints: the whole evolving state of a run (simulation and run record) in one binary
// file, written atomically. Resuming with the same scene and thread count continues bit for
// bit as if never interrupted.
#include <string>

#include "acst_mpm/runner.hpp"

namespace acst::mpm {

void write_checkpoint(const std::string& path, const Scene& scene, const Simulation& sim, const RunState& state);

// Loads into a simulation built from the same scene; throws common::InputError when the file
// cannot be read (missing, not a regular file, too large), SimulationError when it is truncated,
// or was written for another scene or particle count.
void read_checkpoint(const std::string& path, const Scene& scene, Simulation& sim, RunState& state);

}  // namespace acst::mpm
