// Isotropic linear elasticity behind the C ABI (a verification kind): closed-form update, no state.
#include <limits>

#include "abi_convention.hpp"
#include "acst/json_input.hpp"
#include "acst/reference/linear_elastic.hpp"
#include "acst/reference/von_mises.hpp"
#include "c_abi_support.hpp"
#include "model_kind.hpp"

namespace acst::abi {

namespace {

class LinearElasticKind final : public ModelKind {
 public:
  explicit LinearElasticKind(reference::LinearElastic m) : m_(m) {}

  const char* name() const override { return "linear_elastic"; }
  const StateLayout& state() const override {
    static constexpr StateLayout none{};
    return none;
  }

  acst_status initial_state(double*, double* stress_out, const double* stress0, double, const double*) const override {
    const Sym s = stress_to_model(stress0);
    if (!s.allFinite()) return make_status(ACST_INVALID_INPUT, "acst_initial_state: initial stress is not finite", 1.0);
    stress_from_model(s, stress_out);
    return ok_status();
  }

  acst_status update(double* stress, double*, double* tangent, const double* dstrain, const double* /* nothing softens */,
                     integration::Report& rep) const override {
    const Sym s = stress_to_model(stress), deps = strain_to_model(dstrain);
    if (!entry_ok(s, true, deps, rep)) return status_from_report(rep);
    const Sym next = reference::updated_stress(m_, s, deps);
    if (!next.allFinite()) return nonfinite_result("the stress");
    stress_from_model(next, stress);
    if (tangent) tangent_from_model(reference::stiffness(m_), tangent);
    return ok_status();
  }

  ElasticModuli moduli(const double*, const double*) const override { return reference::moduli(m_); }

  void diagnostics(double* out, const double* stress, const double*) const override {
    reference_diagnostics(out, stress_to_model(stress), reference::moduli(m_));
  }

  bool diagnostic_applies(int i) const override { return reference_diagnostic(i); }

 private:
  reference::LinearElastic m_;
};

}  // namespace

std::unique_ptr<const ModelKind> make_linear_elastic_kind(const nlohmann::json& document) {
  return std::make_unique<LinearElasticKind>(linear_elastic_from_json(document["parameters"], "/parameters"));
}

}  // namespace acst::abi
