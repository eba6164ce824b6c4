#include "acst_driver/material_object.hpp"

#include "acst_common/files.hpp"
#include "acst_common/json_fields.hpp"
#include "acst_common/json_file.hpp"

namespace acst::driver {

namespace f = common::fields;
using nlohmann::json;

MaterialObject read_material_object(const json& j, const std::string& path, const std::string& base_dir) {
  f::object(j, path);
  MaterialObject m;
  m.path = path;
  if (!j.contains("file")) {
    f::allow_keys(j, {"model", "parameters", "integrator"}, path);
    m.object = j;
    m.source = "inline";
    return m;
  }
  f::allow_keys(j, {"file", "integrator"}, path);
  m.source = f::string(j["file"], path + "/file");
  const std::string file = common::resolve(base_dir, m.source);
  m.object = f::read_json_file(file, "the material file", path + "/file");
  m.path = path + "/file (" + file + ")";
  f::object(m.object, m.path);
  if (j.contains("integrator")) {
    f::object(j["integrator"], path + "/integrator");
    if (!m.object.contains("integrator")) m.object["integrator"] = json::object();
    f::object(m.object["integrator"], m.path + "/integrator");
    for (const auto& item : j["integrator"].items()) m.object["integrator"][item.key()] = item.value();
  }
  f::allow_keys(m.object, {"model", "parameters", "integrator"}, m.path);
  return m;
}

}  // namespace acst::driver
