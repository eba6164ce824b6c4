// The calibration problem: scenes built from the experiments, runs in parallel, residuals.
#include "acst_calibration/problem.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>
#include <tuple>

#include "acst/material.hpp"
#include "acst_common/interpolate.hpp"
#include "acst_common/json_fields.hpp"
#include "acst_common/memory.hpp"
#include "acst_driver/lab_data.hpp"
#include "acst_driver/record.hpp"
#include "acst_driver/scene.hpp"
#include "acst_common/parallel_for.hpp"

namespace acst::calibration {

using nlohmann::json;

namespace {

// 0.1 in sigma1'/sigma3', 1 kPa in q, 0.2 % volumetric strain, 1 deg of friction angle.
double absolute_scale_floor(Axis axis, StressMeasure measure) {
  switch (axis) {
    case Axis::stress: return measure == StressMeasure::q_kPa ? 1.0 : 0.1;
    case Axis::volumetric: return 0.2;
    case Axis::phi: return 1.0;
    case Axis::closing: break;  // a closing's scale is the description's (/scale)
  }
  return 0.1;
}

}  // namespace

double series_scale(const std::vector<double>& measured, Axis axis, StressMeasure measure) {
  double lo = INFINITY, hi = -INFINITY, big = 0.0;
  for (double v : measured) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    big = std::max(big, std::abs(v));
  }
  return std::max({hi - lo, 0.05 * big, absolute_scale_floor(axis, measure)});
}

double gap_closing(const std::vector<double>& first_eps_a, const std::vector<double>& first_ratio,
                   const std::vector<double>& second_eps_a, const std::vector<double>& second_ratio, double from_pct,
                   double to_pct) {
  auto gap = [&](double at) {
    return common::interpolate(first_eps_a, first_ratio, at) - common::interpolate(second_eps_a, second_ratio, at);
  };
  const double opened = gap(from_pct), left = gap(to_pct);
  return opened != 0.0 ? left / opened : NAN;  // NaN also where either curve does not reach a strain
}

double friction_angle_deg(const Sym& stress) {
  Eigen::Matrix3d s;
  s << stress[0], stress[3], stress[4], stress[3], stress[1], stress[5], stress[4], stress[5], stress[2];
  const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(s, Eigen::EigenvaluesOnly).eigenvalues();
  return std::asin((ev[2] - ev[0]) / (ev[2] + ev[0])) * 180.0 / M_PI;
}

