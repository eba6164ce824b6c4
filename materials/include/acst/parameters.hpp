#pragma once
// ACST material constants and numerical guards (kPa, dimensionless otherwise).
#include <stdexcept>
#include <string>
#include <utility>

#include "acst_common/input_error.hpp"

namespace acst {

// Atmospheric pressure used to normalise p in the elastic and critical-state laws.
inline constexpr double atmospheric_pressure = 101.0;

enum class Variant { anisotropic, isotropic };

struct Parameters {
  // Elasticity (docs/model.md section 2).
  double G0 = 125.0;
  double nu = 0.1;
  // Critical state (docs/model.md section 3).
  double Mc = 1.25;
  double c = 0.75;
  double e_Gamma = 0.934;
  double lambda_c = 0.019;
  double xi = 0.7;
  // Dilatancy and plastic modulus (docs/model.md section 6).
  double d1 = 0.88;
  double m = 3.5;
  double h1 = 3.15;
  double h2 = 3.05;
  double n = 1.1;
  // Fabric (docs/model.md section 4); all zero in the isotropic reduction.
  double e_A = 0.1;
  double F0 = 0.5;
  double k_f = 5.0;
  // Density bounds, for Dr <-> e conversions.
  double e_max = 0.977;
  double e_min = 0.597;
  // Guards (docs/model.md section 10).
  double p_min = 0.5;       // kPa: lowest mean stress a substep may reach
  double h_min = 1e-3;      // floor of h = h1 - h2 e
  double R_tolerance = 1e-9;  // below this R the loading direction is taken from the strain increment

  Variant variant = Variant::anisotropic;
};

// Thrown for any invalid input; the message names the offending key and the allowed range.
using InputError = common::InputError;

// A value outside its range; `parameter` names it (for JSON paths).
struct ParameterRangeError : InputError {
  ParameterRangeError(const std::string& message, std::string name) : InputError(message), parameter(std::move(name)) {}
  std::string parameter;
};

// Checks every value against its physical range; throws InputError naming the first bad one.
void validate(const Parameters& p);

// Names of the material constants in the order of the Abaqus PROPS array (see docs/c-abi.md).
inline constexpr const char* parameter_names[] = {"G0", "nu",  "Mc", "c",   "e_Gamma", "lambda_c",
                                                  "xi", "d1",  "m",  "h1",  "h2",      "n",
                                                  "e_A", "F0", "k_f", "e_max", "e_min", "p_min"};
inline constexpr int parameter_count = 18;

double& parameter_by_index(Parameters& p, int i);
double parameter_by_index(const Parameters& p, int i);

// Relative density Dr (0..1) from the void ratio and back.
inline double relative_density(const Parameters& p, double e) { return (p.e_max - e) / (p.e_max - p.e_min); }
inline double void_ratio_from_relative_density(const Parameters& p, double Dr) {
  return p.e_max - Dr * (p.e_max - p.e_min);
}

}  // namespace acst
