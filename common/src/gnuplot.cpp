#include "acst_common/gnuplot.hpp"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>

#include "acst_common/files.hpp"

namespace acst::common {

std::string shell_quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string gp_quoted(const std::string& s) {
  // Double quotes, because only they have escapes: a line break must not end the string (the
  // next line would be a command), so it and every other control character goes in as an octal
  // escape, which keeps file names exact. gnuplot runs `...` inside double quotes as a shell
  // command before it reads the string: the backquote goes in as \140, seen only after that.
  std::string q = "\"";
  for (const char ch : s) {
    const auto c = static_cast<unsigned char>(ch);
    if (c == '"' || c == '\\') {
      q += '\\';
      q += ch;
    } else if (c < 0x20 || c == 0x7f || c == '`') {
      char oct[8];
      std::snprintf(oct, sizeof oct, "\\%03o", c);
      q += oct;
    } else {
      q += ch;
    }
  }
  return q + "\"";
}

bool gnuplot_available() {
  static const bool found = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  return found;
}

std::string run_gnuplot_command(const std::string& dir, const std::string& args) {
  if (!gnuplot_available()) return "gnuplot was not found on PATH: no PNG written";
  static std::atomic<unsigned> runs{0};  // one log per call, also from several threads
  const std::string log =
      temporary_name((std::filesystem::temp_directory_path() / "acst_gnuplot.log").string()) + "_" + std::to_string(runs++);
  const std::string cmd = (dir.empty() ? std::string() : "cd " + shell_quoted(dir) + " && ") + "gnuplot " + args +
                          " >" + shell_quoted(log) + " 2>&1";
  const int rc = std::system(cmd.c_str());
  std::string output;
  try {
    output = read_input_file(log);
  } catch (const std::exception&) {  // no log: the exit status still says what happened
  }
  std::remove(log.c_str());
  return rc == 0 ? "" : "gnuplot failed (exit " + std::to_string(rc) + "): " + output.substr(0, 600);
}

std::string run_gnuplot(const std::string& script, const std::string& gp_path, const std::string& png_path) {
  if (!gnuplot_available()) return "gnuplot was not found on PATH: no PNG written";
  try {
    write_file_atomically(gp_path, script);
  } catch (const std::exception& e) {
    return e.what();
  }
  const std::string tmp_png = temporary_name(png_path);
  std::string warning = run_gnuplot_command("", "-e " + shell_quoted("png=" + gp_quoted(tmp_png)) + " " + shell_quoted(gp_path));
  if (!warning.empty()) {
    std::remove(tmp_png.c_str());
    return warning;
  }
  std::error_code ec;
  std::filesystem::rename(tmp_png, png_path, ec);
  return ec ? "cannot rename the PNG: " + ec.message() : "";
}

}  // namespace acst::common