namespace {

// Increments of a run to `to_pct` in steps of `step_pct`, counted in double before it becomes an
// int: a lab curve's strains are not bounded by the description.
int run_increments(double to_pct, double step_pct, const ExperimentSpec& x) {
  const double n = std::ceil(to_pct / step_pct);
  if (!(n <= static_cast<double>(driver::max_step_increments)))
    throw common::InputError(x.path + "/strain_increment_pct: a run to " + common::fields::shown(to_pct) + " % in steps of " +
                             common::fields::shown(step_pct) + " % takes " + common::fields::shown(n) +
                             " increments, more than the " + std::to_string(driver::max_step_increments) +
                             " an element-test step may have");
  return static_cast<int>(n);
}

// Scene of one run: optional isotropic consolidation from void_ratio_at_kPa, then shearing.
json scene_json(const FitSpec& spec, const ExperimentSpec& x, TestType test, double b, double bedding,
                double axial_pct, int increments) {
  json steps = json::array();
  const bool consolidate = x.void_ratio_at_kPa > 0.0 && x.void_ratio_at_kPa < x.sigma3_kPa;
  if (consolidate) steps.push_back({{"preset", "isotropic_compression"}, {"p_to", x.sigma3_kPa}, {"increments", 20}});
  // A curve test's name is the driver preset's; a table row runs the true_triaxial preset.
  json shear = {{"preset", name_of(test)}, {"axial_strain_pct", axial_pct}, {"increments", increments}};
  if (test == TestType::true_triaxial) shear["b"] = b;
  steps.push_back(shear);
  json initial = {{"confining_pressure", consolidate ? x.void_ratio_at_kPa : x.sigma3_kPa}, {"void_ratio", x.void_ratio}};
  if (spec.material.value("model", std::string("ACST")) != "isotropic") initial["bedding_angle_deg"] = bedding;
  json scene = {{"material", spec.material}, {"initial_state", initial}, {"steps", steps}, {"output", {{"plot", false}}}};
  if (x.max_cutbacks > 0) scene["solver"] = {{"max_cutbacks", x.max_cutbacks}};
  return scene;
}

// The closing of a gap_closing experiment's two lab curves, each read where it has a stress ratio.
double measured_closing(const ExperimentSpec& x) {
  using common::fields::shown;
  std::vector<double> eps_a[2], ratio[2];
  for (std::size_t i = 0; i < 2; ++i) {
    const std::string& file = x.gap_tests[i].data_file;
    const driver::LabCurve curve = driver::read_lab_curve(file);
    std::tie(eps_a[i], ratio[i]) = common::finite_samples(curve.column("eps_a_pct"), curve.column("stress_ratio"));
    if (ratio[i].empty() || !std::is_sorted(eps_a[i].begin(), eps_a[i].end()) || eps_a[i].front() > x.gap_from_pct ||
        eps_a[i].back() < x.gap_to_pct)
      throw common::InputError(x.path + "/at_axial_strain_pct: the stress_ratio points of '" + file + "' " +
                               (ratio[i].empty() ? std::string("are missing")
                                                 : "span " + shown(eps_a[i].front()) + " to " + shown(eps_a[i].back()) +
                                                       " % of axial strain") +
                               "; both curves must hold " + shown(x.gap_from_pct) + " and " + shown(x.gap_to_pct) +
                               " %, with strains in increasing order");
  }
  const double closing = gap_closing(eps_a[0], ratio[0], eps_a[1], ratio[1], x.gap_from_pct, x.gap_to_pct);
  if (!std::isfinite(closing))
    throw common::InputError(x.path + "/data: the two lab curves have no gap in sigma1'/sigma3' at " + shown(x.gap_from_pct) +
                             " %: the closing is undefined");
  return closing;
}

driver::ElementScene build_scene(const json& j, const ExperimentSpec& x, const std::string& name) {
  try {
    return driver::parse_scene(j.dump(), "", name);
  } catch (const common::InputError& e) {
    throw common::InputError(x.path + ": the element test built from this experiment is invalid: " + e.what());
  }
}

}  // namespace

