#pragma once
// A calibration as read from its JSON fit description (docs/calibration.md): the base material,
// the parameters to fit with bounds and starts (shared or one per group of tests), the
// experiments with their data, conditions, strain ranges and weights, and optimiser settings.
// Units and signs as in the lab-data files and scenes: kPa, strains in percent, compression
// positive.
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "acst_calibration/curve_axis.hpp"
#include "acst_calibration/test_type.hpp"
#include "acst_common/input_error.hpp"

namespace acst::calibration {

struct FittedParameter {
  std::string name;   // a material constant (a row of acst::parameter_table)
  std::string path;   // JSON path, for messages
  double start = 0.0, lower = 0.0, upper = 0.0;
  bool per_group = false;                // one value per group of experiments
  std::map<std::string, double> group_start;  // per-group starts (default: `start`)
};

struct ExperimentSpec {
  std::string id;             // unique; default: the data file's stem
  std::string path;           // JSON path, e.g. /experiments/3
  TestType test = TestType::drained_triaxial_compression;
  std::string group = "all";  // for per-group parameters
  std::string data_file;      // resolved path
  double sigma3_kPa = 0.0;    // confining stress during shearing
  double void_ratio = 0.0;    // at `void_ratio_at_kPa` (isotropic), or at the start of shearing
  double void_ratio_at_kPa = 0.0;  // > 0: start there and consolidate isotropically to sigma3
  double bedding_angle_deg = 0.0;
  double b = 0.0;                  // true_triaxial only
  double strain_lo_pct = 0.0, strain_hi_pct = 0.0;  // axial strain range of the points used
  double strain_increment_pct = 0.05;               // axial strain per increment of the run
  long max_cutbacks = 0;  // the most halvings of a run's increments in all (0: no limit), else a failed test
  double weight = 1.0;             // relative weight inside its test type
  bool fit_stress = true, fit_volumetric = true;
  StressMeasure stress_measure = StressMeasure::stress_ratio;
  // peak_friction: the rows whose `column` holds one of the given numbers (all rows when
  // empty), and the axial strain each row runs to while looking for the peak.
  std::map<std::string, std::vector<double>> row_filter;
  double peak_search_strain_pct = 10.0;
  // peak_friction: the table's columns of each quantity (`columns`). An empty name takes the
  // experiment's one value for every row: b, bedding_angle_deg, sigma3_kPa, void_ratio.
  std::string phi_column = "phi_deg", b_column = "b", bedding_column = "omega_deg";
  std::string sigma3_column, void_ratio_column;
  // gap_closing: the two tests (their data files, conditions and run settings, read like curve
  // experiments; the gap is the first's sigma1'/sigma3' minus the second's), the axial strains
  // the gap is taken at, and the closing's normalising scale.
  std::vector<ExperimentSpec> gap_tests;
  double gap_from_pct = 0.0, gap_to_pct = 0.0;
  double closing_scale = 1.0;
};

struct OptimizerSettings {
  int design_points = 8;    // small space-filling design evaluated before the local fits
  int starts = 2;           // local trust-region fits from the best design points (the start included)
  int max_iterations = 40;  // per local fit
  // A later local fit whose cost, after abandon_after iterations, is still above abandon_factor
  // times the best cost of the fits before it is stopped (0: never; docs/calibration.md).
  double abandon_factor = 0.0;
  int abandon_after = 5;
  double xtol = 1e-5, gtol = 1e-6, ftol = 1e-7;
  double fd_step = 1e-3;    // forward-difference step in the scaled parameters
  double penalty = 10.0;    // normalised residual of every point of a failed simulation
  int threads = 0;          // 0: all hardware threads
  unsigned seed = 1;        // of the design
};

// A fold of a cross-validation: experiments fitted without, then predicted (docs/calibration.md).
struct Fold {
  std::string name;                      // a plain stem: it names a parameter file
  std::vector<std::string> experiments;  // ids
};

struct FitSpec {
  std::string source;    // fit description file ("" when parsed from text)
  std::string base_dir;  // relative paths resolve against it
  std::string name;      // output stem
  std::string description;
  nlohmann::json material;  // {model, parameters, integrator}: fixed values and start point
  std::vector<FittedParameter> parameters;
  std::vector<ExperimentSpec> experiments;
  std::vector<std::string> groups;              // in order of first appearance
  std::map<TestType, double> type_weights;      // normalised to sum to one over the types used
  double stress_axis_weight = 0.5, volumetric_axis_weight = 0.5;  // normalised to sum to one
  OptimizerSettings optimizer;
  std::string output_dir;  // output.directory; default results/calibration/NAME (one result set per folder)
  std::string reference_group;  // whose per-group values go into the main parameter file
  std::vector<Fold> folds;      // cross_validation.folds (acst_fit --cross-validate)
};

// Reads and validates a fit description; relative paths resolve against its directory.
FitSpec read_fit_spec(const std::string& path);
FitSpec parse_fit_spec(const std::string& json_text, const std::string& base_dir, const std::string& default_name);

// Normalised weight of one experiment: its type weight times its share inside the type.
double experiment_weight(const FitSpec& spec, std::size_t experiment);

}  // namespace acst::calibration
