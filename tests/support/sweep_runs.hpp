#pragma once
// The sweep tests' shared steps: the small footing every test sweep starts from, acst_sweep's
// command line run in-process, a file written, a JSON file read, the error a description is
// refused with, a CSV text's data rows and numbers, and a Markdown text's links.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <thread>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "acst_common/files.hpp"
#include "acst_common/input_error.hpp"
#include "acst_sweep/sweep.hpp"
#include "acst_sweep/sweep_runner.hpp"
#include "cli_capture.hpp"

namespace sweep_runs {

inline const std::string small_footing = std::string(ACST_SOURCE_DIR) + "/tests/sweeps/small_footing.json";

inline acst::test::Cli sweep(const std::vector<std::string>& args) {
  return acst::test::run_cli([](const auto& a, auto& o, auto& e) { return acst::mpm::sweep_cli(a, o, e); }, args);
}

inline std::filesystem::path write(const std::filesystem::path& file, const std::string& text) {
  acst::common::write_file_atomically(file.string(), text);
  return file;
}

inline nlohmann::json read_json(const std::filesystem::path& file) {
  return nlohmann::json::parse(acst::common::read_input_file(file.string()));
}

inline std::string parse_error(const std::string& text) {
  try {
    acst::mpm::parse_sweep(text, "");
  } catch (const acst::common::InputError& e) {
    return e.what();
  }
  return "accepted";
}

#ifdef ACST_SWEEP_EXE
// acst_sweep as a process of its own, with `args` (--quiet --no-plot --threads 1 before them),
// killed (SIGKILL) as soon as `when` exists (or after two minutes). Returns whether the kill
// found it still running.
inline bool kill_sweep_when(const std::vector<std::string>& args, const std::filesystem::path& when) {
  std::vector<std::string> all = {"acst_sweep", "--quiet", "--no-plot", "--threads", "1"};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t child = fork();
  if (child < 0) return false;
  if (child == 0) {
    execv(ACST_SWEEP_EXE, argv.data());
    _exit(127);
  }
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (!std::filesystem::exists(when) && std::chrono::steady_clock::now() < give_up)
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
  return WIFSIGNALED(status);
}
#endif

// A sweep's table rows without what differs between two runs of the same cases (time, threads,
// whether a case was resumed).
inline nlohmann::json comparable_rows(const std::filesystem::path& dir) {
  nlohmann::json rows = read_json(dir / "table.json")["cases"];
  for (nlohmann::json& r : rows)
    for (const char* k : {"wall_s", "resumed", "threads"}) r.erase(k);
  return rows;
}

// The data rows of a CSV text (comment lines and the header left out).
inline std::vector<std::string> data_rows(const std::string& text) {
  std::vector<std::string> rows;
  std::istringstream in(text);
  bool header = true;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    if (header) {
      header = false;
      continue;
    }
    rows.push_back(line);
  }
  return rows;
}

// The numbers of a CSV row.
inline std::vector<double> numbers_in(const std::string& row) {
  std::vector<double> v;
  std::istringstream in(row);
  for (std::string cell; std::getline(in, cell, ',');) v.push_back(std::stod(cell));
  return v;
}

// The targets of a Markdown text's links and images that are not URLs, without their anchors.
inline std::vector<std::string> relative_links(const std::string& markdown) {
  std::vector<std::string> out;
  const std::regex link(R"(\]\(([^)\s]+)\))");
  for (auto it = std::sregex_iterator(markdown.begin(), markdown.end(), link); it != std::sregex_iterator(); ++it) {
    const std::string target = (*it)[1].str();
    if (target.find("://") == std::string::npos && target.front() != '#') out.push_back(target.substr(0, target.find('#')));
  }
  return out;
}

}  // namespace sweep_runs