Problem::Problem(const FitSpec& spec) : spec_(spec) {
  threads_ = spec.optimizer.threads > 0 ? spec.optimizer.threads
                                        : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  for (const FittedParameter& p : spec.parameters) {
    if (!p.per_group) {
      variables_.push_back({p.name, "", p.name, p.start, p.lower, p.upper});
      continue;
    }
    for (const std::string& g : spec.groups) {
      const auto it = p.group_start.find(g);
      variables_.push_back({p.name, g, p.name + "[" + g + "]", it == p.group_start.end() ? p.start : it->second, p.lower, p.upper});
    }
  }
  series_.resize(spec.experiments.size());
  runs_of_.resize(spec.experiments.size());
  for (std::size_t k = 0; k < spec.experiments.size(); ++k) {
    const ExperimentSpec& x = spec.experiments[k];
    const double w = experiment_weight(spec, k);
    const bool table = is_table_test(x.test);
    const driver::LabCurve lab = is_gap_closing(x.test) ? driver::LabCurve{}  // reads its two files below
                                 : table                 ? driver::read_commented_csv(x.data_file, true)
                                                         : driver::read_lab_curve(x.data_file);
    // `run`: the experiment with the conditions this run starts from (a table row's own).
    auto add_test_run = [&](int row, const ExperimentSpec& run, double b, double bedding, const json& j, long increments) {
      TestRun s;
      s.experiment = k;
      s.row = row;
      s.b = b;
      s.bedding_angle_deg = bedding;
      s.sigma3_kPa = run.sigma3_kPa;
      s.void_ratio = run.void_ratio;
      s.scene = build_scene(j, x, x.id);
      s.shear_step = static_cast<int>(s.scene.blocks.size()) - 1;
      s.increments = increments;
      runs_of_[k].push_back(test_runs_.size());
      test_runs_.push_back(std::move(s));
    };
    if (is_gap_closing(x.test)) {
      // Each test runs a little past the second strain.
      for (const ExperimentSpec& t : x.gap_tests) {
        const double to = x.gap_to_pct + 2.0 * t.strain_increment_pct;
        const int n = run_increments(to, t.strain_increment_pct, t);
        add_test_run(-1, t, t.b, t.bedding_angle_deg, scene_json(spec, t, t.test, t.b, t.bedding_angle_deg, to, n), n);
      }
      Series closing;
      closing.axis = Axis::closing;
      closing.x = {x.gap_to_pct};
      closing.measured = {measured_closing(x)};
      closing.scale = x.closing_scale;
      closing.point_weight = w;
      series_[k].push_back(closing);
    } else if (table) {
      Series phi;
      phi.axis = Axis::phi;
      const std::vector<double> measured = lab.column(x.phi_column);
      // A quantity from its column, or the experiment's one value for every row.
      auto per_row = [&](const std::string& column, double value) {
        return column.empty() ? std::vector<double>(measured.size(), value) : lab.column(column);
      };
      const auto b = per_row(x.b_column, x.b), omega = per_row(x.bedding_column, x.bedding_angle_deg);
      const auto sigma3 = per_row(x.sigma3_column, x.sigma3_kPa), e0 = per_row(x.void_ratio_column, x.void_ratio);
      const int n = run_increments(x.peak_search_strain_pct, x.strain_increment_pct, x);
      for (std::size_t i = 0; i < measured.size(); ++i) {
        bool wanted = true;  // by the experiment's row filter
        for (const auto& [column, values] : x.row_filter) {
          const double v = lab.column(column)[i];
          wanted = wanted && std::find(values.begin(), values.end(), v) != values.end();
        }
        if (!wanted) continue;
        // An empty cell leaves its row out (the table has no value there); text in a column the
        // experiment reads is a typing slip (4O.3, x) and used to drop its row silently.
        for (const std::string* column : {&x.phi_column, &x.b_column, &x.bedding_column, &x.sigma3_column, &x.void_ratio_column})
          if (const std::string text = column->empty() ? "" : lab.text_at(*column, i); !text.empty())
            throw common::InputError(x.path + "/data: '" + x.data_file + "':" + std::to_string(lab.lines[i]) + ": column " +
                                     *column + ": '" + text + "' is not a number (a cell this experiment reads must be a " +
                                     "number, or empty to leave its row out)");
        if (std::isnan(b[i]) || std::isnan(omega[i]) || std::isnan(measured[i]) || std::isnan(sigma3[i]) || std::isnan(e0[i]))
          continue;
        if (!(measured[i] > 0.0 && measured[i] < 90.0))  // -10, 95 and 1e308 deg were taken as measured
          throw common::InputError(x.path + "/data: '" + x.data_file + "':" + std::to_string(lab.lines[i]) + ": column " +
                                   x.phi_column + ": a peak friction angle of " + common::fields::shown(measured[i]) +
                                   " deg (allowed: between 0 and 90 deg)");
        if (!(b[i] >= 0.0 && b[i] <= 1.0 && sigma3[i] > 0.0 && void_ratio_admissible(e0[i])))
          throw common::InputError(x.path + "/data: row " + std::to_string(i + 1) + " of '" + x.data_file + "' has b " +
                                   common::fields::shown(b[i]) + ", sigma3 " + common::fields::shown(sigma3[i]) +
                                   " kPa, void ratio " + common::fields::shown(e0[i]) +
                                   " (allowed: b in [0, 1], sigma3 > 0, void ratio in (0, 2.97))");
        ExperimentSpec row = x;
        row.sigma3_kPa = sigma3[i];
        row.void_ratio = e0[i];
        add_test_run(static_cast<int>(i), row, b[i], omega[i],
                     scene_json(spec, row, TestType::true_triaxial, b[i], omega[i], x.peak_search_strain_pct, n), n);
        phi.x.push_back(static_cast<double>(i));
        phi.measured.push_back(measured[i]);
      }
      if (phi.x.empty()) throw common::InputError(x.path + "/rows: no row of '" + x.data_file + "' is selected");
      phi.scale = series_scale(phi.measured, phi.axis, x.stress_measure);
      phi.point_weight = w / static_cast<double>(phi.x.size());
      series_[k].push_back(phi);
    } else {
      const auto eps_a = lab.column("eps_a_pct");
      auto collect = [&](const char* column, Axis axis, double axis_weight) {
        Series s;
        s.axis = axis;
        const auto v = lab.column(column);
        if (v.empty()) throw common::InputError(x.path + "/data: '" + x.data_file + "' has no column " + column + " (set \"fit\" to leave that axis out)");
        for (std::size_t i = 0; i < v.size(); ++i)
          if (!std::isnan(v[i]) && eps_a[i] > 0.0 && eps_a[i] >= x.strain_lo_pct && eps_a[i] <= x.strain_hi_pct) {
            s.x.push_back(eps_a[i]);
            s.measured.push_back(v[i]);
          }
        if (s.x.empty())
          throw common::InputError(x.path + "/strain_range_pct: no " + column + " point of '" + x.data_file + "' lies in [" +
                         std::to_string(x.strain_lo_pct) + ", " + std::to_string(x.strain_hi_pct) + "] %");
        s.scale = series_scale(s.measured, axis, x.stress_measure);
        s.point_weight = w * axis_weight / static_cast<double>(s.x.size());
        series_[k].push_back(s);
      };
      const double sa = spec.stress_axis_weight, va = spec.volumetric_axis_weight;
      const double share = (x.fit_stress ? sa : 0.0) + (x.fit_volumetric ? va : 0.0);
      if (!(share > 0.0)) throw common::InputError(x.path + "/fit: the axes this experiment fits have zero weight (/weights/axes)");
      if (x.fit_stress) collect(name_of(x.stress_measure), Axis::stress, sa / share);
      if (x.fit_volumetric) collect("eps_v_pct", Axis::volumetric, va / share);
      // Run a little past the last point so that it is interpolated, not extrapolated.
      double last = 0.0;
      for (const Series& s : series_[k]) last = std::max(last, s.x.back());
      const double to = last + 2.0 * x.strain_increment_pct;
      const int n = run_increments(to, x.strain_increment_pct, x);
      add_test_run(-1, x, x.b, x.bedding_angle_deg, scene_json(spec, x, x.test, x.b, x.bedding_angle_deg, to, n), n);
    }
    for (const Series& s : series_[k]) residual_count_ += static_cast<int>(s.x.size());
  }
  schedule_.resize(test_runs_.size());
  for (std::size_t i = 0; i < schedule_.size(); ++i) schedule_[i] = i;
  std::stable_sort(schedule_.begin(), schedule_.end(),
                   [&](std::size_t a, std::size_t b) { return test_runs_[a].increments > test_runs_[b].increments; });
  base_ = test_runs_.front().scene.material->parameters();
  check_size();
}

