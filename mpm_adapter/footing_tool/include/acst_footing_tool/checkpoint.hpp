#pragma once
// Checkpoints: the whole evolving state of a run (simulation and run record) in one binary file
// with a checksum and a record of the material parameters, written atomically. Resuming with the
// same scene and thread count continues bit for bit as if never interrupted.
#include <string>

#include "acst_common/input_error.hpp"
#include "acst_footing_tool/records.hpp"
#include "acst_footing_tool/scene.hpp"
#include "acst_mpm/simulation.hpp"

namespace acst::mpm {

// A checkpoint refused by read_checkpoint: bad input (exit 2) for acst_mpm --resume; for a
// sweep, a shortcut that is not there (the case runs afresh).
struct CheckpointError : common::InputError {
  using common::InputError::InputError;
};

// The most steps a checkpoint may hold: 1000 times the 1e9 a scene may ask for (scene_size.hpp;
// a run whose time step shrinks runs longer than its estimate, never so much longer), far below
// where a step count or a sum over steps would overflow.
inline constexpr long long max_checkpoint_steps = 1000000000000LL;

void write_checkpoint(const std::string& path, const Scene& scene, const Simulation& sim, const RunState& state);

// Loads into a simulation built from the same scene, or throws CheckpointError (the user's bad
// input, exit 2) and leaves `sim` and `state` untouched when the file cannot be read (missing,
// not a regular file, too large), is damaged (the checksum), truncated, of another format
// version, written for another scene, other material parameters or particle count, or holds a
// value a run cannot go on with (non-finite, an index or a step count out of range, a particle
// off the grid).
void read_checkpoint(const std::string& path, const Scene& scene, Simulation& sim, RunState& state);

}  // namespace acst::mpm
