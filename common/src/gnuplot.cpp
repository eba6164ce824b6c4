#include "acst_common/gnuplot.hpp"

#include <sys/wait.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>

#include "acst_common/files.hpp"
#include "acst_common/png_file.hpp"

namespace acst::common {

namespace {

// Of gnuplot's messages, the start goes into a warning.
constexpr std::size_t max_message_bytes = 600;

}  // namespace

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
  // gnuplot's messages come back through a pipe: a log file under a shared temporary folder has
  // a name others can guess, and a link planted there would have been followed and truncated.
  const std::string cmd = (dir.empty() ? std::string() : "cd " + shell_quoted(dir) + " && ") + "gnuplot " + args + " 2>&1";
  FILE* pipe = ::popen(cmd.c_str(), "re");
  if (!pipe) return std::string("cannot start gnuplot: ") + std::strerror(errno);
  std::string output;
  char chunk[4096];
  // Read to the end, keeping the start: gnuplot would block on a full pipe.
  for (std::size_t n; (n = std::fread(chunk, 1, sizeof chunk, pipe)) > 0;)
    output.append(chunk, std::min(n, max_message_bytes - std::min(output.size(), max_message_bytes)));
  const int status = ::pclose(pipe);
  if (status == 0) return "";
  const std::string how = status == -1          ? std::string("cannot be waited for")
                          : WIFSIGNALED(status) ? "killed by signal " + std::to_string(WTERMSIG(status))
                                                : "exit " + std::to_string(WEXITSTATUS(status));
  return "gnuplot failed (" + how + "): " + output;
}

std::string run_gnuplot(const std::string& script, const std::string& gp_path, const std::string& png_path) {
  if (!gnuplot_available()) return "gnuplot was not found on PATH: no PNG written";
  try {
    write_file_atomically(gp_path, script);
  } catch (const std::exception& e) {
    return e.what();
  }
  const std::string tmp_png = temporary_name(png_path);
  const std::string warning = run_gnuplot_command("", "-e " + shell_quoted("png=" + gp_quoted(tmp_png)) + " " + shell_quoted(gp_path));
  if (!warning.empty()) {
    std::remove(tmp_png.c_str());
    return warning;
  }
  return keep_complete_png(tmp_png, png_path);
}

}  // namespace acst::common
