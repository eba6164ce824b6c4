#pragma once
// The gathered outputs of a sweep (docs/sweeps.md, "The table"): the table of its cases'
// rows as table.csv, table.md and table.json, and the report that judges the findings on it and
// links the figures (sweep_figures.hpp).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "acst_sweep/sweep.hpp"

namespace acst::mpm {

// Writes the three tables into `dir`, each atomically. `rows[i]` is case i's row, in the order of
// the description. Throws std::runtime_error naming a file that cannot be written.
void write_sweep_table(const SweepSpec& sweep, const std::vector<nlohmann::ordered_json>& rows, const std::string& dir);

// report.md in `dir` (and a copy at `extra_report` when not empty, its figure links made relative
// to its own folder): the description, every finding with its checks' numbers and verdict, the
// table and the group figures. `command`: the command line that made it.
void write_sweep_report(const SweepSpec& sweep, const std::vector<nlohmann::ordered_json>& rows, const std::string& dir,
                        const std::string& extra_report, const std::string& command);

// The file names the tables and figures take in a sweep's folder.
bool is_sweep_output_name(const std::string& name);

}  // namespace acst::mpm
