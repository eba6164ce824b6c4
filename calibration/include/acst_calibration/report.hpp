#pragma once
// What a calibration leaves behind (docs/calibration.md, "Output"): the fitted material files,
// the report (JSON and Markdown: per-test and overall errors, the local fits, iterations,
// evaluations, time, standard errors, 95 % intervals and correlations), and the overlays of every
// fitted curve with its data (CSV + PNG per experiment, one overview PNG).
#include <Eigen/Core>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "acst_calibration/least_squares.hpp"
#include "acst_calibration/problem.hpp"

namespace acst::calibration {

struct AxisError {
  std::string axis;  // stress, volumetric, phi
  int points = 0;
  double rms_normalised = 0.0;  // RMS of (simulated - measured) / scale
  double rms = 0.0;             // RMS in the axis' unit (sigma1'/sigma3', kPa, %, deg)
  double max_abs = 0.0;
  double scale = 0.0;
};

struct ExperimentError {
  std::string id, test, group;
  bool ok = true;
  std::string message;     // of a failed run
  double weight = 0.0;     // normalised
  double cost_share = 0.0; // part of the total sum of squares
  std::vector<AxisError> axes;
};

std::vector<ExperimentError> experiment_errors(const Problem& problem, const std::vector<SimulationOutcome>& outcomes);

struct RunInfo {
  double total_seconds = 0.0;  // from reading the description to the end of the fit (before writing)
  int threads = 1;
};

// The material object {model, parameters, integrator} of one group at theta.
nlohmann::json fitted_material(const Problem& problem, const Eigen::VectorXd& theta, const std::string& group);

nlohmann::json report_json(const Problem& problem, const FitResult& fit, const std::vector<ExperimentError>& errors,
                           const RunInfo& info);
std::string report_markdown(const nlohmann::json& report);

// Writes every output into `directory` (created if needed): first into a scratch folder, then
// moved into place file by file, so that a failure never leaves half a result over a good one.
// Returns warnings (gnuplot missing or failed); throws std::runtime_error when a file cannot be written.
std::vector<std::string> write_outputs(const Problem& problem, const FitResult& fit,
                                       const std::vector<SimulationOutcome>& outcomes, const RunInfo& info,
                                       const std::string& directory, bool plot);

}  // namespace acst::calibration
