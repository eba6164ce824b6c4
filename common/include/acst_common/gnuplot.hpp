#pragma once
// PNG figures through gnuplot, the one runner every tool uses.
#include <string>

namespace acst::common {

// Whether gnuplot is on PATH (looked up once).
bool gnuplot_available();

// A string quoted for the POSIX shell.
std::string shell_quoted(const std::string& s);
// The one way text reaches a gnuplot script (titles, labels, file names): a gnuplot string
// literal that reads back as exactly `s` and can neither end early nor run a command, whatever
// `s` holds (quotes, backslashes, line breaks, backquotes, '@').
std::string gp_quoted(const std::string& s);

// Runs `gnuplot ARGS` (arguments already quoted for the shell) inside folder `dir` ("" = the
// current one), its output read through a pipe (no file of ours anywhere). Returns "" on
// success, otherwise a warning with the start of gnuplot's output; never throws. A figure the
// script writes is not checked here: keep_complete_png (png_file.hpp) does that.
std::string run_gnuplot_command(const std::string& dir, const std::string& args);

// Keeps `script` at gp_path and runs it with the gnuplot variable `png` set to a temporary name
// that is renamed to png_path when gnuplot succeeded and the file is a whole PNG. Returns "" on
// success, otherwise a warning (gnuplot missing or failed, the figure cut short: an earlier
// png_path is then kept as it was); never throws.
std::string run_gnuplot(const std::string& script, const std::string& gp_path, const std::string& png_path);

}  // namespace acst::common
