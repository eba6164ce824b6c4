#include "acst_calibration/cross_validation.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <sstream>

#include "acst_calibration/least_squares.hpp"
#include "acst_calibration/problem.hpp"
#include "acst_common/files.hpp"
#include "acst_common/gnuplot.hpp"
#include "acst_common/png_file.hpp"
#include "acst_common/result_folder.hpp"

namespace acst::calibration {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

using WallClock = std::chrono::steady_clock;

// The description with only the experiments `keep` accepts, and without what would then refer
// to nothing: type weights of types no longer used, group starts of groups no longer present, a
// reference group no longer present, the folds.
json subset(const json& d, const FitSpec& spec, const std::function<bool(const ExperimentSpec&)>& keep) {
  json t = d;
  t.erase("cross_validation");
  t["experiments"] = json::array();
  std::set<std::string> groups, types;
  for (std::size_t i = 0; i < spec.experiments.size(); ++i)
    if (keep(spec.experiments[i])) {
      t["experiments"].push_back(d["experiments"][i]);
      groups.insert(spec.experiments[i].group);
      types.insert(name_of(spec.experiments[i].test));
    }
  if (t.contains("weights") && t["weights"].contains("types"))
    for (const auto& [type, w] : d["weights"]["types"].items())
      if (!types.count(type)) t["weights"]["types"].erase(type);
  for (auto& [name, p] : t["parameters"].items())
    if (p.contains("group_start"))
      for (const auto& [group, v] : d["parameters"][name]["group_start"].items())
        if (!groups.count(group)) p["group_start"].erase(group);
  if (t.contains("output") && t["output"].contains("reference_group") &&
      !groups.count(t["output"]["reference_group"].get<std::string>()))
    t["output"].erase("reference_group");
  if (spec.optimizer.threads > 0) t["optimizer"]["threads"] = spec.optimizer.threads;
  return t;
}

struct Fitted {
  FitSpec spec;
  std::unique_ptr<Problem> problem;
  FitResult result;
  std::vector<ExperimentError> errors;
};

Fitted fit_description(const json& d, const FitSpec& parent, const std::string& name) {
  Fitted f;
  f.spec = parse_fit_spec(d.dump(), parent.base_dir, name);
  f.problem = std::make_unique<Problem>(f.spec);
  const Problem& p = *f.problem;
  LeastSquaresProblem ls{p.start(), p.lower(), p.upper(), p.residual_count(),
                         [&](const std::vector<Eigen::VectorXd>& thetas) { return p.residuals(thetas); }};
  f.result = fit(ls, f.spec.optimizer);
  std::vector<TestRunOutcome> outcomes;
  p.residuals(f.result.theta, outcomes);
  f.errors = experiment_errors(p, outcomes);
  return f;
}

json values_of(const Fitted& f) {
  json v = json::object();
  for (std::size_t j = 0; j < f.problem->variables().size(); ++j)
    v[f.problem->variables()[j].label] = f.result.theta[static_cast<Eigen::Index>(j)];
  return v;
}

const ExperimentError& error_of(const std::vector<ExperimentError>& errors, const std::string& id) {
  for (const ExperimentError& e : errors)
    if (e.id == id) return e;
  throw std::logic_error("no error for experiment " + id);
}

json errors_json(const std::vector<ExperimentError>& errors) {
  json out = json::array();
  for (const ExperimentError& e : errors) {
    json axes = json::array();
    for (const AxisError& a : e.axes)
      axes.push_back({{"axis", name_of(a.axis)}, {"points", a.points}, {"rms", std::isfinite(a.rms) ? json(a.rms) : json(nullptr)},
                      {"rms_normalised", a.rms_normalised}, {"mean", std::isfinite(a.mean) ? json(a.mean) : json(nullptr)}});
    out.push_back({{"id", e.id}, {"test", name_of(e.test)}, {"group", e.group}, {"ok", e.ok}, {"message", e.message}, {"axes", axes}});
  }
  return out;
}

std::string num(double v, int digits = 3) {
  if (!std::isfinite(v)) return "failed";
  std::ostringstream s;
  s.precision(digits);
  s << v;
  return s.str();
}

const char* axis_unit(Axis axis) {
  switch (axis) {
    case Axis::stress: break;
    case Axis::volumetric: return "e_v %";
    case Axis::phi: return "phi deg";
    case Axis::closing: return "closing";
  }
  return "stress";
}

std::string markdown(const json& r, const CrossValidation& cv) {
  std::ostringstream m;
  m << "# Cross-validation: " << r["name"].get<std::string>() << "\n\n"
    << "Each fold's experiments are left out, the description is fitted to the rest (the same settings), and the fold is "
       "then predicted with that set. Beside each prediction: the same experiment's error in the fit of all experiments. "
       "Errors are RMS of simulated minus measured at the measured points, in the axis' unit and normalised by the "
       "measured range; mean = simulated minus measured on average (the bias).\n\n"
    << "Fit of all " << r["experiments"] << " experiments: cost " << num(cv.all_data_cost, 4) << ". Wall time of the whole "
    << "cross-validation: " << num(cv.seconds, 3) << " s.\n\n"
    << "| fold | left out | fitted to | RMS/scale as fitted (all data) | RMS/scale predicted | predicted / fitted |\n"
    << "|---|---|---|---|---|---|\n";
  for (const FoldResult& f : cv.folds) {
    const double a = pooled_rms_normalised(f.fitted), b = pooled_rms_normalised(f.predicted);
    m << "| " << f.fold.name << " | " << f.fold.experiments.size() << " | " << f.training_experiments << " | " << num(a)
      << " | " << num(b) << " | " << num(b / a) << " |\n";
  }
  m << "\n## Every left-out experiment\n\n"
    << "| fold | test | axis | points | RMS as fitted | RMS predicted | mean predicted | RMS/scale fitted | RMS/scale predicted |\n"
    << "|---|---|---|---|---|---|---|---|---|\n";
  for (const FoldResult& f : cv.folds)
    for (std::size_t k = 0; k < f.predicted.size(); ++k) {
      const ExperimentError& p = f.predicted[k];
      const ExperimentError& a = f.fitted[k];
      for (std::size_t i = 0; i < p.axes.size() && i < a.axes.size(); ++i)
        m << "| " << f.fold.name << " | " << p.id << (p.ok ? "" : " (FAILED: " + p.message + ")") << " | "
          << axis_unit(p.axes[i].axis) << " | " << p.axes[i].points << " | " << num(a.axes[i].rms) << " | "
          << num(p.axes[i].rms) << " | " << (std::isfinite(p.axes[i].mean) ? (p.axes[i].mean >= 0 ? "+" : "") + num(p.axes[i].mean) : "failed")
          << " | " << num(a.axes[i].rms_normalised) << " | " << num(p.axes[i].rms_normalised) << " |\n";
    }
  m << "\n## Fitted values\n\n| value | all data";
  for (const FoldResult& f : cv.folds) m << " | without " << f.fold.name;
  m << " |\n|---|---";
  for (std::size_t k = 0; k < cv.folds.size(); ++k) m << "|---";
  m << "|\n";
  for (const auto& [label, v] : cv.all_data_values.items()) {
    m << "| " << label << " | " << num(v.get<double>(), 4);
    for (const FoldResult& f : cv.folds)
      m << " | " << (f.values.contains(label) ? num(f.values[label].get<double>(), 4) : std::string("(no data)"));
    m << " |\n";
  }
  bool borrowed = false;
  for (const FoldResult& f : cv.folds) borrowed = borrowed || !f.borrowed_groups.empty();
  if (borrowed) {
    m << "\nA fold that leaves out every experiment of a group cannot fit that group's own values: its prediction takes "
         "the training fit's reference group's values (";
    bool first = true;
    for (const FoldResult& f : cv.folds)
      for (const std::string& g : f.borrowed_groups) {
        m << (first ? "" : "; ") << f.fold.name << ": " << g;
        first = false;
      }
    m << "). That part of its error is the per-group value unknown without the group's tests.\n";
  }
  return m.str();
}

}  // namespace

