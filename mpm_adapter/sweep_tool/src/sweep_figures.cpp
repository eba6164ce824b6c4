#include "acst_sweep/sweep_figures.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <system_error>

#include "acst_common/csv_table.hpp"
#include "acst_common/files.hpp"
#include "acst_common/gnuplot.hpp"
#include "acst_sweep/case_labels.hpp"
#include "acst_sweep/kept_results.hpp"
#include "acst_sweep/sweep_case.hpp"

namespace acst::mpm {
namespace fs = std::filesystem;
using nlohmann::json;
using nlohmann::ordered_json;

namespace {

std::string number(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

// The start of every script: the terminal, the temporary PNG name run_gnuplot hands in, CSV
// input read by column name.
std::string script_head(const std::string& what, const std::string& png, int width, int height) {
  return "# gnuplot script written by acst_sweep: " + what + "\n" +
         "set terminal pngcairo size " + std::to_string(width) + "," + std::to_string(height) +
         " font 'DejaVu Sans,11' noenhanced\n" + "if (!exists('png')) png = " + common::gp_quoted(png) +
         "\nset output png\n" + "set datafile separator ','\nset datafile commentschars '#'\nset datafile columnheaders\n";
}

const SweepCase* case_named(const SweepSpec& sweep, const std::string& name) {
  for (const SweepCase& c : sweep.cases)
    if (c.name == name) return &c;
  return nullptr;
}

fs::path kept_folder(const std::string& dir, const std::string& name) { return fs::path(dir) / sweep_kept_folder / name; }

// The kept load record of a case (the failed one where the run did not end), or "".
fs::path kept_load_record(const std::string& dir, const std::string& name) {
  for (const char* f : {"load_settlement.csv", "load_settlement.failed.csv"})
    if (fs::exists(kept_folder(dir, name) / f)) return fs::absolute(kept_folder(dir, name) / f);
  return {};
}

common::CsvTable table_of(const fs::path& file) {
  try {
    return common::parse_csv_table(common::read_input_file(file.string()));
  } catch (const std::exception&) {
    return {};
  }
}

double largest(const std::vector<double>& v) {
  double m = 0.0;
  for (double x : v)
    if (std::isfinite(x)) m = std::max(m, x);
  return m;
}

// A layout of n panels: columns, rows.
std::pair<int, int> layout(std::size_t n) {
  const int columns = n <= 3 ? static_cast<int>(n) : n == 4 ? 2 : 3;
  return {columns, static_cast<int>((n + static_cast<std::size_t>(columns) - 1) / static_cast<std::size_t>(columns))};
}

// What a reader calls a map's field and its unit.
std::string field_label(const std::string& field) {
  static const std::map<std::string, std::string> known{{"shear_strain", "shear strain γ [-]"},
                                                        {"N", "N = F:n [-]"},
                                                        {"fabric_norm", "|F| [-]"},
                                                        {"displacement", "|u| [m]"},
                                                        {"void_ratio", "e [-]"},
                                                        {"p", "p [kPa]"},
                                                        {"q", "q [kPa]"}};
  const auto it = known.find(field);
  return it == known.end() ? field : it->second;
}

std::string column_label(const std::string& column) {
  for (const char* unit : {"_kPa", "_pct", "_m", "_deg"})
    if (column.size() > std::string(unit).size() && column.compare(column.size() - std::string(unit).size(), std::string::npos, unit) == 0) {
      const std::string base = column.substr(0, column.size() - std::string(unit).size());
      const std::string u = std::string(unit) == "_kPa" ? "kPa" : std::string(unit) == "_pct" ? "%" : std::string(unit) == "_m" ? "m" : "°";
      return base + " [" + u + "]";
    }
  return field_label(column);
}

std::string moment_text(double S_over_B) { return S_over_B < 0.0 ? "at the peak" : "at S/B = " + number(S_over_B); }

// The title of a figure: its own, then what its cases share.
std::string figure_title(const PanelFigure& fig, const std::string& what, const CaseLabels& labels) {
  std::string t = fig.title.empty() ? what : fig.title;
  if (!labels.shared.empty()) t += "\n" + labels.shared;
  return t;
}

std::string load_panels(const SweepSpec& sweep, const PanelFigure& fig, const std::vector<const SweepCase*>& cases,
                        const CaseLabels& labels, const std::string& dir, std::vector<std::string>& warnings) {
  double q_max = 0.0, s_max = 0.0;
  std::vector<fs::path> records;
  for (const SweepCase* c : cases) {
    records.push_back(kept_load_record(dir, c->name));
    if (records.back().empty()) {
      warnings.push_back("figure '" + fig.name + "': case '" + c->name + "' has no kept load record");
      continue;
    }
    const common::CsvTable t = table_of(records.back());
    q_max = std::max(q_max, largest(t.values("q_kPa"))), s_max = std::max(s_max, largest(t.values("S_over_B")));
    if (!c->scene.output.lab_curve.empty()) {
      const common::CsvTable lab = table_of(c->scene.output.lab_curve);
      q_max = std::max(q_max, largest(lab.values("q_kPa"))), s_max = std::max(s_max, largest(lab.values("S_over_B")));
    }
  }
  if (std::all_of(records.begin(), records.end(), [](const fs::path& r) { return r.empty(); })) return "";
  const auto [columns, rows] = layout(cases.size());
  std::string gp = script_head("load panels " + fig.name + " of sweep " + sweep.name, fig.name + ".png", 520 * columns,
                               400 * rows + 60);
  gp += "set multiplot layout " + std::to_string(rows) + "," + std::to_string(columns) + " title " +
        common::gp_quoted(figure_title(fig, "Load against settlement", labels)) + "\n";
  gp += "set xrange [0:" + number(s_max > 0.0 ? 1.02 * s_max : 0.5) + "]\nset yrange [0:" +
        number(q_max > 0.0 ? 1.05 * q_max : 1.0) + "]\n";
  gp += "set xlabel 'S/B [-]'\nset ylabel 'q = V/B [kPa]'\nset grid\nset key bottom right\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    gp += "set title " + common::gp_quoted(labels.legends[i]) + "\n";
    if (records[i].empty()) {
      gp += "set label 1 'not run' at graph 0.5, graph 0.5 center\nplot NaN notitle\nunset label 1\n";
      continue;
    }
    gp += "plot " + common::gp_quoted(records[i].string()) + " using 'S_over_B':'q_kPa' with lines lw 2 title 'MPM'";
    const OutputSpec& o = cases[i]->scene.output;
    if (!o.lab_curve.empty())
      gp += ", " + common::gp_quoted(fs::absolute(o.lab_curve).string()) + " using 'S_over_B':'q_kPa' with points pt 7 ps 0.5 title " +
            common::gp_quoted(o.lab_label.empty() ? "lab data" : o.lab_label);
    gp += "\n";
  }
  return gp + "unset multiplot\n";
}

// The point a tracked particle stands for: a mirror image's ("C_mirror") is its original's, whose
// history it has in a symmetric case.
std::string point_of(const std::string& name) {
  const std::string suffix = "_mirror";
  return name.size() > suffix.size() && name.compare(name.size() - suffix.size(), std::string::npos, suffix) == 0
             ? name.substr(0, name.size() - suffix.size())
             : name;
}

// The p-th quantile (0-1) of v, which is sorted in place.
double quantile(std::vector<double>& v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[static_cast<std::size_t>(std::lround(p * double(v.size() - 1)))];
}

std::string map_panels(const SweepSpec& sweep, const PanelFigure& fig, const std::vector<const SweepCase*>& cases,
                       const CaseLabels& labels, const std::string& dir, std::vector<std::string>& warnings) {
  const KeepSpec& keep = *sweep.keep;
  const MapMoment moment = map_moment(fig.map);
  std::vector<double> all;
  std::vector<fs::path> files;
  for (const SweepCase* c : cases) {
    files.push_back(fs::absolute(kept_folder(dir, c->name) / (fig.map + ".csv")));
    if (!fs::exists(files.back())) {
      warnings.push_back("figure '" + fig.name + "': case '" + c->name + "' has no kept map " + fig.map + ".csv");
      files.back().clear();
      continue;
    }
    for (double v : table_of(files.back()).values("value"))
      if (std::isfinite(v)) all.push_back(v);
  }
  if (all.empty()) return "";
  // One colour scale for every panel, from the 2nd to the 98th percentile of all the cells, so
  // that the few cells at a footing's corner do not wash the bands out.
  double lo = quantile(all, 0.02), hi = quantile(all, 0.98);
  if (!(hi > lo)) hi = lo + 1.0;
  const auto [columns, rows] = layout(cases.size());
  std::string gp = script_head("map panels " + fig.name + " of sweep " + sweep.name, fig.name + ".png", 620 * columns,
                               360 * rows + 60);
  gp += "set multiplot layout " + std::to_string(rows) + "," + std::to_string(columns) + " title " +
        common::gp_quoted(figure_title(fig, field_label(moment.field) + " " + moment_text(moment.S_over_B) +
                                                " (colours: 2nd to 98th percentile of all panels)",
                                            labels)) +
        "\n";
  gp += "set palette defined (0 '#440154', 1 '#3b528b', 2 '#21918c', 3 '#5ec962', 4 '#fde725')\n";
  gp += "set cbrange [" + number(lo) + ":" + number(hi) + "]\nset cblabel " + common::gp_quoted(field_label(moment.field)) + "\n";
  gp += "set size ratio -1\nset xlabel 'x from the footing centre [m]'\nset ylabel 'y from the soil surface [m]'\n";
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const SweepCase& c = *cases[i];
    gp += "set title " + common::gp_quoted(labels.legends[i]) + "\nunset object\nunset label\n";
    if (files[i].empty() || !c.scene.footing) {
      gp += "set label 1 'not kept' at graph 0.5, graph 0.5 center\nplot NaN notitle\n";
      continue;
    }
    const double B = c.scene.footing->width, xc = c.scene.footing->centre_x;
    double top = -1e300;
    for (const BodySpec& b : c.scene.bodies) top = std::max(top, b.y_max);
    const double half = 0.5 * keep.map_width_over_B * B, cell = keep.map_cell_over_B * B;
    double s_over_B = moment.S_over_B;
    if (s_over_B < 0.0) {  // at the peak: the kept summary says where
      try {
        s_over_B = json::parse(common::read_input_file((kept_folder(dir, c.name) / "summary.json").string()))
                       .value("S_ult_over_B", 0.0);
      } catch (const std::exception&) {
        s_over_B = 0.0;
      }
    }
    // The footing at that moment: driven along its inclination, its base S below the surface.
    const double S = s_over_B * B, dx = S * std::tan(c.scene.footing->inclination_deg * M_PI / 180.0);
    gp += "set xrange [" + number(-half) + ":" + number(half) + "]\nset yrange [" + number(-keep.map_depth_over_B * B) + ":" +
          number(0.25 * B) + "]\n";
    gp += "set object 1 rectangle from " + number(dx - 0.5 * B) + "," + number(-S) + " to " + number(dx + 0.5 * B) + "," +
          number(-S + 0.12 * B) + " front fillcolor rgb '#303030' fillstyle solid 1.0 noborder\n";
    // The tracked points where they are at that moment; in a half domain a mirror image
    // ("C_mirror") is drawn where its original is, in the half the figure mirrors in.
    int label = 1;
    for (const ParticleTrack& p : c.scene.output.particle_histories) {
      const common::CsvTable h = table_of(kept_folder(dir, c.name) / ("particle_" + p.name + ".csv"));
      const std::vector<double> sb = h.values("S_over_B"), x = h.values("x_m"), y = h.values("y_m");
      if (sb.empty()) continue;
      std::size_t k = 0;
      for (std::size_t r = 1; r < sb.size(); ++r)
        if (std::fabs(sb[r] - s_over_B) < std::fabs(sb[k] - s_over_B)) k = r;
      const std::string point = point_of(p.name);
      const bool mirrored = c.scene.footing->symmetric_half && point != p.name;
      gp += "set label " + std::to_string(label++) + " " + common::gp_quoted(mirrored ? point : p.name) + " at " +
            number(mirrored ? xc - x[k] : x[k] - xc) + "," + number(y[k] - top) +
            " front point pt 7 ps 0.8 lc rgb 'red' tc rgb 'red' offset 0.5,0.5\n";
    }
    const std::string f = common::gp_quoted(files[i].string()), h = number(0.5 * cell);
    gp += "plot " + f + " using ($1-" + number(xc) + "):($2-" + number(top) + "):(" + h + "):(" + h +
          "):3 with boxxyerror fillstyle solid 1.0 noborder lc palette notitle";
    if (c.scene.footing->symmetric_half)
      gp += ", " + f + " using (" + number(xc) + "-$1):($2-" + number(top) + "):(" + h + "):(" + h +
            "):3 with boxxyerror fillstyle solid 1.0 noborder lc palette notitle";
    gp += "\n";
  }
  return gp + "unset multiplot\n";
}

std::string history_panels(const SweepSpec& sweep, const PanelFigure& fig, const std::vector<const SweepCase*>& cases,
                           const CaseLabels& labels, const std::string& dir) {
  // A panel per point; a mirror image's history stands for its original's ("C_mirror" in C's).
  std::vector<std::string> points;
  for (const SweepCase* c : cases)
    for (const ParticleTrack& p : c->scene.output.particle_histories)
      if (std::find(points.begin(), points.end(), point_of(p.name)) == points.end()) points.push_back(point_of(p.name));
  std::sort(points.begin(), points.end());
  if (points.empty()) return "";
  const auto [columns, rows] = layout(points.size());
  std::string gp = script_head("history panels " + fig.name + " of sweep " + sweep.name, fig.name + ".png", 560 * columns,
                               420 * rows + 60);
  gp += "set multiplot layout " + std::to_string(rows) + "," + std::to_string(columns) + " title " +
        common::gp_quoted(figure_title(fig, column_label(fig.column) + " at the tracked points", labels)) + "\n";
  gp += "set xlabel 'S/B [-]'\nset ylabel " + common::gp_quoted(column_label(fig.column)) + "\nset grid\nset key outside bottom center horizontal\n";
  for (const std::string& point : points) {
    std::string plot;
    for (std::size_t i = 0; i < cases.size(); ++i)
      for (const ParticleTrack& p : cases[i]->scene.output.particle_histories) {
        const fs::path file = kept_folder(dir, cases[i]->name) / ("particle_" + p.name + ".csv");
        if (point_of(p.name) != point || !fs::exists(file)) continue;
        plot += (plot.empty() ? "" : ", ") + common::gp_quoted(fs::absolute(file).string()) + " using 'S_over_B':" +
                common::gp_quoted(fig.column) + " with lines lw 2 lc " + std::to_string(i + 1) + " title " +
                common::gp_quoted(labels.legends[i] + (p.name == point ? "" : " (" + p.name + ")"));
      }
    gp += "set title " + common::gp_quoted("point " + point) + "\n";
    gp += (plot.empty() ? "plot NaN notitle" : "plot " + plot) + "\n";
  }
  return gp + "unset multiplot\n";
}

std::string load_path(const SweepSpec& sweep, const PanelFigure& fig, const std::vector<const SweepCase*>& cases,
                      const CaseLabels& labels, const std::string& dir) {
  std::string plot;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const fs::path record = kept_load_record(dir, cases[i]->name);
    if (record.empty()) continue;
    plot += (plot.empty() ? "" : ", ") + common::gp_quoted(record.string()) +
            " using 'V_kN_per_m':'H_kN_per_m' with lines lw 2 title " + common::gp_quoted(labels.legends[i]);
  }
  if (plot.empty()) return "";
  std::string gp = script_head("load path " + fig.name + " of sweep " + sweep.name, fig.name + ".png", 900, 700);
  gp += "set title " + common::gp_quoted(figure_title(fig, "Load path of the footing", labels)) + "\n";
  gp += "set xlabel 'V [kN/m]'\nset ylabel 'H [kN/m] (positive toward +x)'\nset grid\nset key outside right top\n";
  return gp + "plot " + plot + "\n";
}

}  // namespace

