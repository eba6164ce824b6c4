// The registration list of the C ABI's model kinds: adding a kind is one file (kind_*.cpp,
// implementing ModelKind) plus one line here.
#include <Eigen/Core>
#include <algorithm>
#include <string>

#include "abi_convention.hpp"
#include "acst/json_input.hpp"
#include "c_abi_support.hpp"
#include "model_kind.hpp"
#include "state_layout.hpp"

namespace acst::abi {

namespace {

struct Registration {
  const char* model;  // the JSON "model" value
  bool takes_integrator;
  std::unique_ptr<const ModelKind> (*make)(const nlohmann::json& document);
};

constexpr Registration kinds[] = {
    {"ACST", true, make_sand_kind},
    {"isotropic", true, make_sand_kind},
    {"linear_elastic", false, make_linear_elastic_kind},
    {"von_mises", false, make_von_mises_kind},
    {"drucker_prager", false, make_drucker_prager_kind},
};

std::string allowed_models() {
  std::string s;
  for (const Registration& r : kinds) s += (s.empty() ? "" : ", ") + std::string(r.model);
  return "(allowed: " + s + ")";
}

}  // namespace

std::string ModelKind::state_problem(const double* stress, const double* statev) const {
  if (!all_finite(stress, 6)) return "the stress is not finite";
  if (!all_finite(statev, state().size)) return "a state variable is not finite";
  return "";
}

std::string ModelKind::turned_state_problem(const double*, const double* statev) const {
  return all_finite(statev, state().size) ? "" : "a state variable is not finite";
}

bool ModelKind::diagnostic_applies(int) const { return true; }

void ModelKind::rotated_copy(const double* stress, const double* statev, const double* r, double* s,
                             double* q) const {
  std::copy(statev, statev + state().size, q);
  const Eigen::Matrix3d Q = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(r);
  stress_from_model(rotate(stress_to_model(stress), Q), s);
  rotate_tensorial_state(q, state(), Q);
}

acst_status ModelKind::update_rotated(double* stress, double* statev, double* tangent, const double* r,
                                      const double* dstrain, const double* nonlocal, integration::Report& rep) const {
  // The rotated copies go straight to the update, whose entry checks refuse what is not finite
  // or not physical and whose OK vouches for what it returns: the rotated state is never handed
  // out, so acst_rotate_state's whole check of it and its copies back are not needed (with them,
  // 3-4 % of an MPM step); only what the update would take and the rotation
  // refuses is checked, so that the answer is that of the two calls, as are the numbers.
  double s[6], q[ACST_NSTATV];
  rotated_copy(stress, statev, r, s, q);
  if (const std::string problem = turned_state_problem(s, q); !problem.empty()) {
    rep = integration::Report{};
    return make_status(ACST_NONPHYSICAL_STATE, "acst_update_rotated: " + problem, 1.0);
  }
  const acst_status st = update(s, q, tangent, dstrain, nonlocal, rep);
  if (st.code != ACST_OK) return st;
  std::copy(s, s + 6, stress);
  std::copy(q, q + state().size, statev);
  return st;
}

void ModelKind::update_rotated_points(int m, double* const* stress, double* const* statev, const double* const* r,
                                      const double* const* dstrain, const double* const* nonlocal, int* codes,
                                      integration::Report* reports, acst_status& failure) const {
  for (int k = 0; k < m; ++k) {
    const acst_status st =
        update_rotated(stress[k], statev[k], nullptr, r[k], dstrain[k], nonlocal ? nonlocal[k] : nullptr, reports[k]);
    codes[k] = st.code;
    if (st.code != ACST_OK && failure.code == ACST_OK) failure = st;
  }
}

acst_status ModelKind::void_ratio_from_relative_density(double*, double) const {
  return make_status(ACST_INVALID_INPUT, "acst_void_ratio_from_relative_density: only for sand models (ACST, isotropic)",
                     1.0);
}

nlohmann::json ModelKind::reproducer(const double*, const double*, const double*, const double*) const {
  throw InputError(std::string("reproducers are written for the sand models (ACST, isotropic) that acst_element runs, not for '") +
                   name() + "'");
}

std::unique_ptr<const ModelKind> make_model_kind(const std::string& json_text) {
  const nlohmann::json document = model_document(json_text);
  if (!document.contains("model")) return kinds[0].make(document);
  const nlohmann::json& model = document["model"];
  if (!model.is_string())
    throw InputError("/model: expected a string " + allowed_models() + ", got " + model.type_name());
  const std::string name = model.get<std::string>();
  for (const Registration& r : kinds) {
    if (name != r.model) continue;
    if (!r.takes_integrator && document.contains("integrator"))
      throw InputError("/integrator: model '" + name + "' has a closed-form update and takes no integrator options");
    return r.make(document);
  }
  throw InputError("/model: unknown model '" + name + "' " + allowed_models());
}

}  // namespace acst::abi
