#pragma once
// Writing an element test's results: the CSV table (geotechnical convention, stated in its
// header), the PNG figure through gnuplot, and the reproducer JSON of a failed run. Every file
// is written to a temporary name in its directory and renamed when complete, so an error never
// leaves a half-written file over a good one.
#include <string>

#include "acst_common/files.hpp"
#include "acst_common/gnuplot.hpp"
#include "acst_driver/runner.hpp"
#include "acst_driver/scene.hpp"

namespace acst::driver {

// The CSV text of a run (header comments, column names, one line per record).
std::string csv_text(const Scene& scene, const RunResult& result);

// Writes the 2x2 figure (q and e_v against axial strain, e against log p, q against p, lab
// curves as points) to png_path with gnuplot, keeping the script at gp_path. Returns "" on
// success, otherwise a warning (gnuplot missing or failed); the CSV is never affected.
std::string write_figure(const Scene& scene, const RunResult& result, const std::string& csv_path,
                         const std::string& png_path, const std::string& gp_path);

}  // namespace acst::driver
