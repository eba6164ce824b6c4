#pragma once
// Key figures of a run, and of the lab curves it names, for the summary table of acst_element.
#include <cmath>
#include <string>
#include <vector>

#include "acst_driver/lab_data.hpp"
#include "acst_driver/runner.hpp"

namespace acst::driver {

struct RunSummary {
  double peak_stress_ratio = 0.0;   // max q/p (signed q)
  double final_stress_ratio = 0.0;
  double final_axial_strain_pct = 0.0;
  double final_volumetric_strain_pct = 0.0;
  double final_p = 0.0, final_q = 0.0;
};
RunSummary summarise(const RunResult& r);

// Simulation against one lab curve, at the lab's own strains within its usable range
// (header strain_range_pct), NaN where not comparable.
struct LabComparison {
  std::string id;
  double lab_peak_sr = NAN, sim_peak_sr = NAN;  // max sigma_1/sigma_3 within the lab's strain range
  double strain_pct = NAN;                     // axial strain of the lab's last e_v point
  double lab_ev_pct = NAN, sim_ev_pct = NAN;   // e_v there
};
LabComparison compare_with_lab(const RunResult& r, const LabCurve& lab);

}  // namespace acst::driver
