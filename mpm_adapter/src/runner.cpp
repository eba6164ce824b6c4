#include "acst_mpm/runner.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "acst_common/files.hpp"
#include "acst_common/gnuplot.hpp"
#include "acst_common/progress.hpp"
#include "acst_common/result_folder.hpp"
#include "acst_mpm/checkpoint.hpp"
#include "acst_mpm/fields.hpp"
#include "acst_mpm/first_peak.hpp"
#include "acst_mpm/output.hpp"
#include "acst_mpm/scatter.hpp"
#include "acst_mpm/scene_size.hpp"

namespace acst::mpm {
namespace fs = std::filesystem;

namespace {

using Clock = std::chrono::steady_clock;

class Run {
 public:
  Run(const Scene& scene, const RunOptions& opt) : scene_(scene), opt_(opt), sim_(build_simulation(scene)) {
    B_ = scene.footing ? scene.footing->width : 1.0;
    st_.contours_done.assign(scene.output.contours_at_S_over_B.size(), 0);
    if (!opt.resume_from.empty()) {
      read_checkpoint(opt.resume_from, scene, sim_, st_);
    } else {
      record_tracks();  // the start of every history: the replay's initial state
    }
    // The run's length needs the first time step, known once the wave speeds are: still
    // before anything is written.
    check_run_length(scene, sim_.stable_time_step());
  }

  RunSummary run() {
    // A resumed run goes on in its own folder; a new one never mixes its files with another's.
    if (opt_.resume_from.empty()) {
      const std::size_t moved = common::set_aside_earlier_run(opt_.output_dir, is_run_output_name);
      if (moved > 0 && !opt_.quiet)
        std::cerr << "acst_mpm: moved the " << moved << " files of the earlier run in '" << opt_.output_dir
                  << "' into its subfolder '" << common::previous_run_folder << "'\n";
    } else {
      fs::create_directories(opt_.output_dir);
    }
    const auto start = Clock::now();
    auto last_checkpoint = start;
    const long long first_step = sim_.step_count();
    if (st_.vtk_frames == 0) write_frame();
    try {
      while (!finished()) {
        sim_.step();
        record();
        if (due_frame()) write_frame();
        contours_at_requested();
        const auto now = Clock::now();
        if (progress_.due()) show_progress(sim_.step_count() - first_step);
        if (scene_.output.checkpoint_every_s > 0 &&
            std::chrono::duration<double>(now - last_checkpoint).count() > scene_.output.checkpoint_every_s) {
          checkpoint();
          last_checkpoint = now;
        }
      }
    } catch (const SimulationError& e) {
      progress_.close();
      common::write_file_atomically(path("load_settlement.failed.csv"), load_csv_text(scene_, rows()));
      write_tracks();
      if (e.reproducer.empty()) throw;
      common::write_file_atomically(path("failure_reproducer.json"), e.reproducer);
      throw SimulationError(std::string(e.what()) + "\n(wrote " + path("failure_reproducer.json") +
                                ": the failing material update as an element test, replayed by acst_element, and " +
                                path("load_settlement.failed.csv") + ": the load record up to the failure)",
                            e.reproducer);
    }
    if (st_.period_steps > 0) close_period();
    progress_.close();
    RunSummary sum;
    sum.steps = sim_.step_count() - first_step;
    sum.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
    sum.particle_steps_per_s = sum.wall_s > 0 ? static_cast<double>(sum.steps) * sim_.particles().n / sum.wall_s : 0.0;
    write_results(sum);
    return sum;
  }

 private:
  const Scene& scene_;
  RunOptions opt_;
  Simulation sim_;
  RunState st_;
  double B_ = 1.0;
  common::ProgressLine progress_{std::cerr, !opt_.quiet, 0.2, 1.0};

  std::string path(const std::string& name) const { return (fs::path(opt_.output_dir) / name).string(); }
  double settlement() const { return sim_.footing().settlement(); }
  double S_over_B() const { return settlement() / B_; }
  const std::vector<LoadRecord>& rows() const { return scene_.output.every_step_csv ? st_.every_step : st_.history; }

  bool finished() const {
    if (scene_.stop.S_over_B) return S_over_B() >= *scene_.stop.S_over_B;
    if (scene_.stop.time) return sim_.time() >= *scene_.stop.time;
    return sim_.step_count() >= *scene_.stop.steps;
  }

  double progress_fraction() const {
    if (scene_.stop.S_over_B) return S_over_B() / *scene_.stop.S_over_B;
    if (scene_.stop.time) return sim_.time() / *scene_.stop.time;
    return static_cast<double>(sim_.step_count()) / static_cast<double>(*scene_.stop.steps);
  }

