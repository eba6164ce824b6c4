// MPM throughput in particle-steps per second on the bundled Kimura V85.6 footing scene (the
// converged default: graded grid, micropolar rotations):
// with a linear elastic material through the C ABI (the MPM kernel alone: shape functions,
// the grid maps, XPIC, the micropolar passes, the scene's stress updates) and with ACST (end to end),
// on 1 and 2 threads. The ACST figure covers the first steps of loading (S/B < 0.01), where
// most particles are still elastic; the acceptance run's summary.json has the whole-run figure.
#include <chrono>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "acst_footing_tool/build_simulation.hpp"
#include "bench_args.hpp"

using namespace acst::mpm;

namespace {

double particle_steps_per_s(const Scene& scene, int threads, int steps) {
  Scene s = scene;
  s.solver.threads = threads;
  Simulation sim = build_simulation(s);
  for (int k = 0; k < 20; ++k) sim.step();  // warm-up
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < steps; ++k) sim.step();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return static_cast<double>(steps) * sim.particles().n / wall;
}

}  // namespace

int main(int argc, char** argv) {
  acst::bench::command_line_argument(
      argc, argv,
      "usage: mpm_bench [--help]\n"
      "MPM particle-steps per second on the Kimura V85.6 scene, elastic kernel and ACST, 1 and 2 threads.\n",
      false);
  const std::string path = std::string(ACST_SOURCE_DIR) + "/data/scenes/mpm/kimura_V85.6_alpha0.json";
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  nlohmann::json j = nlohmann::json::parse(ss.str());
  const Scene acst = parse_scene(j.dump(), path);
  j["materials"]["toyoura"] = {{"model", "linear_elastic"}, {"parameters", {{"E", 1e5}, {"nu", 0.3}}}};
  const Scene elastic = parse_scene(j.dump(), path);
  std::printf("scene: %s, %zu particles\n", path.c_str(), build_simulation(acst).particles().n);
  std::printf("%-28s %8s %22s %22s\n", "material", "threads", "particle-steps/s", "per thread");
  for (int threads : {1, 2}) {
    const double e = particle_steps_per_s(elastic, threads, 400);
    std::printf("%-28s %8d %22.3e %22.3e\n", "linear_elastic (kernel)", threads, e, e / threads);
  }
  for (int threads : {1, 2}) {
    const double a = particle_steps_per_s(acst, threads, 150);
    std::printf("%-28s %8d %22.3e %22.3e\n", "ACST (end to end, early)", threads, a, a / threads);
  }
  return 0;
}
