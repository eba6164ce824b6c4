#pragma once
// The step's phases as Simulation::step() runs them (docs/mpm.md, "One step"), and the wall time
// each has taken: a run's summary says where its time went, a profile without a profiler.
#include <array>
#include <chrono>
#include <cstddef>

namespace acst::mpm {

enum class StepPhase {
  regularisation,   // the footing's ramp, the regularisation's averaging, the rows that follow the footing
  time_step,        // wave speeds (every wave_speed_every steps) and the stable time step
  shape_functions,  // every particle's weights and slopes
  map_to_grid,      // mass, momentum and the micropolar rotations' inertia and spin to the nodes
  constraints,      // the nodes' constraints and velocities
  micropolar_stress,
  stress_update,    // the material's calls (both halves with update-stress-average)
  footing_contact,
  internal_force,   // internal force, body forces, walls' and constraints' reactions, accelerations
  particle_update,  // FLIP / XPIC(m) velocities and positions, the micropolar spin
  remap,            // momentum re-mapped from the new velocities
  advance,          // the footing moves on, the clock
  count
};

inline constexpr std::size_t step_phase_count = static_cast<std::size_t>(StepPhase::count);
inline constexpr std::array<const char*, step_phase_count> step_phase_names = {
    "regularisation", "time_step", "shape_functions", "map_to_grid", "constraints", "micropolar_stress",
    "stress_update", "footing_contact", "internal_force", "particle_update", "remap", "advance"};

using StepPhaseSeconds = std::array<double, step_phase_count>;

// Adds the time since the last lap (or its construction) to a phase's total.
class PhaseClock {
 public:
  explicit PhaseClock(StepPhaseSeconds& totals) : totals_(totals), last_(Clock::now()) {}
  void lap(StepPhase phase) {
    const Clock::time_point now = Clock::now();
    totals_[static_cast<std::size_t>(phase)] += std::chrono::duration<double>(now - last_).count();
    last_ = now;
  }

 private:
  using Clock = std::chrono::steady_clock;
  StepPhaseSeconds& totals_;
  Clock::time_point last_;
};

}  // namespace acst::mpm
