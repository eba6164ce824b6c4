#pragma once
// Key figures of a run, and of the lab curves it names, for the summary table of acst_element;
// gathered row by row as the run goes, so that no row needs to be kept.
#include <cmath>
#include <string>
#include <vector>

#include "acst_driver/lab_data.hpp"
#include "acst_driver/runner.hpp"

namespace acst::driver {

struct ElementRunSummary {
  double peak_stress_ratio = 0.0;   // max q/p (signed q)
  double final_stress_ratio = 0.0;
  double final_axial_strain_pct = 0.0;
  double final_volumetric_strain_pct = 0.0;
  double final_p = 0.0, final_q = 0.0;
};
class Summariser {
 public:
  void add(const Record& r);
  const ElementRunSummary& summary() const { return s_; }

 private:
  ElementRunSummary s_;
  bool any_ = false;
};

// Simulation against one lab curve, at the lab's own strains within its usable range
// (header strain_range_pct), NaN where not comparable.
struct LabComparison {
  std::string id;
  double lab_peak_sr = NAN, sim_peak_sr = NAN;  // max sigma_1/sigma_3 within the lab's strain range
  double strain_pct = NAN;                     // axial strain of the lab's last e_v point
  double lab_ev_pct = NAN, sim_ev_pct = NAN;   // e_v there
};
class LabComparer {
 public:
  explicit LabComparer(const LabCurve& lab);
  void add(const Record& r);
  const LabComparison& comparison() const { return c_; }

 private:
  LabComparison c_;
  double lo_ = INFINITY, hi_ = -INFINITY;  // strain range of the lab's stress ratios
  bool have_previous_ = false, ev_found_ = false;
  double previous_ea_ = 0.0, previous_ev_ = 0.0;  // the row before, for interpolating e_v
};

}  // namespace acst::driver
