// acst_mpm: runs MPM scenes (strip footings on ACST sand, verification problems).
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>

#include "acst_mpm/runner.hpp"

namespace {

const char* usage =
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

int main(int argc, char** argv) {
  acst::mpm::RunOptions opt;
  std::string scene_file;
  int threads = -1;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&](const char* what) -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "acst_mpm: %s needs a value\n%s", what, usage);
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--help" || a == "-h") {
      std::fputs(usage, stdout);
      return 0;
    } else if (a == "--quiet") {
      opt.quiet = true;
    } else if (a == "--no-plot") {
      opt.plot = false;
    } else if (a == "--output") {
      opt.output_dir = value("--output");
    } else if (a == "--resume") {
      opt.resume_from = value("--resume");
    } else if (a == "--threads") {
      const std::string v = value("--threads");
      char* end = nullptr;
      const long n = std::strtol(v.c_str(), &end, 10);
      if (v.empty() || *end || n < 1 || n > 1024) {
        std::fprintf(stderr, "acst_mpm: --threads needs an integer in [1, 1024], got '%s'\n", v.c_str());
        return 2;
      }
      threads = static_cast<int>(n);
    } else if (!a.empty() && a[0] == '-') {
      std::fprintf(stderr, "acst_mpm: unknown option '%s'\n%s", a.c_str(), usage);
      return 2;
    } else if (scene_file.empty()) {
      scene_file = a;
    } else {
      std::fprintf(stderr, "acst_mpm: one scene per run (got '%s' and '%s')\n", scene_file.c_str(), a.c_str());
      return 2;
    }
  }
  if (scene_file.empty()) {
    std::fprintf(stderr, "acst_mpm: no scene given\n%s", usage);
    return 2;
  }
  acst::mpm::Scene scene;
  try {
    scene = acst::mpm::read_scene(scene_file);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "acst_mpm: %s\n", e.what());
    return 2;
  }
  if (threads > 0) scene.solver.threads = threads;
  if (opt.output_dir.empty()) opt.output_dir = "results/mpm/" + scene.name;
  try {
    const acst::mpm::RunSummary s = acst::mpm::run_scene(scene, opt);
    for (const auto& w : s.warnings) std::fprintf(stderr, "acst_mpm: warning: %s\n", w.c_str());
    std::printf("%s: %lld steps in %.1f s (%.3g particle-steps/s)", scene.name.c_str(), s.steps, s.wall_s,
                s.particle_steps_per_s);
    if (scene.footing)
      std::printf("; Q_ult %.1f kN/m (q_ult %.1f kPa) at S/B %.4f%s; final V %.1f kN/m", s.Q_ult,
                  s.Q_ult / scene.footing->width, s.S_ult_over_B, s.peak_reached ? "" : " (no peak: load still rising)",
                  s.residual_V);
    std::printf("\nresults: %s\n", opt.output_dir.c_str());
    return 0;
  } catch (const acst::mpm::SceneError& e) {
    std::fprintf(stderr, "acst_mpm: %s\n", e.what());
    return 2;
  } catch (const acst::mpm::MaterialError& e) {
    std::fprintf(stderr, "acst_mpm: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "acst_mpm: %s\n", e.what());
    return 1;
  }
}
