// The PNG figure of an element test: a generated gnuplot script (kept next to the PNG so the
// figure can be restyled) with the lab curves embedded as data blocks.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <sstream>

#include "acst/fabric.hpp"
#include "acst_common/interpolate.hpp"
#include "acst_driver/lab_data.hpp"
#include "acst_driver/output.hpp"

namespace acst::driver {

namespace {

struct LabBlocks {
  std::string title;
  bool plane_strain = false;
  std::string q, ev, pq, elogp;  // data block contents: "x,y" lines
  double p_lo = INFINITY, p_hi = -INFINITY, q_lo = INFINITY, q_hi = -INFINITY, e_lo = INFINITY, e_hi = -INFINITY;
};

LabBlocks lab_blocks(const LabCurve& c) {
  LabBlocks b;
  const std::string id = c.text("id").empty() ? std::filesystem::path(c.path).stem().string() : c.text("id");
  b.title = "lab " + id;
  b.plane_strain = c.text("kind").rfind("PSC", 0) == 0;
  const std::vector<double> ea = c.column("eps_a_pct"), q = c.column("q_kPa"), ev = c.column("eps_v_pct");
  const double s3 = c.number("sigma3_kPa"), e0 = c.number("e0");
  const std::string kind = c.text("kind");
  // p = sigma3 + q/3 only where sigma_2 = sigma_3 (triaxial compression); not in plane strain.
  const bool triaxial = !std::isnan(s3) && (kind.empty() || kind.rfind("TC", 0) == 0);
  const auto [ea_q, q_finite] = common::finite_samples(ea, q);  // lab strain increases along a curve
  char line[96];
  for (std::size_t i = 0; i < ea.size(); ++i) {
    if (!q.empty() && !std::isnan(q[i])) {
      std::snprintf(line, sizeof line, "%.6g,%.6g\n", ea[i], q[i]);
      b.q += line;
      if (triaxial) {
        std::snprintf(line, sizeof line, "%.6g,%.6g\n", s3 + q[i] / 3.0, q[i]);
        b.pq += line;
        b.p_lo = std::min(b.p_lo, s3 + q[i] / 3.0);
        b.p_hi = std::max(b.p_hi, s3 + q[i] / 3.0);
        b.q_lo = std::min(b.q_lo, q[i]);
        b.q_hi = std::max(b.q_hi, q[i]);
      }
    }
    if (!ev.empty() && !std::isnan(ev[i])) {
      std::snprintf(line, sizeof line, "%.6g,%.6g\n", ea[i], ev[i]);
      b.ev += line;
      const double qi = common::interpolate(ea_q, q_finite, ea[i]);
      if (triaxial && !std::isnan(e0) && !std::isnan(qi)) {
        const double e = e0 - (1.0 + e0) * ev[i] / 100.0;
        std::snprintf(line, sizeof line, "%.6g,%.6g\n", s3 + qi / 3.0, e);
        b.e_lo = std::min(b.e_lo, e);
        b.e_hi = std::max(b.e_hi, e);
        b.elogp += line;
      }
    }
  }
  return b;
}

// Tick marks for a log axis over [lo, hi]: 1-2-5 per decade, or finer for a narrow range.
std::string log_ticks(double lo, double hi) {
  std::string out;
  for (const std::vector<double>& mantissas : {std::vector<double>{1, 2, 5}, std::vector<double>{1, 1.5, 2, 3, 4, 5, 6, 7, 8, 9}}) {
    out.clear();
    int n = 0;
    for (double decade = std::pow(10.0, std::floor(std::log10(lo))); decade <= hi; decade *= 10.0)
      for (double m : mantissas) {
        const double v = m * decade;
        if (v < lo || v > hi) continue;
        char buf[32];
        std::snprintf(buf, sizeof buf, "%s%g", n++ ? ", " : "", v);
        out += buf;
      }
    if (n >= 3) break;
  }
  return out;
}

}  // namespace

void PlotRanges::add(const Record& r) {
  const double p = mean_stress(r.stress), q = signed_q(r.stress);
  p_lo = std::min(p_lo, p);
  p_hi = std::max(p_hi, p);
  q_lo = std::min(q_lo, q);
  q_hi = std::max(q_hi, q);
  ev_lo = std::min(ev_lo, volumetric_strain_pct(r.strain));
  ev_hi = std::max(ev_hi, volumetric_strain_pct(r.strain));
  e_lo = std::min(e_lo, r.void_ratio);
  e_hi = std::max(e_hi, r.void_ratio);
}

std::string write_figure(const ElementScene& scene, const PlotRanges& ranges, const std::string& csv_path,
                         const std::string& png_path, const std::string& gp_path) {
  if (!common::gnuplot_available()) return "gnuplot was not found on PATH: no PNG written (the CSV is complete)";
  const Parameters& par = scene.material->parameters();
  std::vector<LabBlocks> labs;
  for (const auto& file : scene.lab_data) {
    try {
      labs.push_back(lab_blocks(read_lab_curve(file)));
    } catch (const std::exception& e) {
      return std::string("lab data not plotted: ") + e.what();
    }
  }
  std::ostringstream gp;
  gp << "# gnuplot script written by acst_element for " << scene.output.name << "\n";
  gp << "set terminal pngcairo size 1400,1000 font 'DejaVu Sans,11' noenhanced\n";
  gp << "# run as: gnuplot " << std::filesystem::path(gp_path).filename().string() << " (or gnuplot -e \"png='other.png'\" ...)\n";
  gp << "if (!exists('png')) png = " << common::gp_quoted(png_path) << "\n";
  gp << "set output png\n";
  gp << "set datafile separator ','\nset datafile columnheaders\n";
  for (std::size_t k = 0; k < labs.size(); ++k) {
    auto block = [&](const char* name, const std::string& body) {
      gp << "$lab" << k << "_" << name << " << EOD\nx,y\n" << (body.empty() ? "NaN,NaN\n" : body) << "EOD\n";
    };
    block("q", labs[k].q);
    block("ev", labs[k].ev);
    block("pq", labs[k].pq);
    block("elogp", labs[k].elogp);
  }
  const std::string data = common::gp_quoted(csv_path);
  // Ranges of p and q from the data, so the reference lines do not stretch the axes.
  double p_lo = ranges.p_lo, p_hi = ranges.p_hi, q_lo = ranges.q_lo, q_hi = ranges.q_hi;
  for (const auto& l : labs) {
    p_lo = std::min(p_lo, l.p_lo);
    p_hi = std::max(p_hi, l.p_hi);
    q_lo = std::min(q_lo, l.q_lo);
    q_hi = std::max(q_hi, l.q_hi);
  }
  if (!(p_hi > p_lo)) p_hi = p_lo * 1.1 + 1.0;
  const double ev_lo = ranges.ev_lo, ev_hi = ranges.ev_hi;
  // Void ratio axis: the simulation, the lab points and the critical state line over the p range.
  double e_lo = ranges.e_lo, e_hi = ranges.e_hi;
  for (const auto& l : labs) {
    e_lo = std::min(e_lo, l.e_lo);
    e_hi = std::max(e_hi, l.e_hi);
  }
  for (const double p : {p_lo / 1.15, p_hi * 1.15}) {
    const double ec = par.e_Gamma - par.lambda_c * std::pow(p / atmospheric_pressure, par.xi);
    e_lo = std::min(e_lo, ec);
    e_hi = std::max(e_hi, ec);
  }
  const double e_pad = std::max(0.05 * (e_hi - e_lo), 0.005);
  bool undrained = false;
  for (const Block& bl : scene.blocks)
    for (const Step& st : bl.steps) undrained = undrained || st.undrained;
  const double q_pad = 0.05 * std::max(q_hi - q_lo, 1.0);
  Eigen::Vector3d b = unit_direction(scene.initial.deposition_direction);  // as the fabric takes it
  for (int i = 0; i < 3; ++i) b[i] = std::abs(b[i]) < 1e-12 ? 0.0 : b[i];  // cos(90 deg) prints as 0
  char title[400];
  std::snprintf(title, sizeof title, "%s: %s model, e0 = %.3f, p0 = %.4g kPa, bedding angle %.3g deg (b = [%.3g, %.3g, %.3g])",
                scene.output.name.c_str(), par.variant == Variant::isotropic ? "isotropic" : "ACST",
                scene.initial.void_ratio, trace(scene.initial.stress) / 3.0, scene.initial.bedding_angle_deg, b[0], b[1], b[2]);
  gp << "set multiplot layout 2,2 title " << common::gp_quoted(title) << "\n";
  gp << "set grid\nset key top left box opaque\nset style data lines\n";
  gp << "sim = 'simulation (" << (par.variant == Variant::isotropic ? "isotropic" : "ACST") << ")'\n";
  const char* point_styles[] = {"pt 7 ps 0.9 lc rgb '#d62728'", "pt 5 ps 0.9 lc rgb '#2ca02c'", "pt 9 ps 1.0 lc rgb '#ff7f0e'",
                                "pt 11 ps 1.0 lc rgb '#9467bd'", "pt 13 ps 1.0 lc rgb '#8c564b'"};
  auto lab_plots = [&](const char* block) {
    std::string s;
    for (std::size_t k = 0; k < labs.size(); ++k)
      s += ", $lab" + std::to_string(k) + "_" + block + " using 1:2 with points " + point_styles[k % 5] + " title " +
           common::gp_quoted(labs[k].title + (labs[k].plane_strain && std::string(block) == "q" ? " (sigma_1 - sigma_3)" : ""));
    return s;
  };
  gp << "set xlabel 'axial strain eps_a [%]'\nset ylabel 'q [kPa]'\nset key bottom right\n";
  // Lab files give sigma_1 - sigma_3; in plane strain that is not the invariant q, so draw both.
  bool plane_strain_lab = false;
  for (const auto& l : labs) plane_strain_lab = plane_strain_lab || l.plane_strain;
  gp << "plot " << data << " using 'eps_a_pct':'q_kPa' lw 2 lc rgb '#1f3f9f' title sim"
     << (plane_strain_lab ? std::string(", ") + data +
                                " using 'eps_a_pct':(column('sigma_11_kPa') - column('sigma_33_kPa')) lw 2 dt 4 title 'simulation sigma_11 - sigma_33'"
                          : std::string())
     << lab_plots("q") << "\n";
  if (undrained) {  // e_v = 0 says nothing there: show the excess pore pressure instead
    gp << "set ylabel 'excess pore pressure u [kPa]'\nset key bottom right\n";
    gp << "plot " << data << " using 'eps_a_pct':'u_excess_kPa' lw 2 lc rgb '#1f3f9f' title sim\n";
  } else {
    gp << "set ylabel 'volumetric strain e_v [%] (compression +)'\nset key bottom left\n";
    if (ev_hi - ev_lo < 1e-3) gp << "set yrange [" << ev_lo - 0.5 << ":" << ev_hi + 0.5 << "]\n";
    gp << "plot " << data << " using 'eps_a_pct':'e_v_pct' lw 2 lc rgb '#1f3f9f' title sim" << lab_plots("ev") << "\n";
    gp << "set autoscale y\n";
  }
  gp << "set logscale x\nset xrange [" << p_lo / 1.15 << ":" << p_hi * 1.15 << "]\nset xtics (" << log_ticks(p_lo / 1.15, p_hi * 1.15)
     << ")\nset yrange [" << e_lo - e_pad << ":" << e_hi + e_pad << "]\nset xlabel 'p [kPa] (log scale)'\nset ylabel 'void ratio e'\nset key top right\n";
  gp << "ec(p) = " << par.e_Gamma << " - " << par.lambda_c << " * (p / " << atmospheric_pressure << ")**" << par.xi << "\n";
  gp << "plot " << data << " using 'p_kPa':'void_ratio' lw 2 lc rgb '#1f3f9f' title sim, ec(x) dt 2 lc rgb 'gray40' title 'critical state line'"
     << lab_plots("elogp") << "\n";
  gp << "unset logscale x\nset xtics auto\nset xrange [0:" << p_hi * 1.1 << "]\nset yrange [" << q_lo - q_pad << ":" << q_hi + q_pad
     << "]\nset xlabel 'p [kPa]'\nset ylabel 'q [kPa] (negative in extension)'\nset key top left\n";
  gp << "plot " << data << " using 'p_kPa':'q_kPa' lw 2 lc rgb '#1f3f9f' title sim, " << par.Mc << " * x dt 2 lc rgb 'gray40' title 'q = Mc p'";
  if (q_lo < 0.0) gp << ", " << -par.c * par.Mc << " * x dt 3 lc rgb 'gray60' title 'q = -c Mc p'";
  gp << lab_plots("pq") << "\n";
  gp << "unset multiplot\nset output\n";
  return common::run_gnuplot(gp.str(), gp_path, png_path);
}

}  // namespace acst::driver
