#include "acst_mpm/sweep_table.hpp"

#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "acst_common/files.hpp"
#include "acst_common/gnuplot.hpp"
#include "acst_common/one_line.hpp"
#include "acst_mpm/sweep_case.hpp"

namespace acst::mpm {
namespace fs = std::filesystem;
using nlohmann::ordered_json;

namespace {

// Every column any row has, in the order they first appear; the message last.
std::vector<std::string> columns_of(const std::vector<ordered_json>& rows) {
  std::vector<std::string> cols;
  std::set<std::string> seen{"message"};
  for (const ordered_json& r : rows)
    for (const auto& item : r.items())
      if (seen.insert(item.key()).second) cols.push_back(item.key());
  cols.push_back("message");
  return cols;
}

std::string csv_cell(const ordered_json& v) {
  if (v.is_null()) return "";
  std::string text = v.is_string() ? common::one_line(v.get<std::string>()) : v.dump();
  if (text.find_first_of(",\"") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char ch : text) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return quoted + "\"";
}

std::string markdown_cell(const ordered_json& v) {
  std::string text;
  if (v.is_null()) return "";
  if (v.is_number_float()) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.4g", v.get<double>());
    text = buf;
  } else {
    text = v.is_string() ? common::one_line(v.get<std::string>()) : v.dump();
  }
  std::string escaped;
  for (char ch : text) escaped += ch == '|' ? std::string("\\|") : std::string(1, ch);
  return escaped;
}

}  // namespace

bool is_sweep_output_name(const std::string& name) {
  static const std::set<std::string> own{sweep_cases_folder, "figures", "table.csv", "table.md", "table.json", "sweep.json"};
  return own.count(name) > 0 || common::is_temporary_name(name);
}

void write_sweep_table(const SweepSpec& sweep, const std::vector<ordered_json>& rows, const std::string& dir) {
  const std::vector<std::string> cols = columns_of(rows);
  std::string csv = "# acst_sweep table of sweep '" + common::one_line(sweep.name) +
                    "': one row per case (docs/sweeps.md); q in kPa, H in kN/m, M in kNm/m, wall time in s\n";
  for (std::size_t k = 0; k < cols.size(); ++k) csv += (k ? "," : "") + cols[k];
  csv += '\n';
  std::string md = "# Sweep " + common::one_line(sweep.name) + "\n\n";
  if (!sweep.description.empty()) md += common::one_line(sweep.description) + "\n\n";
  std::vector<std::string> md_cols;
  for (const std::string& c : cols)
    if (c != "load_file" && c != "particles") md_cols.push_back(c);
  for (const std::string& c : md_cols) md += "| " + c + " ";
  md += "|\n";
  for (std::size_t k = 0; k < md_cols.size(); ++k) md += "|---";
  md += "|\n";
  for (const ordered_json& r : rows) {
    for (std::size_t k = 0; k < cols.size(); ++k) csv += (k ? "," : "") + (r.contains(cols[k]) ? csv_cell(r[cols[k]]) : "");
    csv += '\n';
    for (const std::string& c : md_cols) md += "| " + (r.contains(c) ? markdown_cell(r[c]) : "") + " ";
    md += "|\n";
  }
  const ordered_json table = {{"sweep", sweep.name}, {"description", sweep.description}, {"cases", rows}};
  common::write_file_atomically((fs::path(dir) / "table.csv").string(), csv);
  common::write_file_atomically((fs::path(dir) / "table.md").string(), md);
  common::write_file_atomically((fs::path(dir) / "table.json").string(), table.dump(2) + "\n");
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
    std::ostringstream plot;
    std::set<std::string> lab_curves;
    for (std::size_t i : members) {
      const std::string load_file = rows[i].value("load_file", "");
      if (load_file.empty()) continue;
      const fs::path csv = fs::absolute(fs::path(case_folder(dir, sweep.cases[i].name)) / load_file);
      plot << (plot.tellp() > 0 ? ", " : "") << common::gp_quoted(csv.string())
           << " using 'S_over_B':'q_kPa' with lines lw 2 title " << common::gp_quoted(sweep.cases[i].name);
    }
    for (std::size_t i : members) {
      const OutputSpec& o = sweep.cases[i].scene.output;
      if (o.lab_curve.empty() || !lab_curves.insert(o.lab_curve).second) continue;
      plot << (plot.tellp() > 0 ? ", " : "") << common::gp_quoted(fs::absolute(o.lab_curve).string())
           << " using 'S_over_B':'q_kPa' with points pt 7 ps 0.6 title "
           << common::gp_quoted(o.lab_label.empty() ? "lab data" : o.lab_label);
    }
    if (plot.tellp() == 0) continue;
    std::ostringstream gp;
    gp << "# gnuplot script written by acst_sweep for group " << group << " of sweep " << sweep.name << "\n"
       << "set terminal pngcairo size 1100,800 font 'DejaVu Sans,12' noenhanced\n"
       << "if (!exists('png')) png = " << common::gp_quoted(group + ".png") << "\nset output png\n"
       << "set datafile separator ','\nset datafile commentschars '#'\nset datafile columnheaders\n"
       << "set xlabel 'S/B'\nset ylabel 'q = V/B [kPa]'\nset grid\nset key top right\n"
       << "set title " << common::gp_quoted("Sweep " + sweep.name + ", group " + group) << "\n"
       << "plot " << plot.str() << "\n";
    const std::string w = common::run_gnuplot(gp.str(), (figures / (group + ".gp")).string(), (figures / (group + ".png")).string());
    if (!w.empty()) warnings.push_back("figure of group '" + group + "': " + w);
  }
  return warnings;
}

}  // namespace acst::mpm
