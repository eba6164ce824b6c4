// Reports and overlays of a calibration (see report.hpp).
#include "acst_calibration/report.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "acst_common/files.hpp"
#include "acst_common/gnuplot.hpp"
#include "acst_common/interpolate.hpp"
#include "acst_common/name_table.hpp"
#include "acst_common/png_file.hpp"
#include "acst_common/result_folder.hpp"
#include "acst_driver/lab_data.hpp"
#include "acst_driver/number_format.hpp"
#include "acst_driver/output.hpp"

namespace acst::calibration {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

std::vector<const TestRunOutcome*> view_of(const std::vector<TestRunOutcome>& outcomes) {
  std::vector<const TestRunOutcome*> v;
  for (const auto& o : outcomes) v.push_back(&o);
  return v;
}

json number_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

std::string fmt(double v, const char* f = "%.4g") {
  if (!std::isfinite(v)) return "-";
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}

std::string axis_title(const ExperimentSpec& x, Axis axis) {
  switch (axis) {
    case Axis::phi: return "peak friction angle [deg]";
    case Axis::closing: return "sigma_1/sigma_3 [-]";
    case Axis::volumetric: return "e_v [%] (contraction +)";
    case Axis::stress: break;
  }
  return x.stress_measure == StressMeasure::q_kPa ? "sigma_1 - sigma_3 [kPa]" : "sigma_1/sigma_3 [-]";
}

// The gnuplot commands of one panel of experiment k; `dir` is where its CSV files are, seen from
// the script.
std::string panel(const Problem& problem, std::size_t k, const Series& s, std::size_t index, const std::string& dir,
                  const std::vector<const TestRunOutcome*>& view) {
  const ExperimentSpec& x = problem.spec().experiments[k];
  const std::string points = common::gp_quoted(dir + x.id + "_points.csv");
  std::ostringstream g;
  const std::string title =
      s.axis == Axis::closing
          ? x.id + ": gap(" + fmt(x.gap_to_pct) + " %) / gap(" + fmt(x.gap_from_pct) + " %) lab " + fmt(s.measured.front(), "%.3f") +
                ", fit " + fmt(problem.simulated(k, s, 0, view), "%.3f")
          : x.id + " (" + name_of(x.test) + ", " + name_of(s.axis) + ")";
  g << "set title " << common::gp_quoted(title) << " noenhanced\n";
  if (s.axis == Axis::phi) {
    // Against the void ratio where the rows have their own, else the bedding angle.
    const bool by_density = !x.void_ratio_column.empty();
    const char* xcol = by_density ? "5" : "2";
    g << (by_density ? "set xlabel 'void ratio e_0 [-]'\nset xrange [*:*]\n" : "set xlabel 'bedding angle [deg]'\nset xrange [-10:100]\n")
      << "set ylabel " << common::gp_quoted(axis_title(x, s.axis)) << "\n"
      << "plot " << points << " using " << xcol << ":6:(($3<0.1)?1:(($3>0.9)?3:2)) with points pt 7 ps 1.3 lc variable title 'lab (TC, PSC, TE)', \\\n"
      << "     " << points << " using " << xcol << ":7:(($3<0.1)?1:(($3>0.9)?3:2)) with points pt 6 ps 2 lw 2 lc variable title 'model'\n"
      << "set xrange [*:*]\n";
    return g.str();
  }
  if (s.axis == Axis::closing) {
    // Both tests' curves, simulated and measured, with the two strains the gap is taken at.
    const std::string curves = common::gp_quoted(dir + x.id + ".csv"), lab = common::gp_quoted(dir + x.id + "_lab.csv");
    g << "set xlabel 'axial strain [%]'\nset ylabel " << common::gp_quoted(axis_title(x, s.axis)) << "\nset key bottom right\n";
    for (double at : {x.gap_from_pct, x.gap_to_pct}) g << "set arrow from " << at << ", graph 0 to " << at << ", graph 1 nohead dt 2\n";
    g << "plot " << curves << " using 2:($1==0?$3:1/0) with lines lw 2 lc rgb '#1f77b4' title 'fit, first', \\\n"
      << "     " << curves << " using 2:($1==1?$3:1/0) with lines lw 2 lc rgb '#ff7f0e' title 'fit, second', \\\n"
      << "     " << lab << " using 2:($1==0?$3:1/0) with points pt 7 ps 0.8 lc rgb '#1f77b4' title 'lab, first', \\\n"
      << "     " << lab << " using 2:($1==1?$3:1/0) with points pt 5 ps 0.8 lc rgb '#ff7f0e' title 'lab, second'\n"
      << "unset arrow\nset key top left\n";
    return g.str();
  }
  const int column = s.axis == Axis::stress ? 2 : 3;
  g << "set xlabel 'axial strain [%]'\nset ylabel " << common::gp_quoted(axis_title(x, s.axis)) << "\n"
    << "plot " << common::gp_quoted(dir + x.id + ".csv") << " using 1:" << column << " with lines lw 2 lc rgb '#1f77b4' title 'fit', \\\n"
    << "     " << points << " using 2:($1==" << index << "?$3:1/0) with points pt 7 ps 0.8 lc rgb '#d62728' title 'lab'\n";
  return g.str();
}

void write_text(const fs::path& p, const std::string& text) { common::write_file_atomically(p.string(), text); }

// Runs gnuplot on `script` inside `dir` (its plots name their files relative to it), which
// writes its figure to `png` + ".tmp"; a whole PNG becomes `png`, anything else leaves no file
// in the set (the warning says why).
std::string draw_figure(const fs::path& dir, const std::string& script, const std::string& png) {
  const std::string written = (dir / (png + ".tmp")).string();
  std::string w = common::run_gnuplot_command(dir.string(), common::shell_quoted(script));
  if (w.empty()) w = common::keep_complete_png(written, (dir / png).string());
  std::remove(written.c_str());  // what a failed run left
  return w.empty() ? "" : (dir / script).string() + ": " + w;
}

}  // namespace

