#pragma once
#include <stdexcept>
#include <string>

namespace acst::mpm {

// What stops a run: a material failure (with the scene acst_element replays), a particle off the
// grid, a non-finite state. The step's units return failures by value; Simulation names the
// step and the particle and throws this.
struct SimulationError : std::runtime_error {
  using std::runtime_error::runtime_error;
  SimulationError(const std::string& what, std::string replay) : std::runtime_error(what), reproducer(std::move(replay)) {}
  std::string reproducer;  // for a material failure: the scene acst_element replays ("" otherwise)
};

}  // namespace acst::mpm
