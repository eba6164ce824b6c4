// ACST and its isotropic reduction behind the C ABI: the substepping integrator of
// acst::Material, ten state variables (fabric, void ratio, H, substep hint, floor resets).
#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "abi_convention.hpp"
#include "acst/json_input.hpp"
#include "acst/material.hpp"
#include "acst/reproducer.hpp"
#include "acst/update_lanes.hpp"
#include "acst/yield_function.hpp"
#include "c_abi_support.hpp"
#include "model_kind.hpp"
#include "state_layout.hpp"

namespace acst::abi {

namespace {

std::string tension_problem(const Sym& model_stress) {
  const double p = mean_stress(model_stress);
  return p < 0.0 ? "the mean stress is tensile (p = " + std::to_string(p) + " kPa)" : "";
}

class SandKind final : public ModelKind {
 public:
  explicit SandKind(Material material) : material_(std::move(material)) {}

  const char* name() const override {
    return material_.parameters().variant == Variant::isotropic ? "isotropic" : "ACST";
  }
  const StateLayout& state() const override { return sand_state_layout; }

  acst_status initial_state(double* statev, double* stress_out, const double* stress0, double void_ratio,
                            const double* deposition_direction) const override {
    if (!deposition_direction) return make_status(ACST_INVALID_INPUT, "acst_initial_state: a pointer argument is NULL", 1.0);
    const Eigen::Vector3d b(deposition_direction[0], deposition_direction[1], deposition_direction[2]);
    const State s = material_.initial_state(stress_to_model(stress0), void_ratio, b);
    if (!s.fabric.allFinite() || !std::isfinite(s.H))
      return make_status(ACST_INVALID_INPUT,
                         "acst_initial_state: the initial stress is too large for a finite state (its stress ratio "
                         "overflows)",
                         1.0);
    store_state(s, statev);
    stress_from_model(s.stress, stress_out);
    return ok_status();
  }

  // The checks of Material::update's entry (materials/src/material.cpp), with what failed named,
  // and no tension.
  std::string state_problem(const double* stress, const double* statev) const override {
    if (const std::string p = ModelKind::state_problem(stress, statev); !p.empty()) return p;
    const State s = state_of(stress, statev);
    if (!stress_within_limit(s.stress.data()))
      return "a stress component is beyond 1e100 kPa in size (acst::stress_limit), where the model's arithmetic "
             "overflows";
    if (!void_ratio_admissible(s.void_ratio))
      return "void ratio " + std::to_string(s.void_ratio) + " outside (0, " + std::to_string(void_ratio_limit) + ")";
    if (s.H < 0.0) return "H (state variable 8) is negative";
    return tension_problem(s.stress);
  }

  // Sand carries no tension. acst_update takes such a state (the integrator's p_min floor deals
  // with it); the functions that only read a state refuse it, and so acst_rotate_state does, and
  // acst_update_rotated with it.
  std::string turned_state_problem(const double* stress, const double* statev) const override {
    if (std::string p = ModelKind::turned_state_problem(stress, statev); !p.empty()) return p;
    return tension_problem(stress_to_model(stress));
  }

  // One quantity nonlocally, the void ratio: its offset moves the state parameter (docs/model.md
  // section 11).
  int nonlocal_size() const override { return 1; }
  const char* nonlocal_name(int i) const override { return i == 0 ? "void_ratio" : nullptr; }
  void nonlocal_local(double* out, const double*, const double* statev) const override {
    out[0] = statev[slot_void_ratio];
  }

  acst_status update(double* stress, double* statev, double* tangent, const double* dstrain, const double* nonlocal,
                     integration::Report& rep) const override {
    return update_point(stress, statev, tangent, material_, dstrain, rep, nonlocal ? nonlocal[0] : 0.0);
  }

  // Up to UpdateLanes::width points at a time in SIMD lanes (acst/update_lanes.hpp), each turned
  // straight into its lane and a done lane's result written straight back (through a State and
  // Eigen temporaries, the copies stalled on store forwarding); the points
  // the lanes leave go through update_rotated. The lanes' numbers are update_point's after
  // rotated_copy's turn, so every point's are.
  void update_rotated_points(int m, double* const* stress, double* const* statev, const double* const* r,
                             const double* const* dstrain, const double* const* nonlocal, int* codes,
                             integration::Report* reports, acst_status& failure) const override {
    if (!lanes_apply(material_))
      return ModelKind::update_rotated_points(m, stress, statev, r, dstrain, nonlocal, codes, reports, failure);
    const auto offset_of = [&](int k) { return nonlocal && nonlocal[k] ? nonlocal[k] : nullptr; };
    constexpr int W = UpdateLanes::width;
    for (int first = 0; first < m; first += W) {
      const int end = std::min(m, first + W);
      UpdateLanes lanes;
      int point[W] = {};
      for (int k = first; k < end; ++k) {
        codes[k] = -1;  // not yet updated
        if (!put_turned(lanes, lanes.n, stress[k], statev[k], r[k], dstrain[k], offset_of(k))) continue;
        point[lanes.n++] = k;
      }
      update_lanes(material_, lanes);
      for (int l = 0; l < lanes.n; ++l) {
        if (!lanes.done[l]) continue;
        const int k = point[l];
        take_done(lanes, l, stress[k], statev[k]);
        reports[k] = lane_report(lanes, l);
        codes[k] = ACST_OK;
      }
      for (int k = first; k < end; ++k) {
        if (codes[k] != -1) continue;
        const acst_status st = update_rotated(stress[k], statev[k], nullptr, r[k], dstrain[k], offset_of(k), reports[k]);
        codes[k] = st.code;
        if (st.code != ACST_OK && failure.code == ACST_OK) failure = st;
      }
    }
  }

