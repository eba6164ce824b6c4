#pragma once
// The compact results a sweep keeps of each case (docs/sweeps.md, "Kept results"), so that a
// recorded study can be re-plotted and checked without its case folders or a re-run.
#include <cstddef>
#include <string>
#include <vector>

#include "acst_sweep/sweep.hpp"

namespace acst::mpm {

inline constexpr const char* sweep_kept_folder = "kept";

// A CSV text thinned to at most `rows` data rows spread evenly over it, its first and last row
// among them and, where `peak_column` names a column, the row of that column's largest value;
// comment lines and the header are kept, and every kept row is the original text.
std::string decimated_csv(const std::string& text, std::size_t rows, const std::string& peak_column = "");

// A map's particle values (a CSV x_m,y_m,value) averaged over square cells of `cell` m whose
// edges start at (x0, y0), over [x0, x1] x [y0, y1]: one row x_m,y_m,value,particles per cell
// that holds a particle, at the cell's centre, values to 4 significant digits.
std::string rastered_map(const std::string& text, double cell, double x0, double x1, double y0, double y1);

// Writes SWEEP/kept/CASE/ for a case whose folder holds a run: its record (sweep_case.json, the
// fingerprint and the row) and what `keep` names, built in a hidden folder and put in place whole
// (common::publish_folder), so that a stop at any moment leaves the earlier kept folder or the
// new one, never a part. Returns what could not be kept (a map the case did not write, a file
// that cannot be read), as warnings; throws std::runtime_error when the folder cannot be written.
std::vector<std::string> keep_case_results(const KeepSpec& keep, const SweepCase& c, const std::string& sweep_dir);

// The folder of a case's kept results.
std::string kept_case_folder(const std::string& sweep_dir, const std::string& name);

}  // namespace acst::mpm
