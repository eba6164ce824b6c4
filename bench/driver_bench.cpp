// End-to-end speed of the element-test driver: a 2000-increment drained triaxial compression
// (dense Toyoura sand, e0 = 0.67, sigma3 = 100 kPa, guide set, 1e-4 axial strain per increment),
// JSON scene file in, CSV out, as acst_element does it without the figure. Median of repeated
// runs; also the stages (read + parse, run, CSV) and an estimate of the material's share: the
// converged strain increments replayed through Material::update with tangent, scaled by the
// Newton iterations per increment (every iteration makes one such call).
//
// Usage: driver_bench [--help] [repeats]   (default 51)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "acst_driver/output.hpp"
#include "bench_args.hpp"
#include "acst_driver/runner.hpp"
#include "acst_driver/scene.hpp"

namespace {

using WallClock = std::chrono::steady_clock;

double ms_since(WallClock::time_point t0) { return std::chrono::duration<double, std::milli>(WallClock::now() - t0).count(); }

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  namespace fs = std::filesystem;
  namespace drv = acst::driver;
  const char* usage =
      "usage: driver_bench [--help] [REPEATS]\n"
      "A 2000-increment drained triaxial test end to end, the median of REPEATS runs (1 to 100000, default 51).\n";
  int repeats = 51;
  if (const auto given = acst::bench::command_line_argument(argc, argv, usage, true)) {
    char* end = nullptr;
    const long n = std::strtol(given->c_str(), &end, 10);
    if (end == given->c_str() || *end != '\0' || n < 1 || n > 100000) {
      std::fprintf(stderr, "driver_bench: REPEATS must be a whole number from 1 to 100000, got '%s'\n%s", given->c_str(),
                   usage);
      return 2;
    }
    repeats = static_cast<int>(n);
  }
  const fs::path dir = fs::temp_directory_path() / ("acst_driver_bench_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path scene_file = dir / "drained_tc_2000.json";
  std::ofstream(scene_file) << "{\"material\": {\"file\": \"" << ACST_SOURCE_DIR
                            << "/data/parameters/toyoura_acst_guide.json\"},\n"
                               " \"initial_state\": {\"confining_pressure\": 100, \"void_ratio\": 0.67, \"bedding_angle_deg\": 0},\n"
                               " \"steps\": [{\"preset\": \"drained_triaxial_compression\", \"axial_strain_pct\": 20, \"increments\": 2000}],\n"
                               " \"output\": {\"plot\": false}}\n";
  const std::string csv = (dir / "drained_tc_2000.csv").string();

  std::vector<double> total, parse, run, write, material;
  drv::RunResult last;
  for (int k = 0; k < repeats; ++k) {
    const auto t0 = WallClock::now();
    const drv::ElementScene s = drv::read_scene(scene_file.string());
    const double t_parse = ms_since(t0);
    const auto t1 = WallClock::now();
    drv::RunResult r = drv::run_scene(s);
    const double t_run = ms_since(t1);
    const auto t2 = WallClock::now();
    acst::common::write_file_atomically(csv, drv::csv_text(s, r));
    const double t_write = ms_since(t2);
    total.push_back(ms_since(t0));
    parse.push_back(t_parse);
    run.push_back(t_run);
    write.push_back(t_write);
    if (!r.ok) {
      std::fprintf(stderr, "run failed: %s\n", r.message.c_str());
      return 1;
    }
    // The material alone: the same converged increments through Material::update (with tangent).
    acst::State st = s.material->initial_state(s.initial.stress, s.initial.void_ratio, s.initial.deposition_direction);
    acst::Mat6 D;
    const auto t3 = WallClock::now();
    for (std::size_t i = 1; i < r.records.size(); ++i)
      s.material->update(st, r.records[i].strain - r.records[i - 1].strain, &D);
    material.push_back(ms_since(t3) * static_cast<double>(r.iterations) / static_cast<double>(r.increments));
    last = std::move(r);
  }
  const std::uintmax_t bytes = fs::file_size(csv);
  fs::remove_all(dir);
  const double per_iteration = static_cast<double>(last.iterations) / static_cast<double>(last.increments);
  std::printf("driver_bench: 2000-increment drained triaxial compression, JSON in, CSV out (%ju bytes), median of %d runs\n",
              bytes, repeats);
  std::printf("  end to end          %8.2f ms   (target < 20 ms)\n", median(total));
  std::printf("    read + parse JSON %8.2f ms\n", median(parse));
  std::printf("    run (Newton)      %8.2f ms   (%.2f Newton iterations per increment, %ld material substeps)\n", median(run),
              per_iteration, last.substeps);
  std::printf("    write CSV         %8.2f ms\n", median(write));
  std::printf("  material alone, estimated %6.2f ms = %.0f %% of end to end (converged increments replayed through\n"
              "    Material::update with tangent, times %.2f iterations per increment)\n",
              median(material), 100.0 * median(material) / median(total), per_iteration);
  return 0;
}