  LoadRecord current(double V, double H, double M, double penetration) const {
    LoadRecord r;
    r.step = sim_.step_count();
    r.time = sim_.time();
    r.settlement = settlement();
    r.S_over_B = S_over_B();
    r.V_kN_per_m = V;
    r.H_kN_per_m = H;
    r.M_kNm_per_m = M;
    r.penetration_m = penetration;
    r.q_kPa = V / B_;
    r.kinetic_J_per_m = sim_.kinetic_energy();
    r.footing_work_J_per_m = sim_.footing().motion().work;
    return r;
  }

  void record() {
    const Reaction& f = sim_.reaction(reaction_footing);
    const double V = -f.fy / 1000.0, H = f.fx / 1000.0;  // N/m -> kN/m
    const double M = sim_.contact().moment / 1000.0, depth = sim_.contact().max_penetration;
    st_.sum_V += V;
    st_.sum_H += H;
    st_.sum_M += M;
    st_.max_penetration = std::max(st_.max_penetration, depth);
    if (scene_.output.every_step_csv) {
      st_.every_step.push_back(current(V, H, M, depth));
      record_tracks();  // the histories follow the load record's rows: every step here
    }
    if (++st_.period_steps == scene_.solver.xpic_every) close_period();
  }

  void close_period() {
    const double n = static_cast<double>(st_.period_steps);
    const LoadRecord r = current(st_.sum_V / n, st_.sum_H / n, st_.sum_M / n, st_.max_penetration);
    st_.history.push_back(r);
    if (scene_.quasi_static.stop_on_excess && kinetic_ratio(r) > scene_.quasi_static.kinetic_ratio_limit)
      throw SimulationError(quasi_static_message(r) + " (quasi_static/on_excess 'stop')");
    st_.sum_V = st_.sum_H = st_.sum_M = st_.max_penetration = 0.0;
    st_.period_steps = 0;
    if (!scene_.output.every_step_csv) record_tracks();
    if (scene_.footing && r.V_kN_per_m > st_.peak.V_kN_per_m) {
      Snapshot& s = st_.peak;
      s.S_over_B = r.S_over_B;
      s.V_kN_per_m = r.V_kN_per_m;
      const Particles& P = sim_.particles();
      s.x = P.x;
      s.y = P.y;
      s.shear_strain.resize(P.n);
      s.displacement.resize(P.n);
      for (std::size_t i = 0; i < P.n; ++i) {
        s.shear_strain[i] = max_shear_strain(&P.strain[3 * i]);
        s.displacement[i] = std::hypot(P.x[i] - P.x_initial[i], P.y[i] - P.y_initial[i]);
      }
    }
  }

  void record_tracks() {
    for (std::size_t k = 0; k < sim_.particles().tracked.size(); ++k)
      st_.tracks.push_back(track_record(sim_, static_cast<int>(k), S_over_B()));
  }

  void write_tracks() const {
    for (std::size_t k = 0; k < scene_.output.particle_histories.size(); ++k)
      common::write_file_atomically(path("particle_" + scene_.output.particle_histories[k].name + ".csv"),
                                    track_csv_text(scene_, static_cast<int>(k), st_.tracks));
  }

  bool due_frame() const {
    const int k = st_.vtk_frames;
    if (scene_.output.vtk_every_time) return sim_.time() >= k * *scene_.output.vtk_every_time;
    if (scene_.footing && scene_.output.vtk_every_S_over_B > 0) return S_over_B() >= k * scene_.output.vtk_every_S_over_B;
    return false;
  }

  void write_frame() {
    char name[64];
    std::snprintf(name, sizeof name, "particles_%04d.vtp", st_.vtk_frames);
    common::write_file_atomically(path(name), vtp_text(sim_));
    st_.vtk_times.push_back(sim_.time());
    ++st_.vtk_frames;
    common::write_file_atomically(path("particles.pvd"), pvd_text("particles", st_.vtk_times));
  }

