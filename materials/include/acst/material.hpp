#pragma once
// The ACST material: parameters + integrator options, and the stress update of one point.
// This C++ API uses the model's convention (compression positive, tensor shear strain, kPa);
// the C ABI (acst.h) converts to its own convention in exactly one place.
#include <Eigen/Core>
#include <string>

#include "acst/elasticity.hpp"
#include "acst/integration/options.hpp"
#include "acst/integration/report.hpp"
#include "acst/parameters.hpp"
#include "acst/state.hpp"
#include "acst/tensor.hpp"

namespace acst {

// Derived quantities of a state, for output and tests.
struct Diagnostics {
  double p, q, R;           // mean stress, sqrt(3/2)|s|, q/p in general form
  double sin3theta, g;      // Lode measure and interpolation
  double psi, zeta, A;      // state parameter, dilatancy state parameter, F:n
  double fabric_norm;       // |F|
  double critical_void_ratio;
  double D, Kp;             // dilatancy and plastic modulus at this state
  double G, K;              // elastic moduli
};

class Material {
 public:
  Material(const Parameters& parameters, const integration::Options& options);

  // Parses {"model": "ACST"|"isotropic", "parameters": {...}, "integrator": {...}}; throws
  // InputError naming the JSON path and the allowed range of any bad value.
  static Material from_json(const std::string& json_text);

  // Initial state: stress (compression positive), void ratio, deposition direction (normal to
  // the bedding planes, any length > 0). H starts on the yield surface through the stress.
  State initial_state(const Sym& stress, double void_ratio, const Eigen::Vector3d& deposition_direction) const;

  // Advances the state over a strain increment (compression positive, tensor shear).
  // On failure the state is left as it was and the report asks for a smaller increment.
  // If tangent is given it receives d(stress)/d(strain) (continuum tangent at the end state).
  // `void_ratio_offset`: a host's nonlocal void ratio minus the state's own at the start of the
  // increment (docs/model.md section 11; finite, below void_ratio_limit in size); 0: local.
  integration::Report update(State& state, const Sym& strain_increment, Mat6* tangent = nullptr,
                             double void_ratio_offset = 0.0) const;

  // Continuum tangent: elastoplastic if `plastic`, elastic otherwise; the strain direction picks
  // n where the stress ratio vanishes.
  Mat6 tangent(const State& state, bool plastic, const Sym& strain_direction, double void_ratio_offset = 0.0) const;

  Diagnostics diagnostics(const State& state, const Sym& strain_direction = Sym::Zero()) const;

  // The elastic stiffness of a state (p at least p_min), for wave speeds and tangents.
  ElasticModuli elastic_moduli(const State& state) const;

  const Parameters& parameters() const { return parameters_; }
  const integration::Options& options() const { return options_; }

 private:
  Parameters parameters_;
  integration::Options options_;
};

}  // namespace acst
