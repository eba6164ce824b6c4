// Scene JSON -> ElementScene: the top level (material, initial state, solver, lab data, output).
// Steps are read in step_reader.cpp. Every error names the JSON path.
#include <Eigen/SVD>
#include <filesystem>

#include "acst/fabric.hpp"
#include "acst/json_input.hpp"
#include "acst_common/files.hpp"
#include "acst_common/json_fields.hpp"
#include "acst_common/json_file.hpp"
#include "acst_common/plain_stem.hpp"
#include "acst_driver/lab_data.hpp"
#include "acst_driver/material_object.hpp"
#include "acst_driver/presets.hpp"
#include "acst_driver/scene.hpp"
#include "step_reader.hpp"

namespace acst::driver {

using nlohmann::json;
namespace f = common::fields;

namespace {

// Prefixes the material library's own messages (which start with their JSON path) with ours.
template <class Fn>
auto with_prefix(const std::string& prefix, Fn&& fn) -> decltype(fn()) {
  try {
    return fn();
  } catch (const InputError& e) {
    const std::string m = e.what();
    throw common::InputError(m.rfind('/', 0) == 0 ? prefix + m : prefix + ": " + m);
  }
}

// "material": {"file": "...", "integrator": {...}} or {"model", "parameters", "integrator"}.
void read_material(const json& j, const std::string& path, const std::string& base_dir, ElementScene& scene) {
  const MaterialObject m = read_material_object(j, path, base_dir);
  const json& effective = m.object;
  const std::string& prefix = m.path;
  scene.material_source = m.source;
  if (!effective.contains("parameters")) f::fail(prefix + "/parameters", "required object is missing");
  const Variant variant = effective.contains("model")
      ? with_prefix(prefix, [&] { return variant_from_json(effective["model"], "/model"); })
      : Variant::anisotropic;  // as acst::Material::from_json
  const Parameters p = with_prefix(prefix, [&] { return parameters_from_json(effective["parameters"], variant, "/parameters"); });
  // A file's integrator errors are the override's when it gave one; name that path.
  const std::string ipath = j.contains("file") && j.contains("integrator") ? path : prefix;
  const integration::Options o = effective.contains("integrator")
      ? with_prefix(ipath, [&] { return options_from_json(effective["integrator"], "/integrator"); })
      : integration::Options{};
  scene.material.emplace(with_prefix(ipath + "/integrator", [&] { return Material(p, o); }));
  scene.material_json = effective;
}

void read_initial_state(const json& j, const std::string& path, ElementScene& scene) {
  f::allow_keys(j, {"stress", "confining_pressure", "void_ratio", "relative_density_pct", "bedding_angle_deg",
                    "deposition_direction", "fabric", "H", "substep_hint", "void_ratio_offset"},
                path);
  const Material& m = *scene.material;
  InitialState& s = scene.initial;
  const std::string sk = f::one_of(j, {"stress", "confining_pressure"}, path);
  if (sk == "stress") {
    const auto v = f::numbers(j["stress"], path + "/stress", 6, "sigma_11, sigma_22, sigma_33, sigma_12, sigma_13, sigma_23 in kPa, compression positive");
    for (int i = 0; i < 6; ++i) s.stress[i] = v[i];
    if (!(trace(s.stress) / 3.0 >= m.parameters().p_min))
      f::fail(path + "/stress", "the mean stress " + f::shown(trace(s.stress) / 3.0) + " kPa is below p_min = " +
                                    f::shown(m.parameters().p_min) + " kPa (compression is positive)");
  } else {
    const double pc = f::number(j["confining_pressure"], path + "/confining_pressure",
                                {m.parameters().p_min, 1e6, false, false}, "kPa");
    s.stress = pc * identity_tensor();
  }
  const std::string ek = f::one_of(j, {"void_ratio", "relative_density_pct"}, path);
  if (ek == "void_ratio") {
    s.void_ratio = f::number(j["void_ratio"], path + "/void_ratio", {0.0, 2.97, true, true});
  } else {
    const double dr = f::number(j["relative_density_pct"], path + "/relative_density_pct", {0.0, 100.0}, "%");
    s.void_ratio = void_ratio_from_relative_density(m.parameters(), dr / 100.0);
  }
  const bool anisotropic = m.parameters().variant == Variant::anisotropic;
  const std::string bk = f::one_of(j, {"bedding_angle_deg", "deposition_direction"}, path, false);
  if (bk.empty() && anisotropic && !j.contains("fabric"))
    f::fail(path, "one of bedding_angle_deg, deposition_direction is required for the ACST model (it sets the initial fabric)");
  s.bedding_angle_deg = 0.0;
  if (bk == "bedding_angle_deg") {
    s.bedding_angle_deg = f::number(j[bk], path + "/" + bk, {0.0, 180.0}, "degrees between the deposition direction and the axial (1) axis");
    s.deposition_direction = bedding_direction(s.bedding_angle_deg, 0, 2);
  } else if (bk == "deposition_direction") {
    const auto d = f::numbers(j[bk], path + "/" + bk, 3, "a non-zero direction in the test frame");
    s.deposition_direction = Eigen::Vector3d(d[0], d[1], d[2]);
    // The model's own test (acst/fabric.hpp): (1e-320, 0, 0) is a direction, as the C ABI takes it.
    if (!usable_direction(s.deposition_direction)) f::fail(path + "/" + bk, "must not be the zero vector");
    s.bedding_angle_deg = std::acos(std::min(1.0, std::abs(unit_direction(s.deposition_direction)[0]))) * 180.0 / M_PI;
  }
  if (j.contains("fabric")) {
    const auto v = f::numbers(j["fabric"], path + "/fabric", 6, "fabric tensor F_11 ... F_23, tensor components");
    Sym F;
    for (int i = 0; i < 6; ++i) F[i] = v[i];
    if (std::abs(trace(F)) > 1e-9 * std::max(1.0, norm(F))) f::fail(path + "/fabric", "the fabric tensor must be deviatoric (trace 0)");
    s.fabric = F;
  }
  if (j.contains("H")) s.H = f::number(j["H"], path + "/H", {0.0, 1e3}, "(cone size R/g)");
  if (j.contains("substep_hint")) s.substep_hint = f::number(j["substep_hint"], path + "/substep_hint", {0.0, 1.0, true, false});
  if (j.contains("void_ratio_offset"))
    s.void_ratio_offset = f::number(j["void_ratio_offset"], path + "/void_ratio_offset", {-void_ratio_limit, void_ratio_limit, true, true},
                                    "(a nonlocal void ratio minus the point's own)");
  with_prefix(path, [&] { return m.initial_state(s.stress, s.void_ratio, s.deposition_direction); });
}

void read_solver(const json& j, const std::string& path, SolverSettings& s) {
  f::allow_keys(j, {"max_iterations", "stress_tolerance", "strain_tolerance", "max_halvings", "max_cutbacks"}, path);
  if (j.contains("max_iterations"))
    s.newton.max_iterations = static_cast<int>(f::integer(j["max_iterations"], path + "/max_iterations", 1, 200));
  if (j.contains("stress_tolerance"))
    s.newton.stress_tolerance = f::number(j["stress_tolerance"], path + "/stress_tolerance", {0.0, 1e-2, true, false}, "(relative to max(p, pa))");
  if (j.contains("strain_tolerance"))
    s.newton.strain_tolerance = f::number(j["strain_tolerance"], path + "/strain_tolerance", {0.0, 1e-6, true, false}, "(absolute strain)");
  if (j.contains("max_halvings")) s.max_halvings = static_cast<int>(f::integer(j["max_halvings"], path + "/max_halvings", 0, 40));
  if (j.contains("max_cutbacks")) s.max_cutbacks = f::integer(j["max_cutbacks"], path + "/max_cutbacks", 1, 1000000000);
}

void read_output(const json& j, const std::string& path, ElementOutputSpec& o) {
  f::allow_keys(j, {"directory", "name", "every", "plot"}, path);
  if (j.contains("directory")) {
    o.directory = f::string(j["directory"], path + "/directory");
    if (o.directory.empty()) f::fail(path + "/directory", "must not be empty");
  }
  if (j.contains("name")) {
    o.name = common::require_plain_stem(f::string(j["name"], path + "/name"), path + "/name");
  }
  if (j.contains("every")) o.every = static_cast<int>(f::integer(j["every"], path + "/every", 1, 1000000000));
  if (j.contains("plot")) o.plot = f::boolean(j["plot"], path + "/plot");
}

void read_lab_data(const json& j, const std::string& path, const std::string& base_dir, ElementScene& scene) {
  std::vector<std::pair<std::string, std::string>> names;  // (json path, file name)
  if (j.is_string()) {
    names.emplace_back(path, j.get<std::string>());
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i)
      names.emplace_back(path + "/" + std::to_string(i), f::string(j[i], path + "/" + std::to_string(i)));
  } else {
    f::fail(path, std::string("expected a file name or an array of file names, got ") + j.type_name());
  }
  for (const auto& [p, name] : names) {
    const std::string file = common::resolve(base_dir, name);
    try {
      read_lab_curve(file);
    } catch (const std::exception& e) {
      f::fail(p, e.what());
    }
    scene.lab_data.push_back(file);
  }
}

}  // namespace

