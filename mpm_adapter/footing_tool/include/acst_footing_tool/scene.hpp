#pragma once
// An MPM scene as read from JSON (docs/mpm.md): grid, materials with their parameter files,
// bodies of soil, initial stress, walls, surcharge, footing, solver, stop and output.
// Lengths in m, stresses in kPa, density in kg/m^3, angles in degrees, velocity in m/s.
#include <optional>
#include <string>
#include <vector>

#include "acst_common/input_error.hpp"
#include "acst_mpm/footing.hpp"
#include "acst_mpm/settings.hpp"
#include "acst_mpm/walls.hpp"

namespace acst::mpm {

struct MaterialSpec {
  std::string name;
  std::string json_text;  // {"model", "parameters", ...} for acst_model_create
  std::string source;     // the parameter file, or "inline"
  int state_size = 0;     // state variables per particle
};

// A rectangle of soil filled with particles_per_cell^2 particles per cell.
struct BodySpec {
  std::string name, material;
  double x_min = 0, x_max = 0, y_min = 0, y_max = 0;
  double density = 0;
  int particles_per_cell = 1;
  std::optional<double> void_ratio, relative_density;  // sand only; relative density as a fraction
  double bedding_angle_deg = 0;                        // angle of the deposition direction from vertical
};

// The check that a footing run stays quasi-static: the kinetic energy over the footing's work,
// past check_from_S_over_B, against the limit; over it the run warns, or stops if asked.
struct QuasiStaticSpec {
  double kinetic_ratio_limit = 0.01;
  double check_from_S_over_B = 0.02;
  bool stop_on_excess = false;
};

struct StopSpec {
  std::optional<double> S_over_B, time;
  std::optional<long long> steps;
};

// A particle whose history is written (particle_NAME.csv): the one nearest (x, y) at the start.
struct ParticleTrack {
  std::string name;
  double x = 0, y = 0;
};

// Particle fields drawn as maps at contours_at_S_over_B (docs/mpm.md, "Output").
enum class ContourField { shear_strain, displacement, fabric_norm, N, void_ratio };

struct OutputSpec {
  double vtk_every_S_over_B = 0.05;         // also used for time-driven runs via vtk_every_time
  std::optional<double> vtk_every_time;
  std::vector<double> contours_at_S_over_B;  // maps of contour_fields there
  std::vector<ContourField> contour_fields{ContourField::shear_strain, ContourField::displacement};
  bool contours_at_peak = true;
  std::string lab_curve;                     // CSV with S_over_B and q_kPa columns, overlaid
  std::string lab_label;
  double checkpoint_every_s = 120.0;         // wall-clock seconds between checkpoints (0: none)
  bool every_step_csv = false;
  std::vector<ParticleTrack> particle_histories;
};

// The stress the particles start from: none, from the overburden (sigma_v, sigma_h = sigma_zz =
// K0 sigma_v), or isotropic (a biaxial test's consolidation).
enum class InitialStress { zero, geostatic, isotropic };

// /grid/graded (docs/mpm.md, "The graded grid"): cells of /grid/cell_size in a window around the
// footing, its half-width and its depth below the footing's base in footing widths, growing by at
// most `growth` per cell toward the walls, up to about `largest_cell` (m).
struct GradedGridSpec {
  double half_width_B = 3.0, depth_B = 3.0, growth = 1.2, largest_cell = 0.0;
};

struct Scene {
  std::string name, file, text;  // text: the canonical JSON, stored in checkpoints
  double cell_size = 0;
  std::optional<GradedGridSpec> graded;
  int cells_above = 6;           // empty cells kept above the highest body (heave room)
  int cells_beside = 0;          // empty cells beside the bodies, more than the stencil's (free sides)
  std::vector<MaterialSpec> materials;
  std::vector<BodySpec> bodies;
  double gravity = 0, K0 = 0.5;
  InitialStress initial_stress = InitialStress::zero;
  double initial_p = 0;          // kPa, of InitialStress::isotropic
  WallKind base = WallKind::fixed;     // walls/base: "fixed", "smooth" or "none"
  WallKind sides = WallKind::smooth;   // walls/sides: "smooth", "fixed" or "none"
  double surcharge = 0;          // kPa on the top surface outside the footing
  double confining_pressure = 0; // kPa on the soil's left and right sides (a biaxial test)
  std::optional<FootingSpec> footing;
  QuasiStaticSpec quasi_static;
  Settings solver;
  StopSpec stop;
  OutputSpec output;
};

Scene parse_scene(const std::string& json_text, const std::string& file = "");
Scene read_scene(const std::string& path);

}  // namespace acst::mpm