  void contours_at_requested() {
    const auto& targets = scene_.output.contours_at_S_over_B;
    for (std::size_t k = 0; k < targets.size(); ++k) {
      if (st_.contours_done[k] || S_over_B() < targets[k]) continue;
      st_.contours_done[k] = 1;
      if (!opt_.plot) continue;
      const ParticleFields f = particle_fields(sim_);
      char tag[48];
      const bool three = std::fabs(targets[k] * 1000.0 - std::round(targets[k] * 1000.0)) < 1e-9;
      std::snprintf(tag, sizeof tag, three ? "SB%.3f" : "SB%.4f", targets[k]);  // SB0.500, SB0.0125
      const std::string when = " at S/B = " + std::to_string(S_over_B()).substr(0, 6);
      for (ContourField field : scene_.output.contour_fields) {
        const auto map = [&](const char* stem, const std::string& what, const char* label, const std::vector<double>& v) {
          const std::string w = write_contour_figure(opt_.output_dir, stem + std::string("_") + tag,
                                                     scene_.name + ": " + what + when, label, scene_.cell_size,
                                                     sim_.particles().x, sim_.particles().y, v, field == ContourField::N);
          if (!w.empty()) std::fprintf(stderr, "warning: %s\n", w.c_str());
        };
        switch (field) {
          case ContourField::shear_strain: map("shear_strain", "shear strain", "max shear strain (engineering)", f.shear_strain); break;
          case ContourField::displacement: map("displacement", "displacement", "|u| [m]", f.displacement); break;
          case ContourField::fabric_norm: map("fabric_norm", "fabric norm |F|", "|F|", f.fabric_norm); break;
          case ContourField::N: map("N", "N = F:n / |F| (fabric against loading direction)", "N", f.N); break;
          case ContourField::void_ratio: map("void_ratio", "void ratio", "e", f.void_ratio); break;
        }
      }
    }
  }

  void contour_pair(const std::string& tag, const std::string& when, const std::vector<double>& x,
                    const std::vector<double>& y, const std::vector<double>& gamma, const std::vector<double>& u) {
    for (const std::string& w :
         {write_contour_figure(opt_.output_dir, "shear_strain_" + tag, scene_.name + ": shear strain at " + when,
                               "max shear strain (engineering)", scene_.cell_size, x, y, gamma),
          write_contour_figure(opt_.output_dir, "displacement_" + tag, scene_.name + ": displacement at " + when,
                               "|u| [m]", scene_.cell_size, x, y, u)})
      if (!w.empty()) std::fprintf(stderr, "warning: %s\n", w.c_str());
  }

  void show_progress(long long steps) {
    const double wall = progress_.elapsed_s(), rate = steps / std::max(wall, 1e-9);
    const double q = st_.history.empty() ? 0.0 : st_.history.back().q_kPa;
    char text[256];
    std::snprintf(text, sizeof text, "%s: step %lld  t %.3f s  S/B %.4f  q %.1f kPa  %.0f steps/s  ", scene_.name.c_str(),
                  sim_.step_count(), sim_.time(), S_over_B(), q, rate);
    progress_.show(text + common::ProgressLine::time_left(wall, progress_fraction()));
  }

  void checkpoint() {
    write_checkpoint(path("checkpoint.bin"), scene_, sim_, st_);
    common::write_file_atomically(path("load_settlement.partial.csv"), load_csv_text(scene_, rows()));
  }

  // Kinetic energy over the footing's work for a record past the check's start (0 before it).
  double kinetic_ratio(const LoadRecord& r) const {
    if (!scene_.footing || r.S_over_B < scene_.quasi_static.check_from_S_over_B || r.footing_work_J_per_m <= 0.0)
      return 0.0;
    return r.kinetic_J_per_m / r.footing_work_J_per_m;
  }

  std::string quasi_static_message(const LoadRecord& r) const {
    char text[320];
    std::snprintf(text, sizeof text,
                  "not quasi-static: the kinetic energy is %.3g of the footing's work at S/B %.4f, above "
                  "quasi_static/kinetic_ratio_limit %.3g; slow the footing or lower solver/mass_scaling",
                  kinetic_ratio(r), r.S_over_B, scene_.quasi_static.kinetic_ratio_limit);
    return text;
  }

