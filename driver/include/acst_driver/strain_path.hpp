#pragma once
// The steps of a strain_path_csv step (docs/element-tests.md): one segment per row of the file's
// table, its strains (eps_11_pct ... gamma_23_pct) since the start of the step.
#include <string>
#include <vector>

#include "acst_driver/lab_data.hpp"
#include "acst_driver/scene.hpp"

namespace acst::driver {

// The segments of `table`, read from `file`; InputError at `path` (the step's JSON path), naming
// the file and the row or column that is wrong.
std::vector<Segment> strain_path_segments(const LabCurve& table, const std::string& file, const std::string& path,
                                          int increments_per_row);

}  // namespace acst::driver