void check_rows_complete(const ControlRows& rows, const Material& material, const std::string& path) {
  // Elastic stiffness with G = 1 and the material's Poisson ratio: the rank does not depend on
  // the modulus scale. Rows are normalised so that stress and strain rows weigh alike.
  const double nu = material.parameters().nu, G = 1.0, K = 2.0 * G * (1.0 + nu) / (3.0 * (1.0 - 2.0 * nu));
  Mat6 D = Mat6::Zero();
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) D(i, k) = K + (i == k ? 4.0 : -2.0) * G / 3.0;
  for (int i = 3; i < 6; ++i) D(i, i) = 2.0 * G;
  Mat6 J = rows.A * D + rows.B;
  for (int i = 0; i < 6; ++i) {
    const double s = J.row(i).cwiseAbs().maxCoeff();
    if (s > 0.0) J.row(i) /= s;
  }
  const Eigen::JacobiSVD<Mat6> svd(J, Eigen::ComputeFullV);
  const auto& sv = svd.singularValues();
  if (sv[5] > 1e-9 * sv[0]) return;
  int rank = 0;
  for (int i = 0; i < 6; ++i) rank += sv[i] > 1e-9 * sv[0];
  const Sym free = svd.matrixV().col(5);
  int worst = 0;
  for (int i = 1; i < 6; ++i)
    if (std::abs(free[i]) > std::abs(free[worst])) worst = i;
  f::fail(path, std::string("the control leaves the strain component eps_") + component_name(worst) +
                    " free (the six rows have rank " + std::to_string(rank) +
                    " of 6 with an elastic stiffness): every component must be controlled or constrained");
}

