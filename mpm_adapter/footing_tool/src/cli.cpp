#include "acst_footing_tool/cli.hpp"

#include <cstdio>
#include <exception>
#include <ostream>

#include "acst_common/cli.hpp"
#include "acst_common/input_error.hpp"
#include "acst_footing_tool/runner.hpp"
#include "acst_mpm/simulation.hpp"

namespace acst::mpm {

namespace {

const char* const usage =
    "usage: acst_mpm [--help] [--quiet] [--no-plot] [--output DIR] [--threads N] [--resume CHECKPOINT] SCENE.json\n"
    "\n"
    "Runs a 2-D plane-strain MPM scene (B2GIMP, USAVG, FLIP/PIC/XPIC(m), grid damping) whose soil is\n"
    "a material of the ACST library reached through its C ABI (docs/mpm.md).\n"
    "  --output DIR      results folder (default results/mpm/<scene name>)\n"
    "  --threads N       OpenMP threads (default: the scene's solver/threads, else all cores);\n"
    "                    results are identical for a given thread count\n"
    "  --resume FILE     continue from a checkpoint written by a run of the same scene\n"
    "  --quiet           no progress line\n"
    "  --no-plot         no PNG figures\n"
    "Writes load_settlement.csv (S, S/B, V, H, q = V/B per period), particles_NNNN.vtp + particles.pvd\n"
    "(ParaView), load_settlement.png with the lab curve, contour PNGs, summary.json and checkpoint.bin.\n"
    "Exit status: 0 done, 1 the simulation failed (message names step and particle), 2 bad input.\n";

}  // namespace

int mpm_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  common::CliSpec spec("acst_mpm", "scene");
  spec.threads = true;
  spec.value_options = {"--resume"};
  common::CliArgs cli;
  const int early = common::parse_command_line(spec, args, usage, out, err, cli);
  if (early >= 0) return early;
  RunOptions opt;
  opt.quiet = cli.quiet;
  opt.plot = cli.plot;
  opt.output_dir = cli.output;
  if (cli.values.count("--resume")) opt.resume_from = cli.values.at("--resume");
  Scene scene;
  try {
    scene = read_scene(cli.inputs.front());
  } catch (const std::exception& e) {
    err << "acst_mpm: " << e.what() << "\n";
    return common::exit_bad_input;
  }
  if (cli.threads > 0) scene.solver.threads = cli.threads;
  if (opt.output_dir.empty()) opt.output_dir = "results/mpm/" + scene.name;
  try {
    const RunSummary s = run_scene(scene, opt);
    for (const auto& w : s.warnings) err << "acst_mpm: warning: " << w << "\n";
    char line[512];
    std::snprintf(line, sizeof line, "%s: %lld steps in %.1f s (%.3g particle-steps/s)", scene.name.c_str(), s.steps,
                  s.wall_s, s.particle_steps_per_s);
    out << line;
    if (scene.footing) {
      std::snprintf(line, sizeof line, "; Q_ult %.1f kN/m (q_ult %.1f kPa) at S/B %.4f%s; final V %.1f kN/m", s.Q_ult,
                    s.Q_ult / scene.footing->width, s.S_ult_over_B,
                    s.peak_reached ? "" : " (no peak: load still rising)", s.residual_V);
      out << line;
    }
    out << "\nresults: " << opt.output_dir << "\n";
    return common::exit_done;
  } catch (const common::InputError& e) {
    err << "acst_mpm: " << e.what() << "\n";
    return common::exit_bad_input;
  } catch (const MaterialError& e) {
    err << "acst_mpm: " << e.what() << "\n";
    return common::exit_bad_input;
  } catch (const std::exception& e) {
    err << "acst_mpm: " << e.what() << "\n";
    return common::exit_failed;
  }
}

}  // namespace acst::mpm
