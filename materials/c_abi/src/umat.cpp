// Abaqus-compatible UMAT entry point over the same update path as acst_update.
//
// PROPS(1..18): the material constants in the order of acst::parameter_table (docs/model.md
// section 9 lists them with their PROPS numbers).
// PROPS(19) (optional): scheme, 0 FE-1, 1 ME (default), 2 RK23, 3 RK45;  PROPS(20) (optional): STOL;
// PROPS(21) (optional): pressure floor, 0 reset to p_min (default), 1 fail with PNEWDT < 1.
// PROPS(22) (optional): frame of STATEV's fabric, 0 (default) the host's rotating frame as in
// Abaqus/Standard: STRESS arrives rotated, so the fabric F (STATEV 1-6) is turned with DROT
// (F -> DROT F DROT^T) before the update; 1 the material frame (hosts such as CalculiX's
// ABAQUSNL interface, which rotate back themselves): DROT is ignored.
// STATEV(1..10): as acst_state_name (F11..F23, void ratio, H, substep hint, floor resets);
// the host initialises them (acst_initial_state gives the values).
// NTENS 6 (11 22 33 12 13 23) or 4 (11 22 33 12). Abaqus convention: tension positive,
// engineering shear strain, DDSDDE column-major.
#include <Eigen/LU>  // determinant of DROT
#include <algorithm>

#include "abi_convention.hpp"
#include "acst.h"
#include "c_abi_support.hpp"
#include "state_layout.hpp"

namespace {

// PROPS(22): whether the tensorial state variables are turned with DROT.
bool rotates_with_drot(const double* props, int nprops) {
  if (nprops <= 21) return true;
  if (props[21] != 0.0 && props[21] != 1.0)
    throw acst::InputError("PROPS(22) must be 0 (rotate the fabric with DROT) or 1 (material frame)");
  return props[21] == 0.0;
}

// DROT, Fortran column-major DROT(i, j) = drot[i + 3 j], as a rotation; NULL is the identity.
Eigen::Matrix3d rotation_increment(const double* drot) {
  if (!drot) return Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d R = Eigen::Map<const Eigen::Matrix3d>(drot);  // Eigen is column-major too
  if (!R.allFinite() || (R * R.transpose() - Eigen::Matrix3d::Identity()).norm() > 1e-8 || R.determinant() <= 0.0)
    throw acst::InputError("DROT is not a proper rotation");
  return R;
}

acst::Material material_from_props(const double* props, int nprops) {
  acst::Parameters p;
  for (int i = 0; i < acst::parameter_count; ++i) acst::parameter_by_index(p, i) = props[i];
  acst::integration::Options o;
  if (nprops > 18) {
    const int code = static_cast<int>(props[18]);
    if (code < 0 || code > 3 || props[18] != code) throw acst::InputError("PROPS(19) must be 0, 1, 2 or 3");
    o.scheme = static_cast<acst::integration::Scheme>(code);
  }
  if (nprops > 19) o.stol = props[19];
  if (nprops > 20) {
    if (props[20] != 0.0 && props[20] != 1.0) throw acst::InputError("PROPS(21) must be 0 (reset) or 1 (fail)");
    o.pressure_floor = props[20] == 0.0 ? acst::integration::PressureFloorPolicy::reset
                                         : acst::integration::PressureFloorPolicy::fail;
  }
  return acst::Material(p, o);
}

}  // namespace

extern "C" void umat_(double* stress, double* statev, double* ddsdde, double*, double*, double*, double*, double*,
                      double*, double*, const double*, const double* dstran, const double*, const double*,
                      const double*, const double*, const double*, const double*, const char*, const int*,
                      const int*, const int* ntens, const int* nstatv, const double* props, const int* nprops,
                      const double*, const double* drot, double* pnewdt, const double*, const double*, const double*,
                      const int*, const int*, const int*, const int*, const int*, const int*, size_t) {
  // A failure that no smaller time step can fix: PNEWDT = 0 tells the host to stop cutting back.
  constexpr double unrecoverable = 0.0;
  try {
    const int nt = ntens ? *ntens : 0;
    if ((nt != 6 && nt != 4) || !nstatv || *nstatv < ACST_NSTATV || !nprops || *nprops < acst::parameter_count ||
        !stress || !statev || !ddsdde || !dstran || !props || !pnewdt) {
      if (pnewdt) *pnewdt = unrecoverable;
      return;
    }
    const acst::Material mat = material_from_props(props, *nprops);
    double s6[6] = {0, 0, 0, 0, 0, 0}, d6[6] = {0, 0, 0, 0, 0, 0}, tangent[36];
    std::copy(stress, stress + nt, s6);
    std::copy(dstran, dstran + nt, d6);
    // The update works on a copy of the state, so a failure leaves STATEV as it came.
    double state[ACST_NSTATV];
    std::copy(statev, statev + ACST_NSTATV, state);
    if (rotates_with_drot(props, *nprops)) {
      const Eigen::Matrix3d R = rotation_increment(drot);
      if (!R.isIdentity(0.0)) acst::abi::rotate_tensorial_state(state, acst::abi::sand_state_layout, R);
    }
    acst::integration::Report rep;
    const acst_status st = acst::abi::update_point(s6, state, tangent, mat, d6, rep);
    if (st.code != ACST_OK) {
      *pnewdt = st.code == ACST_STEP_REDUCTION ? std::min(*pnewdt, st.suggested_step_factor) : unrecoverable;
      return;
    }
    std::copy(state, state + ACST_NSTATV, statev);
    std::copy(s6, s6 + nt, stress);
    for (int i = 0; i < nt; ++i)
      for (int j = 0; j < nt; ++j) ddsdde[i + j * nt] = tangent[6 * i + j];
  } catch (...) {
    if (pnewdt) *pnewdt = unrecoverable;
  }
}
