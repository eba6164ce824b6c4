#include "acst_calibration/cli.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <sstream>

#include "acst_calibration/cross_validation.hpp"
#include "acst_calibration/fit_spec.hpp"
#include "acst_common/cli.hpp"
#include "acst_common/duration.hpp"
#include "acst_common/json_file.hpp"
#include "acst_common/result_folder.hpp"
#include "acst_calibration/least_squares.hpp"
#include "acst_calibration/problem.hpp"
#include "acst_calibration/report.hpp"

namespace acst::calibration {

namespace {

using WallClock = std::chrono::steady_clock;

void usage(std::ostream& o) {
  o << "Usage: acst_fit [--help] [--quiet] [--no-plot] [--output DIR] [--threads N] [--cross-validate] FIT.json\n"
       "\n"
       "Fits ACST (or isotropic) parameters to lab curves described by a JSON fit description\n"
       "(docs/calibration.md): a small design of parameter sets, then GSL trust-region least-squares\n"
       "fits from the best of them, each evaluation running every element test in parallel.\n"
       "With \"parameters\": {} nothing is fitted: the material is evaluated once (a prediction).\n"
       "Writes into the description's output.directory (default results/calibration/NAME) or DIR,\n"
       "a folder that holds nothing or an earlier result of the same fit, replaced as a whole:\n"
       "  NAME_parameters.json            the fitted material (loadable by acst_element scenes)\n"
       "  NAME_parameters_GROUP.json      one per group, when a parameter is fitted per group\n"
       "  NAME_report.md, NAME_report.json  errors per test, standard errors, 95 % intervals,\n"
       "                                  correlations, iterations, evaluations, time\n"
       "  NAME_overview.png               every fitted curve with its data\n"
       "  curves/ID.csv, ID_points.csv, ID.png, ID.gp  per experiment\n"
       "\n"
       "Options:\n"
       "  --output DIR  write into DIR\n"
       "  --threads N   element tests run on N threads (default: the description's optimizer.threads,\n"
       "                0 = all hardware threads)\n"
       "  --quiet       no progress lines\n"
       "  --no-plot     no PNG figures\n"
       "  --cross-validate  for each fold of the description's cross_validation, fit without its\n"
       "                experiments and predict them; write NAME_cv_report.md/.json, NAME_cv.png and\n"
       "                each fold's fitted set into DIR (default output.directory + _cross_validation)\n"
       "  --help        this text\n"
       "\n"
       "Exit status: 0 fitted and written; 1 the results could not be written; 2 bad command line or\n"
       "invalid fit description (then nothing is run or written).\n"
       "Example: acst_fit data/calibration/toyoura_acst_fit.json\n";
}

// acst_fit --cross-validate: the folds of the description, each fitted without and predicted.
int cross_validation_cli(const std::string& file, const common::CliArgs& cli, std::ostream& out, std::ostream& err) {
  FitSpec spec;
  nlohmann::json description;
  std::string directory;
  try {
    spec = read_fit_spec(file);
    if (spec.folds.empty()) throw common::InputError("/cross_validation: required by --cross-validate (no folds are named)");
    description = common::fields::read_json_file(file, "the fit description");
    if (cli.threads >= 0) spec.optimizer.threads = cli.threads;
    directory = cli.output.empty() ? spec.output_dir + "_cross_validation" : cli.output;
    common::require_own_folder(directory, [&](const std::string& e) { return is_cross_validation_output_name(spec.name, e); });
    common::require_replaceable_folder(directory);
  } catch (const common::InputError& e) {
    err << "acst_fit: " << file << ": " << e.what() << '\n';
    return 2;
  }
  CrossValidation cv;
  try {
    cv = cross_validate(description, spec, [&](const std::string& line) {
      if (!cli.quiet) err << "acst_fit: cross-validation of " << spec.name << ": " << line << '\n';
    });
  } catch (const common::InputError& e) {  // a fold whose training set is not a valid description
    err << "acst_fit: " << file << ": cross-validation: " << e.what() << '\n';
    return 2;
  } catch (const std::exception& e) {  // nothing was written
    err << "acst_fit: " << file << ": cross-validation failed: " << e.what() << '\n';
    return 1;
  }
  try {
    for (const auto& w : write_cross_validation(cv, spec, directory, cli.plot)) err << "acst_fit: warning: " << w << '\n';
  } catch (const std::exception& e) {
    err << "acst_fit: cannot write the cross-validation into '" << directory << "': " << e.what() << '\n';
    return 1;
  }
  if (!cli.quiet) out << "written to " << directory << "/" << spec.name << "_cv_report.md\n";
  return 0;
}

}  // namespace

int fit_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::ostringstream help;
  usage(help);
  common::CliSpec spec_cli("acst_fit", "fit description");
  spec_cli.threads = true;
  spec_cli.min_threads = 0;
  spec_cli.flag_options = {"--cross-validate"};
  common::CliArgs cli;
  const int early = common::parse_command_line(spec_cli, args, help.str(), out, err, cli);
  if (early >= 0) return early;
  const bool quiet = cli.quiet, plot = cli.plot;
  const std::string& output = cli.output;
  const std::string& file = cli.inputs.front();
  const int threads = cli.threads;

