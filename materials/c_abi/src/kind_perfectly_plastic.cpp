// The perfectly plastic verification kinds behind the C ABI: von Mises (radial return) and
// Drucker-Prager matched to Mohr-Coulomb in plane strain (return onto the cone or its apex).
// Both carry one state variable, the equivalent plastic strain, and differ only in the model,
// its return and what they say of an initial stress outside the surface.
#include <cmath>
#include <string>

#include "abi_convention.hpp"
#include "acst/json_input.hpp"
#include "acst/reference/drucker_prager.hpp"
#include "acst/reference/von_mises.hpp"
#include "c_abi_support.hpp"
#include "model_kind.hpp"

namespace acst::abi {

namespace {

constexpr const char* state_names[] = {"equivalent_plastic_strain"};
constexpr StateLayout layout{state_names, 1, nullptr, 0};

template <class Model, class Point>
class PerfectlyPlasticKind final : public ModelKind {
 public:
  // What the kind says of an initial stress outside its surface, after "acst_initial_state: ".
  using OutsideMessage = std::string (*)(const Model&, const Sym&);

  PerfectlyPlasticKind(const char* name, Model m, OutsideMessage outside) : name_(name), m_(m), outside_(outside) {}

  const char* name() const override { return name_; }
  const StateLayout& state() const override { return layout; }

  acst_status initial_state(double* statev, double* stress_out, const double* stress0, double,
                            const double*) const override {
    const Sym s = stress_to_model(stress0);
    if (!s.allFinite()) return make_status(ACST_INVALID_INPUT, "acst_initial_state: initial stress is not finite", 1.0);
    if (!reference::within_yield_surface(m_, s))
      return make_status(ACST_NONPHYSICAL_STATE, "acst_initial_state: " + outside_(m_, s), 1.0);
    statev[0] = 0.0;
    stress_from_model(s, stress_out);
    return ok_status();
  }

  acst_status update(double* stress, double* statev, double* tangent, const double* dstrain,
                     const double* /* nothing softens */, integration::Report& rep) const override {
    Point point{stress_to_model(stress), statev[0]};
    const Sym deps = strain_to_model(dstrain);
    const bool state_ok = std::isfinite(point.equivalent_plastic_strain) && point.equivalent_plastic_strain >= 0.0;
    if (!entry_ok(point.stress, state_ok, deps, rep)) return status_from_report(rep);
    Mat6 D;
    rep.plastic = reference::radial_return(m_, point, deps, tangent ? &D : nullptr);
    if (!point.stress.allFinite() || !std::isfinite(point.equivalent_plastic_strain) || (tangent && !D.allFinite()))
      return nonfinite_result("the stress, plastic strain or tangent");
    stress_from_model(point.stress, stress);
    statev[0] = point.equivalent_plastic_strain;
    if (tangent) tangent_from_model(D, tangent);
    return ok_status();
  }

  std::string state_problem(const double* stress, const double* statev) const override {
    if (const std::string p = ModelKind::state_problem(stress, statev); !p.empty()) return p;
    return statev[0] >= 0.0 ? "" : "the equivalent plastic strain is negative";
  }

  ElasticModuli moduli(const double*, const double*) const override { return reference::moduli(m_.elastic); }

  void diagnostics(double* out, const double* stress, const double*) const override {
    reference_diagnostics(out, stress_to_model(stress), reference::moduli(m_.elastic));
  }

  bool diagnostic_applies(int i) const override { return reference_diagnostic(i); }

 private:
  const char* name_;
  Model m_;
  OutsideMessage outside_;
};

std::string outside_von_mises(const reference::VonMises& m, const Sym& s) {
  return "initial stress lies outside the von Mises yield surface (q = " +
         std::to_string(reference::equivalent_stress(s)) + " kPa > yield_stress = " + std::to_string(m.yield_stress) +
         " kPa)";
}

std::string outside_drucker_prager(const reference::DruckerPrager& m, const Sym& s) {
  return "initial stress lies outside the Drucker-Prager cone (sqrt(J2) = " + std::to_string(reference::sqrt_J2(s)) +
         " kPa > " + std::to_string(m.k + m.alpha * trace(s)) + " kPa at p = " + std::to_string(trace(s) / 3.0) +
         " kPa, compression positive)";
}

}  // namespace

std::unique_ptr<const ModelKind> make_von_mises_kind(const nlohmann::json& document) {
  return std::make_unique<PerfectlyPlasticKind<reference::VonMises, reference::VonMisesPoint>>(
      "von_mises", von_mises_from_json(document["parameters"], "/parameters"), outside_von_mises);
}

std::unique_ptr<const ModelKind> make_drucker_prager_kind(const nlohmann::json& document) {
  return std::make_unique<PerfectlyPlasticKind<reference::DruckerPrager, reference::DruckerPragerPoint>>(
      "drucker_prager", drucker_prager_from_json(document["parameters"], "/parameters"), outside_drucker_prager);
}

}  // namespace acst::abi
