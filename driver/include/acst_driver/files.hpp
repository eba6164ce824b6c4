#pragma once
// Output files that are never left half written, and PNG figures through gnuplot. Shared by the
// element-test driver, the calibration and the MPM code; independent of the material.
#include <string>

namespace acst::driver {

// Writes `text` to `path` through a temporary file in the same folder and a rename; throws
// std::runtime_error naming the file.
void write_file_atomically(const std::string& path, const std::string& text);

// Whether gnuplot is on PATH (looked up once), and a string quoted for the POSIX shell.
bool gnuplot_available();
std::string shell_quoted(const std::string& s);

// A string quoted for gnuplot (single quotes).
std::string gp_quoted(const std::string& s);

// Keeps `script` at gp_path and runs it with the gnuplot variable `png` set to a temporary name
// that is renamed to png_path on success. Returns "" on success, otherwise a warning (gnuplot
// missing or failed); never throws.
std::string run_gnuplot(const std::string& script, const std::string& gp_path, const std::string& png_path);

}  // namespace acst::driver