std::vector<ExperimentError> experiment_errors(const Problem& problem, const std::vector<TestRunOutcome>& outcomes) {
  const auto view = view_of(outcomes);
  std::vector<ExperimentError> errors;
  double total = 0.0;
  for (std::size_t k = 0; k < problem.spec().experiments.size(); ++k) {
    const ExperimentSpec& x = problem.spec().experiments[k];
    ExperimentError e;
    e.id = x.id;
    e.test = x.test;
    e.group = x.group;
    e.weight = experiment_weight(problem.spec(), k);
    for (std::size_t sim : problem.test_runs_of(k))
      if (!outcomes[sim].ok) {
        e.ok = false;
        if (e.message.empty()) e.message = outcomes[sim].message;
      }
    for (const Series& s : problem.series(k)) {
      AxisError a;
      a.axis = s.axis;
      a.points = static_cast<int>(s.x.size());
      a.scale = s.scale;
      double sum = 0.0, sum_n = 0.0;
      for (std::size_t i = 0; i < s.x.size(); ++i) {
        const double simulated = problem.simulated(k, s, i, view), d = simulated - s.measured[i];
        const double n = problem.normalised_error(s, i, simulated);
        sum += std::isfinite(d) ? d * d : NAN;
        a.mean += d;
        a.measured_mean += s.measured[i];
        sum_n += n * n;
        a.max_abs = std::max(a.max_abs, std::isfinite(d) ? std::abs(d) : INFINITY);
        e.cost_share += s.point_weight * n * n;
      }
      a.rms = std::sqrt(sum / a.points);
      a.mean /= a.points;
      a.measured_mean /= a.points;
      a.rms_normalised = std::sqrt(sum_n / a.points);
      e.axes.push_back(a);
    }
    total += e.cost_share;
    errors.push_back(e);
  }
  for (auto& e : errors) e.cost_share = total > 0.0 ? e.cost_share / total : 0.0;
  return errors;
}

