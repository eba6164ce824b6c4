#include "acst_sweep/sweep_table.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <sstream>

#include "acst_common/files.hpp"
#include "acst_common/gnuplot.hpp"
#include "acst_common/one_line.hpp"
#include "acst_sweep/kept_results.hpp"
#include "acst_sweep/sweep_case.hpp"

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

// The rows as a markdown table, without the file names.
std::string markdown_table(const std::vector<ordered_json>& rows) {
  std::vector<std::string> cols;
  for (const std::string& c : columns_of(rows))
    if (c != "load_file" && c != "particles") cols.push_back(c);
  std::string md;
  for (const std::string& c : cols) md += "| " + c + " ";
  md += "|\n";
  for (std::size_t k = 0; k < cols.size(); ++k) md += "|---";
  md += "|\n";
  for (const ordered_json& r : rows) {
    for (const std::string& c : cols) md += "| " + (r.contains(c) ? markdown_cell(r[c]) : "") + " ";
    md += "|\n";
  }
  return md;
}

}  // namespace

bool is_sweep_output_name(const std::string& name) {
  static const std::set<std::string> own{sweep_cases_folder, sweep_kept_folder, "figures", "table.csv", "table.md",
                                         "table.json",       "sweep.json", "report.md", sweep_lock_file};
  return own.count(name) > 0 || common::is_temporary_name(name);
}

void write_sweep_table(const SweepSpec& sweep, const std::vector<ordered_json>& rows, const std::string& dir) {
  const std::vector<std::string> cols = columns_of(rows);
  std::string csv = "# acst_sweep table of sweep '" + common::one_line(sweep.name) +
                    "': one row per case (docs/sweeps.md); q in kPa, H in kN/m, M in kNm/m, wall time in s\n";
  for (std::size_t k = 0; k < cols.size(); ++k) csv += (k ? "," : "") + cols[k];
  csv += '\n';
  for (const ordered_json& r : rows) {
    for (std::size_t k = 0; k < cols.size(); ++k) csv += (k ? "," : "") + (r.contains(cols[k]) ? csv_cell(r[cols[k]]) : "");
    csv += '\n';
  }
  std::string md = "# Sweep " + common::one_line(sweep.name) + "\n\n";
  if (!sweep.description.empty()) md += common::one_line(sweep.description) + "\n\n";
  md += markdown_table(rows);
  const ordered_json table = {{"sweep", sweep.name}, {"description", sweep.description}, {"cases", rows}};
  common::write_file_atomically((fs::path(dir) / "table.csv").string(), csv);
  common::write_file_atomically((fs::path(dir) / "table.md").string(), md);
  common::write_file_atomically((fs::path(dir) / "table.json").string(), table.dump(2) + "\n");
}

