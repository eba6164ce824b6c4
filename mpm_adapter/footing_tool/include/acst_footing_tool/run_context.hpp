#pragma once
// What the parts of a run share (runner.cpp: the step loop; load_record.cpp: the load record;
// frames.cpp: VTK frames and contour maps; run_results.cpp: the files written at the end).
#include <filesystem>
#include <string>
#include <vector>

#include "acst_footing_tool/records.hpp"
#include "acst_footing_tool/run_options.hpp"
#include "acst_footing_tool/scene.hpp"
#include "acst_mpm/simulation.hpp"

namespace acst::mpm {

struct RunContext {
  const Scene& scene;
  const RunOptions& options;
  Simulation& sim;
  RunState& state;
  double B = 1.0;  // the footing's width (1 without a footing)

  std::string path(const std::string& name) const { return (std::filesystem::path(options.output_dir) / name).string(); }
  double S_over_B() const { return sim.footing().settlement() / B; }
  // The rows load_settlement.csv holds: every step's, or the periods'.
  const std::vector<LoadRecord>& rows() const {
    return scene.output.every_step_csv ? state.every_step : state.history;
  }
};

}  // namespace acst::mpm