  void write_results(RunSummary& sum) {
    common::write_file_atomically(path("load_settlement.csv"), load_csv_text(scene_, rows()));
    std::remove(path("load_settlement.partial.csv").c_str());
    write_tracks();
    if (!st_.history.empty()) sum.residual_V = st_.history.back().V_kN_per_m;
    sum.Q_ult = st_.peak.V_kN_per_m;
    sum.S_ult_over_B = st_.peak.S_over_B;
    sum.S_ult = st_.peak.S_over_B * B_;
    sum.peak_reached = scene_.footing && sum.residual_V < 0.98 * sum.Q_ult;
    std::vector<double> S, V;
    for (const LoadRecord& r : st_.history) S.push_back(r.S_over_B), V.push_back(r.V_kN_per_m);
    const std::optional<std::size_t> first = first_peak(S, V);
    // The whole record is judged (it is checkpointed, so a resumed run judges its whole run too).
    double max_ratio = 0.0;
    const LoadRecord* worst = nullptr;
    for (const LoadRecord& r : st_.history)
      if (kinetic_ratio(r) > max_ratio) max_ratio = kinetic_ratio(r), worst = &r;
    if (max_ratio > scene_.quasi_static.kinetic_ratio_limit) sum.warnings.push_back(quasi_static_message(*worst));
    if (opt_.plot && scene_.footing) {
      const std::string w = write_load_figure(scene_, opt_.output_dir, "load_settlement.csv");
      if (!w.empty()) sum.warnings.push_back(w);
      if (!scene_.output.particle_histories.empty()) {
        const std::string h = write_history_figure(scene_, opt_.output_dir);
        if (!h.empty()) sum.warnings.push_back(h);
      }
      if (scene_.output.contours_at_peak && !st_.peak.x.empty())
        contour_pair("peak", "Q_ult (S/B = " + std::to_string(st_.peak.S_over_B).substr(0, 5) + ")", st_.peak.x,
                     st_.peak.y, st_.peak.shear_strain, st_.peak.displacement);
    }
    const nlohmann::ordered_json summary = {{"scene", scene_.name},
                                            {"particles", sim_.particles().n},
                                            {"steps", sim_.step_count()},
                                            {"time_s", sim_.time()},
                                            {"wall_s", sum.wall_s},
                                            {"threads", thread_count_used()},
                                            {"particle_steps_per_s", sum.particle_steps_per_s},
                                            {"Q_ult_kN_per_m", sum.Q_ult},
                                            {"q_ult_kPa", sum.Q_ult / B_},
                                            {"S_ult_m", sum.S_ult},
                                            {"S_ult_over_B", sum.S_ult_over_B},
                                            {"peak_reached", sum.peak_reached},
                                            {"q_first_peak_kPa", first ? nlohmann::ordered_json(V[*first] / B_) : nullptr},
                                            {"S_first_peak_over_B", first ? nlohmann::ordered_json(S[*first]) : nullptr},
                                            {"residual_V_kN_per_m", sum.residual_V},
                                            {"final_S_over_B", S_over_B()},
                                            {"footing_contact", footing_contact_name()},
                                            {"symmetric_half", scene_.footing && scene_.footing->symmetric_half},
                                            {"max_kinetic_ratio", max_ratio},
                                            {"kinetic_ratio_limit", scene_.quasi_static.kinetic_ratio_limit},
                                            {"quasi_static", max_ratio <= scene_.quasi_static.kinetic_ratio_limit},
                                            {"max_penetration_m", max_penetration()},
                                            {"sides", sides_json()}};
    common::write_file_atomically(path("summary.json"), summary.dump(2) + "\n");
  }

  // The soil left and right of the footing at the peak and at the end (fields.hpp, SideMeasures).
  nlohmann::ordered_json sides_json() const {
    if (!scene_.footing) return nullptr;
    const Particles& P = sim_.particles();
    std::vector<double> gamma_now(P.n);
    for (std::size_t i = 0; i < P.n; ++i) gamma_now[i] = max_shear_strain(&P.strain[3 * i]);
    const auto side = [&](const SideMeasures& m) {
      return nlohmann::ordered_json{{"sheared_area_left_m2", m.sheared_area_left},
                                    {"sheared_area_right_m2", m.sheared_area_right},
                                    {"heave_left_m", m.heave_left},
                                    {"heave_right_m", m.heave_right}};
    };
    const double c = scene_.footing->centre_x;
    const bool mirror = scene_.footing->symmetric_half;
    return {{"sheared_above_gamma", sheared_area_gamma},
            {"at_peak", side(side_measures(P, st_.peak.y, st_.peak.shear_strain, c, mirror))},
            {"at_end", side(side_measures(P, P.y, gamma_now, c, mirror))}};
  }

  int thread_count_used() const { return thread_count(scene_.solver.threads); }

  std::string footing_contact_name() const {
    if (!scene_.footing) return "none";
    return scene_.footing->contact == FootingContact::penalty ? "penalty" : "node_rows";
  }

  double max_penetration() const {
    double deepest = 0.0;
    for (const LoadRecord& r : st_.history) deepest = std::max(deepest, r.penetration_m);
    return deepest;
  }
};

}  // namespace

RunSummary run_scene(const Scene& scene, const RunOptions& options) {
  Run run(scene, options);
  return run.run();
}

}  // namespace acst::mpm
