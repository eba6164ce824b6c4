#pragma once
// Replayed strain paths for the integrator tests: compute a strain path once (with the mixed-
// control driver at a fine tolerance), then push exactly those strain increments through
// Material::update with different integrator options, so every scheme sees the same path.
// Model convention: compression positive, tensor shear strain, kPa.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "acst/material.hpp"
#include "acst/yield_function.hpp"
#include "acst_driver/mixed_control.hpp"

namespace acst::test {

// The same material constants with other integrator options (also used by bench/).
inline Material with_integrator(const Material& base, integration::Scheme scheme, double stol, int fe_substeps = 1,
                                bool reuse_last_substep = true,
                                integration::PressureFloorPolicy floor = integration::PressureFloorPolicy::reset) {
  integration::Options o = base.options();
  o.scheme = scheme;
  o.stol = stol;
  o.fe_substeps = fe_substeps;
  o.reuse_last_substep = reuse_last_substep;
  o.pressure_floor = floor;
  return Material(base.parameters(), o);
}

// Sample axis (1) along the deposition direction: triaxial compression normal to the bedding.
inline State isotropic_sample(const Material& m, double p, double void_ratio) {
  return m.initial_state(p * identity_tensor(), void_ratio, Eigen::Vector3d(1.0, 0.0, 0.0));
}

// Strain increments of a drained triaxial test (lateral stresses held), solved by the driver
// with RK45 at a fine tolerance. Throws if an increment does not converge.
inline std::vector<Sym> drained_triaxial_strain_path(const Material& base, State state, double axial_increment,
                                                     int increments) {
  const Material fine = with_integrator(base, integration::Scheme::rk45, 1e-10);
  std::vector<Sym> path;
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

// Result of pushing a strain path through one material.
struct Replay {
  std::vector<State> states;  // state after each increment (only the successful ones)
  integration::Counters counters;
  bool ok = true;
  integration::Reason reason = integration::Reason::none;
};

inline Replay replay(const Material& m, State state, const std::vector<Sym>& path) {
  Replay out;
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

// Error of a state's stress against a reference, as docs/integration.md section 3 defines it.
inline double relative_stress_error(const State& s, const State& ref) {
  return norm(s.stress - ref.stress) / std::max(norm(ref.stress), atmospheric_pressure);
}

// max over the path of |sigma - sigma_ref| / max(|sigma_ref|, pa). Both runs must be complete.
inline double max_stress_error(const std::vector<State>& run, const std::vector<State>& ref) {
  if (run.size() != ref.size()) throw std::runtime_error("max_stress_error: runs of different length");
  double e = 0.0;
  for (size_t i = 0; i < run.size(); ++i) e = std::max(e, relative_stress_error(run[i], ref[i]));
  return e;
}

// A fine-increment reference for one strain increment: `pieces` equal parts of it, each
// integrated with RK45 at STOL 1e-10. For a rate-independent model the exact solution along a
// straight strain path does not depend on how the path is cut into increments.
inline integration::Report fine_increment_reference(const Material& base, State& state, const Sym& deps, int pieces) {
  const Material fine = with_integrator(base, integration::Scheme::rk45, 1e-10);
  integration::Report total;
  for (int i = 0; i < pieces; ++i) {
    const integration::Report r = fine.update(state, deps / pieces);
    total.counters += r.counters;
    if (r.status != integration::Status::ok) {
      total.status = r.status;
      total.reason = r.reason;
      return total;
    }
  }
  return total;
}

inline bool all_finite(const State& s) {
  return s.stress.allFinite() && s.fabric.allFinite() && std::isfinite(s.void_ratio) && std::isfinite(s.H) &&
         std::isfinite(s.substep_hint);
}

}  // namespace acst::test
