// The step loop of a run and what it does between steps: the load record, frames and maps,
// checkpoints and the progress line; a material failure keeps the record so far.
#include "acst_footing_tool/runner.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include "acst_common/files.hpp"
#include "acst_common/progress.hpp"
#include "acst_common/result_folder.hpp"
#include "acst_footing_tool/build_simulation.hpp"
#include "acst_footing_tool/checkpoint.hpp"
#include "acst_footing_tool/frames.hpp"
#include "acst_footing_tool/load_record.hpp"
#include "acst_footing_tool/output.hpp"
#include "acst_footing_tool/run_context.hpp"
#include "acst_footing_tool/run_results.hpp"
#include "acst_footing_tool/scene_size.hpp"

namespace acst::mpm {
namespace fs = std::filesystem;

namespace {

using WallClock = std::chrono::steady_clock;

class Run {
 public:
  Run(const Scene& scene, const RunOptions& opt)
      : sim_(build_simulation(scene)), run_{scene, opt, sim_, state_, scene.footing ? scene.footing->width : 1.0} {
    state_.contours_done.assign(scene.output.contours_at_S_over_B.size(), 0);
    if (!opt.resume_from.empty()) {
      read_checkpoint(opt.resume_from, scene, sim_, state_);
    } else {
      record_tracks(run_);  // the start of every history: the replay's initial state
    }
    // The run's length needs the first time step, known once the wave speeds are: still
    // before anything is written.
    check_run_length(scene, sim_.stable_time_step());
  }

  RunSummary run() {
    prepare_folder();
    const auto start = WallClock::now();
    auto last_checkpoint = start;
    const long long first_step = sim_.step_count();
    if (state_.vtk_frames == 0) write_frame(run_);
    RunSummary sum;
    try {
      while (!finished()) {
        if (run_.options.stop_at && WallClock::now() >= *run_.options.stop_at) {
          checkpoint();
          progress_.close();
          sum.interrupted = true;
          sum.steps = sim_.step_count() - first_step;
          sum.wall_s = std::chrono::duration<double>(WallClock::now() - start).count();
          return sum;
        }
        sim_.step();
        record_step(run_);
        if (frame_due(run_)) write_frame(run_);
        contours_at_requested(run_);
        const auto now = WallClock::now();
        if (progress_.due()) show_progress(sim_.step_count() - first_step);
        const double every = run_.scene.output.checkpoint_every_s;
        if (every > 0 && std::chrono::duration<double>(now - last_checkpoint).count() > every) {
          checkpoint();
          last_checkpoint = now;
        }
      }
    } catch (const SimulationError& e) {
      keep_failed_run(e);
    }
    if (state_.period_steps > 0) close_period(run_);
    progress_.close();
    sum.steps = sim_.step_count() - first_step;
    sum.wall_s = std::chrono::duration<double>(WallClock::now() - start).count();
    sum.particle_steps_per_s = sum.wall_s > 0 ? static_cast<double>(sum.steps) * sim_.particles().n / sum.wall_s : 0.0;
    write_results(run_, sum);
    return sum;
  }

 private:
  Simulation sim_;
  RunState state_;
  RunContext run_;
  common::ProgressLine progress_{std::cerr, !run_.options.quiet, 0.2, 1.0};

  // A resumed run goes on in its own folder; a new one never mixes its files with another's.
  void prepare_folder() const {
    const RunOptions& opt = run_.options;
    if (!opt.resume_from.empty()) {
      fs::create_directories(opt.output_dir);
      return;
    }
    const std::size_t moved = common::set_aside_earlier_run(opt.output_dir, is_run_output_name);
    if (moved > 0 && !opt.quiet)
      std::cerr << "acst_mpm: moved the " << moved << " files of the earlier run in '" << opt.output_dir
                << "' into its subfolder '" << common::previous_run_folder << "'\n";
  }

  // The record so far next to the good files, the failing update as an element test; rethrown.
  [[noreturn]] void keep_failed_run(const SimulationError& e) {
    progress_.close();
    common::write_file_atomically(run_.path("load_settlement.failed.csv"), load_csv_text(run_.scene, run_.rows()));
    write_tracks(run_);
    if (e.reproducer.empty()) throw;
    common::write_file_atomically(run_.path("failure_reproducer.json"), e.reproducer);
    throw SimulationError(std::string(e.what()) + "\n(wrote " + run_.path("failure_reproducer.json") +
                              ": the failing material update as an element test, replayed by acst_element, and " +
                              run_.path("load_settlement.failed.csv") + ": the load record up to the failure)",
                          e.reproducer);
  }

  bool finished() const {
    const StopSpec& stop = run_.scene.stop;
    if (stop.S_over_B) return run_.S_over_B() >= *stop.S_over_B;
    if (stop.time) return sim_.time() >= *stop.time;
    return sim_.step_count() >= *stop.steps;
  }

  double progress_fraction() const {
    const StopSpec& stop = run_.scene.stop;
    if (stop.S_over_B) return run_.S_over_B() / *stop.S_over_B;
    if (stop.time) return sim_.time() / *stop.time;
    return static_cast<double>(sim_.step_count()) / static_cast<double>(*stop.steps);
  }

  void show_progress(long long steps) {
    const double wall = progress_.elapsed_s(), rate = steps / std::max(wall, 1e-9);
    const double q = state_.history.empty() ? 0.0 : state_.history.back().q_kPa;
    char text[256];
    std::snprintf(text, sizeof text, "%s: step %lld  t %.3f s  S/B %.4f  q %.1f kPa  %.0f steps/s  ",
                  run_.scene.name.c_str(), sim_.step_count(), sim_.time(), run_.S_over_B(), q, rate);
    progress_.show(text + common::ProgressLine::time_left(wall, progress_fraction()));
  }

  void checkpoint() {
    write_checkpoint(run_.path("checkpoint.bin"), run_.scene, sim_, state_);
    common::write_file_atomically(run_.path("load_settlement.partial.csv"), load_csv_text(run_.scene, run_.rows()));
  }
};

}  // namespace

RunSummary run_scene(const Scene& scene, const RunOptions& options) {
  Run run(scene, options);
  return run.run();
}

}  // namespace acst::mpm