  if (cli.flags.count("--cross-validate")) return cross_validation_cli(cli.inputs.front(), cli, out, err);
  const auto t0 = WallClock::now();
  FitSpec spec;
  try {
    spec = read_fit_spec(file);
    if (threads >= 0) spec.optimizer.threads = threads;
    if (!output.empty()) spec.output_dir = output;
    // Before hours of fitting, not after: the result set replaces the folder as a whole.
    common::require_own_folder(spec.output_dir, [&](const std::string& e) { return is_fit_output_name(spec.name, e); });
    common::require_replaceable_folder(spec.output_dir);
  } catch (const common::InputError& e) {
    err << "acst_fit: " << file << ": " << e.what() << '\n';
    return 2;
  }
  std::unique_ptr<Problem> problem;
  try {
    problem = std::make_unique<Problem>(spec);
  } catch (const std::exception& e) {
    err << "acst_fit: " << file << ": " << e.what() << '\n';
    return 2;
  }
  if (!quiet)
    err << "acst_fit: " << spec.name << ": " << problem->variables().size() << " values, " << spec.experiments.size()
        << " experiments (" << problem->test_runs().size() << " element tests per evaluation), "
        << problem->residual_count() << " points, " << problem->threads() << " threads\n";

  LeastSquaresProblem ls{problem->start(), problem->lower(), problem->upper(), problem->residual_count(),
                         [&](const std::vector<Eigen::VectorXd>& thetas) { return problem->residuals(thetas); }};
  FitProgress progress = [&](const std::string& phase, int iteration, double cost, long evaluations) {
    const double s = std::chrono::duration<double>(WallClock::now() - t0).count();
    err << "  [" << phase << "] ";
    if (phase == "design") err << spec.optimizer.design_points << " points";
    else err << "iteration " << iteration << " of at most " << spec.optimizer.max_iterations << ", cost " << cost;
    err << ", " << evaluations << " evaluations, " << common::duration_text(s) << " elapsed ("
        << static_cast<long>(problem->counters().simulations.load() / std::max(s, 1e-9)) << " element tests/s)\n";
  };
  FitResult result;
  try {
    result = fit(ls, spec.optimizer, quiet ? FitProgress{} : progress);
  } catch (const common::InputError& e) {
    err << "acst_fit: " << file << ": " << e.what() << '\n';
    return 2;
  }
  std::vector<TestRunOutcome> outcomes;
  problem->residuals(result.theta, outcomes);
  bool any_ok = false;
  for (const auto& o : outcomes) any_ok = any_ok || o.ok;

  RunInfo info;
  info.threads = problem->threads();
  info.total_seconds = std::chrono::duration<double>(WallClock::now() - t0).count();
  try {
    for (const auto& w : write_outputs(*problem, result, outcomes, info, spec.output_dir, plot))
      err << "acst_fit: warning: " << w << '\n';
  } catch (const std::exception& e) {
    err << "acst_fit: cannot write the results into '" << spec.output_dir << "': " << e.what() << '\n';
    return 1;
  }
  if (!quiet) {
    out << spec.name << ": cost " << result.cost << " (RMS normalised error " << std::sqrt(result.cost) << ") after "
        << result.evaluations << " evaluations in " << common::duration_text(info.total_seconds) << "\n";
    for (std::size_t j = 0; j < problem->variables().size(); ++j) {
      const auto i = static_cast<Eigen::Index>(j);
      char line[160];
      std::snprintf(line, sizeof line, "  %-16s %10.4g  +- %-10.3g (95 %%: %.4g .. %.4g)%s\n", problem->variables()[j].label.c_str(),
                    result.theta[i], result.uncertainty.standard_error[i], result.uncertainty.ci95_lower[i],
                    result.uncertainty.ci95_upper[i], result.uncertainty.at_bound[j] ? "  at a bound" : "");
      out << line;
    }
    out << "written to " << spec.output_dir << "/" << spec.name << "_report.md\n";
  }
  if (!any_ok) {
    err << "acst_fit: every element test failed at the fitted parameters; see the report\n";
    return 1;
  }
  return 0;
}

}  // namespace acst::calibration