json fitted_material(const Problem& problem, const Eigen::VectorXd& theta, const std::string& group) {
  json m = problem.spec().material;
  const Parameters p = problem.parameters(theta, group);
  for (const FitVariable& v : problem.variables()) m["parameters"][v.parameter] = p.*parameter_info(v.parameter)->member;
  return m;
}

json report_json(const Problem& problem, const FitResult& fit, const std::vector<ExperimentError>& errors, const RunInfo& info) {
  const FitSpec& spec = problem.spec();
  const auto& vars = problem.variables();
  const Uncertainty& u = fit.uncertainty;
  json r;
  r["name"] = spec.name;
  r["description"] = spec.description;
  r["fit_description"] = spec.source;
  r["model"] = spec.material.value("model", std::string("ACST"));
  r["objective"] = {{"sum_of_squares", fit.cost},
                    {"rms_normalised_error", std::sqrt(fit.cost)},
                    {"residuals", problem.residual_count()},
                    {"fitted_values", vars.size()},
                    {"degrees_of_freedom", u.degrees_of_freedom},
                    {"residual_variance", u.residual_variance},
                    {"condition_number", number_or_null(u.condition_number)}};
  json params = json::array(), labels = json::array();
  for (std::size_t j = 0; j < vars.size(); ++j) {
    const auto i = static_cast<Eigen::Index>(j);
    params.push_back({{"label", vars[j].label}, {"parameter", vars[j].parameter}, {"group", vars[j].group},
                      {"start", vars[j].start}, {"bounds", {vars[j].lower, vars[j].upper}}, {"value", fit.theta[i]},
                      {"standard_error", number_or_null(u.standard_error[i])},
                      {"ci95", {number_or_null(u.ci95_lower[i]), number_or_null(u.ci95_upper[i])}},
                      {"at_bound", static_cast<bool>(u.at_bound[j])}});
    labels.push_back(vars[j].label);
  }
  r["parameters"] = params;
  json corr = json::array();
  for (Eigen::Index i = 0; i < u.correlation.rows(); ++i) {
    json row = json::array();
    for (Eigen::Index j = 0; j < u.correlation.cols(); ++j) row.push_back(number_or_null(u.correlation(i, j)));
    corr.push_back(row);
  }
  r["correlation"] = {{"labels", labels}, {"matrix", corr}};
  json fixed = json::object();
  for (const auto& item : spec.material["parameters"].items()) {
    bool fitted = false;
    for (const FitVariable& v : vars) fitted = fitted || v.parameter == item.key();
    if (!fitted) fixed[item.key()] = item.value();
  }
  r["fixed"] = fixed;
  json ex = json::array();
  for (const ExperimentError& e : errors) {
    json axes = json::array();
    for (const AxisError& a : e.axes) {
      axes.push_back({{"axis", name_of(a.axis)}, {"points", a.points}, {"rms_normalised", number_or_null(a.rms_normalised)},
                      {"rms", number_or_null(a.rms)}, {"max_abs", number_or_null(a.max_abs)}, {"mean", number_or_null(a.mean)},
                      {"scale", a.scale}});
      if (a.axis == Axis::closing) axes.back()["measured"] = a.measured_mean;
    }
    ex.push_back({{"id", e.id}, {"test", name_of(e.test)}, {"group", e.group}, {"ok", e.ok}, {"message", e.message},
                  {"weight", e.weight}, {"cost_share", e.cost_share}, {"axes", axes}});
  }
  r["experiments"] = ex;
  json design = json::array();
  for (std::size_t k = 0; k < fit.design.size(); ++k) design.push_back({{"cost", fit.design_costs[k]}});
  json local = json::array();
  for (const LocalFit& l : fit.local_fits) {
    json from = json::object(), to = json::object();
    for (std::size_t j = 0; j < vars.size(); ++j) {
      from[vars[j].label] = l.from[static_cast<Eigen::Index>(j)];
      to[vars[j].label] = l.theta[static_cast<Eigen::Index>(j)];
    }
    local.push_back({{"from", from}, {"start_cost", l.start_cost}, {"cost", l.cost}, {"iterations", l.iterations},
                     {"evaluations", l.evaluations}, {"stop", l.stop}, {"abandoned", l.abandoned}, {"result", to}});
  }
  r["multistart"] = {{"design_costs", fit.design_costs}, {"local_fits", local}, {"best", fit.best}};
  const WorkCounters& c = problem.counters();
  const long evaluations = fit.evaluations;
  r["work"] = {{"objective_evaluations", evaluations},
               {"simulations", c.simulations.load()},
               {"simulations_per_evaluation", problem.test_runs().size()},
               {"failed_simulations", c.failed.load()},
               {"increments", c.increments.load()},
               {"newton_iterations", c.iterations.load()},
               {"material_substeps", c.substeps.load()}};
  r["time"] = {{"total_s", info.total_seconds},
               {"design_s", fit.design_seconds},
               {"local_fits_s", fit.local_seconds},
               {"final_jacobian_s", fit.jacobian_seconds},
               {"threads", info.threads},
               {"simulation_cpu_s", static_cast<double>(c.simulation_ns.load()) * 1e-9}};
  return r;
}

