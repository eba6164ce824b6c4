#include "acst/json_input.hpp"

#include <cmath>
#include <limits>
#include <vector>
#include <sstream>

#include "acst/material.hpp"
#include "acst_common/json_fields.hpp"

namespace acst {

using nlohmann::json;

namespace {

namespace f = common::fields;

double number_at(const json& j, const std::string& key, const std::string& path) {
  return f::number(j.at(key), path + "/" + key);
}

// A required number in the open interval (lo, hi).
double number_in_open_range(const json& j, const std::string& key, const std::string& path, double lo, double hi) {
  if (!j.contains(key)) throw InputError(path + "/" + key + ": required parameter is missing");
  const double v = number_at(j, key, path);
  if (!(v > lo && v < hi)) {
    std::ostringstream os;
    os << path << "/" << key << " = " << v << ": parameter '" << key << "' is outside its allowed range (" << lo
       << ", ";
    if (std::isinf(hi))
      os << "inf)";
    else
      os << hi << ")";
    throw InputError(os.str());
  }
  return v;
}

constexpr double unbounded = std::numeric_limits<double>::infinity();

reference::LinearElastic elastic_constants(const json& j, const std::string& path) {
  return {number_in_open_range(j, "E", path, 0.0, unbounded), number_in_open_range(j, "nu", path, -1.0, 0.5)};
}

}  // namespace

Variant variant_from_json(const json& j, const std::string& path) {
  if (!j.is_string()) throw InputError(path + ": expected \"ACST\" or \"isotropic\", got " + j.type_name());
  const std::string s = j.get<std::string>();
  if (s == "ACST") return Variant::anisotropic;
  if (s == "isotropic") return Variant::isotropic;
  throw InputError(path + ": unknown model '" + s + "' (allowed: ACST, isotropic)");
}

Parameters parameters_from_json(const json& j, Variant variant, const std::string& path) {
  f::object(j, path);
  std::vector<std::string> allowed;
  for (const ParameterInfo& info : parameter_table) allowed.push_back(info.name);
  f::allow_keys(j, allowed, path);
  Parameters p;
  p.variant = variant;
  for (const ParameterInfo& info : parameter_table) {
    const bool isotropic_zero = variant == Variant::isotropic && info.fabric;
    if (j.contains(info.name))
      p.*info.member = number_at(j, info.name, path);
    else if (isotropic_zero)
      p.*info.member = 0.0;
    else if (!info.optional)
      throw InputError(path + "/" + info.name + ": required parameter is missing");
  }
  try {
    validate(p);
  } catch (const ParameterRangeError& e) {
    throw InputError(path + "/" + e.parameter + ": " + e.what());
  } catch (const InputError& e) {
    throw InputError(path + ": " + e.what());
  }
  return p;
}

integration::Options options_from_json(const json& j, const std::string& path) {
  f::object(j, path);
  f::allow_keys(j, {"scheme", "stol", "ftol", "ltol", "min_substep", "max_substeps", "fe_substeps",
                       "unload_scan_intervals", "reuse_last_substep", "pressure_floor"},
                      path);
  integration::Options o;
  if (j.contains("scheme")) {
    if (!j["scheme"].is_string()) throw InputError(path + "/scheme: expected a string (FE, ME, RK23, RK45)");
    try {
      o.scheme = integration::scheme_from_name(j["scheme"].get<std::string>());
    } catch (const InputError& e) {
      throw InputError(path + "/scheme: " + e.what());
    }
  }
  auto number = [&](const char* key, double& slot) {
    if (j.contains(key)) slot = number_at(j, key, path);
  };
  // Integers beyond int's range are refused here; options_problem below checks every range.
  auto count = [&](const char* key, int& slot) {
    if (!j.contains(key)) return;
    if (!j[key].is_number_integer() || j[key].get<long long>() < 1 || j[key].get<long long>() > 100000000)
      throw InputError(path + "/" + key + ": expected an integer in [1, 100000000]");
    slot = j[key].get<int>();
  };
  number("stol", o.stol);
  number("ftol", o.ftol);
  number("ltol", o.ltol);
  number("min_substep", o.min_substep);
  count("max_substeps", o.max_substeps);
  count("fe_substeps", o.fe_substeps);
  count("unload_scan_intervals", o.unload_scan_intervals);
  if (j.contains("reuse_last_substep")) {
    if (!j["reuse_last_substep"].is_boolean()) throw InputError(path + "/reuse_last_substep: expected true or false");
    o.reuse_last_substep = j["reuse_last_substep"].get<bool>();
  }
  if (j.contains("pressure_floor")) {
    const json& v = j["pressure_floor"];
    if (v == "reset")
      o.pressure_floor = integration::PressureFloorPolicy::reset;
    else if (v == "fail")
      o.pressure_floor = integration::PressureFloorPolicy::fail;
    else
      throw InputError(path + "/pressure_floor: expected \"reset\" or \"fail\"");
  }
  if (const std::string problem = integration::options_problem(o); !problem.empty())
    throw InputError(path + "/" + problem);
  return o;
}

json model_document(const std::string& text) {
  json j;
  try {
    j = f::parse_document(text);  // syntax errors, numbers beyond double range, too deep a nesting
  } catch (const InputError& e) {
    throw InputError(std::string("material JSON does not parse: ") + e.what());
  }
  f::object(j, "");
  f::allow_keys(j, {"model", "parameters", "integrator"}, "");
  if (!j.contains("parameters")) throw InputError("/parameters: required object is missing");
  return j;
}

Material material_from_document(const json& j) {
  const Variant v = j.contains("model") ? variant_from_json(j["model"], "/model") : Variant::anisotropic;
  const Parameters p = parameters_from_json(j["parameters"], v, "/parameters");
  const integration::Options o =
      j.contains("integrator") ? options_from_json(j["integrator"], "/integrator") : integration::Options{};
  return Material(p, o);
}

Material Material::from_json(const std::string& text) { return material_from_document(model_document(text)); }

reference::LinearElastic linear_elastic_from_json(const json& j, const std::string& path) {
  f::object(j, path);
  f::allow_keys(j, {"E", "nu"}, path);
  return elastic_constants(j, path);
}

reference::VonMises von_mises_from_json(const json& j, const std::string& path) {
  f::object(j, path);
  f::allow_keys(j, {"E", "nu", "yield_stress", "undrained_shear_strength"}, path);
  const bool by_yield_stress = j.contains("yield_stress");
  if (by_yield_stress == j.contains("undrained_shear_strength"))
    throw InputError(path + ": give exactly one of yield_stress or undrained_shear_strength (kPa, > 0)");
  const reference::LinearElastic elastic = elastic_constants(j, path);
  const double yield_stress =
      by_yield_stress ? number_in_open_range(j, "yield_stress", path, 0.0, unbounded)
                      : std::sqrt(3.0) * number_in_open_range(j, "undrained_shear_strength", path, 0.0, unbounded);
  return {elastic, yield_stress};
}

reference::DruckerPrager drucker_prager_from_json(const json& j, const std::string& path) {
  f::object(j, path);
  f::allow_keys(j, {"E", "nu", "friction_angle_deg", "cohesion", "dilation_angle_deg"}, path);
  const reference::LinearElastic elastic = elastic_constants(j, path);
  // Closed below: phi = 0 is the Tresca-like cylinder, c = 0 a cohesionless cone.
  auto at_least = [&](const char* key, double lo, double hi, const char* range) {
    if (!j.contains(key)) throw InputError(path + "/" + key + ": required parameter is missing");
    const double v = number_at(j, key, path);
    if (!(v >= lo && v < hi))
      throw InputError(path + "/" + key + " = " + std::to_string(v) + ": parameter '" + key +
                       "' is outside its allowed range " + range);
    return v;
  };
  const double phi = at_least("friction_angle_deg", 0.0, 60.0, "[0, 60)");
  const double c = at_least("cohesion", 0.0, unbounded, "[0, inf)");
  if (phi == 0.0 && c == 0.0)
    throw InputError(path + ": friction_angle_deg and cohesion are both zero, a material without strength");
  const double psi = j.contains("dilation_angle_deg") ? at_least("dilation_angle_deg", 0.0, phi + 1e-12, "[0, friction_angle_deg]") : phi;
  return reference::drucker_prager_plane_strain(elastic, phi, c, psi);
}


}  // namespace acst
