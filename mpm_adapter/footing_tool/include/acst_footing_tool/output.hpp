#pragma once
// Files of an MPM run, each written to a temporary name and renamed when complete: the load
// record as CSV, particle fields as VTK XML PolyData (.vtp) with a ParaView .pvd series, and PNG
// figures through gnuplot (load-settlement with lab data, contours of particle fields).
#include <string>
#include <vector>

#include "acst_footing_tool/records.hpp"
#include "acst_footing_tool/scene.hpp"
#include "acst_mpm/simulation.hpp"

namespace acst::mpm {

// Whether `name` is a file a run writes into its output folder (the list in docs/mpm.md), so that
// a new run may set it aside with the rest of an earlier run.
bool is_run_output_name(const std::string& name);

std::string load_csv_text(const Scene& scene, const std::vector<LoadRecord>& history);
// The history of one particle as the CSV acst_element's strain_path_csv and the replay script
// read: the test frame there is axis 1 = y (vertical), 2 = z (out of plane), 3 = x, compression
// positive, strains in percent with engineering shear. The one place that conversion is made.
std::string track_csv_text(const Scene& scene, int k, const std::vector<TrackRecord>& rows);
std::string vtp_text(const Simulation& sim);
std::string pvd_text(const std::string& stem, const std::vector<double>& times);

// Figures: return "" or a warning (gnuplot missing or failed); they never throw.
std::string write_load_figure(const Scene& scene, const std::string& dir, const std::string& csv_file);
// particle_histories.png: q, e_v, |F| and N of every followed particle against S/B.
std::string write_history_figure(const Scene& scene, const std::string& dir);
std::string write_contour_figure(const std::string& dir, const std::string& stem, const std::string& title,
                                 const std::string& label, double cell, const std::vector<double>& x,
                                 const std::vector<double>& y, const std::vector<double>& value,
                                 bool signed_unit = false);

}  // namespace acst::mpm