std::string report_markdown(const json& r) {
  std::ostringstream m;
  m << "# Calibration report: " << r["name"].get<std::string>() << "\n\n";
  if (!r["description"].get<std::string>().empty()) m << r["description"].get<std::string>() << "\n\n";
  m << "Model: " << r["model"].get<std::string>() << ". Fit description: `" << r["fit_description"].get<std::string>() << "`.\n\n";
  const json& o = r["objective"];
  m << "Objective (weighted mean of squared normalised errors): " << fmt(o["sum_of_squares"].get<double>())
    << "; RMS normalised error " << fmt(o["rms_normalised_error"].get<double>()) << " over " << o["residuals"] << " points, "
    << o["fitted_values"] << " fitted values.\n\n";
  // The material's values as given: every one when nothing is fitted (a prediction), else the fixed ones.
  auto values = [&](const char* heading) {
    m << heading;
    bool first = true;
    for (const auto& item : r["fixed"].items()) {
      m << (first ? "" : ", ") << item.key() << " " << item.value().dump();
      first = false;
    }
  };
  if (r["parameters"].empty()) {
    values("## Material\n\nNothing is fitted; the values: ");
    m << ".\n";
  } else {
    m << "## Parameters\n\n| parameter | start | bounds | value | std. error | 95 % interval | note |\n|---|---|---|---|---|---|---|\n";
    for (const json& p : r["parameters"]) {
      auto num = [](const json& v) { return v.is_null() ? std::string("-") : fmt(v.get<double>()); };
      m << "| " << p["label"].get<std::string>() << " | " << fmt(p["start"].get<double>()) << " | ["
        << fmt(p["bounds"][0].get<double>()) << ", " << fmt(p["bounds"][1].get<double>()) << "] | "
        << fmt(p["value"].get<double>()) << " | " << num(p["standard_error"]) << " | [" << num(p["ci95"][0]) << ", "
        << num(p["ci95"][1]) << "] | " << (p["at_bound"].get<bool>() ? "at a bound: interval not meaningful" : "") << " |\n";
    }
    values("\nFixed: ");
    m << ".\n\nStandard errors are s (J^T J)^-1/2 with s^2 = " << fmt(o["residual_variance"].get<double>())
      << " (sum of squares / degrees of freedom) and J the Jacobian at the optimum (condition number of the column-scaled J^T J: "
      << (o["condition_number"].is_null() ? std::string("inf") : fmt(o["condition_number"].get<double>(), "%.3g"))
      << "). They treat the digitised points as independent, which they are not: read them as lower bounds.\n\n";
    m << "### Correlation\n\n|";
    for (const json& l : r["correlation"]["labels"]) m << " | " << l.get<std::string>();
    m << " |\n|---";
    for (std::size_t j = 0; j < r["correlation"]["labels"].size(); ++j) m << "|---";
    m << "|\n";
    for (std::size_t i = 0; i < r["correlation"]["labels"].size(); ++i) {
      m << "| " << r["correlation"]["labels"][i].get<std::string>();
      for (const json& v : r["correlation"]["matrix"][i]) m << " | " << (v.is_null() ? std::string("-") : fmt(v.get<double>(), "%.2f"));
      m << " |\n";
    }
  }
  m << "\n## Errors per test\n\nRMS of simulated minus measured at the measured points, in the axis' unit and normalised by the "
       "measured range (scale); share = part of the objective.\n\n"
       "| test | type | group | weight | share | stress RMS | stress RMS/scale | e_v RMS % | e_v RMS/scale | phi RMS deg (mean: bias)";
  // The closings' column only where a test has one.
  bool closings = false;
  for (const json& e : r["experiments"])
    for (const json& a : e["axes"]) closings = closings || a["axis"] == name_of(Axis::closing);
  m << (closings ? " | closing: lab, fit" : "") << " | status |\n|---|---|---|---|---|---|---|---|---|---|" << (closings ? "---|" : "")
    << "---|\n";
  for (const json& e : r["experiments"]) {
    std::vector<std::string> cells(closings ? 6 : 5, "-");
    for (const json& a : e["axes"]) {
      auto num = [](const json& v, const char* f) { return v.is_null() ? std::string("failed") : fmt(v.get<double>(), f); };
      const auto axis = common::value_in(axis_names, a["axis"].get<std::string>());
      if (axis == Axis::stress) {
        cells[0] = num(a["rms"], "%.3g");
        cells[1] = num(a["rms_normalised"], "%.3f");
      } else if (axis == Axis::volumetric) {
        cells[2] = num(a["rms"], "%.3g");
        cells[3] = num(a["rms_normalised"], "%.3f");
      } else if (axis == Axis::closing) {
        const double lab = a["measured"].get<double>();
        cells[5] = fmt(lab, "%.3f") + ", " + (a["mean"].is_null() ? std::string("failed") : fmt(lab + a["mean"].get<double>(), "%.3f"));
      } else {
        cells[4] = num(a["rms"], "%.3g") + (a["mean"].is_null() ? "" : " (mean " + fmt(a["mean"].get<double>(), "%+.2f") + ")");
      }
    }
    m << "| " << e["id"].get<std::string>() << " | " << e["test"].get<std::string>() << " | " << e["group"].get<std::string>()
      << " | " << fmt(e["weight"].get<double>(), "%.3f") << " | " << fmt(e["cost_share"].get<double>(), "%.3f");
    for (const auto& c : cells) m << " | " << c;
    m << " | " << (e["ok"].get<bool>() ? "ok" : "FAILED: " + e["message"].get<std::string>()) << " |\n";
  }
  if (r["multistart"]["local_fits"].empty())
    m << "\n## Optimiser\n\nNo parameter is fitted (`/parameters` is empty): the errors above are predictions of the "
         "material as given, evaluated once.\n";
  else
    m << "\n## Optimiser\n\nDesign of " << r["multistart"]["design_costs"].size() << " points, then "
      << r["multistart"]["local_fits"].size() << " trust-region fits (GSL gsl_multifit_nlinear, Levenberg-Marquardt):\n\n"
      << "| fit | start cost | final cost | iterations | evaluations | stop |\n|---|---|---|---|---|---|\n";
  int k = 0;
  for (const json& l : r["multistart"]["local_fits"]) {
    ++k;
    m << "| " << k << (k - 1 == r["multistart"]["best"].get<int>() ? " (best)" : "") << " | " << fmt(l["start_cost"].get<double>())
      << " | " << fmt(l["cost"].get<double>()) << " | " << l["iterations"] << " | " << l["evaluations"] << " | "
      << l["stop"].get<std::string>() << " |\n";
  }
  const json& w = r["work"];
  const json& t = r["time"];
  m << "\n## Work and time\n\n" << w["objective_evaluations"] << " objective evaluations of " << w["simulations_per_evaluation"]
    << " element tests each: " << w["simulations"] << " element tests (" << w["failed_simulations"] << " failed), "
    << w["increments"] << " increments, " << w["newton_iterations"] << " Newton iterations, " << w["material_substeps"]
    << " material substeps.\n\n| phase | wall s |\n|---|---|\n| design | " << fmt(t["design_s"].get<double>(), "%.1f")
    << " |\n| local fits | " << fmt(t["local_fits_s"].get<double>(), "%.1f") << " |\n| final Jacobian and uncertainty | "
    << fmt(t["final_jacobian_s"].get<double>(), "%.1f") << " |\n| total (reading to fitted; figures not included) | " << fmt(t["total_s"].get<double>(), "%.1f") << " |\n\nElement tests ran on " << t["threads"]
    << " threads and took " << fmt(t["simulation_cpu_s"].get<double>(), "%.1f") << " thread-seconds in all.\n";
  return m.str();
}

