#pragma once
// Shared by the benchmark programs: the guide material, replayed drained triaxial strain paths,
// errors against a reference, and median timing. Model convention: compression positive,
// tensor shear strain, kPa.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "acst/material.hpp"
#include "acst_common/files.hpp"
#include "acst_driver/number_format.hpp"
#include "bench_args.hpp"
#include "acst/yield_function.hpp"
#include "acst_driver/mixed_control.hpp"
#include "strain_path_replay.hpp"  // tests/support: the replayed strain paths the tests use too

namespace acst::bench {

inline std::string read_text(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

inline const std::string& guide_json() {
  static const std::string text = read_text(std::string(ACST_SOURCE_DIR) + "/data/parameters/toyoura_acst_guide.json");
  return text;
}

inline Material guide_material() { return Material::from_json(guide_json()); }

// Output folder: the command line's one argument if given, else <source>/bench/results; created if
// missing. `usage` answers --help and follows a refused command line (bench_args.hpp).
inline std::string output_dir(int argc, char** argv, const char* usage) {
  const std::string dir =
      command_line_argument(argc, argv, usage, true).value_or(std::string(ACST_SOURCE_DIR) + "/bench/results");
  std::filesystem::create_directories(dir);
  return dir;
}

// A CSV table built in memory and published whole (common::write_file_atomically): a run that fails
// half way leaves the previous table in place. Numbers as the element tests' CSV writes them (10
// significant digits); text quoted where it holds a comma, a quote or a line break (quotes doubled).
class CsvTable {
 public:
  explicit CsvTable(const std::string& header) : text_(header + "\n") {}
  CsvTable& cell(double v) {
    separate();
    driver::append_number(text_, v);
    return *this;
  }
  CsvTable& cell(const std::string& v) {
    separate();
    if (v.find_first_of(",\"\r\n") == std::string::npos) {
      text_ += v;
      return *this;
    }
    text_ += '"';
    for (char c : v) text_ += c == '"' ? std::string("\"\"") : std::string(1, c);
    text_ += '"';
    return *this;
  }
  CsvTable& blank() {
    separate();
    return *this;
  }
  void end_row() {
    text_ += '\n';
    row_started_ = false;
  }
  // Throws std::runtime_error naming the file when it cannot be written.
  void publish(const std::string& path) const { common::write_file_atomically(path, text_); }

 private:
  void separate() {
    if (row_started_) text_ += ',';
    row_started_ = true;
  }
  std::string text_;
  bool row_started_ = false;
};

using test::drained_triaxial_strain_path;
using test::isotropic_sample;
using test::replay;
using test::Replay;

// A point that falls below p_min is a failure with a reason here, not a silent reset.
inline Material with_integrator(const Material& base, integration::Scheme scheme, double stol, int fe_substeps = 1,
                                bool reuse_last_substep = true) {
  return test::with_integrator(base, scheme, stol, fe_substeps, reuse_last_substep,
                               integration::PressureFloorPolicy::fail);
}

// Errors of a run against a reference over the increments both have (docs section 3):
// stress |sigma - sigma_ref| / max(|sigma_ref|, pa); void ratio |e - e_ref| / e_ref;
// fabric |F - F_ref| / max(|F_ref|, 0.01). Max over the path.
struct PathError {
  double stress = 0.0, void_ratio = 0.0, fabric = 0.0;
};

inline PathError path_error(const std::vector<State>& run, const std::vector<State>& ref) {
  PathError e;
  const size_t n = std::min(run.size(), ref.size());
  for (size_t i = 0; i < n; ++i) {
    e.stress = std::max(e.stress, norm(run[i].stress - ref[i].stress) / std::max(norm(ref[i].stress), atmospheric_pressure));
    e.void_ratio = std::max(e.void_ratio, std::abs(run[i].void_ratio - ref[i].void_ratio) / ref[i].void_ratio);
    e.fabric = std::max(e.fabric, norm(run[i].fabric - ref[i].fabric) / std::max(norm(ref[i].fabric), 1e-2));
  }
  return e;
}

inline double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

}  // namespace acst::bench