// One batch of evaluations (the design, or a Jacobian's columns) holds the shearing curve of
// every run at every point, and each evaluation runs every element test: refuse a description
// whose batch cannot fit in memory or whose evaluation runs more increments than the largest
// element test may have (driver::max_total_increments).
void Problem::check_size() const {
  using common::fields::shown;
  double increments = 0.0;
  for (const TestRun& s : test_runs_) increments += static_cast<double>(s.increments) + 2.0;
  const std::string tests = std::to_string(test_runs_.size()) + " element tests";
  if (increments > driver::max_total_increments)
    throw common::InputError("/experiments: one evaluation runs " + shown(increments) + " increments over " + tests +
                             ", more than the " + shown(driver::max_total_increments) + " allowed");
  const double variables = static_cast<double>(variables_.size()), residuals = residual_count_;
  const double points = std::max<double>(spec_.optimizer.design_points, variables);
  const double bytes = points * (increments * 3 * sizeof(double) + residuals * sizeof(double)) + residuals * variables * sizeof(double);
  const double cap = common::memory_limit_bytes(max_memory_bytes);
  if (bytes > cap)
    throw common::InputError(std::string(spec_.optimizer.design_points >= variables ? "/optimizer/design_points" : "/parameters") +
                             ": a batch of " + shown(points) + " evaluations of " + tests + " (" + shown(increments) +
                             " increments, " + shown(residuals) + " points) needs about " + common::gib_text(bytes) +
                             " of memory, more than the " + common::gib_text(cap) + " allowed (the smaller of " +
                             common::gib_text(max_memory_bytes) + " and this machine's physical memory)");
}