bool is_fit_output_name(const std::string& fit_name, const std::string& entry) {
  return entry == "curves" || entry.rfind(fit_name + "_", 0) == 0 || common::is_temporary_name(entry);
}

std::vector<std::string> write_outputs(const Problem& problem, const FitResult& fit, const std::vector<TestRunOutcome>& outcomes,
                                       const RunInfo& info, const std::string& directory, bool plot) {
  const FitSpec& spec = problem.spec();
  common::require_own_folder(directory, [&](const std::string& e) { return is_fit_output_name(spec.name, e); });
  const fs::path scratch = common::staging_folder_for(directory);
  fs::remove_all(scratch);
  fs::create_directories(scratch / "curves");
  std::vector<std::string> warnings;
  auto add = [&](const fs::path& rel, const std::string& text) { write_text(scratch / rel, text); };
  try {
    add(spec.name + "_parameters.json", fitted_material(problem, fit.theta, spec.reference_group).dump(2) + "\n");
    bool per_group = false;
    for (const FitVariable& v : problem.variables()) per_group = per_group || !v.group.empty();
    if (per_group)
      for (const std::string& g : spec.groups)
        add(spec.name + "_parameters_" + g + ".json", fitted_material(problem, fit.theta, g).dump(2) + "\n");
    const json report = report_json(problem, fit, experiment_errors(problem, outcomes), info);
    add(spec.name + "_report.json", report.dump(2) + "\n");
    add(spec.name + "_report.md", report_markdown(report));

    const auto view = view_of(outcomes);
    std::string overview;
    int panels = 0;
    for (std::size_t k = 0; k < spec.experiments.size(); ++k) {
      const ExperimentSpec& x = spec.experiments[k];
      const bool table = is_table_test(x.test);
      std::ostringstream pts;
      pts << (table ? "row,omega_deg,b,sigma3_kPa,void_ratio,measured,simulated\n" : "series,eps_a_pct,measured,simulated\n");
      for (std::size_t si = 0; si < problem.series(k).size(); ++si) {
        const Series& s = problem.series(k)[si];
        for (std::size_t i = 0; i < s.x.size(); ++i) {
          const double sim = problem.simulated(k, s, i, view);
          if (table) {
            const TestRun& row_sim = problem.test_runs()[problem.test_runs_of(k)[i]];
            pts << s.x[i] << ',' << row_sim.bedding_angle_deg << ',' << row_sim.b << ',' << row_sim.sigma3_kPa << ','
                << row_sim.void_ratio << ',' << s.measured[i] << ',' << (std::isfinite(sim) ? fmt(sim, "%.6g") : "") << '\n';
          } else {
            pts << si << ',' << s.x[i] << ',' << s.measured[i] << ',' << (std::isfinite(sim) ? fmt(sim, "%.6g") : "") << '\n';
          }
        }
      }
      add(fs::path("curves") / (x.id + "_points.csv"), pts.str());
      if (is_gap_closing(x.test)) {
        std::ostringstream c, lab;
        c << "test,eps_a_pct,stress_ratio\n";
        lab << "test,eps_a_pct,stress_ratio\n";
        for (std::size_t t = 0; t < 2; ++t) {
          const TestRunOutcome& o = outcomes[problem.test_runs_of(k)[t]];
          for (std::size_t i = 0; i < o.eps_a_pct.size(); ++i) c << t << ',' << fmt(o.eps_a_pct[i], "%.6g") << ',' << fmt(o.stress[i], "%.6g") << '\n';
          const driver::LabCurve curve = driver::read_lab_curve(x.gap_tests[t].data_file);
          const auto [eps_a, ratio] = common::finite_samples(curve.column("eps_a_pct"), curve.column("stress_ratio"));
          for (std::size_t i = 0; i < eps_a.size(); ++i) lab << t << ',' << eps_a[i] << ',' << ratio[i] << '\n';
        }
        add(fs::path("curves") / (x.id + ".csv"), c.str());
        add(fs::path("curves") / (x.id + "_lab.csv"), lab.str());
      } else if (!table) {
        const TestRunOutcome& o = outcomes[problem.test_runs_of(k).front()];
        std::ostringstream c;
        c << "eps_a_pct," << name_of(x.stress_measure) << ",eps_v_pct\n";
        for (std::size_t i = 0; i < o.eps_a_pct.size(); ++i)
          c << fmt(o.eps_a_pct[i], "%.6g") << ',' << fmt(o.stress[i], "%.6g") << ',' << fmt(o.eps_v_pct[i], "%.6g") << '\n';
        add(fs::path("curves") / (x.id + ".csv"), c.str());
      }
      std::ostringstream gp;
      const int n = static_cast<int>(problem.series(k).size());
      gp << "set terminal pngcairo size " << 600 * n << ",450 font ',10'\nset output " << common::gp_quoted(x.id + ".png.tmp") << "\n"
         << "set datafile separator ','\nset key top left\nset grid\nset multiplot layout 1," << n << "\n";
      for (std::size_t si = 0; si < problem.series(k).size(); ++si) {
        gp << panel(problem, k, problem.series(k)[si], si, "", view);
        overview += panel(problem, k, problem.series(k)[si], si, "curves/", view);
        ++panels;
      }
      gp << "unset multiplot\nset output\n";
      add(fs::path("curves") / (x.id + ".gp"), gp.str());
    }
    const int columns = 6, rows = (panels + columns - 1) / columns;
    add(spec.name + "_overview.gp", "set terminal pngcairo size " + std::to_string(400 * columns) + "," + std::to_string(320 * rows) +
                                        " font ',8'\nset output " + common::gp_quoted(spec.name + "_overview.png.tmp") + "\nset datafile separator ','\n"
                                        "set key top left\nset grid\nset multiplot layout " + std::to_string(rows) + "," +
                                        std::to_string(columns) + "\n" + overview + "unset multiplot\nset output\n");
    if (plot && !common::gnuplot_available()) {
      warnings.push_back("gnuplot not found: no PNG figures (the CSV and .gp files are written)");
    } else if (plot) {
      for (const ExperimentSpec& x : spec.experiments)
        if (const std::string w = draw_figure(scratch / "curves", x.id + ".gp", x.id + ".png"); !w.empty())
          warnings.push_back(w);
      if (const std::string w = draw_figure(scratch, spec.name + "_overview.gp", spec.name + "_overview.png"); !w.empty())
        warnings.push_back(w);
    }
    if (const std::string w = common::publish_folder(scratch.string(), directory); !w.empty()) warnings.push_back(w);
  } catch (...) {
    std::error_code ec;
    fs::remove_all(scratch, ec);
    throw;
  }
  return warnings;
}

}  // namespace acst::calibration