double pooled_rms_normalised(const std::vector<ExperimentError>& errors) {
  double sum = 0.0;
  int n = 0;
  for (const ExperimentError& e : errors)
    for (const AxisError& a : e.axes) {
      sum += a.rms_normalised * a.rms_normalised * a.points;
      n += a.points;
    }
  return n > 0 ? std::sqrt(sum / n) : NAN;
}

CrossValidation cross_validate(const json& description, const FitSpec& spec, const std::function<void(const std::string&)>& progress) {
  const auto t0 = WallClock::now();
  auto elapsed = [&] { return std::chrono::duration<double>(WallClock::now() - t0).count(); };
  CrossValidation cv;
  const Fitted all = fit_description(subset(description, spec, [](const ExperimentSpec&) { return true; }), spec, spec.name);
  cv.all_data_cost = all.result.cost;
  cv.all_data_values = values_of(all);
  const std::size_t fits = spec.folds.size() + 1;
  // Elapsed and an estimate of what is left (fits take about equally long) after `done` fits.
  auto timing = [&](std::size_t done) {
    const double t = elapsed();
    return num(t, 3) + " s elapsed, about " + num(t / static_cast<double>(done) * static_cast<double>(fits - done), 2) +
           " s left";
  };
  if (progress) progress("fit 1/" + std::to_string(fits) + ", all data: cost " + num(all.result.cost, 4) + "; " + timing(1));
  for (std::size_t k = 0; k < spec.folds.size(); ++k) {
    const Fold& fold = spec.folds[k];
    auto in_fold = [&](const ExperimentSpec& x) {
      return std::find(fold.experiments.begin(), fold.experiments.end(), x.id) != fold.experiments.end();
    };
    const Fitted training = fit_description(subset(description, spec, [&](const ExperimentSpec& x) { return !in_fold(x); }),
                                            spec, spec.name + "_without_" + fold.name);
    FoldResult r;
    r.fold = fold;
    r.training_experiments = static_cast<int>(training.spec.experiments.size());
    r.training_cost = training.result.cost;
    r.values = values_of(training);
    r.material = fitted_material(*training.problem, training.result.theta, training.spec.reference_group);
    // One prediction per group of the fold, each with its group's values where the training fit has them.
    std::vector<std::string> groups;
    for (const ExperimentSpec& x : spec.experiments)
      if (in_fold(x) && std::find(groups.begin(), groups.end(), x.group) == groups.end()) groups.push_back(x.group);
    bool per_group = false;
    for (const FitVariable& v : training.problem->variables()) per_group = per_group || !v.group.empty();
    const auto& trained = training.spec.groups;
    std::map<std::string, ExperimentError> predicted;
    for (const std::string& g : groups) {
      const bool known = std::find(trained.begin(), trained.end(), g) != trained.end();
      if (!known && per_group) r.borrowed_groups.push_back(g);
      json d = subset(description, spec, [&](const ExperimentSpec& x) { return in_fold(x) && x.group == g; });
      d["material"] = fitted_material(*training.problem, training.result.theta, known ? g : training.spec.reference_group);
      d["parameters"] = json::object();
      const Fitted p = fit_description(d, spec, spec.name + "_predict_" + fold.name);
      for (const ExperimentError& e : p.errors) predicted[e.id] = e;
    }
    for (const std::string& id : fold.experiments) {
      r.predicted.push_back(predicted.at(id));
      r.fitted.push_back(error_of(all.errors, id));
    }
    if (progress)
      progress("fit " + std::to_string(k + 2) + "/" + std::to_string(fits) + ", without '" + fold.name + "': fitted to " +
               std::to_string(r.training_experiments) + " experiments (cost " + num(r.training_cost, 4) +
               "), predicted RMS/scale " + num(pooled_rms_normalised(r.predicted)) + " against " +
               num(pooled_rms_normalised(r.fitted)) + " as fitted; " + timing(k + 2));
    cv.folds.push_back(std::move(r));
  }
  cv.seconds = elapsed();
  return cv;
}

