#include "acst_driver/summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace acst::driver {

void Summariser::add(const Record& r) {
  const double ratio = stress_ratio_of(r.stress);
  s_.peak_stress_ratio = any_ ? std::max(s_.peak_stress_ratio, ratio) : std::max<double>(-INFINITY, ratio);
  any_ = true;
  s_.final_stress_ratio = ratio;
  s_.final_axial_strain_pct = axial_strain_pct(r.strain);
  s_.final_volumetric_strain_pct = volumetric_strain_pct(r.strain);
  s_.final_p = mean_stress(r.stress);
  s_.final_q = signed_q(r.stress);
}

LabComparer::LabComparer(const LabCurve& lab) {
  LabComparison& c = c_;
  c.id = lab.text("id").empty() ? std::filesystem::path(lab.path).stem().string() : lab.text("id");
  const std::vector<double> ea = lab.column("eps_a_pct"), sr = lab.column("stress_ratio"), ev = lab.column("eps_v_pct");
  // Only the usable strain range of the file counts (strain_range_pct: "lo hi"; PSC to the peak).
  double use_lo = -INFINITY, use_hi = INFINITY;
  if (std::sscanf(lab.text("strain_range_pct").c_str(), "%lf %lf", &use_lo, &use_hi) != 2) {
    use_lo = -INFINITY;
    use_hi = INFINITY;
  }
  for (std::size_t i = 0; i < ea.size(); ++i) {
    if (ea[i] < use_lo || ea[i] > use_hi) continue;
    if (!sr.empty() && !std::isnan(sr[i])) {
      c.lab_peak_sr = std::isnan(c.lab_peak_sr) ? sr[i] : std::max(c.lab_peak_sr, sr[i]);
      lo_ = std::min(lo_, ea[i]);
      hi_ = std::max(hi_, ea[i]);
    }
    if (!ev.empty() && !std::isnan(ev[i]) && ea[i] > 0.0) {
      c.strain_pct = ea[i];
      c.lab_ev_pct = ev[i];
    }
  }
}

void LabComparer::add(const Record& rec) {
  LabComparison& c = c_;
  const double e = axial_strain_pct(rec.strain), ev = volumetric_strain_pct(rec.strain);
  if (e >= lo_ && e <= hi_ && rec.stress[2] > 0.0) {
    const double ratio = rec.stress[0] / rec.stress[2];
    c.sim_peak_sr = std::isnan(c.sim_peak_sr) ? ratio : std::max(c.sim_peak_sr, ratio);
  }
  // e_v of the simulation at the lab's last e_v strain: linear between the first two rows
  // around it.
  if (have_previous_ && !ev_found_ && !std::isnan(c.strain_pct) && previous_ea_ <= c.strain_pct &&
      c.strain_pct <= e && e > previous_ea_) {
    const double t = (c.strain_pct - previous_ea_) / (e - previous_ea_);
    c.sim_ev_pct = (1 - t) * previous_ev_ + t * ev;
    ev_found_ = true;
  }
  have_previous_ = true;
  previous_ea_ = e;
  previous_ev_ = ev;
}

}  // namespace acst::driver
