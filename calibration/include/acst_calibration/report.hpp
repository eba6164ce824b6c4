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
  Axis axis = Axis::stress;
  int points = 0;
  double rms_normalised = 0.0;  // RMS of (simulated - measured) / scale
  double rms = 0.0;             // RMS in the axis' unit (sigma1'/sigma3', kPa, %, deg)
  double max_abs = 0.0;
  double mean = 0.0;            // mean of simulated - measured: the bias, in the axis' unit
  double scale = 0.0;
  double measured_mean = 0.0;   // mean of the measured values (a closing: its one lab value)
};

struct ExperimentError {
  std::string id;
  TestType test = TestType::drained_triaxial_compression;
  std::string group;
  bool ok = true;
  std::string message;     // of a failed run
  double weight = 0.0;     // normalised
  double cost_share = 0.0; // part of the total sum of squares
  std::vector<AxisError> axes;
};

std::vector<ExperimentError> experiment_errors(const Problem& problem, const std::vector<TestRunOutcome>& outcomes);

struct RunInfo {
  double total_seconds = 0.0;  // from reading the description to the end of the fit (before writing)
  int threads = 1;
};

// The material object {model, parameters, integrator} of one group at theta.
nlohmann::json fitted_material(const Problem& problem, const Eigen::VectorXd& theta, const std::string& group);

nlohmann::json report_json(const Problem& problem, const FitResult& fit, const std::vector<ExperimentError>& errors,
                           const RunInfo& info);
std::string report_markdown(const nlohmann::json& report);

// Whether `entry` (a name in the output folder) is part of a result set of the fit `fit_name`:
// what write_outputs writes, and nothing else may be in the folder it replaces.
bool is_fit_output_name(const std::string& fit_name, const std::string& entry);

// Writes the result set into a new folder beside `directory`, then puts it in the place of
// `directory` as a whole (common::publish_folder): the folder holds the whole earlier set or the
// whole new one, never a mixture, and a failure leaves the earlier set as it was. The folder may
// only hold an earlier result of the same fit (checked first by the tool, see is_fit_output_name).
// Returns warnings (gnuplot missing or failed); throws std::runtime_error when a file cannot be written.
std::vector<std::string> write_outputs(const Problem& problem, const FitResult& fit,
                                       const std::vector<TestRunOutcome>& outcomes, const RunInfo& info,
                                       const std::string& directory, bool plot);

}  // namespace acst::calibration
