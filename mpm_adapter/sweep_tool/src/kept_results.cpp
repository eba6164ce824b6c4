#include "acst_sweep/kept_results.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <sstream>
#include <system_error>

#include "acst_common/csv_table.hpp"
#include "acst_common/files.hpp"
#include "acst_common/result_folder.hpp"
#include "acst_sweep/sweep_case.hpp"

namespace acst::mpm {
namespace fs = std::filesystem;

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

double number_in(const std::vector<std::string>& cells, std::size_t k) {
  if (k >= cells.size()) return std::numeric_limits<double>::quiet_NaN();
  double v = std::numeric_limits<double>::quiet_NaN();
  const char* b = cells[k].data();
  std::from_chars(b, b + cells[k].size(), v);
  return v;
}

void put(std::string& out, double v, int digits) {
  char buf[40];
  const auto r = std::to_chars(buf, buf + sizeof buf, v + 0.0, std::chars_format::general, digits);
  out.append(buf, r.ptr);
}

}  // namespace

std::string decimated_csv(const std::string& text, std::size_t rows, const std::string& peak_column) {
  const std::vector<std::string> lines = lines_of(text);
  std::string out;
  std::vector<std::size_t> data;  // indices of the data rows
  std::vector<std::string> header;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].empty() || lines[i][0] == '#' || header.empty()) {
      if (!lines[i].empty() && lines[i][0] != '#') header = common::csv_cells(lines[i]);
      out += lines[i] + "\n";
      continue;
    }
    data.push_back(i);
  }
  std::vector<bool> kept(data.size(), data.size() <= rows);
  if (data.size() > rows && rows >= 2)
    for (std::size_t k = 0; k < rows; ++k)
      kept[static_cast<std::size_t>(std::llround(double(k) * double(data.size() - 1) / double(rows - 1)))] = true;
  const auto column = std::find(header.begin(), header.end(), peak_column);
  if (!peak_column.empty() && column != header.end() && !data.empty()) {
    const std::size_t c = static_cast<std::size_t>(column - header.begin());
    std::size_t best = 0;
    double largest = -std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < data.size(); ++k) {
      const double v = number_in(common::csv_cells(lines[data[k]]), c);
      if (v > largest) largest = v, best = k;
    }
    kept[best] = true;
  }
  for (std::size_t k = 0; k < data.size(); ++k)
    if (kept[k]) out += lines[data[k]] + "\n";
  return out;
}

std::string rastered_map(const std::string& text, double cell, double x0, double x1, double y0, double y1) {
  const long nx = std::max(1L, std::lround(std::ceil((x1 - x0) / cell)));
  const long ny = std::max(1L, std::lround(std::ceil((y1 - y0) / cell)));
  std::map<std::pair<long, long>, std::pair<double, long>> sums;  // (j, i) -> (sum, count): rows by height
  for (const std::vector<double>& c : common::parse_csv_table(text).rows) {
    if (c.size() < 3) continue;
    const double x = c[0], y = c[1], v = c[2];
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(v) || x < x0 || x > x1 || y < y0 || y > y1) continue;
    const long i = std::min(nx - 1, static_cast<long>(std::floor((x - x0) / cell)));
    const long j = std::min(ny - 1, static_cast<long>(std::floor((y - y0) / cell)));
    auto& s = sums[{j, i}];
    s.first += v, ++s.second;
  }
  std::string out = "x_m,y_m,value,particles\n";
  for (const auto& [ji, s] : sums) {
    put(out, x0 + (double(ji.second) + 0.5) * cell, 6), out += ',';
    put(out, y0 + (double(ji.first) + 0.5) * cell, 6), out += ',';
    put(out, s.first / double(s.second), 4), out += ',' + std::to_string(s.second) + "\n";
  }
  return out;
}

std::string kept_case_folder(const std::string& sweep_dir, const std::string& name) {
  return (fs::path(sweep_dir) / sweep_kept_folder / name).string();
}

std::vector<std::string> keep_case_results(const KeepSpec& keep, const SweepCase& c, const std::string& sweep_dir) {
  std::vector<std::string> warnings;
  const fs::path from = case_folder(sweep_dir, c.name);
  if (!fs::is_regular_file(from / sweep_case_record)) return warnings;
  const fs::path kept = kept_case_folder(sweep_dir, c.name);
  const fs::path to = fs::path(sweep_dir) / sweep_kept_folder / ("." + c.name + ".partial");
  fs::remove_all(to);
  fs::create_directories(to);
  const auto copy = [&](const std::string& name, const auto& transform) {
    try {
      const std::string text = common::read_input_file((from / name).string());
      common::write_file_atomically((to / name).string(), transform(text));
    } catch (const std::exception& e) {
      warnings.push_back("case '" + c.name + "': cannot keep " + name + ": " + e.what());
    }
  };
  const auto as_is = [](const std::string& t) { return t; };
  const auto thinned = [&](const std::string& t) { return decimated_csv(t, keep.rows); };
  copy(sweep_case_record, as_is);
  if (fs::exists(from / "summary.json")) copy("summary.json", as_is);
  for (const char* record : {"load_settlement.csv", "load_settlement.failed.csv"})
    if (fs::exists(from / record)) copy(record, [&](const std::string& t) { return decimated_csv(t, keep.rows, "q_kPa"); });
  for (const ParticleTrack& p : c.scene.output.particle_histories)
    if (fs::exists(from / ("particle_" + p.name + ".csv"))) copy("particle_" + p.name + ".csv", thinned);
  const auto publish = [&] {
    const std::string left = common::publish_folder(to.string(), kept.string());
    if (!left.empty()) warnings.push_back("case '" + c.name + "': " + left);
    return warnings;
  };
  if (keep.maps.empty()) return publish();
  if (!c.scene.footing) {
    warnings.push_back("case '" + c.name + "': no footing to centre its maps on; none kept");
    return publish();
  }
  double top = -std::numeric_limits<double>::infinity();
  for (const BodySpec& b : c.scene.bodies) top = std::max(top, b.y_max);
  const double B = c.scene.footing->width, half = 0.5 * keep.map_width_over_B * B;
  const double x0 = c.scene.footing->centre_x - half, y0 = top - keep.map_depth_over_B * B;
  for (const std::string& map : keep.maps) {
    if (!fs::exists(from / (map + ".csv"))) {
      warnings.push_back("case '" + c.name + "': it wrote no map " + map + ".csv (see its scene's output)");
      continue;
    }
    copy(map + ".csv", [&](const std::string& t) {
      return rastered_map(t, keep.map_cell_over_B * B, x0, x0 + 2.0 * half, y0, top + 0.25 * B);
    });
  }
  return publish();
}

}  // namespace acst::mpm
