#include "acst_calibration/cli.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>

#include "acst_calibration/fit_spec.hpp"
#include "acst_calibration/least_squares.hpp"
#include "acst_calibration/problem.hpp"
#include "acst_calibration/report.hpp"

namespace acst::calibration {

namespace {

using Clock = std::chrono::steady_clock;

void usage(std::ostream& o) {
  o << "Usage: acst_fit [--help] [--quiet] [--no-plot] [--output DIR] [--threads N] FIT.json\n"
       "\n"
       "Fits ACST (or isotropic) parameters to lab curves described by a JSON fit description\n"
       "(docs/calibration.md): a small design of parameter sets, then GSL trust-region least-squares\n"
       "fits from the best of them, each evaluation running every element test in parallel.\n"
       "Writes into the description's output.directory (default results/calibration) or DIR:\n"
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
       "  --help        this text\n"
       "\n"
       "Exit status: 0 fitted and written; 1 the results could not be written; 2 bad command line or\n"
       "invalid fit description (then nothing is run or written).\n"
       "Example: acst_fit data/calibration/toyoura_acst_fit.json\n";
}

std::string seconds_text(double s) {
  char buf[48];
  if (s < 60) std::snprintf(buf, sizeof buf, "%.1f s", s);
  else std::snprintf(buf, sizeof buf, "%d min %02d s", static_cast<int>(s / 60), static_cast<int>(s) % 60);
  return buf;
}

}  // namespace

int fit_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  bool quiet = false, plot = true;
  std::string output, file;
  int threads = -1;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if (a == "--help" || a == "-h") {
      usage(out);
      return 0;
    } else if (a == "--quiet") {
      quiet = true;
    } else if (a == "--no-plot") {
      plot = false;
    } else if (a == "--output" || a == "--threads") {
      if (i + 1 >= args.size()) {
        err << "acst_fit: " << a << " needs a value\n";
        return 2;
      }
      const std::string v = args[++i];
      if (a == "--output") {
        output = v;
      } else {
        char* end = nullptr;
        const long n = std::strtol(v.c_str(), &end, 10);
        if (*end != '\0' || v.empty() || n < 0 || n > 1024) {
          err << "acst_fit: --threads needs an integer in [0, 1024], got '" << v << "'\n";
          return 2;
        }
        threads = static_cast<int>(n);
      }
    } else if (!a.empty() && a[0] == '-') {
      err << "acst_fit: unknown option '" << a << "' (see --help)\n";
      return 2;
    } else if (!file.empty()) {
      err << "acst_fit: one fit description at a time (got '" << file << "' and '" << a << "')\n";
      return 2;
    } else {
      file = a;
    }
  }
  if (file.empty()) {
    usage(err);
    return 2;
  }

  const auto t0 = Clock::now();
  FitSpec spec;
  try {
    spec = read_fit_spec(file);
    if (threads >= 0) spec.optimizer.threads = threads;
    if (!output.empty()) spec.output_dir = output;
  } catch (const FitError& e) {
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
        << " experiments (" << problem->simulations().size() << " element tests per evaluation), "
        << problem->residual_count() << " points, " << problem->threads() << " threads\n";

  LeastSquaresProblem ls{problem->start(), problem->lower(), problem->upper(), problem->residual_count(),
                         [&](const std::vector<Eigen::VectorXd>& thetas) { return problem->residuals(thetas); }};
  FitProgress progress = [&](const std::string& phase, int iteration, double cost, long evaluations) {
    const double s = std::chrono::duration<double>(Clock::now() - t0).count();
    err << "  [" << phase << "] ";
    if (phase == "design") err << spec.optimizer.design_points << " points";
    else err << "iteration " << iteration << " of at most " << spec.optimizer.max_iterations << ", cost " << cost;
    err << ", " << evaluations << " evaluations, " << seconds_text(s) << " elapsed ("
        << static_cast<long>(problem->counters().simulations.load() / std::max(s, 1e-9)) << " element tests/s)\n";
  };
  FitResult result;
  try {
    result = fit(ls, spec.optimizer, quiet ? FitProgress{} : progress);
  } catch (const FitError& e) {
    err << "acst_fit: " << file << ": " << e.what() << '\n';
    return 2;
  }
  std::vector<SimulationOutcome> outcomes;
  problem->residuals(result.theta, outcomes);
  bool any_ok = false;
  for (const auto& o : outcomes) any_ok = any_ok || o.ok;

  RunInfo info;
  info.threads = problem->threads();
  info.total_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  try {
    for (const auto& w : write_outputs(*problem, result, outcomes, info, spec.output_dir, plot))
      err << "acst_fit: warning: " << w << '\n';
  } catch (const std::exception& e) {
    err << "acst_fit: cannot write the results into '" << spec.output_dir << "': " << e.what() << '\n';
    return 1;
  }
  if (!quiet) {
    out << spec.name << ": cost " << result.cost << " (RMS normalised error " << std::sqrt(result.cost) << ") after "
        << result.evaluations << " evaluations in " << seconds_text(info.total_seconds) << "\n";
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
