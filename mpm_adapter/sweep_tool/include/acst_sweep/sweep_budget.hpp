#pragma once
// acst_sweep --budget MINUTES (docs/sweeps.md, "Pieces, shards and budgets"): a wall-clock limit
// for one invocation, as a batch job's walltime. A case starts only when its expected time fits
// in what is left; cases still running near the end are checkpointed, to resume on the next run.
#include <chrono>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace acst::mpm {

using SweepClock = std::chrono::steady_clock;

class SweepBudget {
 public:
  SweepBudget() = default;  // no limit
  // `minutes` from `start`; the last `reserve_s()` of it are left for checkpoints, the table,
  // the report and the figures.
  SweepBudget(double minutes, SweepClock::time_point start);
  bool limited() const { return limited_; }
  double minutes() const { return minutes_; }
  double reserve_s() const { return reserve_s_; }
  // When running cases are checkpointed and stopped.
  SweepClock::time_point deadline() const { return deadline_; }
  double left_s(SweepClock::time_point now = SweepClock::now()) const;

 private:
  bool limited_ = false;
  double minutes_ = 0.0, reserve_s_ = 0.0;
  SweepClock::time_point deadline_{};
};

// "MINUTES" of --budget: a number > 0 (fractions allowed) and at most a year; InputError naming
// --budget otherwise.
double parse_budget_minutes(const std::string& text);

// How long a case is expected to take: its expected work (particle-steps at its first time step)
// times the seconds per unit of work measured on the cases of the folder that ran whole (not
// resumed) with their threads (wall_s x threads / work, summed over them, per thread of the case
// to run), else the assumed rate below; times a margin, since a case's time step shrinks and its
// threads scale less than linearly.
struct CaseTimeEstimate {
  double seconds_per_work_thread = 0.0;  // measured or assumed
  std::size_t measured_on = 0;           // cases measured (0: assumed)
  double seconds(double work, int threads, double fraction_left = 1.0) const;
};
// 0.75 M particle-steps a second a thread: three quarters of the converged footing's measured rate
// on a slow core (docs/sweeps.md), so that the first case's estimate errs long.
inline constexpr double assumed_particle_steps_per_s_thread = 0.75e6;
inline constexpr double estimate_margin = 1.25;

// `assumed_rate`: particle-steps a second a thread before any case has run whole (0: the one above).
CaseTimeEstimate estimate_from(const std::vector<nlohmann::ordered_json>& rows, const std::vector<double>& work,
                               double assumed_rate = 0);

// What is left of an interrupted case whose checkpoint is in `partial_folder`: 1 minus the S/B its
// record reached over the stop's (1 for a stop by time or steps, or no record).
double fraction_left(const std::string& partial_folder, double stop_S_over_B);

}  // namespace acst::mpm
