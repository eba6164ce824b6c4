// ACST and its isotropic reduction behind the C ABI: the substepping integrator of
// acst::Material, ten state variables (fabric, void ratio, H, substep hint, floor resets).
#include <Eigen/Core>
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
    if (!void_ratio_admissible(s.void_ratio))
      return "void ratio " + std::to_string(s.void_ratio) + " outside (0, " + std::to_string(void_ratio_limit) + ")";
    if (s.H < 0.0) return "H (state variable 8) is negative";
    // Sand carries no tension. (An update takes such a state: the integrator's p_min floor deals
    // with it; the functions that only read a state refuse it.)
    if (mean_stress(s.stress) < 0.0) return "the mean stress is tensile (p = " + std::to_string(mean_stress(s.stress)) + " kPa)";
    return "";
  }

  acst_status update(double* stress, double* statev, double* tangent, const double* dstrain,
                     integration::Report& rep) const override {
    return update_point(stress, statev, tangent, material_, dstrain, rep);
  }

  // Up to UpdateLanes::width points at a time in SIMD lanes (acst/update_lanes.hpp); the points
  // the lanes leave, and those update_point would refuse before converting, go through
  // update_point. The lanes' numbers are update_point's, so every point's are.
  void update_points(int m, double* const* stress, double* const* statev, const double* const* dstrain, int* codes,
                     integration::Report* reports, acst_status& failure) const override {
    if (!lanes_apply(material_)) return ModelKind::update_points(m, stress, statev, dstrain, codes, reports, failure);
    constexpr int W = UpdateLanes::width;
    for (int first = 0; first < m; first += W) {
      UpdateLanes lanes;
      int point[W] = {};
      State states[W];
      for (int k = first; k < m && k < first + W; ++k) {
        codes[k] = -1;  // not yet updated
        if (!state_variables_finite(statev[k])) continue;
        const int l = lanes.n++;
        point[l] = k;
        State& s = states[l];
        s.stress = stress_to_model(stress[k]);
        fill_state(s, statev[k]);
        put_lane(lanes, l, s, strain_to_model(dstrain[k]));
      }
      update_lanes(material_, lanes);
      for (int l = 0; l < lanes.n; ++l) {
        if (!lanes.done[l]) continue;
        const int k = point[l];
        State& s = states[l];
        take_lane(lanes, l, s);
        stress_from_model(s.stress, stress[k]);
        store_state(s, statev[k]);
        reports[k] = lane_report(lanes, l);
        codes[k] = ACST_OK;
      }
      for (int k = first; k < m && k < first + W; ++k) {
        if (codes[k] != -1) continue;
        const acst_status st = update(stress[k], statev[k], nullptr, dstrain[k], reports[k]);
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

  nlohmann::json reproducer(const double* stress, const double* statev, const double* dstrain) const override {
    return update_reproducer(material_, state_of(stress, statev), strain_to_model(dstrain),
                             "One-increment reproducer of a material update written through the C ABI");
  }

  acst_status void_ratio_from_relative_density(double* void_ratio, double relative_density) const override {
    if (!(relative_density >= 0.0 && relative_density <= 1.0))
      return make_status(ACST_INVALID_INPUT,
                         "acst_void_ratio_from_relative_density: relative density must lie in [0, 1]", 1.0);
    *void_ratio = acst::void_ratio_from_relative_density(material_.parameters(), relative_density);
    return ok_status();
  }

 private:
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
