#include "acst_mpm/material_adapter.hpp"

#include <cmath>
#include <cstring>

namespace acst::mpm {
namespace {

acst_model* create(const std::string& name, const std::string& json_text) {
  acst_model* m = nullptr;
  const acst_status st = acst_model_create(&m, json_text.c_str());
  if (st.code != ACST_OK) throw MaterialError("material '" + name + "': " + st.message);
  return m;
}

void check(const acst_status& st, const std::string& what) {
  if (st.code != ACST_OK) throw MaterialError(what + ": " + st.message);
}

// The update ended on a reset to the pressure floor: a reset leaves the stress exactly
// isotropic; strain after it in the same call would not.
bool reset_to_floor(const double* stress, const acst_counters& counters) {
  return counters.pressure_floor_resets > 0 && stress[0] == stress[1] && stress[1] == stress[2] && stress[3] == 0.0 &&
         stress[4] == 0.0 && stress[5] == 0.0;
}

}  // namespace

AbiMaterial::AbiMaterial(const std::string& name, const std::string& json_text)
    : name_(name), model_(create(name, json_text), acst_model_destroy) {
  state_size_ = acst_state_size(model_.get());
  if (state_size_ < 0 || state_size_ > max_state_size)
    throw MaterialError("material '" + name + "': unsupported number of state variables");
  nonlocal_size_ = acst_nonlocal_size(model_.get());
  if (nonlocal_size_ < 0 || nonlocal_size_ > 1)
    throw MaterialError("material '" + name + "': unsupported number of nonlocal quantities");
}

std::string AbiMaterial::kind() const {
  const char* k = acst_model_kind(model_.get());
  return k ? k : "";
}

bool AbiMaterial::is_sand() const {
  const std::string k = kind();
  return k == "ACST" || k == "isotropic";
}

std::vector<std::string> AbiMaterial::state_names() const {
  std::vector<std::string> names;
  for (int i = 0; i < state_size_; ++i) names.emplace_back(acst_state_name(model_.get(), i));
  return names;
}

void AbiMaterial::initial_state(double* statev, double* stress, double void_ratio, const double* deposition) const {
  check(acst_initial_state(statev, stress, model_.get(), stress, void_ratio, deposition),
        "material '" + name_ + "': initial state");
}

double AbiMaterial::void_ratio_from_relative_density(double Dr) const {
  double e = 0.0;
  check(acst_void_ratio_from_relative_density(&e, model_.get(), Dr), "material '" + name_ + "'");
  return e;
}

double AbiMaterial::wave_speed(const double* stress, const double* statev, double density) const {
  double c = 0.0;
  check(acst_wave_speed(&c, model_.get(), stress, statev, density), "material '" + name_ + "': wave speed");
  return c;
}

void AbiMaterial::diagnostics(double* out, const double* stress, const double* statev) const {
  check(acst_diagnostics(out, model_.get(), stress, statev), "material '" + name_ + "': diagnostics");
}

void AbiMaterial::nonlocal_local(double* out, const double* stress, const double* statev) const {
  check(acst_nonlocal_local(out, model_.get(), stress, statev), "material '" + name_ + "': nonlocal quantities");
}

int AbiMaterial::state_index(const std::string& name) const {
  for (int i = 0; i < state_size_; ++i)
    if (name == acst_state_name(model_.get(), i)) return i;
  return -1;
}

namespace {

// The rotation and the strain increment of a half step from L (plane strain: eps_zz = 0; ABI
// strain is tension positive with engineering shear).
void increment_of(const double* L, double dt, double* Q, double* de) {
  const PlaneRotation r = hughes_winget_rotation(L, dt);
  const double q[9] = {r.c, r.s, 0.0, -r.s, r.c, 0.0, 0.0, 0.0, 1.0};
  const double e[6] = {L[0] * dt, L[3] * dt, 0.0, (L[1] + L[2]) * dt, 0.0, 0.0};
  std::memcpy(Q, q, sizeof q);
  std::memcpy(de, e, sizeof e);
}

}  // namespace

acst_status AbiMaterial::update(double* stress, double* statev, const double* L, double dt, bool& stress_free,
                                std::string* reproducer, const double* offset) const {
  stress_free = false;
  double Q[9], de[6];
  increment_of(L, dt, Q, de);
  acst_counters counters{};
  // Turned and updated in one call, the common case. A failure leaves the state as it came: the
  // rare retry turns it on its own, updates it again and subdivides the increment (the numbers
  // of the two calls). Every return is `st`, so the status is built where the caller keeps it.
  acst_status st = acst_update_rotated_nonlocal(stress, statev, nullptr, &counters, model_.get(), Q, de, offset);
  if (st.code == ACST_OK) {
    stress_free = reset_to_floor(stress, counters);
    return st;
  }
  return retry(stress, statev, Q, de, stress_free, reproducer, offset);
}

std::size_t AbiMaterial::update_batch(std::size_t n, double* stress, double* statev, const double* L, double dt,
                                      int* stress_free, acst_status& failure, std::string* reproducer,
                                      const double* offset) const {
  double Q[9 * batch_size] = {}, de[6 * batch_size] = {};
  int codes[batch_size];
  acst_counters counters[batch_size];
  for (std::size_t k = 0; k < n; ++k) increment_of(L + 4 * k, dt, Q + 9 * k, de + 6 * k);
  const size_t stride = static_cast<size_t>(state_size_);
  acst_update_rotated_batch_nonlocal(stress, 6, statev, stride, codes, counters, model_.get(), n, Q, de, offset);
  std::size_t first = n;
  for (std::size_t k = 0; k < n; ++k) {
    double* s = stress + 6 * k;
    double* q = statev + stride * k;
    if (codes[k] == ACST_OK) {
      stress_free[k] = reset_to_floor(s, counters[k]);
      continue;
    }
    bool free = false;
    const bool first_failure = first == n;
    const double* point_offset = offset ? offset + static_cast<std::size_t>(nonlocal_size_) * k : nullptr;
    const acst_status st = retry(s, q, Q + 9 * k, de + 6 * k, free, first_failure ? reproducer : nullptr, point_offset);
    stress_free[k] = free;
    if (st.code != ACST_OK && first_failure) {
      first = k;
      failure = st;
    }
  }
  return first;
}

acst_status AbiMaterial::retry(double* stress, double* statev, const double* Q, const double* de, bool& stress_free,
                               std::string* reproducer, const double* offset) const {
  acst_status st = acst_rotate_state(stress, statev, model_.get(), Q);
  if (st.code != ACST_OK) return st;
  acst_counters counters{};
  st = acst_update_nonlocal(stress, statev, nullptr, &counters, model_.get(), de, offset);
  for (int parts = 2; st.code == ACST_STEP_REDUCTION && parts <= 64; parts *= 2) {
    double part[6];
    for (int k = 0; k < 6; ++k) part[k] = de[k] / parts;
    double s_try[6], q_try[max_state_size];
    std::memcpy(s_try, stress, sizeof s_try);
    std::memcpy(q_try, statev, sizeof(double) * static_cast<size_t>(state_size_));
    for (int k = 0; k < parts && (k == 0 || st.code == ACST_OK); ++k)
      st = acst_update_nonlocal(s_try, q_try, nullptr, &counters, model_.get(), part, offset);
    if (st.code == ACST_OK) {
      std::memcpy(stress, s_try, sizeof s_try);
      std::memcpy(statev, q_try, sizeof(double) * static_cast<size_t>(state_size_));
    }
  }
  stress_free = st.code == ACST_OK && reset_to_floor(stress, counters);
  if (st.code != ACST_OK && reproducer) {
    size_t length = 0;
    reproducer->clear();
    if (acst_reproducer_nonlocal(nullptr, &length, model_.get(), stress, statev, de, offset).code == ACST_OK) {
      reproducer->assign(length, '\0');
      if (acst_reproducer_nonlocal(reproducer->data(), &length, model_.get(), stress, statev, de, offset).code == ACST_OK)
        reproducer->resize(length - 1);
      else
        reproducer->clear();
    }
  }
  return st;
}

}  // namespace acst::mpm
