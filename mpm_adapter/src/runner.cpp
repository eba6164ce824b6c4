#include "acst_mpm/runner.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <unistd.h>

#include "acst_driver/files.hpp"
#include "acst_mpm/checkpoint.hpp"
#include "acst_mpm/fields.hpp"
#include "acst_mpm/output.hpp"
#include "scatter.hpp"

namespace acst::mpm {
namespace fs = std::filesystem;
using acst::driver::write_file_atomically;

namespace {

using Clock = std::chrono::steady_clock;

std::string duration_text(double s) {
  char buf[32];
  if (!std::isfinite(s) || s < 0) return "?";
  if (s < 120) std::snprintf(buf, sizeof buf, "%.0fs", s);
  else if (s < 7200) std::snprintf(buf, sizeof buf, "%.0fm%02.0fs", std::floor(s / 60), std::fmod(s, 60));
  else std::snprintf(buf, sizeof buf, "%.1fh", s / 3600);
  return buf;
}

class Run {
 public:
  Run(const Scene& scene, const RunOptions& opt) : scene_(scene), opt_(opt), sim_(build_simulation(scene)) {
    B_ = scene.footing ? scene.footing->width : 1.0;
    st_.contours_done.assign(scene.output.contours_at_S_over_B.size(), 0);
    if (!opt.resume_from.empty()) {
      read_checkpoint(opt.resume_from, scene, sim_, st_);
      sim_.prepare();
    }
  }

  RunSummary run() {
    fs::create_directories(opt_.output_dir);
    const auto start = Clock::now();
    auto last_print = start, last_checkpoint = start;
    const long long first_step = sim_.step_count;
    if (st_.vtk_frames == 0) write_frame();
    try {
      while (!finished()) {
        sim_.step();
        record();
        if (due_frame()) write_frame();
        contours_at_requested();
        const auto now = Clock::now();
        if (!opt_.quiet && now - last_print > std::chrono::seconds(1)) {
          progress(std::chrono::duration<double>(now - start).count(), sim_.step_count - first_step);
          last_print = now;
        }
        if (scene_.output.checkpoint_every_s > 0 &&
            std::chrono::duration<double>(now - last_checkpoint).count() > scene_.output.checkpoint_every_s) {
          checkpoint();
          last_checkpoint = now;
        }
      }
    } catch (const SimulationError&) {
      if (!opt_.quiet) std::fprintf(stderr, "\n");
      write_file_atomically(path("load_settlement.failed.csv"), load_csv_text(scene_, rows()));
      throw;
    }
    if (st_.period_steps > 0) close_period();
    if (!opt_.quiet) std::fprintf(stderr, "\n");
    RunSummary sum;
    sum.steps = sim_.step_count - first_step;
    sum.wall_s = std::chrono::duration<double>(Clock::now() - start).count();
    sum.particle_steps_per_s = sum.wall_s > 0 ? static_cast<double>(sum.steps) * sim_.particles.n / sum.wall_s : 0.0;
    write_results(sum);
    return sum;
  }

 private:
  const Scene& scene_;
  RunOptions opt_;
  Simulation sim_;
  RunState st_;
  double B_ = 1.0;

  std::string path(const std::string& name) const { return (fs::path(opt_.output_dir) / name).string(); }
  double settlement() const { return -sim_.footing_dy; }
  double S_over_B() const { return settlement() / B_; }
  const std::vector<LoadRecord>& rows() const { return scene_.output.every_step_csv ? st_.every_step : st_.history; }

  bool finished() const {
    if (scene_.stop.S_over_B) return S_over_B() >= *scene_.stop.S_over_B;
    if (scene_.stop.time) return sim_.time >= *scene_.stop.time;
    return sim_.step_count >= *scene_.stop.steps;
  }

  double progress_fraction() const {
    if (scene_.stop.S_over_B) return S_over_B() / *scene_.stop.S_over_B;
    if (scene_.stop.time) return sim_.time / *scene_.stop.time;
    return static_cast<double>(sim_.step_count) / static_cast<double>(*scene_.stop.steps);
  }

  LoadRecord current(double V, double H) const {
    LoadRecord r;
    r.step = sim_.step_count;
    r.time = sim_.time;
    r.settlement = settlement();
    r.S_over_B = S_over_B();
    r.V_kN_per_m = V;
    r.H_kN_per_m = H;
    r.q_kPa = V / B_;
    r.kinetic_J_per_m = sim_.kinetic_energy();
    r.footing_work_J_per_m = sim_.footing_work;
    return r;
  }

  void record() {
    const Reaction& f = sim_.reaction[reaction_footing];
    const double V = -f.fy / 1000.0, H = f.fx / 1000.0;  // N/m -> kN/m
    st_.sum_V += V;
    st_.sum_H += H;
    if (scene_.output.every_step_csv) st_.every_step.push_back(current(V, H));
    if (++st_.period_steps == scene_.solver.xpic_every) close_period();
  }

