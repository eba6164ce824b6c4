#include "acst_driver/files.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace acst::driver {
namespace {

std::string temporary_name(const std::string& path) {
  const std::filesystem::path p(path);
  return (p.parent_path() / ("." + p.filename().string() + ".tmp" + std::to_string(::getpid()))).string();
}

}  // namespace

void write_file_atomically(const std::string& path, const std::string& text) {
  const std::string tmp = temporary_name(path);
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw std::runtime_error("cannot write '" + tmp + "'");
    f.write(text.data(), static_cast<std::streamsize>(text.size()));
    f.close();
    if (!f) {
      std::remove(tmp.c_str());
      throw std::runtime_error("writing '" + tmp + "' failed");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::remove(tmp.c_str());
    throw std::runtime_error("cannot rename '" + tmp + "' to '" + path + "': " + ec.message());
  }
}

std::string shell_quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

std::string gp_quoted(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("''") : std::string(1, c);
  return q + "'";
}

bool gnuplot_available() {
  static const bool found = std::system("command -v gnuplot >/dev/null 2>&1") == 0;
  return found;
}

std::string run_gnuplot(const std::string& script, const std::string& gp_path, const std::string& png_path) {
  if (!gnuplot_available()) return "gnuplot was not found on PATH: no PNG written";
  try {
    write_file_atomically(gp_path, script);
  } catch (const std::exception& e) {
    return e.what();
  }
  const std::string tmp_png = temporary_name(png_path);
  const std::string log = tmp_png + ".log";
  const std::string cmd = "gnuplot -e " + shell_quoted("png=" + gp_quoted(tmp_png)) + " " + shell_quoted(gp_path) +
                          " >" + shell_quoted(log) + " 2>&1";
  const int rc = std::system(cmd.c_str());
  std::string warning;
  if (rc != 0) {
    std::ifstream in(log);
    std::stringstream ss;
    ss << in.rdbuf();
    warning = "gnuplot failed (exit " + std::to_string(rc) + "): " + ss.str().substr(0, 600);
    std::remove(tmp_png.c_str());
  } else {
    std::error_code ec;
    std::filesystem::rename(tmp_png, png_path, ec);
    if (ec) warning = "cannot rename the PNG: " + ec.message();
  }
  std::remove(log.c_str());
  return warning;
}

}  // namespace acst::driver