MapMoment map_moment(const std::string& stem) {
  MapMoment m;
  const std::size_t sb = stem.rfind("_SB");
  if (sb != std::string::npos) {
    m.field = stem.substr(0, sb);
    try {
      m.S_over_B = std::stod(stem.substr(sb + 3));
    } catch (const std::exception&) {
      m.field = stem;
    }
    return m;
  }
  const std::string peak = "_peak";
  if (stem.size() > peak.size() && stem.compare(stem.size() - peak.size(), std::string::npos, peak) == 0)
    m.field = stem.substr(0, stem.size() - peak.size());
  else
    m.field = stem;
  return m;
}

std::vector<std::string> write_group_figures(const SweepSpec& sweep, const std::vector<ordered_json>& rows,
                                             const std::string& dir) {
  std::vector<std::string> warnings;
  std::map<std::string, std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < sweep.cases.size(); ++i)
    for (const std::string& g : sweep.cases[i].groups) groups[g].push_back(i);
  const fs::path figures = fs::path(dir) / "figures";
  fs::create_directories(figures);
  for (const auto& [group, members] : groups) {
    std::vector<const SweepCase*> cases;
    for (std::size_t i : members) cases.push_back(&sweep.cases[i]);
    const CaseLabels labels = case_labels(cases);
    std::ostringstream plot;
    std::set<std::string> lab_curves;
    for (std::size_t m = 0; m < members.size(); ++m) {
      const std::size_t i = members[m];
      const std::string load_file = rows[i].value("load_file", "");
      fs::path csv = load_file.empty() ? fs::path() : fs::absolute(fs::path(case_folder(dir, sweep.cases[i].name)) / load_file);
      if (csv.empty() || !fs::exists(csv)) csv = kept_load_record(dir, sweep.cases[i].name);
      if (csv.empty()) continue;
      plot << (plot.tellp() > 0 ? ", " : "") << common::gp_quoted(csv.string())
           << " using 'S_over_B':'q_kPa' with lines lw 2 title " << common::gp_quoted(labels.legends[m]);
    }
    if (plot.tellp() == 0) continue;  // no case has a record: an earlier figure is left as it is
    for (std::size_t i : members) {
      const OutputSpec& o = sweep.cases[i].scene.output;
      if (o.lab_curve.empty() || !lab_curves.insert(o.lab_curve).second) continue;
      plot << (plot.tellp() > 0 ? ", " : "") << common::gp_quoted(fs::absolute(o.lab_curve).string())
           << " using 'S_over_B':'q_kPa' with points pt 7 ps 0.6 title "
           << common::gp_quoted(o.lab_label.empty() ? "lab data" : o.lab_label);
    }
    std::string gp = script_head("group " + group + " of sweep " + sweep.name, group + ".png", 1100, 800);
    gp += "set xlabel 'S/B [-]'\nset ylabel 'q = V/B [kPa]'\nset grid\nset key top right\n";
    gp += "set title " + common::gp_quoted("Sweep " + sweep.name + ", group " + group +
                                           (labels.shared.empty() ? "" : "\n" + labels.shared)) + "\n";
    gp += "plot " + plot.str() + "\n";
    const std::string w = common::run_gnuplot(gp, (figures / (group + ".gp")).string(), (figures / (group + ".png")).string());
    if (!w.empty()) warnings.push_back("figure of group '" + group + "': " + w);
  }
  // The figures of each case the description asks for, beside the group figures.
  for (const SweepCase& c : sweep.cases)
    for (const std::string& name : sweep.case_figures) {
      const fs::path from = fs::path(case_folder(dir, c.name)) / name;
      if (!fs::exists(from)) continue;
      fs::create_directories(figures / "cases");
      std::error_code ec;
      const fs::path to = figures / "cases" / (c.name + "_" + name), temporary = common::temporary_name(to.string());
      fs::copy_file(from, temporary, fs::copy_options::overwrite_existing, ec);
      if (!ec) fs::rename(temporary, to, ec);
      if (ec) {
        warnings.push_back("cannot copy " + from.string() + ": " + ec.message());
        fs::remove(temporary, ec);  // a copy cut short (a full disk) never takes the earlier one's place
      }
    }
  return warnings;
}