Eigen::VectorXd Problem::start() const {
  Eigen::VectorXd v(variables_.size());
  for (std::size_t i = 0; i < variables_.size(); ++i) v[i] = variables_[i].start;
  return v;
}
Eigen::VectorXd Problem::lower() const {
  Eigen::VectorXd v(variables_.size());
  for (std::size_t i = 0; i < variables_.size(); ++i) v[i] = variables_[i].lower;
  return v;
}
Eigen::VectorXd Problem::upper() const {
  Eigen::VectorXd v(variables_.size());
  for (std::size_t i = 0; i < variables_.size(); ++i) v[i] = variables_[i].upper;
  return v;
}

Parameters Problem::parameters(const Eigen::VectorXd& theta, const std::string& group) const {
  Parameters p = base_;
  for (std::size_t i = 0; i < variables_.size(); ++i)
    if (variables_[i].group.empty() || variables_[i].group == group)
      p.*parameter_info(variables_[i].parameter)->member = theta[static_cast<Eigen::Index>(i)];
  return p;
}

TestRunOutcome Problem::simulate(const TestRun& sim, const Eigen::VectorXd& theta, bool keep_run) const {
  const auto t0 = std::chrono::steady_clock::now();
  TestRunOutcome out;
  const ExperimentSpec& x = spec_.experiments[sim.experiment];
  driver::ElementScene scene = sim.scene;
  try {
    const Parameters p = parameters(theta, x.group);
    validate(p);
    scene.material.emplace(p, sim.scene.material->options());
    Sym start_strain = Sym::Zero();
    bool started = false;
    std::vector<driver::Record> kept;
    // The rows are used as they come: only the shearing curve is kept, and every row only for a report.
    driver::RunResult run = driver::stream_scene(scene, [&](const driver::Record& rec) {
      if (keep_run) kept.push_back(rec);
      if (rec.step < sim.shear_step) {
        start_strain = rec.strain;
        return;
      }
      if (!started) {
        started = true;
        out.eps_a_pct.push_back(0.0);  // the start of shearing
        out.stress.push_back(x.stress_measure == StressMeasure::q_kPa ? 0.0 : 1.0);
        out.eps_v_pct.push_back(0.0);
      }
      const Sym strain = rec.strain - start_strain;
      const double eps_a = driver::axial_strain_pct(strain);
      if (eps_a <= out.eps_a_pct.back()) return;  // a cut-back row may repeat a strain
      out.eps_a_pct.push_back(eps_a);
      out.stress.push_back(x.stress_measure == StressMeasure::q_kPa ? rec.stress[0] - rec.stress[2]
                                                                       : rec.stress[0] / rec.stress[2]);
      out.eps_v_pct.push_back(driver::volumetric_strain_pct(strain));
      out.peak_phi_deg = std::max(out.peak_phi_deg, friction_angle_deg(rec.stress));
    });
    run.records = std::move(kept);
    out.ok = run.ok;
    out.message = run.message;
    counters_.increments += run.increments;
    counters_.substeps += run.substeps;
    counters_.iterations += run.iterations;
    if (keep_run) out.run = std::move(run);
  } catch (const std::exception& e) {  // parameters outside the material's ranges, or worse
    out.ok = false;
    out.message = e.what();
  }
  if (!out.ok) ++counters_.failed;
  ++counters_.simulations;
  counters_.simulation_ns += std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now() - t0).count();
  return out;
}

