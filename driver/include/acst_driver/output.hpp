#pragma once
// Writing an element test's results: the CSV table (geotechnical convention, stated in its
// header), the PNG figure through gnuplot, and the reproducer JSON of a failed run. Every file
// is written to a temporary name in its directory and renamed when complete, so an error never
// leaves a half-written file over a good one.
#include <cmath>
#include <cstdint>
#include <string>

#include "acst_common/atomic_file.hpp"
#include "acst_common/files.hpp"
#include "acst_common/gnuplot.hpp"
#include "acst_driver/runner.hpp"
#include "acst_driver/scene.hpp"

namespace acst::driver {

// The CSV text of a run held in memory: header comments, the failure line of a failed run,
// column names, one line per record.
std::string csv_text(const ElementScene& scene, const RunResult& result);
// Its parts, for writing the rows as they come.
std::string csv_comments(const ElementScene& scene);
std::string csv_failure_line(const std::string& message);
const std::string& csv_column_names();
void append_csv_row(std::string& out, const Record& r);

// The CSV of a run written row by row while it runs (memory does not grow with the rows), to a
// temporary file that becomes NAME.csv when the run succeeds, or NAME.failed.csv, with the
// failure line in its header, when it fails; the other name is left untouched either way.
class CsvStream {
 public:
  CsvStream(const ElementScene& scene, const std::string& csv_path);  // throws std::runtime_error
  void add(const Record& r);
  void publish();                                                          // as csv_path
  void publish_failed(const std::string& failed_path, const std::string& message);

 private:
  common::AtomicFileWriter file_;
  std::uint64_t comments_end_ = 0;  // where a failure line goes
  std::string row_;
};

// The ranges of p, q, e_v and e over a run's rows, for the figure's axes.
struct PlotRanges {
  double p_lo = INFINITY, p_hi = -INFINITY, q_lo = 0.0, q_hi = 0.0;
  double ev_lo = 0.0, ev_hi = 0.0, e_lo = INFINITY, e_hi = -INFINITY;
  void add(const Record& r);
};

// Writes the 2x2 figure (q and e_v against axial strain, e against log p, q against p, lab
// curves as points) to png_path with gnuplot, keeping the script at gp_path; gnuplot reads the
// run's rows from the CSV, `ranges` sets the axes. Returns "" on success, otherwise a warning
// (gnuplot missing or failed); the CSV is never affected.
std::string write_figure(const ElementScene& scene, const PlotRanges& ranges, const std::string& csv_path,
                         const std::string& png_path, const std::string& gp_path);

}  // namespace acst::driver
