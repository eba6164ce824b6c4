#include "acst_common/csv_table.hpp"

#include <algorithm>
#include <charconv>
#include <limits>
#include <sstream>

namespace acst::common {

std::vector<std::string> csv_cells(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) out.push_back(cell);
  return out;
}

std::optional<std::size_t> CsvTable::column(const std::string& name) const {
  const auto it = std::find(header.begin(), header.end(), name);
  if (it == header.end()) return std::nullopt;
  return static_cast<std::size_t>(it - header.begin());
}

std::vector<double> CsvTable::values(const std::string& name) const {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> out(rows.size(), nan);
  if (const std::optional<std::size_t> k = column(name))
    for (std::size_t i = 0; i < rows.size(); ++i) out[i] = *k < rows[i].size() ? rows[i][*k] : nan;
  return out;
}

CsvTable parse_csv_table(const std::string& text) {
  CsvTable t;
  std::istringstream in(text);
  bool header = true;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells = csv_cells(line);
    if (header) {
      t.header = std::move(cells);
      header = false;
      continue;
    }
    std::vector<double> row;
    row.reserve(cells.size());
    for (const std::string& c : cells) {
      double v = std::numeric_limits<double>::quiet_NaN();
      const char *b = c.data(), *e = c.data() + c.size();
      while (b < e && (*b == ' ' || *b == '\t')) ++b;
      while (e > b && (e[-1] == ' ' || e[-1] == '\t')) --e;
      if (b < e && *b == '+') ++b;  // from_chars takes no leading '+'
      const auto r = std::from_chars(b, e, v);
      if (r.ec != std::errc() || r.ptr != e) v = std::numeric_limits<double>::quiet_NaN();
      row.push_back(v);
    }
    t.rows.push_back(std::move(row));
  }
  return t;
}

}  // namespace acst::common
