#pragma once
// Measured curves in the project's lab-data format (data/lab/README.md): `# key: value` header
// lines, then a CSV table with the columns eps_a_pct, stress_ratio, q_kPa, eps_v_pct
// (compression positive; an EMPTY cell means the series has no value at that row).
#include <map>
#include <string>
#include <vector>

namespace acst::driver {

struct LabCurve {
  std::string path;
  std::map<std::string, std::string> meta;  // header keys: sigma3_kPa, e0, bedding_angle_deg, ...
  std::vector<std::string> columns;
  std::vector<std::vector<double>> values;  // values[column][row], NaN where the cell is empty
  std::vector<int> lines;                   // lines[row]: the row's line in the file, for messages
  // Read with text_as_nan: the cells that held text (not a number, not empty), as
  // (column, row) -> the text, so that a user of a column can tell text from an empty cell.
  std::map<std::pair<std::size_t, std::size_t>, std::string> text_cells;

  // The column's values (NaN where empty); an empty vector if the file has no such column.
  std::vector<double> column(const std::string& name) const;
  // Header value as a number, or NaN when absent or not a number.
  double number(const std::string& key) const;
  std::string text(const std::string& key) const;  // "" when absent
  // The text a cell of `column` held at `row` where it was no number ("" for a number, an empty
  // cell, or no such column).
  std::string text_at(const std::string& column, std::size_t row) const;
};

// Throws std::runtime_error("path:line: what") on unreadable or malformed files, and on rows not
// sorted by eps_a_pct (ties allowed; rows without eps_a_pct are skipped).
LabCurve read_lab_curve(const std::string& path);

// Generic reader of `# ...` commented CSV tables with a header row (also used for strain paths
// and the CSV files acst_element writes). A cell that is not a number is an error, or NaN when
// `text_as_nan` is set.
LabCurve read_commented_csv(const std::string& path, bool text_as_nan = false);

// The two readers on a file's text already read (`path` names it in the messages): what the
// readers above do once the file is read, and what tests/fuzz/fuzz_lab_csv feeds.
LabCurve parse_commented_csv(const std::string& text, const std::string& path, bool text_as_nan = false);
LabCurve parse_lab_curve(const std::string& text, const std::string& path);

}  // namespace acst::driver
