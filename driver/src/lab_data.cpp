#include "acst_driver/lab_data.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <stdexcept>

#include "acst_common/files.hpp"

namespace acst::driver {

namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  for (char ch : line) {
    if (ch == ',') {
      cells.push_back(trim(cell));
      cell.clear();
    } else {
      cell += ch;
    }
  }
  cells.push_back(trim(cell));
  return cells;
}

}  // namespace

std::vector<double> LabCurve::column(const std::string& name) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) return values[i];
  return {};
}

std::string LabCurve::text_at(const std::string& name, std::size_t row) const {
  for (std::size_t i = 0; i < columns.size(); ++i)
    if (columns[i] == name) {
      const auto it = text_cells.find({i, row});
      return it == text_cells.end() ? std::string() : it->second;
    }
  return {};
}

double LabCurve::number(const std::string& key) const {
  const auto it = meta.find(key);
  if (it == meta.end()) return std::numeric_limits<double>::quiet_NaN();
  char* end = nullptr;
  const double v = std::strtod(it->second.c_str(), &end);
  return end != it->second.c_str() ? v : std::numeric_limits<double>::quiet_NaN();
}

std::string LabCurve::text(const std::string& key) const {
  const auto it = meta.find(key);
  return it == meta.end() ? std::string() : it->second;
}

LabCurve read_commented_csv(const std::string& path, bool text_as_nan) {
  // A regular file of bounded size, or why not.
  return parse_commented_csv(common::read_input_file(path), path, text_as_nan);
}

LabCurve parse_commented_csv(const std::string& text, const std::string& path, bool text_as_nan) {
  std::istringstream in(text);
  LabCurve c;
  c.path = path;
  std::string line;
  int line_no = 0;
  auto where = [&] { return path + ":" + std::to_string(line_no) + ": "; };
  while (std::getline(in, line)) {
    ++line_no;
    const std::string t = trim(line);
    if (t.empty()) continue;
    if (t[0] == '#') {
      const std::string body = trim(t.substr(1));
      const auto colon = body.find(':');
      if (colon != std::string::npos && colon > 0 && body.find(' ') > colon)
        c.meta.emplace(trim(body.substr(0, colon)), trim(body.substr(colon + 1)));
      continue;
    }
    const std::vector<std::string> cells = split(t);
    if (c.columns.empty()) {
      c.columns = cells;
      c.values.assign(cells.size(), {});
      continue;
    }
    if (cells.size() != c.columns.size())
      throw std::runtime_error(where() + "expected " + std::to_string(c.columns.size()) + " cells, found " +
                               std::to_string(cells.size()));
    for (std::size_t i = 0; i < cells.size(); ++i) {
      double v = std::numeric_limits<double>::quiet_NaN();
      if (!cells[i].empty()) {
        char* end = nullptr;
        v = std::strtod(cells[i].c_str(), &end);
        if ((*end != '\0' || !std::isfinite(v)) && text_as_nan) {
          v = std::numeric_limits<double>::quiet_NaN();
          c.text_cells[{i, c.values[i].size()}] = cells[i];
        }
        else if (*end != '\0' || !std::isfinite(v))
          throw std::runtime_error(where() + "column " + c.columns[i] + ": '" + cells[i] + "' is not a number");
      }
      c.values[i].push_back(v);
    }
    c.lines.push_back(line_no);
  }
  if (c.columns.empty()) throw std::runtime_error(path + ": no header row (column names) found");
  return c;
}

LabCurve read_lab_curve(const std::string& path) { return parse_lab_curve(common::read_input_file(path), path); }

LabCurve parse_lab_curve(const std::string& text, const std::string& path) {
  LabCurve c = parse_commented_csv(text, path);
  if (c.column("eps_a_pct").empty() && c.values.empty())
    throw std::runtime_error(path + ": no data rows");
  bool has_axis = false;
  for (const auto& name : c.columns) has_axis = has_axis || name == "eps_a_pct";
  if (!has_axis) throw std::runtime_error(path + ": the column eps_a_pct is missing (lab-data format, data/lab/README.md)");
  bool has_series = false;
  for (const auto& name : c.columns) has_series = has_series || name == "q_kPa" || name == "eps_v_pct" || name == "stress_ratio";
  if (!has_series) throw std::runtime_error(path + ": none of the columns q_kPa, stress_ratio, eps_v_pct is present");
  // Readers interpolate along the strain and take a series' extent from its last row: rows out of
  // order would silently change both.
  const std::vector<double> eps_a = c.column("eps_a_pct");
  std::size_t previous = eps_a.size();
  for (std::size_t i = 0; i < eps_a.size(); ++i) {
    if (std::isnan(eps_a[i])) continue;
    if (previous < eps_a.size() && eps_a[i] < eps_a[previous]) {
      char what[160];
      std::snprintf(what, sizeof what, "eps_a_pct %.6g is below the %.6g of line %d", eps_a[i], eps_a[previous], c.lines[previous]);
      throw std::runtime_error(path + ":" + std::to_string(c.lines[i]) + ": " + what +
                               ": rows must be sorted by eps_a_pct (lab-data format, data/lab/README.md)");
    }
    previous = i;
  }
  return c;
}

}  // namespace acst::driver
