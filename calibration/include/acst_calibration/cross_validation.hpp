#pragma once
// Cross-validation of a fit description (docs/calibration.md, "Cross-validation"): each fold of
// experiments is fitted without, then predicted with the set fitted to the rest; beside it, the
// same experiments' errors in the fit of all of them. The difference is what a fit's error hides.
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "acst_calibration/fit_spec.hpp"
#include "acst_calibration/report.hpp"

namespace acst::calibration {

struct FoldResult {
  Fold fold;
  int training_experiments = 0;
  double training_cost = 0.0;
  nlohmann::json values;  // the training fit's values, label -> value
  // Groups of the fold with no experiment left to fit: their per-group values are the training
  // fit's reference group's.
  std::vector<std::string> borrowed_groups;
  std::vector<ExperimentError> predicted;  // the fold's experiments, predicted by the training fit
  std::vector<ExperimentError> fitted;     // the same, as fitted with every experiment
  nlohmann::json material;                 // the training fit's material (its reference group)
};

struct CrossValidation {
  double all_data_cost = 0.0;
  nlohmann::json all_data_values;  // label -> value
  std::vector<FoldResult> folds;
  double seconds = 0.0;
};

// `description` is the fit description as read (its folds already checked into spec.folds).
// `progress` gets one line per finished fit.
CrossValidation cross_validate(const nlohmann::json& description, const FitSpec& spec,
                               const std::function<void(const std::string&)>& progress);

// Root mean square of the normalised errors over all points of `errors` (a failed run counts
// its points at the penalty).
double pooled_rms_normalised(const std::vector<ExperimentError>& errors);

// NAME_cv_report.md / .json, NAME_cv_FOLD_parameters.json per fold, NAME_cv.csv and NAME_cv.png
// (fitted against predicted error per fold), published into `directory` as a whole. Returns
// warnings (gnuplot); throws std::runtime_error when a file cannot be written.
bool is_cross_validation_output_name(const std::string& fit_name, const std::string& entry);
std::vector<std::string> write_cross_validation(const CrossValidation& cv, const FitSpec& spec, const std::string& directory,
                                                bool plot);

}  // namespace acst::calibration
