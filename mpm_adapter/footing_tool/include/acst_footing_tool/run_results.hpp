#pragma once
// The files a run writes at its end (docs/mpm.md, "Outputs"): load_settlement.csv with its
// figure, the particle histories with theirs, the maps at the peak and summary.json.
#include "acst_footing_tool/run_context.hpp"

namespace acst::mpm {

// particle_NAME.csv of every followed particle (also after a failure: the rows so far).
void write_tracks(const RunContext& run);
// The load record, the histories, the figures and summary.json; fills the summary's peak,
// residual load and warnings (quasi-static check, figures that could not be drawn).
void write_results(const RunContext& run, RunSummary& summary);

}  // namespace acst::mpm