std::vector<std::string> write_panel_figures(const SweepSpec& sweep, const std::string& dir) {
  std::vector<std::string> warnings;
  const fs::path figures = fs::path(dir) / "figures";
  std::error_code ec;
  fs::create_directories(figures, ec);
  for (const PanelFigure& fig : sweep.panels) {
    std::vector<const SweepCase*> cases;
    for (const std::string& name : fig.cases)
      if (const SweepCase* c = case_named(sweep, name)) cases.push_back(c);
    const CaseLabels labels = case_labels(cases);
    std::string gp;
    switch (fig.kind) {
      case PanelKind::load: gp = load_panels(sweep, fig, cases, labels, dir, warnings); break;
      case PanelKind::map: gp = map_panels(sweep, fig, cases, labels, dir, warnings); break;
      case PanelKind::histories: gp = history_panels(sweep, fig, cases, labels, dir); break;
      case PanelKind::load_path: gp = load_path(sweep, fig, cases, labels, dir); break;
    }
    if (gp.empty()) {
      warnings.push_back("figure '" + fig.name + "': none of its cases has kept what it draws");
      continue;
    }
    const std::string w = common::run_gnuplot(gp, (figures / (fig.name + ".gp")).string(), (figures / (fig.name + ".png")).string());
    if (!w.empty()) warnings.push_back("figure '" + fig.name + "': " + w);
  }
  return warnings;
}

}  // namespace acst::mpm
