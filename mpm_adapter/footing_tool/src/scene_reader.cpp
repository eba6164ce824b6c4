// Reads and validates an MPM scene; every error names the JSON path and the allowed values.
#include <cmath>
#include <filesystem>

#include "acst_common/files.hpp"
#include "acst_common/json_fields.hpp"
#include "acst_common/json_file.hpp"
#include "acst_common/plain_stem.hpp"
#include "acst_footing_tool/internal_length.hpp"
#include "acst_footing_tool/scene.hpp"
#include "acst_footing_tool/scene_size.hpp"
#include "acst_mpm/material_adapter.hpp"

namespace acst::mpm {
namespace f = acst::common::fields;
using nlohmann::json;

namespace {

std::string read_text(const std::string& file, const std::string& path) {
  try {
    return common::read_input_file(file);
  } catch (const common::InputError& e) {
    f::fail(path, e.what());
  }
}

void read_materials(const json& j, const std::string& path, const std::string& dir, Scene& s) {
  f::object(j, path);
  if (j.empty()) f::fail(path, "at least one material is required");
  for (const auto& item : j.items()) {
    const std::string p = path + "/" + item.key();
    MaterialSpec m;
    m.name = item.key();
    if (item.value().is_string()) {
      const std::string file = common::resolve(dir, item.value().get<std::string>());
      m.json_text = read_text(file, p);
      m.source = file;
    } else {
      f::allow_keys(item.value(), {"model", "parameters", "integrator"}, p);
      m.json_text = item.value().dump();
      m.source = "inline";
    }
    try {
      m.state_size = AbiMaterial(m.name, m.json_text).state_size();
    } catch (const MaterialError& e) {
      f::fail(p, e.what());
    }
    s.materials.push_back(m);
  }
}

BodySpec read_body(const json& j, const std::string& p, const Scene& s) {
  f::allow_keys(j, {"name", "material", "x_range", "y_range", "density", "particles_per_cell", "void_ratio",
                    "relative_density_pct", "bedding_angle_deg"},
                p);
  BodySpec b;
  b.name = j.contains("name") ? f::string(j["name"], p + "/name") : "body";
  if (!j.contains("material")) f::fail(p, "'material' (a name from /materials) is required");
  b.material = f::string(j["material"], p + "/material");
  bool known = false;
  for (const auto& m : s.materials) known = known || m.name == b.material;
  if (!known) f::fail(p + "/material", "'" + b.material + "' is not defined in /materials");
  for (const char* k : {"x_range", "y_range", "density"})
    if (!j.contains(k)) f::fail(p, std::string("'") + k + "' is required");
  const auto xr = f::numbers(j["x_range"], p + "/x_range", 2, "x_min, x_max in m");
  const auto yr = f::numbers(j["y_range"], p + "/y_range", 2, "y_min, y_max in m");
  if (!(xr[1] > xr[0])) f::fail(p + "/x_range", "x_max must exceed x_min");
  if (!(yr[1] > yr[0])) f::fail(p + "/y_range", "y_max must exceed y_min");
  b.x_min = xr[0], b.x_max = xr[1], b.y_min = yr[0], b.y_max = yr[1];
  b.density = f::number(j["density"], p + "/density", {1.0, 1e5}, "kg/m^3");
  if (j.contains("particles_per_cell"))
    b.particles_per_cell = static_cast<int>(f::integer(j["particles_per_cell"], p + "/particles_per_cell", 1, 4));
  const std::string e = f::one_of(j, {"void_ratio", "relative_density_pct"}, p, false);
  if (e == "void_ratio") b.void_ratio = f::number(j["void_ratio"], p + "/void_ratio", f::positive());
  if (e == "relative_density_pct")
    b.relative_density = f::number(j["relative_density_pct"], p + "/relative_density_pct", {0.0, 100.0}, "%") / 100.0;
  if (j.contains("bedding_angle_deg"))
    b.bedding_angle_deg = f::number(j["bedding_angle_deg"], p + "/bedding_angle_deg", {-180.0, 180.0}, "deg");
  return b;
}

Settings read_solver(const json& j, const std::string& p) {
  f::allow_keys(j, {"cfl", "particle_update", "stress_update", "volumetric_averaging", "xpic_order", "xpic_every",
                    "grid_damping", "particle_damping", "wave_speed_every", "mass_scaling", "threads"},
                p);
  Settings s;
  if (j.contains("cfl")) s.cfl = f::number(j["cfl"], p + "/cfl", {0.0, 1.0, true, false});
  if (j.contains("particle_update"))
    s.update = f::choice<ParticleUpdate>(j["particle_update"], p + "/particle_update",
                                         {{"FLIP", ParticleUpdate::FLIP}, {"PIC", ParticleUpdate::PIC}, {"XPIC", ParticleUpdate::XPIC}});
  if (j.contains("stress_update"))
    s.stress_update = f::choice<StressUpdate>(
        j["stress_update"], p + "/stress_update",
        {{"average", StressUpdate::average}, {"first", StressUpdate::first}, {"last", StressUpdate::last}});
  if (j.contains("volumetric_averaging"))
    s.volumetric_averaging =
        f::choice<VolumetricAveraging>(j["volumetric_averaging"], p + "/volumetric_averaging",
                                       {{"none", VolumetricAveraging::none}, {"cell", VolumetricAveraging::cell}});
  if (j.contains("xpic_order")) s.xpic_order = static_cast<int>(f::integer(j["xpic_order"], p + "/xpic_order", 1, 16));
  if (j.contains("xpic_every")) s.xpic_every = static_cast<int>(f::integer(j["xpic_every"], p + "/xpic_every", 1, 100000));
  if (j.contains("grid_damping")) s.grid_damping = f::number(j["grid_damping"], p + "/grid_damping", {0.0, 1e4}, "1/s");
  if (j.contains("particle_damping"))
    s.particle_damping = f::number(j["particle_damping"], p + "/particle_damping", {0.0, 1e4}, "1/s");
  if (j.contains("wave_speed_every"))
    s.wave_speed_every = static_cast<int>(f::integer(j["wave_speed_every"], p + "/wave_speed_every", 1, 100000));
  if (j.contains("mass_scaling")) s.mass_scaling = f::number(j["mass_scaling"], p + "/mass_scaling", {1.0, 1e6});
  if (j.contains("threads")) s.threads = static_cast<int>(f::integer(j["threads"], p + "/threads", 0, 1024));
  return s;
}

// The sand's nonlocal regularisation (docs/mpm.md, "Nonlocal regularisation"): its internal
// length given, or derived from the grain size and the acceleration level (internal_length.hpp).
// Defaults (docs/mpm.md, "The graded grid"): the window reaches 3 B from the footing's centre and
// 3 B below its base. With 2 B (the failure zone's 1.5 B and a margin) V85.6 carried 2.9 % more
// before its peak than on the uniform grid; with 3 B the same to 0.01 %. The largest cells are 4
// fine ones.
GradedGridSpec read_graded(const json& j, const std::string& p, double cell_size) {
  f::allow_keys(j, {"window_half_width_B", "window_depth_B", "growth_ratio", "largest_cell"}, p);
  GradedGridSpec g;
  g.largest_cell = 4.0 * cell_size;
  if (j.contains("window_half_width_B"))
    g.half_width_B = f::number(j["window_half_width_B"], p + "/window_half_width_B", {0.5, 100.0});
  if (j.contains("window_depth_B")) g.depth_B = f::number(j["window_depth_B"], p + "/window_depth_B", {0.5, 100.0});
  if (j.contains("growth_ratio")) g.growth = f::number(j["growth_ratio"], p + "/growth_ratio", {1.0, 1.5, true, false});
  if (j.contains("largest_cell"))
    g.largest_cell = f::number(j["largest_cell"], p + "/largest_cell", {cell_size, 1000.0 * cell_size}, "m");
  return g;
}

// A length given as `key` (m), or derived from the grains by `from_grains(d50_mm, level)` with
// `d50_mm` (Toyoura's by default) and `acceleration_level` (1 by default).
double length_given_or_from_grains(const json& j, const std::string& p, const char* key,
                                   double (*from_grains)(double, double)) {
  if (j.contains(key)) {
    for (const char* k : {"d50_mm", "acceleration_level"})
      if (j.contains(k)) f::fail(p + "/" + k, std::string("not with ") + key + " (which it would derive)");
    return f::number(j[key], p + "/" + key, {0.0, 100.0}, "m");
  }
  const double d50 =
      j.contains("d50_mm") ? f::number(j["d50_mm"], p + "/d50_mm", {0.0, 100.0, true, false}, "mm") : toyoura_d50_mm;
  const double level =
      j.contains("acceleration_level") ? f::number(j["acceleration_level"], p + "/acceleration_level", {1.0, 1000.0}) : 1.0;
  const double length = from_grains(d50, level);
  if (!(length <= 100.0))  // the same cap as a given length's
    f::fail(p, "the length derived from d50_mm " + f::shown(d50) + " and acceleration_level " + f::shown(level) + " is " +
                   f::shown(length) + " m; allowed: at most 100 m (give " + key + " instead)");
  return length;
}

Regularisation read_regularisation(const json& j, const std::string& p) {
  f::allow_keys(j, {"internal_length_m", "d50_mm", "acceleration_level", "kernel", "averaged", "over_nonlocal",
                    "every_steps"},
                p);
  Regularisation r;
  r.internal_length = length_given_or_from_grains(j, p, "internal_length_m", internal_length_from_grains);
  if (j.contains("kernel"))
    r.kernel = f::choice<NonlocalKernel>(j["kernel"], p + "/kernel",
                                         {{"gauss", NonlocalKernel::gauss}, {"galavi_schweiger", NonlocalKernel::galavi_schweiger}});
  if (j.contains("averaged"))
    r.quantity = f::choice<NonlocalQuantity>(j["averaged"], p + "/averaged",
                                             {{"void_ratio_increments", NonlocalQuantity::void_ratio_increments},
                                              {"void_ratio", NonlocalQuantity::void_ratio}});
  if (j.contains("over_nonlocal")) r.over_nonlocal = f::number(j["over_nonlocal"], p + "/over_nonlocal", {1.0, 4.0});
  if (j.contains("every_steps")) r.every = static_cast<int>(f::integer(j["every_steps"], p + "/every_steps", 1, 100000));
  return r;
}

// The soil's micropolar rotations (docs/mpm.md, "Micropolar rotations"): their length, given or
// the grains' (internal_length.hpp), and the modulus's share of the constrained modulus.
Micropolar read_micropolar(const json& j, const std::string& p) {
  f::allow_keys(j, {"length_m", "d50_mm", "acceleration_level", "modulus_ratio"}, p);
  Micropolar m;
  m.length = length_given_or_from_grains(j, p, "length_m", micropolar_length_from_grains);
  if (j.contains("modulus_ratio"))
    m.modulus_ratio = f::number(j["modulus_ratio"], p + "/modulus_ratio", {0.0, 1.0, true, false});
  return m;
}

// The averaging reaches 2.5 l: a length above 0 and under the particles' spacing (the cell over the particles
// per cell) reaches no other particle, so the sand stays local, and far under it the averaging's
// bins outnumber the particles (1e-300 m overflowed their count). Refused here, naming the key that
// set the length, before anything is written; docs/mpm.md asks two cells per l.
void require_length_reaches_neighbours(const Scene& s, const json& j) {
  double spacing = 0.0;
  for (const BodySpec& b : s.bodies) spacing = std::max(spacing, s.cell_size / b.particles_per_cell);
  const double l = s.solver.regularisation.internal_length;
  if (l == 0.0 || l >= spacing) return;  // 0: the local model
  const bool given = j.contains("internal_length_m");
  f::fail(given ? "/regularisation/internal_length_m" : "/regularisation",
          (given ? f::shown(l) + " m" : "the length derived from the grains, " + f::shown(l) + " m,") +
              " is shorter than the particles' spacing (" + f::shown(spacing) +
              " m: /grid/cell_size over particles_per_cell): the average would reach no other particle; allowed: at least " +
              f::shown(spacing) + " m (docs/mpm.md, \"Nonlocal regularisation\": two cells per length)" +
              (given ? "" : "; set acceleration_level or internal_length_m"));
}

FootingSpec read_footing(const json& j, const std::string& p) {
  f::allow_keys(j, {"width", "centre_x", "speed", "inclination_deg", "interface", "friction_coefficient", "contact",
                    "penalty_factor", "unload_at_S_over_B", "symmetric_half", "ramp_S_over_B"},
                p);
  FootingSpec fs;
  for (const char* k : {"width", "centre_x", "speed"})
    if (!j.contains(k)) f::fail(p, std::string("'") + k + "' is required");
  fs.width = f::number(j["width"], p + "/width", f::positive(), "m");
  fs.centre_x = f::number(j["centre_x"], p + "/centre_x", f::any(), "m");
  fs.speed = f::number(j["speed"], p + "/speed", f::positive(), "m/s");
  if (j.contains("inclination_deg"))
    fs.inclination_deg = f::number(j["inclination_deg"], p + "/inclination_deg", {-80.0, 80.0}, "deg");
  if (j.contains("contact"))
    fs.contact = f::choice<FootingContact>(j["contact"], p + "/contact",
                                           {{"penalty", FootingContact::penalty}, {"node_rows", FootingContact::node_rows}});
  if (j.contains("interface"))
    fs.interface = f::choice<FootingInterface>(
        j["interface"], p + "/interface",
        {{"rough", FootingInterface::rough}, {"smooth", FootingInterface::smooth}, {"coulomb", FootingInterface::coulomb}});
  if (fs.interface == FootingInterface::coulomb) {
    if (!j.contains("friction_coefficient")) f::fail(p, "interface 'coulomb' needs 'friction_coefficient'");
    fs.friction_coefficient = f::number(j["friction_coefficient"], p + "/friction_coefficient", {0.0, 10.0});
    if (fs.contact == FootingContact::node_rows)
      f::fail(p + "/interface", "'coulomb' needs contact 'penalty' (node rows are rough or smooth only)");
  } else if (j.contains("friction_coefficient")) {
    f::fail(p + "/friction_coefficient", "only with interface 'coulomb'");
  }
  if (j.contains("penalty_factor")) {
    if (fs.contact != FootingContact::penalty) f::fail(p + "/penalty_factor", "only with contact 'penalty'");
    fs.penalty_factor = f::number(j["penalty_factor"], p + "/penalty_factor", {0.01, 100.0});
  }
  if (j.contains("unload_at_S_over_B"))
    fs.unload_at_S_over_B = f::number(j["unload_at_S_over_B"], p + "/unload_at_S_over_B", {0.0, 10.0, true, false});
  if (j.contains("ramp_S_over_B")) fs.ramp_S_over_B = f::number(j["ramp_S_over_B"], p + "/ramp_S_over_B", {0.0, 1.0});
  if (j.contains("symmetric_half")) fs.symmetric_half = f::boolean(j["symmetric_half"], p + "/symmetric_half");
  if (fs.symmetric_half && fs.contact != FootingContact::penalty)
    f::fail(p + "/symmetric_half", "needs contact 'penalty' (the loads are the contact forces doubled)");
  if (fs.symmetric_half && fs.inclination_deg != 0.0)
    f::fail(p + "/symmetric_half", "needs a vertical load (inclination_deg 0): an inclined load is not symmetric");
  return fs;
}

QuasiStaticSpec read_quasi_static(const json& j, const std::string& p) {
  f::allow_keys(j, {"kinetic_ratio_limit", "check_from_S_over_B", "on_excess"}, p);
  QuasiStaticSpec q;
  if (j.contains("kinetic_ratio_limit"))
    q.kinetic_ratio_limit = f::number(j["kinetic_ratio_limit"], p + "/kinetic_ratio_limit", {0.0, 1.0, true, true});
  if (j.contains("check_from_S_over_B"))
    q.check_from_S_over_B = f::number(j["check_from_S_over_B"], p + "/check_from_S_over_B", {0.0, 5.0});
  if (j.contains("on_excess")) {
    const std::string a = f::string(j["on_excess"], p + "/on_excess");
    if (a != "warn" && a != "stop") f::fail(p + "/on_excess", "'" + a + "' is not one of warn, stop");
    q.stop_on_excess = a == "stop";
  }
  return q;
}

// [{"name": STEM, "at": [x, y]}, ...]: each name becomes particle_NAME.csv.
std::vector<ParticleTrack> read_particle_histories(const json& j, const std::string& p) {
  if (!j.is_array()) f::fail(p, "expected an array of {\"name\": ..., \"at\": [x, y]}");
  if (j.size() > max_particle_histories)
    f::fail(p, std::to_string(j.size()) + " particles: at most " + std::to_string(max_particle_histories));
  std::vector<ParticleTrack> tracks;
  for (std::size_t i = 0; i < j.size(); ++i) {
    const std::string at = p + "/" + std::to_string(i);
    f::object(j[i], at);
    f::allow_keys(j[i], {"name", "at"}, at);
    if (!j[i].contains("name")) f::fail(at + "/name", "required: a plain stem naming the particle's file");
    if (!j[i].contains("at")) f::fail(at + "/at", "required: [x, y] in m, the particle's position at the start");
    ParticleTrack t;
    t.name = common::require_plain_stem(f::string(j[i]["name"], at + "/name"), at + "/name");
    for (const ParticleTrack& other : tracks)
      if (other.name == t.name) f::fail(at + "/name", "'" + t.name + "' names two particles");
    const auto xy = f::numbers(j[i]["at"], at + "/at", 2, "x, y in m");
    t.x = xy[0];
    t.y = xy[1];
    tracks.push_back(t);
  }
  return tracks;
}

OutputSpec read_output(const json& j, const std::string& p, const std::string& dir) {
  f::allow_keys(j, {"vtk_every_S_over_B", "vtk_every_time", "contours_at_S_over_B", "contour_fields", "contours_at_peak",
                    "lab_curve", "lab_label", "checkpoint_every_s", "every_step_csv", "particle_histories"},
                p);
  OutputSpec o;
  if (j.contains("vtk_every_S_over_B"))
    o.vtk_every_S_over_B = f::number(j["vtk_every_S_over_B"], p + "/vtk_every_S_over_B", {0.0, 10.0});
  if (j.contains("vtk_every_time")) o.vtk_every_time = f::number(j["vtk_every_time"], p + "/vtk_every_time", f::positive(), "s");
  if (j.contains("contours_at_S_over_B")) {
    const json& c = j["contours_at_S_over_B"];
    if (!c.is_array()) f::fail(p + "/contours_at_S_over_B", "expected an array of S/B values");
    for (std::size_t i = 0; i < c.size(); ++i)
      o.contours_at_S_over_B.push_back(
          f::number(c[i], p + "/contours_at_S_over_B/" + std::to_string(i), {0.0, 10.0, true, false}));
  }
  if (j.contains("contour_fields")) {
    const json& c = j["contour_fields"];
    if (!c.is_array() || c.empty()) f::fail(p + "/contour_fields", "expected a non-empty array of field names");
    o.contour_fields.clear();
    for (std::size_t i = 0; i < c.size(); ++i) {
      const std::string q = p + "/contour_fields/" + std::to_string(i);
      o.contour_fields.push_back(f::choice<ContourField>(c[i], q,
                                                         {{"shear_strain", ContourField::shear_strain},
                                                          {"displacement", ContourField::displacement},
                                                          {"fabric_norm", ContourField::fabric_norm},
                                                          {"N", ContourField::N},
                                                          {"void_ratio", ContourField::void_ratio}}));
      for (std::size_t k = 0; k < i; ++k)
        if (o.contour_fields[k] == o.contour_fields[i]) f::fail(q, "named twice");
    }
  }
  if (j.contains("contours_at_peak")) o.contours_at_peak = f::boolean(j["contours_at_peak"], p + "/contours_at_peak");
  if (j.contains("lab_curve")) {
    o.lab_curve = common::resolve(dir, f::string(j["lab_curve"], p + "/lab_curve"));
    read_text(o.lab_curve, p + "/lab_curve");  // gnuplot reads it later: a regular file of bounded size
  }
  if (j.contains("lab_label")) o.lab_label = f::string(j["lab_label"], p + "/lab_label");
  if (j.contains("checkpoint_every_s"))
    o.checkpoint_every_s = f::number(j["checkpoint_every_s"], p + "/checkpoint_every_s", {0.0, 1e6}, "s");
  if (j.contains("every_step_csv")) o.every_step_csv = f::boolean(j["every_step_csv"], p + "/every_step_csv");
  if (j.contains("particle_histories")) o.particle_histories = read_particle_histories(j["particle_histories"], p + "/particle_histories");
  return o;
}

// A half-domain run stands for the whole only if the scene is its own mirror image about the
// footing's centre line: bodies spanning symmetric ranges, fabric symmetric (bedding planes
// horizontal or vertical), walls alike on both sides (they are: one /walls/sides).
void check_symmetric(const Scene& s) {
  const std::string p = "/footing/symmetric_half";
  const double c = s.footing->centre_x, h = s.cell_size;
  if (std::fabs(c / h - std::round(c / h)) > 1e-6)
    f::fail(p, "the symmetry plane (/footing/centre_x = " + f::shown(c) + " m) must lie on a grid line");
  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const BodySpec& b = s.bodies[i];
    const std::string where = "/bodies/" + std::to_string(i);
    if (std::fabs((b.x_min + b.x_max) - 2.0 * c) > 1e-6 * h)
      f::fail(p, "body " + where + " spans x " + f::shown(b.x_min) + " to " + f::shown(b.x_max) +
                     " m, not symmetric about /footing/centre_x = " + f::shown(c) + " m");
    const double a = std::fmod(std::fabs(b.bedding_angle_deg), 90.0);
    if (a > 1e-9 && a < 90.0 - 1e-9)
      f::fail(p, "body " + where + " has bedding_angle_deg " + f::shown(b.bedding_angle_deg) +
                     ": only bedding planes at 0 or 90 deg are their own mirror image");
  }
}

Scene scene_from_document(const json& j, const std::string& file) {
  f::allow_keys(j, {"name", "description", "grid", "materials", "bodies", "initial_stress", "gravity", "walls",
                    "surcharge_kPa", "confining_pressure_kPa", "footing", "quasi_static", "solver", "regularisation",
                    "micropolar", "stop", "output"},
                "");
  const std::string dir = file.empty() ? "" : std::filesystem::path(file).parent_path().string();
  Scene s;
  s.file = file;
  s.text = j.dump();
  s.name = common::require_plain_stem(
      j.contains("name") ? f::string(j["name"], "/name") : std::filesystem::path(file).stem().string(), "/name");
  for (const char* k : {"grid", "materials", "bodies", "stop"})
    if (!j.contains(k)) f::fail("", std::string("'") + k + "' is required");

  f::allow_keys(j["grid"], {"cell_size", "cells_above", "cells_beside", "follow_footing", "graded"}, "/grid");
  if (!j["grid"].contains("cell_size")) f::fail("/grid", "'cell_size' is required");
  s.cell_size = f::number(j["grid"]["cell_size"], "/grid/cell_size", f::positive(), "m");
  if (j["grid"].contains("cells_above"))
    s.cells_above = static_cast<int>(f::integer(j["grid"]["cells_above"], "/grid/cells_above", 2, 1000));
  if (j["grid"].contains("cells_beside"))
    s.cells_beside = static_cast<int>(f::integer(j["grid"]["cells_beside"], "/grid/cells_beside", 0, 1000));
  const bool follow_footing =
      j["grid"].contains("follow_footing") && f::boolean(j["grid"]["follow_footing"], "/grid/follow_footing");
  if (j["grid"].contains("graded")) s.graded = read_graded(j["grid"]["graded"], "/grid/graded", s.cell_size);

  read_materials(j["materials"], "/materials", dir, s);
  if (!j["bodies"].is_array() || j["bodies"].empty()) f::fail("/bodies", "expected a non-empty array of bodies");
  for (std::size_t i = 0; i < j["bodies"].size(); ++i)
    s.bodies.push_back(read_body(j["bodies"][i], "/bodies/" + std::to_string(i), s));

  if (j.contains("gravity")) s.gravity = f::number(j["gravity"], "/gravity", {0.0, 1000.0}, "m/s^2");
  if (j.contains("initial_stress")) {
    const json& is = j["initial_stress"];
    f::allow_keys(is, {"type", "K0", "p_kPa"}, "/initial_stress");
    s.initial_stress = is.contains("type") ? f::choice<InitialStress>(is["type"], "/initial_stress/type",
                                                                        {{"geostatic", InitialStress::geostatic},
                                                                         {"zero", InitialStress::zero},
                                                                         {"isotropic", InitialStress::isotropic}})
                                           : InitialStress::geostatic;
    if (is.contains("K0")) {
      if (s.initial_stress != InitialStress::geostatic) f::fail("/initial_stress/K0", "only with type 'geostatic'");
      s.K0 = f::number(is["K0"], "/initial_stress/K0", {0.0, 5.0, true, false});
    }
    if (s.initial_stress == InitialStress::isotropic) {
      if (!is.contains("p_kPa")) f::fail("/initial_stress", "type 'isotropic' needs 'p_kPa'");
      s.initial_p = f::number(is["p_kPa"], "/initial_stress/p_kPa", {0.0, 1e5, true, false}, "kPa");
    } else if (is.contains("p_kPa")) {
      f::fail("/initial_stress/p_kPa", "only with type 'isotropic'");
    }
  }
  if (j.contains("walls")) {
    f::allow_keys(j["walls"], {"base", "sides"}, "/walls");
    const auto wall = [&](const char* key, WallKind& kind) {
      if (j["walls"].contains(key))
        kind = f::choice<WallKind>(j["walls"][key], std::string("/walls/") + key,
                                   {{"smooth", WallKind::smooth}, {"fixed", WallKind::fixed}, {"none", WallKind::none}});
    };
    wall("base", s.base);
    wall("sides", s.sides);
  }
  if (j.contains("surcharge_kPa")) s.surcharge = f::number(j["surcharge_kPa"], "/surcharge_kPa", {0.0, 1e5}, "kPa");
  if (j.contains("confining_pressure_kPa")) {
    s.confining_pressure = f::number(j["confining_pressure_kPa"], "/confining_pressure_kPa", {0.0, 1e5}, "kPa");
    if (s.sides != WallKind::none && s.confining_pressure > 0)
      f::fail("/confining_pressure_kPa", "loads the soil's sides: needs /walls/sides 'none'");
  }
  if (j.contains("footing")) s.footing = read_footing(j["footing"], "/footing");
  if (j.contains("quasi_static")) {
    if (!s.footing) f::fail("/quasi_static", "needs a /footing (the check compares kinetic energy with its work)");
    s.quasi_static = read_quasi_static(j["quasi_static"], "/quasi_static");
  }
  if (j.contains("solver")) s.solver = read_solver(j["solver"], "/solver");
  if (j.contains("regularisation")) s.solver.regularisation = read_regularisation(j["regularisation"], "/regularisation");
  if (j.contains("micropolar")) s.solver.micropolar = read_micropolar(j["micropolar"], "/micropolar");
  if (j.contains("regularisation")) require_length_reaches_neighbours(s, j["regularisation"]);
  s.solver.gravity = s.gravity;
  if (follow_footing && !s.footing) f::fail("/grid/follow_footing", "needs a /footing (the rows follow its base)");
  s.solver.grid_follows_footing = follow_footing;
  if (s.graded && !s.footing) f::fail("/grid/graded", "needs a /footing (the refined window lies around it)");
  if (s.graded && follow_footing) f::fail("/grid/graded", "not with /grid/follow_footing (the rows keep their places)");
  if (s.graded && s.solver.update == ParticleUpdate::FLIP)
    f::fail("/solver/particle_update", "FLIP alone grows unstable on a graded grid (docs/mpm.md, \"The graded grid\"): "
                                       "use XPIC (the default, FLIP between its steps) or PIC");

  f::allow_keys(j["stop"], {"S_over_B", "time", "steps"}, "/stop");
  const std::string stop = f::one_of(j["stop"], {"S_over_B", "time", "steps"}, "/stop");
  if (stop == "S_over_B") {
    if (!s.footing) f::fail("/stop/S_over_B", "needs a /footing");
    if (s.footing->unload_at_S_over_B > 0)
      f::fail("/stop/S_over_B", "a footing that unloads (unload_at_S_over_B) stops by time or steps");
    s.stop.S_over_B = f::number(j["stop"]["S_over_B"], "/stop/S_over_B", {0.0, 5.0, true, false});
  }
  if (stop == "time") s.stop.time = f::number(j["stop"]["time"], "/stop/time", f::positive(), "s");
  if (stop == "steps") s.stop.steps = f::integer(j["stop"]["steps"], "/stop/steps", 1, static_cast<long long>(max_steps));
  if (j.contains("output")) s.output = read_output(j["output"], "/output", dir);
  check_scene_size(s);  // the counts in double, before the checks below divide by the cell size

  for (std::size_t i = 0; i < s.bodies.size(); ++i) {
    const BodySpec& b = s.bodies[i];
    const std::string p = "/bodies/" + std::to_string(i);
    for (double v : {b.x_min, b.x_max, b.y_min, b.y_max}) {
      const double cells = v / s.cell_size;
      if (std::fabs(cells - std::round(cells)) > 1e-6)
        f::fail(p, "the body's edges must lie on grid lines (multiples of /grid/cell_size = " + f::shown(s.cell_size) + " m)");
    }
  }
  if (s.footing && s.footing->symmetric_half) check_symmetric(s);
  return s;
}

}  // namespace

Scene parse_scene(const std::string& json_text, const std::string& file) {
  return scene_from_document(f::parse(json_text, "", "the scene"), file);
}

Scene read_scene(const std::string& path) {
  const json j = f::read_json_file(path, "the scene file");
  try {
    return scene_from_document(j, path);
  } catch (const common::InputError& e) {  // an error inside the document: its path, after the file's
    throw common::InputError(path + ": " + e.what());
  }
}

}  // namespace acst::mpm
