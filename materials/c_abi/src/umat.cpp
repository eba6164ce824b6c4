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
// engineering shear strain, DDSDDE column-major. Failures follow the protocol in acst.h (acst_umat).
#include <Eigen/LU>  // determinant of DROT
#include <algorithm>
#include <cmath>
#include <exception>
#include <string>

#include "abi_convention.hpp"
#include "acst.h"
#include "acst/reproducer.hpp"
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
  if (nprops > 22) p.lode_form = props[22];  // checked with the others (0 or 1)
  if (nprops > 23) p.elastic_anisotropy = props[23];  // checked with the others ([-5, 5])
  if (nprops > 24) p.peak_pressure_exponent = props[24];  // checked with the others ([-1, 1])
  acst::integration::Options o;
  if (nprops > 18) {
    // Compared as a double before it becomes an int: converting NaN, an infinity or 1e300 to an
    // int is undefined behaviour.
    const double code = props[18];
    if (!(code == 0.0 || code == 1.0 || code == 2.0 || code == 3.0))
      throw acst::InputError("PROPS(19) must be 0, 1, 2 or 3");
    o.scheme = static_cast<acst::integration::Scheme>(static_cast<int>(code));
  }
  if (nprops > 19) o.stol = props[19];
  if (nprops > 20) {
    if (props[20] != 0.0 && props[20] != 1.0) throw acst::InputError("PROPS(21) must be 0 (reset) or 1 (fail)");
    o.pressure_floor = props[20] == 0.0 ? acst::integration::PressureFloorPolicy::reset
                                         : acst::integration::PressureFloorPolicy::fail;
  }
  return acst::Material(p, o);
}

// What umat_ integrates: the material from PROPS, stress and strain increment padded to six
// components, and a copy of the state with the fabric turned by DROT where PROPS(22) asks.
struct UmatPoint {
  acst::Material material;
  double stress[6] = {0, 0, 0, 0, 0, 0}, dstrain[6] = {0, 0, 0, 0, 0, 0}, state[ACST_NSTATV] = {};
};

UmatPoint umat_point(const double* stress, const double* statev, const double* dstran, int nt, const double* props,
                     int nprops, const double* drot) {
  UmatPoint u{material_from_props(props, nprops)};
  std::copy(stress, stress + nt, u.stress);
  std::copy(dstran, dstran + nt, u.dstrain);
  std::copy(statev, statev + ACST_NSTATV, u.state);
  if (rotates_with_drot(props, nprops)) {
    const Eigen::Matrix3d R = rotation_increment(drot);
    if (!R.isIdentity(0.0)) acst::abi::rotate_tensorial_state(u.state, acst::abi::sand_state_layout, R);
  }
  return u;
}

// DDSDDE of a failed call (docs/c-abi.md, "umat_ and its hosts"): the elastic tangent of the
// start state, with p raised to p_min and a void ratio outside (0, 2.97) read as 1, so it is
// finite and positive definite whatever the state; from PROPS that do not form a material, a
// nominal isotropic stiffness (G = K = 1000 p_atm). Some hosts assemble DDSDDE even after a
// cut-back request, and CalculiX hands over an uninitialised matrix.
void write_fallback_tangent(double* ddsdde, int nt, const double* stress, const double* statev, int nstatv,
                            const double* props, int nprops) {
  acst::ElasticModuli mod{1000.0 * acst::atmospheric_pressure, 1000.0 * acst::atmospheric_pressure};
  if (props && nprops >= acst::parameter_count) {
    acst::Parameters p;
    for (int i = 0; i < acst::parameter_count; ++i) acst::parameter_by_index(p, i) = props[i];
    double e = statev && nstatv >= ACST_NSTATV ? statev[acst::abi::slot_void_ratio] : 1.0;
    if (!acst::void_ratio_admissible(e)) e = 1.0;
    double mean = 0.0;
    for (int i = 0; i < 3 && stress; ++i) mean -= stress[i] / 3.0;  // tension positive here
    const double p_min = std::isfinite(p.p_min) && p.p_min > 0.0 ? p.p_min : 1.0;
    const acst::ElasticModuli m = acst::isotropic_elastic_moduli(p, e, std::isfinite(mean) ? std::max(mean, p_min) : p_min);
    if (std::isfinite(m.G) && std::isfinite(m.K) && m.G > 0.0 && m.K > 0.0) mod = m;
  }
  double tangent[36];
  acst::abi::tangent_from_model(acst::elastic_stiffness(mod), tangent);
  for (int i = 0; i < nt; ++i)
    for (int j = 0; j < nt; ++j) ddsdde[i + j * nt] = tangent[6 * i + j];
}

// PNEWDT after a failure: a factor in (0, 1). A host that has not asked for anything yet passes
// PNEWDT <= 0 (CalculiX: -1) or >= 1 (Abaqus: a large value); a smaller request already made at
// another point of the same increment is kept.
void request_cut_back(double* pnewdt, double factor) {
  if (!pnewdt) return;
  *pnewdt = *pnewdt > 0.0 ? std::min(*pnewdt, factor) : factor;
}

