#pragma once
// The figures of a sweep (docs/sweeps.md, "Figures"): one overlay of the load curves per group,
// the files of each case the description names, and the panel figures drawn from the kept
// results, all in SWEEP/figures/, titled and labelled in the reference study's symbols.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "acst_sweep/sweep.hpp"

namespace acst::mpm {

// One PNG per group and the case files of gather/case_figures; a case's load curve comes from
// its folder, or from its kept record where the folder is gone (a recorded study re-plotted).
// Returns the warnings (gnuplot missing or failed, a file that cannot be copied).
std::vector<std::string> write_group_figures(const SweepSpec& sweep, const std::vector<nlohmann::ordered_json>& rows,
                                             const std::string& dir);

// The figures of gather/panels, from SWEEP/kept/ alone; returns the warnings (a case with no
// kept file for its panel, gnuplot missing or failed).
std::vector<std::string> write_panel_figures(const SweepSpec& sweep, const std::string& dir);

// The quantities of a kept map's stem: "shear_strain_SB0.500" is the field shear_strain at
// S/B 0.5; "N_peak" is N at the peak (S/B < 0).
struct MapMoment {
  std::string field;
  double S_over_B = -1.0;
};
MapMoment map_moment(const std::string& stem);

}  // namespace acst::mpm
