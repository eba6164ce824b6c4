#pragma once
// ACST material constants and numerical guards (kPa, dimensionless otherwise).
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "acst/inline.hpp"
#include "acst/lode.hpp"
#include "acst_common/input_error.hpp"

namespace acst {

// Atmospheric pressure used to normalise p in the elastic and critical-state laws.
inline constexpr double atmospheric_pressure = 101.0;

// p/pa with p floored at p_floor: p_min for the moduli and the peak state, 0 for the critical
// state line.
ACST_INLINE double normalised_pressure(double p, double p_floor) { return max_of(p, p_floor) / atmospheric_pressure; }

// The void ratios a state may have: e > 0, and e below 2.97, where the shear modulus's
// (2.97 - e)^2 (elasticity.hpp) vanishes and would grow again. One check for every entry point
// (initial states, states handed to an update, states an update returns).
inline constexpr double void_ratio_limit = 2.97;
ACST_INLINE bool void_ratio_admissible(double e) { return e > 0.0 && e < void_ratio_limit; }

// The stresses a state may have: every component at most 1e100 kPa in size. The model cubes
// stress components (J3 of the Lode angle), which overflow from about 5.6e102, and beyond that
// an update failed at every increment size, even zero (an isotropic 1e308 kPa came back as a step
// reduction, which a host retries for ever); 1e100 kPa is beyond any pressure in sand by 90
// orders of magnitude. One check for every entry point, as for the void ratio; a NaN fails it.
inline constexpr double stress_limit = 1e100;
ACST_INLINE bool stress_within_limit(const double* stress) {
  bool within = true;
  for (int i = 0; i < 6; ++i) within = within & (stress[i] <= stress_limit) & (stress[i] >= -stress_limit);
  return within;
}

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
  // Lode interpolation (docs/model.md section 1): 0 Li (2002), 1 Willam & Warnke (1975).
  double lode_form = 0.0;
  // Fabric-dependent cross-anisotropic elasticity (docs/model.md section 2): 0 isotropic.
  double elastic_anisotropy = 0.0;
  // Pressure-dependent peak-state coefficient (docs/model.md section 6): 0 the published constant n.
  double peak_pressure_exponent = 0.0;

  Variant variant = Variant::anisotropic;
};

// Thrown for any invalid input; the message names the offending key and the allowed range.
using InputError = common::InputError;

// A value outside its range; `parameter` names it (for JSON paths).
struct ParameterRangeError : InputError {
  ParameterRangeError(const std::string& message, std::string name) : InputError(message), parameter(std::move(name)) {}
  std::string parameter;
};

// The one table of the material constants: every list of them (JSON keys, validation, the
// umat_ PROPS order, the documentation's table) derives from it. Entries with `props` come
// first, in PROPS order.
struct ParameterInfo {
  const char* name;
  double Parameters::*member;
  double lo, hi;
  bool lo_open, hi_open;
  const char* unit;
  bool fabric;    // zero (may be omitted) in the isotropic reduction
  bool optional;  // a guard with a default value
  bool props;     // an entry of umat_'s PROPS array
  const char* meaning;
};

inline constexpr double no_upper_bound = std::numeric_limits<double>::infinity();

