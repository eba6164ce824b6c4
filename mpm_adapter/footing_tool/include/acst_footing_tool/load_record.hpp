#pragma once
// The load record of a run: the footing's loads every step, averaged over each XPIC period, the
// followed particles' rows, the snapshot at the peak and the quasi-static check.
#include <string>

#include "acst_footing_tool/run_context.hpp"

namespace acst::mpm {

// After each step: adds the step's loads to the period's sums (and its row, with every_step_csv)
// and closes the period once it holds xpic_every steps.
void record_step(RunContext& run);
// The period's mean loads as a row; the peak's snapshot where the row's V is the largest yet.
// Throws SimulationError when the row fails the quasi-static check with on_excess "stop".
void close_period(RunContext& run);
// Every followed particle's row now.
void record_tracks(RunContext& run);

// Kinetic energy over the footing's work for a row past the check's start (0 before it).
double kinetic_ratio(const Scene& scene, const LoadRecord& row);
std::string quasi_static_message(const Scene& scene, const LoadRecord& row);

}  // namespace acst::mpm
