#include "acst_driver/summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace acst::driver {

RunSummary summarise(const RunResult& r) {
  RunSummary s;
  if (r.records.empty()) return s;
  s.peak_stress_ratio = -INFINITY;
  for (const Record& rec : r.records) s.peak_stress_ratio = std::max(s.peak_stress_ratio, stress_ratio_of(rec.stress));
  const Record& last = r.records.back();
  s.final_stress_ratio = stress_ratio_of(last.stress);
  s.final_axial_strain_pct = axial_strain_pct(last.strain);
  s.final_volumetric_strain_pct = volumetric_strain_pct(last.strain);
  s.final_p = mean_stress(last.stress);
  s.final_q = signed_q(last.stress);
  return s;
}

LabComparison compare_with_lab(const RunResult& r, const LabCurve& lab) {
  LabComparison c;
  c.id = lab.text("id").empty() ? std::filesystem::path(lab.path).stem().string() : lab.text("id");
  const std::vector<double> ea = lab.column("eps_a_pct"), sr = lab.column("stress_ratio"), ev = lab.column("eps_v_pct");
  // Only the usable strain range of the file counts (strain_range_pct: "lo hi"; PSC to the peak).
  double use_lo = -INFINITY, use_hi = INFINITY;
  if (std::sscanf(lab.text("strain_range_pct").c_str(), "%lf %lf", &use_lo, &use_hi) != 2) {
    use_lo = -INFINITY;
    use_hi = INFINITY;
  }
  double lo = INFINITY, hi = -INFINITY;
  for (std::size_t i = 0; i < ea.size(); ++i) {
    if (ea[i] < use_lo || ea[i] > use_hi) continue;
    if (!sr.empty() && !std::isnan(sr[i])) {
      c.lab_peak_sr = std::isnan(c.lab_peak_sr) ? sr[i] : std::max(c.lab_peak_sr, sr[i]);
      lo = std::min(lo, ea[i]);
      hi = std::max(hi, ea[i]);
    }
    if (!ev.empty() && !std::isnan(ev[i]) && ea[i] > 0.0) {
      c.strain_pct = ea[i];
      c.lab_ev_pct = ev[i];
    }
  }
  for (const Record& rec : r.records) {
    const double e = axial_strain_pct(rec.strain);
    if (e >= lo && e <= hi && rec.stress[2] > 0.0) {
      const double ratio = rec.stress[0] / rec.stress[2];
      c.sim_peak_sr = std::isnan(c.sim_peak_sr) ? ratio : std::max(c.sim_peak_sr, ratio);
    }
  }
  // e_v of the simulation at the lab's last e_v strain: linear between the records around it.
  for (std::size_t i = 1; i < r.records.size() && !std::isnan(c.strain_pct); ++i) {
    const double e0 = axial_strain_pct(r.records[i - 1].strain), e1 = axial_strain_pct(r.records[i].strain);
    if (e0 <= c.strain_pct && c.strain_pct <= e1 && e1 > e0) {
      const double t = (c.strain_pct - e0) / (e1 - e0);
      c.sim_ev_pct = (1 - t) * volumetric_strain_pct(r.records[i - 1].strain) + t * volumetric_strain_pct(r.records[i].strain);
      break;
    }
  }
  return c;
}

}  // namespace acst::driver
