#pragma once
// Numbers read from a CSV text with a header line: the one reader of the tools' own records
// (load records, particle histories, maps). Empty lines and lines that start with '#' are
// skipped; the first other line is the header.
#include <optional>
#include <string>
#include <vector>

namespace acst::common {

// The cells of one CSV line, split at every comma (no quoting: the records hold none).
std::vector<std::string> csv_cells(const std::string& line);

struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;  // NaN where a cell is missing or not a whole number

  std::optional<std::size_t> column(const std::string& name) const;
  // The column's values, one per row; NaN in every row when there is no such column.
  std::vector<double> values(const std::string& name) const;
};

CsvTable parse_csv_table(const std::string& text);

}  // namespace acst::common