namespace {

ElementScene scene_from_document(const json& j, const std::string& base_dir, const std::string& default_name) {
  f::allow_keys(j, {"description", "material", "initial_state", "steps", "solver", "lab_data", "output"}, "");
  for (const char* key : {"material", "initial_state", "steps"})
    if (!j.contains(key)) f::fail(std::string("/") + key, "required key is missing");
  ElementScene scene;
  scene.base_dir = base_dir;
  if (j.contains("description")) f::string(j["description"], "/description");
  read_material(j["material"], "/material", base_dir, scene);
  read_initial_state(f::object(j["initial_state"], "/initial_state"), "/initial_state", scene);
  scene.blocks = read_steps(j["steps"], "/steps", base_dir);
  if (j.contains("solver")) read_solver(j["solver"], "/solver", scene.solver);
  if (j.contains("output")) read_output(j["output"], "/output", scene.output);
  check_scene_size(scene.blocks, scene.output.every);
  if (scene.output.name.empty())  // the scene file's stem names the outputs and reaches the figure's script
    scene.output.name = common::require_plain_stem(default_name.empty() ? "element_test" : default_name,
                                                   "/output/name (not given; the scene file's name would be used)");
  if (j.contains("lab_data")) read_lab_data(j["lab_data"], "/lab_data", base_dir, scene);
  for (const Block& b : scene.blocks)
    for (const Step& s : b.steps)
      for (std::size_t k = 0; k < s.segments.size(); ++k)
        check_rows_complete(s.segments[k].rows, *scene.material,
                            s.path + (s.segments.size() > 1 ? " (row " + std::to_string(k + 1) + " of the strain path)" : ""));
  return scene;
}

}  // namespace

ElementScene parse_scene(const std::string& text, const std::string& base_dir, const std::string& default_name) {
  return scene_from_document(f::parse(text, "", "the scene"), base_dir, default_name);
}

ElementScene read_scene(const std::string& path) {
  const std::filesystem::path p(path);
  ElementScene s = scene_from_document(f::read_json_file(path, "the scene file"), p.parent_path().string(), p.stem().string());
  s.source = path;
  return s;
}

}  // namespace acst::driver