double Problem::simulated(std::size_t k, const Series& s, std::size_t i,
                          const std::vector<const TestRunOutcome*>& outcomes) const {
  if (s.axis == Axis::phi) {
    const TestRunOutcome& o = *outcomes[runs_of_[k][i]];
    return o.ok ? o.peak_phi_deg : NAN;
  }
  if (s.axis == Axis::closing) {
    const TestRunOutcome &a = *outcomes[runs_of_[k][0]], &b = *outcomes[runs_of_[k][1]];
    const ExperimentSpec& x = spec_.experiments[k];
    return a.ok && b.ok ? gap_closing(a.eps_a_pct, a.stress, b.eps_a_pct, b.stress, x.gap_from_pct, x.gap_to_pct) : NAN;
  }
  const TestRunOutcome& o = *outcomes[runs_of_[k].front()];
  return o.ok ? common::interpolate(o.eps_a_pct, s.axis == Axis::stress ? o.stress : o.eps_v_pct, s.x[i]) : NAN;
}

double Problem::normalised_error(const Series& s, std::size_t i, double simulated) const {
  const double e = (simulated - s.measured[i]) / s.scale, penalty = spec_.optimizer.penalty;
  if (!std::isfinite(e)) return penalty;
  // A closing whose simulated gap nearly vanishes at the first strain is a ratio without bound.
  return s.axis == Axis::closing ? std::clamp(e, -penalty, penalty) : e;
}

void Problem::assemble(const std::vector<const TestRunOutcome*>& outcomes, Eigen::VectorXd& r) const {
  r.resize(residual_count_);
  Eigen::Index at = 0;
  for (std::size_t k = 0; k < series_.size(); ++k)
    for (const Series& s : series_[k])
      for (std::size_t i = 0; i < s.x.size(); ++i, ++at)
        r[at] = std::sqrt(s.point_weight) * normalised_error(s, i, simulated(k, s, i, outcomes));
}

std::vector<Eigen::VectorXd> Problem::residuals(const std::vector<Eigen::VectorXd>& thetas) const {
  const std::size_t ns = test_runs_.size();
  std::vector<TestRunOutcome> outcomes(thetas.size() * ns);
  // Longest runs first over all points, so that the threads finish together.
  common::parallel_for(
      threads_, outcomes.size(),
      [&](int, std::size_t job) {
        const std::size_t point = job % thetas.size(), sim = schedule_[job / thetas.size()];
        outcomes[point * ns + sim] = simulate(test_runs_[sim], thetas[point], false);
      },
      common::Schedule::dynamic);
  std::vector<Eigen::VectorXd> r(thetas.size());
  std::vector<const TestRunOutcome*> view(ns);
  for (std::size_t point = 0; point < thetas.size(); ++point) {
    for (std::size_t s = 0; s < ns; ++s) view[s] = &outcomes[point * ns + s];
    assemble(view, r[point]);
  }
  return r;
}

Eigen::VectorXd Problem::residuals(const Eigen::VectorXd& theta, std::vector<TestRunOutcome>& outcomes) const {
  outcomes.assign(test_runs_.size(), {});
  common::parallel_for(
      threads_, schedule_.size(),
      [&](int, std::size_t job) { outcomes[schedule_[job]] = simulate(test_runs_[schedule_[job]], theta, true); },
      common::Schedule::dynamic);
  std::vector<const TestRunOutcome*> view;
  for (const auto& o : outcomes) view.push_back(&o);
  Eigen::VectorXd r;
  assemble(view, r);
  return r;
}

}  // namespace acst::calibration
