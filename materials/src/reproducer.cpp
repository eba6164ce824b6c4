#include "acst/reproducer.hpp"

#include "acst/scene_units.hpp"

namespace acst {

using nlohmann::json;

namespace {

json six(const Sym& v) {
  json a = json::array();
  for (int i = 0; i < 6; ++i) a.push_back(v[i]);
  return a;
}

}  // namespace

json material_document(const Material& material) {
  const Parameters& p = material.parameters();
  json parameters = json::object();
  for (const ParameterInfo& info : parameter_table) parameters[info.name] = p.*info.member;
  const integration::Options& o = material.options();
  const json integrator = {{"scheme", integration::scheme_name(o.scheme)},
                           {"stol", o.stol},
                           {"ftol", o.ftol},
                           {"ltol", o.ltol},
                           {"min_substep", o.min_substep},
                           {"max_substeps", o.max_substeps},
                           {"fe_substeps", o.fe_substeps},
                           {"unload_scan_intervals", o.unload_scan_intervals},
                           {"reuse_last_substep", o.reuse_last_substep},
                           {"pressure_floor", o.pressure_floor == integration::PressureFloorPolicy::reset ? "reset" : "fail"}};
  return {{"model", p.variant == Variant::isotropic ? "isotropic" : "ACST"},
          {"parameters", parameters},
          {"integrator", integrator}};
}

json update_reproducer(const Material& material, const State& start, const Sym& strain_increment,
                       const std::string& description, double void_ratio_offset) {
  json rows = json::array();
  for (int i = 0; i < 6; ++i) {
    json strain = json::array();
    for (int k = 0; k < 6; ++k) strain.push_back(k == i ? 1.0 : 0.0);
    rows.push_back({{"stress", {0, 0, 0, 0, 0, 0}},
                    {"strain_pct", strain},
                    {"change", units::strain_to_scene(strain_increment[i], i)}});
  }
  json initial = {{"stress", six(start.stress)},
                  {"void_ratio", start.void_ratio},
                  {"fabric", six(start.fabric)},
                  {"H", start.H},
                  {"substep_hint", start.substep_hint}};
  if (void_ratio_offset != 0.0) initial["void_ratio_offset"] = void_ratio_offset;
  return {{"description", description},
          {"material", material_document(material)},
          {"initial_state", initial},
          {"steps", json::array({{{"constraints", rows}, {"increments", 1}}})},
          {"solver", {{"max_halvings", 0}}},
          {"output", {{"name", "reproducer"}, {"plot", false}}}};
}

}  // namespace acst