bool is_cross_validation_output_name(const std::string& fit_name, const std::string& entry) {
  return entry.rfind(fit_name + "_cv", 0) == 0;
}

std::vector<std::string> write_cross_validation(const CrossValidation& cv, const FitSpec& spec, const std::string& directory,
                                                bool plot) {
  const std::string stem = spec.name + "_cv";
  json r = {{"name", spec.name},
            {"fit_description", spec.source},
            {"experiments", spec.experiments.size()},
            {"all_data", {{"cost", cv.all_data_cost}, {"values", cv.all_data_values}}},
            {"seconds", cv.seconds}};
  json folds = json::array();
  std::ostringstream csv;  // the figure's data: one row per fold
  csv << "fold,fitted_rms_normalised,predicted_rms_normalised\n";
  for (const FoldResult& f : cv.folds) {
    folds.push_back({{"name", f.fold.name},
                     {"left_out", f.fold.experiments},
                     {"training_experiments", f.training_experiments},
                     {"training_cost", f.training_cost},
                     {"values", f.values},
                     {"borrowed_groups", f.borrowed_groups},
                     {"fitted_rms_normalised", pooled_rms_normalised(f.fitted)},
                     {"predicted_rms_normalised", pooled_rms_normalised(f.predicted)},
                     {"predicted", errors_json(f.predicted)},
                     {"fitted", errors_json(f.fitted)}});
    csv << f.fold.name << ',' << pooled_rms_normalised(f.fitted) << ',' << pooled_rms_normalised(f.predicted) << '\n';
  }
  r["folds"] = folds;

  const std::string staging = common::staging_folder_for(directory);
  fs::create_directories(staging);
  auto put = [&](const std::string& name, const std::string& text) { common::write_file_atomically((fs::path(staging) / name).string(), text); };
  put(stem + "_report.json", r.dump(2) + "\n");
  put(stem + "_report.md", markdown(r, cv));
  put(stem + ".csv", csv.str());
  for (const FoldResult& f : cv.folds) put(stem + "_" + f.fold.name + "_parameters.json", f.material.dump(2) + "\n");
  std::vector<std::string> warnings;
  if (plot) {
    std::ostringstream gp;
    gp << "set terminal pngcairo size 900,520 noenhanced\nset output " << common::gp_quoted(stem + ".png")
       << "\nset datafile separator ','\n"
       << "set title " << common::gp_quoted("Cross-validation of " + spec.name + ": error of each fold's experiments") << "\n"
       << "set ylabel 'RMS of (simulated - measured) / measured range'\nset style data histograms\n"
       << "set style histogram clustered gap 1\nset style fill solid 0.8 border -1\nset grid ytics\nset key below\n"
       << "set xtics rotate by -30\nset yrange [0:*]\n"
       << "plot " << common::gp_quoted(stem + ".csv") << " using 2:xtic(1) skip 1 title 'as fitted (all data)' lc rgb '#1f77b4', \\\n"
       << "     '' using 3 skip 1 title 'predicted (fold left out)' lc rgb '#d62728'\n";
    put(stem + ".gp", gp.str());
    // Run inside the folder: the script names its files relative to it, so it works where it is kept.
    std::string w = common::gnuplot_available() ? common::run_gnuplot_command(staging, common::shell_quoted(stem + ".gp"))
                                                : "gnuplot not found: no PNG figure (the CSV and .gp files are written)";
    // The figure lies in the new set only: one cut short (a full disk) is taken out of it.
    const std::string png = (fs::path(staging) / (stem + ".png")).string();
    if (w.empty()) w = common::keep_complete_png(png, png);
    if (!w.empty()) warnings.push_back(w);
  }
  if (const std::string w = common::publish_folder(staging, directory); !w.empty()) warnings.push_back(w);
  return warnings;
}

}  // namespace acst::calibration
