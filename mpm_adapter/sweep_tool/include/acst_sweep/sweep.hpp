#pragma once
// A footing sweep (docs/sweeps.md): a base scene and named cases, each the base with a few values
// replaced, run one whole case at a time by acst_sweep (in turn, or spread over MPI ranks) and
// gathered into one table and one overlay figure per group of cases.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "acst_footing_tool/scene.hpp"
#include "acst_sweep/sweep_findings.hpp"

namespace acst::mpm {

// One case: its scene (already read and checked) and what made it.
struct SweepCase {
  std::string name;
  std::vector<std::string> groups;  // the figures it appears in
  std::string origin;              // "/cases/3": the entry of the description that made it
  nlohmann::ordered_json varied;   // {"alpha": 20, ...}: the case's values of its entry's "vary" list
  Scene scene;
};

// What each case keeps in SWEEP/kept/CASE/ (docs/sweeps.md, "Kept results"): its summary, its
// load record and particle histories thinned to `rows` rows, and the maps named in `maps` (stems
// of its FIELD_SB*.csv or FIELD_peak.csv) averaged on square cells of map_cell_over_B B over a
// window map_width_over_B B wide about the footing's centre and map_depth_over_B B deep below
// the soil's top (and B/4 above it, for the heave).
struct KeepSpec {
  std::vector<std::string> maps;
  std::size_t rows = 150;
  double map_cell_over_B = 1.0 / 15.0;
  double map_width_over_B = 4.0, map_depth_over_B = 1.5;
};

// A figure of several cases drawn from their kept results (docs/sweeps.md, "Figures"):
// `load`, one panel per case with its own lab curve; `map`, one panel per case of a kept map on
// one colour scale, the footing drawn and a half domain mirrored; `histories`, one panel per
// tracked point (A, B, C) with one curve of a history column per case; `load_path`, H against V.
enum class PanelKind { load, map, histories, load_path };

// The cases one figure of gather/panels may draw: 64 panels (8 x 8) are still readable.
inline constexpr std::size_t max_panel_cases = 64;

struct PanelFigure {
  std::string name, title;  // figures/NAME.png; the title ("" : from what the cases share)
  PanelKind kind = PanelKind::load;
  std::vector<std::string> cases;
  std::string map;          // kind map: one of the kept maps
  std::string column = "N"; // kind histories: a column of the particle histories
};

struct SweepSpec {
  std::string name, description, file, text;
  std::vector<SweepCase> cases;
  std::vector<double> load_at_S_over_B{0.5};  // S/B values at which the table gives q
  bool figures = true;                         // one overlay of the load curves per group
  std::vector<std::string> case_figures;       // files of each case copied to figures/cases/ for the report
  std::vector<Finding> findings;               // judged in report.md
  std::vector<Band> bands;                     // the method's own spread of a column, for the findings
  std::optional<KeepSpec> keep;                // gather/keep: compact results of each case
  std::vector<PanelFigure> panels;             // gather/panels: figures drawn from the kept results
};

// Reads a sweep description (docs/sweeps.md, "The description"). Every case's scene is built and
// read here, so a bad override fails before anything runs: InputError naming the sweep's JSON
// path, and for a scene error also the case and the scene's own path. `extra_set`: a JSON object
// of pointers and values (acst_sweep --set) applied to every case after the description's "set".
SweepSpec parse_sweep(const std::string& json_text, const std::string& file, const std::string& extra_set = "");

// The cases a description's /cases array makes (each entry one, or its 'vary' lists' product),
// counted in double before any is made, so that no product can overflow; entries of the wrong
// shape count one each. The reader refuses more than max_sweep_cases at once.
double sweep_case_count(const nlohmann::json& cases);
inline constexpr double max_sweep_cases = 10000;
SweepSpec read_sweep(const std::string& path, const std::string& extra_set = "");

// `scene` with `value` put at the JSON pointer `pointer`, which must name a member of an object
// that exists (the member itself may be new; null removes it) or an element of an array that
// exists; anything else fails at `where`.
void set_at_pointer(nlohmann::json& scene, const std::string& pointer, const nlohmann::json& value,
                    const std::string& where);

}  // namespace acst::mpm