acst_status checked_umat(double* stress, double* statev, double* ddsdde, const double* dstran, int nt, int nstatv,
                         const double* props, int nprops, const double* drot) {
  using acst::abi::make_status;
  if (nstatv < ACST_NSTATV || nprops < acst::parameter_count)
    return make_status(ACST_INVALID_INPUT,
                       "umat_: NSTATV must be at least " + std::to_string(ACST_NSTATV) + " and NPROPS at least " +
                           std::to_string(acst::parameter_count) + " (got " + std::to_string(nstatv) + " and " +
                           std::to_string(nprops) + ")",
                       1.0);
  // The update works on a copy of the state, so a failure leaves STATEV as it came.
  UmatPoint u = umat_point(stress, statev, dstran, nt, props, nprops, drot);
  double tangent[36];
  acst::integration::Report rep;
  const acst_status st = acst::abi::update_point(u.stress, u.state, tangent, u.material, u.dstrain, rep);
  if (st.code != ACST_OK) return st;
  std::copy(u.state, u.state + ACST_NSTATV, statev);
  std::copy(u.stress, u.stress + nt, stress);
  for (int i = 0; i < nt; ++i)
    for (int j = 0; j < nt; ++j) ddsdde[i + j * nt] = tangent[6 * i + j];
  return st;
}

}  // namespace

extern "C" acst_status acst_umat(double* stress, double* statev, double* ddsdde, const double* dstran, int ntens,
                                 int nstatv, const double* props, int nprops, const double* drot, double* pnewdt) {
  using acst::abi::make_status;
  // DDSDDE's size is unknown, or an array is missing: nothing but PNEWDT can be written.
  const char* unusable = ntens != 6 && ntens != 4                                  ? "NTENS must be 6 or 4"
                         : !stress || !statev || !ddsdde || !dstran || !props ? "a required array argument is NULL"
                                                                                 : nullptr;
  if (unusable) {
    request_cut_back(pnewdt, ACST_UMAT_UNRECOVERABLE_PNEWDT);
    return make_status(ACST_INVALID_INPUT, std::string("umat_: ") + unusable + " (NTENS " + std::to_string(ntens) + ")", 1.0);
  }
  if (!pnewdt) return make_status(ACST_INVALID_INPUT, "umat_: PNEWDT is NULL", 1.0);
  acst_status st;
  try {
    st = checked_umat(stress, statev, ddsdde, dstran, ntens, nstatv, props, nprops, drot);
  } catch (const std::exception& e) {
    st = make_status(ACST_INVALID_INPUT, std::string("umat_: ") + e.what(), 1.0);
  } catch (...) {
    st = make_status(ACST_INTERNAL_ERROR, "umat_: unknown exception", 1.0);
  }
  if (st.code == ACST_OK) return st;  // PNEWDT stays as it came
  write_fallback_tangent(ddsdde, ntens, stress, statev, nstatv, props, nprops);
  request_cut_back(pnewdt, st.code == ACST_STEP_REDUCTION ? std::clamp(st.suggested_step_factor, 0.01, 0.9)
                                                          : ACST_UMAT_UNRECOVERABLE_PNEWDT);
  return st;
}

extern "C" void umat_(double* stress, double* statev, double* ddsdde, double*, double*, double*, double*, double*,
                      double*, double*, const double*, const double* dstran, const double*, const double*,
                      const double*, const double*, const double*, const double*, const char*, const int*,
                      const int*, const int* ntens, const int* nstatv, const double* props, const int* nprops,
                      const double*, const double* drot, double* pnewdt, const double*, const double*, const double*,
                      const int*, const int*, const int*, const int*, const int*, const int*, size_t) {
  if (!ntens || !nstatv || !nprops) {
    request_cut_back(pnewdt, ACST_UMAT_UNRECOVERABLE_PNEWDT);
    return;
  }
  acst_umat(stress, statev, ddsdde, dstran, *ntens, *nstatv, props, *nprops, drot, pnewdt);
}

extern "C" acst_status acst_umat_reproducer(char* buffer, size_t* length, const double* stress, const double* statev,
                                            const double* dstran, int ntens, const double* props, int nprops,
                                            const double* drot) {
  using acst::abi::make_status;
  if (!length || !stress || !statev || !dstran || !props)
    return make_status(ACST_INVALID_INPUT, "acst_umat_reproducer: a required pointer argument is NULL", 1.0);
  if ((ntens != 6 && ntens != 4) || nprops < acst::parameter_count)
    return make_status(ACST_INVALID_INPUT,
                       "acst_umat_reproducer: NTENS must be 6 or 4 and NPROPS at least " +
                           std::to_string(acst::parameter_count),
                       1.0);
  try {
    const UmatPoint u = umat_point(stress, statev, dstran, ntens, props, nprops, drot);
    acst::State start;
    start.stress = acst::abi::stress_to_model(u.stress);
    acst::abi::fill_state(start, u.state);
    const std::string text =
        acst::update_reproducer(u.material, start, acst::abi::strain_to_model(u.dstrain),
                                "One-increment reproducer of a umat_ call (NTENS " + std::to_string(ntens) + ")")
            .dump(2) +
        "\n";
    return acst::abi::text_to_buffer(text, buffer, length, "acst_umat_reproducer");
  } catch (const std::exception& e) {
    return make_status(ACST_INVALID_INPUT, std::string("acst_umat_reproducer: ") + e.what(), 1.0);
  } catch (...) {
    return make_status(ACST_INTERNAL_ERROR, "acst_umat_reproducer: unknown exception", 1.0);
  }
}