  ElasticModuli moduli(const double* stress, const double* statev) const override {
    return material_.elastic_moduli(state_of(stress, statev));
  }

  void diagnostics(double* out, const double* stress, const double* statev) const override {
    const Diagnostics d = material_.diagnostics(state_of(stress, statev));
    const double v[ACST_NDIAGNOSTICS] = {d.p,           d.q,   d.R, d.sin3theta, d.psi, d.zeta, d.A,
                                         d.fabric_norm, d.critical_void_ratio, d.D, d.Kp, d.G, d.K};
    std::memcpy(out, v, sizeof v);
  }

  nlohmann::json reproducer(const double* stress, const double* statev, const double* dstrain,
                            const double* nonlocal) const override {
    return update_reproducer(material_, state_of(stress, statev), strain_to_model(dstrain),
                             "One-increment reproducer of a material update written through the C ABI",
                             nonlocal ? nonlocal[0] : 0.0);
  }

  acst_status void_ratio_from_relative_density(double* void_ratio, double relative_density) const override {
    if (!(relative_density >= 0.0 && relative_density <= 1.0))
      return make_status(ACST_INVALID_INPUT,
                         "acst_void_ratio_from_relative_density: relative density must lie in [0, 1]", 1.0);
    *void_ratio = acst::void_ratio_from_relative_density(material_.parameters(), relative_density);
    return ok_status();
  }

 private:
  // Into lane l, the state of rotated_copy(stress, statev, r) as update_point reads it and the
  // increment, for a turn about axis 3 (a plane-strain host's); false, and the lane not written,
  // where update_rotated would refuse the state before converting (a state variable not finite,
  // the substep hint too, or a tensile turned stress) and for other turns, which give shear out
  // of the plane that the lanes leave anyway.
  static bool put_turned(UpdateLanes& lanes, int l, const double* stress, const double* statev, const double* r,
                         const double* dstrain, const double* nonlocal) {
    if (!turns_about_axis3(r)) return false;
    double a[6], s[6], f[6];
    for (int i = 0; i < 6; ++i) a[i] = stress_entry_to_model(stress, i);
    rotate_about_axis3(a, r[0], r[1], r[3], r[4], s);
    if (mean_stress(s) < 0.0) return false;  // refused by update_rotated (tension_problem)
    rotate_about_axis3(statev + slot_fabric, r[0], r[1], r[3], r[4], f);
    bool finite = std::isfinite(statev[slot_void_ratio]) && std::isfinite(statev[slot_H]) &&
                  std::isfinite(statev[slot_floor_resets]) && std::isfinite(statev[slot_substep_hint]);
    for (int i = 0; i < 6; ++i) finite = finite && std::isfinite(f[i]);
    if (!finite) return false;
    for (int i = 0; i < 6; ++i) {
      lanes.stress[i][l] = s[i];
      lanes.fabric[i][l] = f[i];
      lanes.strain_increment[i][l] = strain_entry_to_model(dstrain, i);
    }
    lanes.void_ratio[l] = statev[slot_void_ratio];
    lanes.void_ratio_offset[l] = nonlocal ? nonlocal[0] : 0.0;
    lanes.H[l] = statev[slot_H];
    lanes.substep_hint[l] = statev[slot_substep_hint];
    return true;
  }

  // Done lane l back into the point's arrays, as update_point's store_state writes them.
  static void take_done(const UpdateLanes& lanes, int l, double* stress, double* statev) {
    for (int i = 0; i < 6; ++i) {
      stress[i] = stress_entry_from_model(lanes.stress[i][l]);
      statev[slot_fabric + i] = lanes.fabric[i][l];
    }
    statev[slot_void_ratio] = lanes.void_ratio[l];
    statev[slot_H] = lanes.H[l];
    statev[slot_substep_hint] = lanes.substep_hint[l];
    statev[slot_floor_resets] = floor_resets_of(statev);
  }

  static State state_of(const double* stress, const double* statev) {
    State s;
    s.stress = stress_to_model(stress);
    fill_state(s, statev);
    return s;
  }

  Material material_;
};

}  // namespace

std::unique_ptr<const ModelKind> make_sand_kind(const nlohmann::json& document) {
  return std::make_unique<SandKind>(material_from_document(document));
}

}  // namespace acst::abi
