#pragma once
// One model kind behind the C ABI. The acst_* functions know nothing of the kinds: each kind
// implements this interface in its own file and is registered once in model_kinds.cpp. All
// arrays are in the ABI's convention (tension positive, engineering shear; docs/conventions.md).
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "acst.h"
#include "acst/elasticity.hpp"
#include "acst/integration/report.hpp"

namespace acst::abi {

// The state variables of a kind: names (their count is the state size) and where symmetric
// tensors sit (6 slots each, tensor components 11 22 33 12 13 23), which turn with the material.
struct StateLayout {
  const char* const* names = nullptr;
  int size = 0;
  const int* tensor_offsets = nullptr;
  int tensors = 0;
};

class ModelKind {
 public:
  virtual ~ModelKind() = default;
  virtual const char* name() const = 0;  // as acst_model_kind returns it
  virtual const StateLayout& state() const = 0;
  virtual acst_status initial_state(double* statev, double* stress_out, const double* stress0, double void_ratio,
                                    const double* deposition_direction) const = 0;
  // The quantities the kind takes nonlocally (acst_nonlocal_size: none by default), their names
  // and a point's local values.
  virtual int nonlocal_size() const { return 0; }
  virtual const char* nonlocal_name(int) const { return nullptr; }
  virtual void nonlocal_local(double*, const double*, const double*) const {}
  // Stress and state unchanged unless the status is OK; `rep` gets the counters. `nonlocal`: the
  // point's nonlocal offsets (nonlocal_size() doubles), or null for the local model.
  virtual acst_status update(double* stress, double* statev, double* tangent, const double* dstrain,
                             const double* nonlocal, integration::Report& rep) const = 0;
  // The stress and the tensorial state variables turned by the row-major rotation r (T -> Q T
  // Q^T, acst_rotate_state) into copies s (6) and q (the state size), the others copied.
  void rotated_copy(const double* stress, const double* statev, const double* r, double* s, double* q) const;
  // update() of the state turned by r (rotated_copy): acst_update_rotated's numbers, in place,
  // and stress and state unchanged unless the status is OK.
  acst_status update_rotated(double* stress, double* statev, double* tangent, const double* r,
                             const double* dstrain, const double* nonlocal, integration::Report& rep) const;
  // update_rotated() (no tangent) of m points at once, each's code in codes and counters in
  // reports; a failed point's status also in `failure` (the first one's only). By default one
  // after the other; a kind may update several points together where each point's numbers stay
  // update_rotated()'s.
  // `nonlocal`: each point's offsets (null pointers where local), or null for all local.
  virtual void update_rotated_points(int m, double* const* stress, double* const* statev, const double* const* r,
                                     const double* const* dstrain, const double* const* nonlocal, int* codes,
                                     integration::Report* reports, acst_status& failure) const;
  // "" for a stress and state an update may start from, else what is wrong with which value
  // (the entry check of acst_diagnostics, acst_wave_speed, acst_rotate_state). By default:
  // a finite stress and finite state variables.
  virtual std::string state_problem(const double* stress, const double* statev) const;
  // Of what state_problem refuses, what an update takes: a state variable that is not a number
  // (the sand's substep hint, which an update reads as no hint) and, for sand, a tensile mean
  // stress (the integrator's pressure floor deals with it). update_rotated refuses it in the
  // turned state, so that it answers as its documented equivalent, acst_rotate_state and then
  // acst_update, does. Cheap: it runs on every point of an MPM step.
  virtual std::string turned_state_problem(const double* stress, const double* statev) const;
  virtual ElasticModuli moduli(const double* stress, const double* statev) const = 0;
  virtual void diagnostics(double* out, const double* stress, const double* statev) const = 0;
  // Whether diagnostic i means something for this kind (the others are NaN by contract).
  virtual bool diagnostic_applies(int i) const;
  // Relative density -> void ratio; kinds without a void ratio refuse.
  virtual acst_status void_ratio_from_relative_density(double* void_ratio, double relative_density) const;
  // The element-test scene replaying one update (acst/reproducer.hpp); kinds the element driver
  // cannot run throw InputError.
  virtual nlohmann::json reproducer(const double* stress, const double* statev, const double* dstrain,
                                    const double* nonlocal) const;
};

// Reads a material document and builds its kind; throws InputError naming the JSON path.
std::unique_ptr<const ModelKind> make_model_kind(const std::string& json_text);

// The kinds, one file each (kind_*.cpp); `document` is the checked {"model", "parameters", ...}.
std::unique_ptr<const ModelKind> make_sand_kind(const nlohmann::json& document);
std::unique_ptr<const ModelKind> make_linear_elastic_kind(const nlohmann::json& document);
std::unique_ptr<const ModelKind> make_von_mises_kind(const nlohmann::json& document);
std::unique_ptr<const ModelKind> make_drucker_prager_kind(const nlohmann::json& document);

}  // namespace acst::abi
