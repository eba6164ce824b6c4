#include "acst_driver/strain_path.hpp"

#include <algorithm>
#include <cmath>

#include "acst/scene_units.hpp"
#include "acst_common/json_fields.hpp"
#include "acst_driver/presets.hpp"

namespace acst::driver {

namespace f = common::fields;
using units::strain_from_scene;

std::vector<Segment> strain_path_segments(const LabCurve& table, const std::string& file, const std::string& path,
                                          int increments_per_row) {
  static const char* names[] = {"eps_11_pct", "eps_22_pct", "eps_33_pct", "gamma_12_pct", "gamma_13_pct", "gamma_23_pct"};
  std::vector<std::vector<double>> cols(6);
  std::size_t rows = 0;
  for (int k = 0; k < 6; ++k) {
    cols[k] = table.column(names[k]);
    if (cols[k].empty() && k < 3)
      f::fail(path, file + ": column " + names[k] + " is missing (need eps_11_pct, eps_22_pct, eps_33_pct; gamma_12_pct, gamma_13_pct, gamma_23_pct optional)");
    rows = std::max(rows, cols[k].size());
  }
  for (const auto& name : table.columns) {
    bool known = false;
    for (const char* n : names) known = known || name == n;
    if (!known) f::fail(path, file + ": unknown column '" + name + "' (allowed: eps_11_pct ... gamma_23_pct)");
  }
  if (rows == 0) f::fail(path, file + ": the strain path has no rows");
  std::vector<Segment> segments;
  Sym previous = Sym::Zero();
  for (std::size_t r = 0; r < rows; ++r) {
    Sym eps = Sym::Zero();
    for (int k = 0; k < 6; ++k) {
      if (cols[k].empty()) continue;
      if (std::isnan(cols[k][r]))
        f::fail(path, file + ": row " + std::to_string(r + 1) + ", column " + names[k] + " is empty");
      eps[k] = strain_from_scene(cols[k][r], k);
    }
    segments.push_back({strain_rows(eps - previous), increments_per_row});
    previous = eps;
  }
  return segments;
}

}  // namespace acst::driver
