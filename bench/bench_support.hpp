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
#include "acst/yield_function.hpp"
#include "acst_driver/mixed_control.hpp"

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

// Output folder: argv[1] if given, else <source>/bench/results; created if missing.
inline std::string output_dir(int argc, char** argv) {
  const std::string dir = argc > 1 ? argv[1] : std::string(ACST_SOURCE_DIR) + "/bench/results";
  std::filesystem::create_directories(dir);
  return dir;
}

inline Material with_integrator(const Material& base, integration::Scheme scheme, double stol, int fe_substeps = 1,
                                bool reuse_last_substep = true) {
  integration::Options o = base.options();
  o.scheme = scheme;
  o.stol = stol;
  o.fe_substeps = fe_substeps;
  o.reuse_last_substep = reuse_last_substep;
  // A point that falls below p_min is a failure with a reason here, not a silent reset.
  o.pressure_floor = integration::PressureFloorPolicy::fail;
  return Material(base.parameters(), o);
}

// Isotropic sample, axis 1 along the deposition direction.
inline State isotropic_sample(const Material& m, double p, double void_ratio) {
  return m.initial_state(p * identity_tensor(), void_ratio, Eigen::Vector3d(1.0, 0.0, 0.0));
}

// Strain increments of a drained triaxial test, solved by the driver with RK45 at STOL 1e-10.
inline std::vector<Sym> drained_triaxial_strain_path(const Material& base, State state, double axial_increment,
                                                     int increments) {
  const Material fine = with_integrator(base, integration::Scheme::rk45, 1e-10);
  std::vector<Sym> path;
  path.reserve(increments);
  Sym guess = Sym::Zero();
  guess[0] = axial_increment;
  guess[1] = guess[2] = -0.3 * axial_increment;
  for (int i = 0; i < increments; ++i) {
    const driver::IncrementResult r = driver::solve_increment(fine, state, driver::drained_triaxial(axial_increment), guess);
    if (!r.converged) throw std::runtime_error("drained triaxial path: increment " + std::to_string(i) + " failed");
    path.push_back(r.strain_increment);
    guess = r.strain_increment;
  }
  return path;
}

struct Replay {
  std::vector<State> states;  // after each successful increment
  integration::Counters counters;
  bool ok = true;
  integration::Reason reason = integration::Reason::none;
};

inline Replay replay(const Material& m, State state, const std::vector<Sym>& path) {
  Replay out;
  out.states.reserve(path.size());
  for (const Sym& deps : path) {
    const integration::Report r = m.update(state, deps);
    out.counters += r.counters;
    if (r.status != integration::Status::ok) {
      out.ok = false;
      out.reason = r.reason;
      break;
    }
    out.states.push_back(state);
  }
  return out;
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