void write_sweep_report(const SweepSpec& sweep, const std::vector<ordered_json>& rows, const std::string& dir,
                        const std::string& extra_report, const std::string& command) {
  std::size_t done = 0;
  for (const ordered_json& r : rows) done += status_of(r) == CaseStatus::done;
  std::set<std::string> groups;
  for (const SweepCase& c : sweep.cases) groups.insert(c.groups.begin(), c.groups.end());
  // The same text in both places; only the folder the figure links start from differs.
  const auto text = [&](const fs::path& report_dir) {
    const fs::path figures = fs::relative(fs::absolute(fs::path(dir) / "figures"), fs::absolute(report_dir));
    std::string md = "# " + common::one_line(sweep.name) + "\n\n";
    if (!sweep.description.empty()) md += common::one_line(sweep.description) + "\n\n";
    md += "Written by acst_sweep (`docs/sweeps.md`) from `" + common::one_line(sweep.file) + "` with\n\n```\n" +
          common::one_line(command) + "\n```\n\n" + std::to_string(done) + " of " + std::to_string(rows.size()) +
          " cases done. Verdicts are judged on the table below by the checks the description states. A check reads the "
          "cases that ran to their end and those that failed after their peak (the record up to the failure); it is "
          "open while a case it reads has not, and *not decided: cases pending* while a case it reads has not run yet "
          "(docs/sweeps.md, \"Findings\").\n\n";
    if (!sweep.bands.empty()) {
      md += "## Bands\n\nA check is judged against the band of its column: the spread the method itself leaves in "
            "that column (cell, loading speed, round-off, the material's length). A part common to every case cancels "
            "between cases and counts only against an outside value. It holds or fails only where the whole band agrees; "
            "otherwise it is *within the band* and says nothing either way.\n\n| column | band | measured in |\n|---|---|---|\n";
      const auto width = [](const Band& b, double w) {
        return std::isnan(b.absolute) ? markdown_cell(ordered_json(100.0 * w)) + " %" : markdown_cell(ordered_json(w));
      };
      for (const Band& b : sweep.bands)
        md += "| " + markdown_cell(b.column) + " | +-" + width(b, b.about(1.0)) +
              (b.common > 0.0 ? " between cases; +-" + width(b, b.common) + " common to every case" : "") + " | " +
              markdown_cell(b.source) + " |\n";
      md += "\n";
    }
    if (!sweep.findings.empty()) md += "## Findings\n\n";
    for (std::size_t i = 0; i < sweep.findings.size(); ++i) {
      const Finding& fd = sweep.findings[i];
      std::vector<CheckResult> results;
      for (const FindingCheck& c : fd.checks) results.push_back(judge(c, rows, sweep.bands));
      md += "### " + std::to_string(i + 1) + ". " + common::one_line(fd.claim) + ": **" + verdict(results) + "**\n\n";
      md += "| check | values | result |\n|---|---|---|\n";
      for (std::size_t k = 0; k < fd.checks.size(); ++k) {
        const FindingCheck& c = fd.checks[k];
        std::string what = c.what;
        if (what.empty()) {
          what = c.columns[0] + (c.columns.size() > 1 ? " > " + c.columns[1] : "") + ": " + name_of(c.expect);
        }
        md += "| " + markdown_cell(what) + " | " + markdown_cell(results[k].numbers) + " | " + name_of(results[k].status) + " |\n";
      }
      md += "\n";
      if (!fd.note.empty()) md += common::one_line(fd.note) + "\n\n";
    }
    md += "## Cases\n\n" + markdown_table(rows) + "\n## Figures\n\n";
    for (const std::string& g : groups) {
      if (!fs::exists(fs::path(dir) / "figures" / (g + ".png"))) continue;
      md += "- " + g + ": ![" + g + "](" + (figures / (g + ".png")).generic_string() + ")\n";
    }
    for (const PanelFigure& fig : sweep.panels) {
      if (!fs::exists(fs::path(dir) / "figures" / (fig.name + ".png"))) continue;
      md += "- " + fig.name + ": ![" + fig.name + "](" + (figures / (fig.name + ".png")).generic_string() + ")\n";
    }
    if (!sweep.case_figures.empty()) {
      md += "\n### Of each case\n\n| case |";
      for (const std::string& name : sweep.case_figures) md += " " + markdown_cell(name) + " |";
      md += "\n|---|";
      for (std::size_t k = 0; k < sweep.case_figures.size(); ++k) md += "---|";
      md += "\n";
      for (const SweepCase& c : sweep.cases) {
        md += "| " + c.name + " |";
        for (const std::string& name : sweep.case_figures) {
          const std::string file = c.name + "_" + name;
          md += fs::exists(fs::path(dir) / "figures" / "cases" / file)
                    ? " [" + name + "](" + (figures / "cases" / file).generic_string() + ") |"
                    : " |";
        }
        md += "\n";
      }
    }
    return md;
  };
  common::write_file_atomically((fs::path(dir) / "report.md").string(), text(dir));
  if (!extra_report.empty())
    common::write_file_atomically(extra_report, text(fs::absolute(extra_report).parent_path()));
}

}  // namespace acst::mpm