  void close_period() {
    const double n = static_cast<double>(st_.period_steps);
    const LoadRecord r = current(st_.sum_V / n, st_.sum_H / n);
    st_.history.push_back(r);
    st_.sum_V = st_.sum_H = 0.0;
    st_.period_steps = 0;
    if (scene_.footing && r.V_kN_per_m > st_.peak.V_kN_per_m) {
      Snapshot& s = st_.peak;
      s.S_over_B = r.S_over_B;
      s.V_kN_per_m = r.V_kN_per_m;
      const Particles& P = sim_.particles;
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

  bool due_frame() const {
    const int k = st_.vtk_frames;
    if (scene_.output.vtk_every_time) return sim_.time >= k * *scene_.output.vtk_every_time;
    if (scene_.footing && scene_.output.vtk_every_S_over_B > 0) return S_over_B() >= k * scene_.output.vtk_every_S_over_B;
    return false;
  }

  void write_frame() {
    char name[64];
    std::snprintf(name, sizeof name, "particles_%04d.vtp", st_.vtk_frames);
    write_file_atomically(path(name), vtp_text(sim_));
    st_.vtk_times.push_back(sim_.time);
    ++st_.vtk_frames;
    write_file_atomically(path("particles.pvd"), pvd_text("particles", st_.vtk_times));
  }

  void contours_at_requested() {
    const auto& targets = scene_.output.contours_at_S_over_B;
    for (std::size_t k = 0; k < targets.size(); ++k) {
      if (st_.contours_done[k] || S_over_B() < targets[k]) continue;
      st_.contours_done[k] = 1;
      if (!opt_.plot) continue;
      const ParticleFields f = particle_fields(sim_);
      char tag[48];
      std::snprintf(tag, sizeof tag, "SB%.3f", targets[k]);
      contour_pair(tag, "S/B = " + std::to_string(S_over_B()).substr(0, 5), sim_.particles.x, sim_.particles.y,
                   f.shear_strain, f.displacement);
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

  void progress(double wall, long long steps) {
    const double rate = steps / std::max(wall, 1e-9), frac = progress_fraction();
    const double left = frac > 0 ? wall * (1.0 - frac) / frac : NAN;
    const double q = st_.history.empty() ? 0.0 : st_.history.back().q_kPa;
    std::fprintf(stderr, "\r%s: step %lld  t %.3f s  S/B %.4f  q %.1f kPa  %.0f steps/s  left %s   ", scene_.name.c_str(),
                 sim_.step_count, sim_.time, S_over_B(), q, rate, duration_text(left).c_str());
    if (!isatty(fileno(stderr))) std::fprintf(stderr, "\n");
    std::fflush(stderr);
  }

  void checkpoint() {
    write_checkpoint(path("checkpoint.bin"), scene_, sim_, st_);
    write_file_atomically(path("load_settlement.partial.csv"), load_csv_text(scene_, rows()));
  }

  void write_results(RunSummary& sum) {
    write_file_atomically(path("load_settlement.csv"), load_csv_text(scene_, rows()));
    std::remove(path("load_settlement.partial.csv").c_str());
    if (!st_.history.empty()) sum.residual_V = st_.history.back().V_kN_per_m;
    sum.Q_ult = st_.peak.V_kN_per_m;
    sum.S_ult_over_B = st_.peak.S_over_B;
    sum.S_ult = st_.peak.S_over_B * B_;
    sum.peak_reached = scene_.footing && sum.residual_V < 0.98 * sum.Q_ult;
    if (opt_.plot && scene_.footing) {
      const std::string w = write_load_figure(scene_, opt_.output_dir, "load_settlement.csv");
      if (!w.empty()) sum.warnings.push_back(w);
      if (scene_.output.contours_at_peak && !st_.peak.x.empty())
        contour_pair("peak", "Q_ult (S/B = " + std::to_string(st_.peak.S_over_B).substr(0, 5) + ")", st_.peak.x,
                     st_.peak.y, st_.peak.shear_strain, st_.peak.displacement);
    }
    char buf[1024];
    std::snprintf(buf, sizeof buf,
                  "{\n  \"scene\": \"%s\",\n  \"particles\": %zu,\n  \"steps\": %lld,\n  \"time_s\": %.6g,\n"
                  "  \"wall_s\": %.3f,\n  \"threads\": %d,\n  \"particle_steps_per_s\": %.4g,\n"
                  "  \"Q_ult_kN_per_m\": %.6g,\n  \"q_ult_kPa\": %.6g,\n  \"S_ult_m\": %.6g,\n  \"S_ult_over_B\": %.6g,\n"
                  "  \"peak_reached\": %s,\n  \"residual_V_kN_per_m\": %.6g,\n  \"final_S_over_B\": %.6g\n}\n",
                  scene_.name.c_str(), sim_.particles.n, sim_.step_count, sim_.time, sum.wall_s,
                  thread_count_used(), sum.particle_steps_per_s, sum.Q_ult, sum.Q_ult / B_, sum.S_ult,
                  sum.S_ult_over_B, sum.peak_reached ? "true" : "false", sum.residual_V, S_over_B());
    write_file_atomically(path("summary.json"), buf);
  }

  int thread_count_used() const { return thread_count(scene_.solver.threads); }
};

}  // namespace

RunSummary run_scene(const Scene& scene, const RunOptions& options) {
  Run run(scene, options);
  return run.run();
}

}  // namespace acst::mpm