inline constexpr ParameterInfo parameter_table[] = {
    {"G0", &Parameters::G0, 0, no_upper_bound, true, true, "-", false, false, true, "shear modulus constant"},
    {"nu", &Parameters::nu, 0, 0.5, false, true, "-", false, false, true, "Poisson's ratio"},
    {"Mc", &Parameters::Mc, 0, 3, true, false, "-", false, false, true, "critical stress ratio in compression"},
    {"c", &Parameters::c, 0.5, 1, true, false, "-", false, false, true,
     "extension/compression ratio of g (convex from 0.7 with lode_form 0)"},
    {"e_Gamma", &Parameters::e_Gamma, 0, 2.97, true, true, "-", false, false, true, "critical void ratio at p = 0"},
    {"lambda_c", &Parameters::lambda_c, 0, no_upper_bound, true, true, "-", false, false, true, "slope of the critical state line"},
    {"xi", &Parameters::xi, 0, 2, true, false, "-", false, false, true, "exponent of the critical state line"},
    {"d1", &Parameters::d1, 0, no_upper_bound, true, true, "-", false, false, true, "dilatancy constant"},
    {"m", &Parameters::m, 0, no_upper_bound, false, true, "-", false, false, true, "dilatancy exponent"},
    {"h1", &Parameters::h1, 0, no_upper_bound, true, true, "-", false, false, true, "plastic modulus constant"},
    {"h2", &Parameters::h2, 0, no_upper_bound, false, true, "-", false, false, true, "void-ratio dependence of h"},
    {"n", &Parameters::n, 0, no_upper_bound, false, true, "-", false, false, true, "plastic modulus exponent"},
    {"e_A", &Parameters::e_A, 0, no_upper_bound, false, true, "-", true, false, true, "fabric weight in the dilatancy state"},
    {"F0", &Parameters::F0, 0, no_upper_bound, false, true, "-", true, false, true, "initial fabric norm"},
    {"k_f", &Parameters::k_f, 0, no_upper_bound, false, true, "-", true, false, true, "rate of fabric evolution"},
    {"e_max", &Parameters::e_max, 0, 2.97, true, true, "-", false, false, true, "loosest void ratio (above e_min)"},
    {"e_min", &Parameters::e_min, 0, no_upper_bound, true, true, "-", false, false, true, "densest void ratio"},
    {"p_min", &Parameters::p_min, 0, no_upper_bound, true, true, "kPa", false, true, true, "pressure floor of a substep (0.5)"},
    {"h_min", &Parameters::h_min, 0, no_upper_bound, true, true, "-", false, true, false, "floor of h = h1 - h2 e (1e-3)"},
    {"R_tolerance", &Parameters::R_tolerance, 0, 1e-3, true, false, "-", false, true, false,
     "below it n follows the strain increment (1e-9)"},
    {"lode_form", &Parameters::lode_form, 0, 1, false, false, "-", false, true, false,
     "g(theta): 0 Li (2002), 1 Willam & Warnke (1975) (0)"},
    {"elastic_anisotropy", &Parameters::elastic_anisotropy, -5, 5, false, false, "-", true, true, false,
     "a: Young's modulus along F's major axis exp(a |F|) times across it (0)"},
    {"peak_pressure_exponent", &Parameters::peak_pressure_exponent, -1, 1, false, false, "-", false, true, false,
     "beta: the peak-state coefficient is n (p/pa)^beta (0)"},
};

inline constexpr int parameter_table_size = sizeof parameter_table / sizeof parameter_table[0];

// The table's row of a parameter name (any row, PROPS entry or not); nullptr when there is none.
inline const ParameterInfo* parameter_info(const std::string& name) {
  for (const ParameterInfo& info : parameter_table)
    if (name == info.name) return &info;
  return nullptr;
}

constexpr int count_props() {
  int k = 0;
  while (k < parameter_table_size && parameter_table[k].props) ++k;
  return k;
}

// The umat_ PROPS entries (the first parameter_count rows of the table).
inline constexpr int parameter_count = count_props();

struct ParameterNames {
  const char* names[parameter_count];
  constexpr const char* operator[](int i) const { return names[i]; }
  constexpr const char* const* begin() const { return names; }
  constexpr const char* const* end() const { return names + parameter_count; }
};

constexpr ParameterNames props_names() {
  ParameterNames n{};
  for (int i = 0; i < parameter_count; ++i) n.names[i] = parameter_table[i].name;
  return n;
}

// Names of the PROPS entries in their order (docs/c-abi.md).
inline constexpr ParameterNames parameter_names = props_names();

// Checks every value against its range in the table (and e_max > e_min); throws a
// ParameterRangeError naming the first bad one.
void validate(const Parameters& p);

double& parameter_by_index(Parameters& p, int i);
double parameter_by_index(const Parameters& p, int i);

// The table as Markdown, for docs/model.md section 9 (a test keeps the two equal).
std::string parameter_table_markdown();

// The Lode interpolation of a parameter set.
inline LodeShape lode_shape(const Parameters& p) {
  return {p.c, p.lode_form == 1.0 ? LodeForm::willam_warnke : LodeForm::li2002};
}

// Relative density Dr (0..1) from the void ratio and back.
inline double relative_density(const Parameters& p, double e) { return (p.e_max - e) / (p.e_max - p.e_min); }
inline double void_ratio_from_relative_density(const Parameters& p, double Dr) {
  return p.e_max - Dr * (p.e_max - p.e_min);
}

}  // namespace acst
