#pragma once
// An element test as read from its JSON scene (docs/element-tests.md): material, initial state,
// steps reduced to six linear rows A d_sigma + B d_eps = c each, solver settings and output.
// Everything here is in the model convention (compression positive, tensor shear strain,
// strain as a fraction); the JSON reader converts from the scene's units (percent, engineering
// shear) in one place.
#include <Eigen/Core>
#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "acst/material.hpp"
#include "acst_driver/mixed_control.hpp"
#include "acst_common/input_error.hpp"

namespace acst::driver {


// Six rows of A d_sigma + B d_eps = c over a step. A row's `value` is either its change over the
// segment, or (absolute) the value its expression A sigma + B eps must reach at the end of the
// segment, with eps the strain since the start of the test.
struct ControlRows {
  Mat6 A = Mat6::Zero();
  Mat6 B = Mat6::Zero();
  Sym value = Sym::Zero();
  std::array<bool, 6> absolute{};
  std::array<std::string, 6> names;  // what each row controls, for messages ("eps_11", "p", ...)
};

// A piece of a step with its own rows and number of increments (a strain path read from CSV
// gives one segment per row of the file; every other step has one).
struct Segment {
  ControlRows rows;
  int increments = 1;
};

// Quantities an exit condition can watch (output convention: q and the stress ratio signed,
// negative in extension; strains in percent, compression positive).
enum class ExitQuantity { q, stress_ratio, p, axial_strain_pct, volumetric_strain_pct, excess_pore_pressure };

struct ExitCondition {
  ExitQuantity quantity = ExitQuantity::q;
  bool above = true;  // met when the quantity is >= threshold (above) or <= threshold (below)
  double threshold = 0.0;
  std::string key;    // JSON key, e.g. "q_above"
  std::string path;   // JSON path of the key
};

struct Step {
  std::string path;   // JSON path of the step, e.g. /steps/2
  std::string kind;   // preset name, "control" or "constraints"
  std::vector<Segment> segments;
  std::vector<ExitCondition> exits;
  bool undrained = false;           // count the excess pore pressure (total lateral stress held)
  std::optional<Sym> newton_guess;  // first Newton guess of the first increment (reproducers)
};

// A plain step is a block of one step run once; a repeat block runs its steps `cycles` times
// unless one of its own exit conditions ends it first.
struct Block {
  std::string path;
  bool repeat = false;
  int cycles = 1;
  std::vector<Step> steps;
  std::vector<ExitCondition> exits;
};

struct InitialState {
  Sym stress = Sym::Zero();
  double void_ratio = 0.0;
  Eigen::Vector3d deposition_direction = Eigen::Vector3d::UnitX();
  double bedding_angle_deg = 0.0;  // for the CSV header (NaN when a direction was given)
  // Optional full state (reproducers): fabric tensor, cone size H, substep hint.
  std::optional<Sym> fabric;
  std::optional<double> H;
  std::optional<double> substep_hint;
  // A host's nonlocal offset of the void ratio (Material::update), applied to every increment: a
  // reproducer of a regularised MPM particle's update replays with it (0: the local model).
  double void_ratio_offset = 0.0;
};

struct SolverSettings {
  NewtonOptions newton;
  int max_halvings = 12;  // cut-back: an increment may be halved this many times
  long max_cutbacks = 0;  // the most halvings of the whole run (0: no limit)
};

struct ElementOutputSpec {
  std::string directory = "results/element";  // relative to the current working directory
  std::string name;                            // file stem; default: the scene file's stem
  int every = 1;                               // write every n-th increment (and every step end)
  bool plot = true;
};

struct ElementScene {
  std::string source;     // scene file (empty when parsed from text)
  std::string base_dir;   // relative file names in the scene resolve against this directory
  nlohmann::json material_json;  // the effective material object {model, parameters, integrator}
  std::string material_source;   // "inline" or the file it came from
  std::optional<Material> material;
  InitialState initial;
  std::vector<Block> blocks;
  SolverSettings solver;
  std::vector<std::string> lab_data;  // resolved paths
  ElementOutputSpec output;
};

// Reads and validates a scene file. Relative paths inside it (material file, lab data, strain
// path CSV) are resolved against the directory of the scene file.
ElementScene read_scene(const std::string& path);

// The same from JSON text; `base_dir` resolves relative paths, `default_name` names the output.
ElementScene parse_scene(const std::string& json_text, const std::string& base_dir, const std::string& default_name);

// What a scene asks for, counted in double so that no count can overflow before it is checked:
// the increments (every segment's, times its block's cycles) and the CSV rows (every n-th
// increment plus every segment's end). parse_scene refuses more than the caps.
struct ElementSceneSize {
  double increments = 0.0;
  double rows = 0.0;
};
ElementSceneSize scene_size(const std::vector<Block>& blocks, int every);
// A run of 1e9 increments takes hours at the driver's speed (docs/element-tests.md); 1e8 rows
// are some 35 GB of CSV.
inline constexpr double max_total_increments = 1e9;
inline constexpr long long max_step_increments = 10000000;  // of one step, or one row of a strain path
inline constexpr double max_csv_rows = 1e8;
// Throws common::InputError naming /steps (and the largest block) or /output/every.
void check_scene_size(const std::vector<Block>& blocks, int every);

// Throws common::InputError if the six rows cannot fix all six strain components with an elastic
// stiffness of this material (rank < 6), naming the free component; `path` prefixes the message.
void check_rows_complete(const ControlRows& rows, const Material& material, const std::string& path);

}  // namespace acst::driver
