#include "acst_driver/cli.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>

#include "acst_common/cli.hpp"
#include "acst_common/duration.hpp"
#include "acst_common/files.hpp"
#include "acst_common/progress.hpp"
#include "acst_driver/output.hpp"
#include "acst_driver/runner.hpp"
#include "acst_driver/scene.hpp"
#include "acst_driver/summary.hpp"
#include "step_reader.hpp"

namespace acst::driver {

namespace {

namespace fs = std::filesystem;
using WallClock = std::chrono::steady_clock;

void usage(std::ostream& o) {
  o << "Usage: acst_element [--help] [--quiet] [--no-plot] [--output DIR] SCENE.json...\n"
       "\n"
       "Runs element tests of the ACST sand model described by JSON scenes (docs/element-tests.md)\n"
       "and writes, per scene, NAME.csv (geotechnical convention: compression positive, strains in %,\n"
       "engineering shear), NAME.png (q and e_v against axial strain, e against log p, q against p,\n"
       "with the lab curves the scene names) and NAME.gp (the gnuplot script of the figure).\n"
       "A run that fails writes NAME.failed.csv (the rows up to the failure) and NAME.reproducer.json\n"
       "(one increment that replays the failure: acst_element NAME.reproducer.json).\n"
       "\n"
       "Options:\n"
       "  --output DIR  write into DIR instead of each scene's output.directory (default results/element,\n"
       "                relative to the current directory)\n"
       "  --quiet       no progress and no summary (errors and warnings are still printed)\n"
       "  --no-plot     write the CSV only\n"
       "  --help        this text\n"
       "\n"
       "Files named inside a scene (material file, lab data, strain path) are relative to the scene file.\n"
       "Every scene is validated before any runs; an invalid scene is reported with the JSON path of the\n"
       "error and nothing is written.\n"
       "Presets:";
  for (const auto& p : preset_names()) o << ' ' << p;
  o << "\n\nExit status: 0 all scenes ran; 1 a scene failed while running; 2 bad command line or invalid scene.\n"
       "Example: acst_element data/scenes/element/*.json\n";
}

std::string fixed(double v, int decimals) {
  if (std::isnan(v)) return "-";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// The batch's progress: scene i/n, increments done, rate and time left; one line per finished
// scene when there are several.
class Progress {
 public:
  Progress(std::ostream& err, bool enabled, int scenes, long planned)
      : line_(err, enabled), scenes_(scenes), planned_(planned) {}

  void update(int index, const std::string& name, long done) {
    if (line_.on_terminal() && line_.due()) line_.show(text(index, name, done_before_ + done));
  }

  void finished(int index, const std::string& name, long increments, bool ok, double seconds) {
    done_before_ += increments;
    if (scenes_ == 1 && !line_.on_terminal()) return;
    line_.finish(text(index + 1, name, done_before_) + " (" + name + " " + (ok ? "done" : "FAILED") + " in " +
                 common::duration_text(seconds) + ")");
  }

  double elapsed() const { return line_.elapsed_s(); }

 private:
  std::string text(int index, const std::string& name, long done) const {
    const double t = elapsed();
    const double rate = t > 0 ? done / t : 0.0;
    std::string s = "[" + std::to_string(std::min(index + (index < scenes_ ? 1 : 0), scenes_)) + "/" +
                    std::to_string(scenes_) + "] ";
    if (index < scenes_) s += name + " ";
    const double fraction = planned_ > 0 ? static_cast<double>(done) / planned_ : 1.0;
    char buf[160];
    std::snprintf(buf, sizeof buf, "%.0f%% of %ld increments, %.0f increments/s, %s elapsed, ", 100.0 * fraction,
                  planned_, rate, common::duration_text(t).c_str());
    return s + buf + common::ProgressLine::time_left(t, fraction);
  }

  common::ProgressLine line_;
  int scenes_;
  long planned_, done_before_ = 0;
};

struct Outcome {
  std::string name;
  bool ok = false;
  long increments = 0;
  ElementRunSummary summary;
  std::vector<LabComparison> labs;
  std::string csv;
};

void print_summary(std::ostream& out, const std::vector<Outcome>& outcomes) {
  char buf[400];
  out << "\nSummary (q/p signed, negative in extension; e_v compression positive; lab: peak sigma_1/sigma_3 over the\n"
         "lab's strain range and e_v at the lab's last e_v strain, simulation vs lab)\n";
  std::snprintf(buf, sizeof buf, "%-36s %-6s %7s %9s %9s %8s %8s   %s\n", "scene", "status", "incr", "peak q/p",
                "final q/p", "eps_a %", "e_v %", "lab comparison");
  out << buf;
  for (const Outcome& o : outcomes) {
    std::string lab;
    for (const LabComparison& c : o.labs)
      lab += (lab.empty() ? "" : "; ") + c.id + ": s1/s3 " + fixed(c.sim_peak_sr, 2) + " vs " + fixed(c.lab_peak_sr, 2) +
             ", e_v " + fixed(c.sim_ev_pct, 2) + " vs " + fixed(c.lab_ev_pct, 2) + " % at " + fixed(c.strain_pct, 1) + " %";
    std::snprintf(buf, sizeof buf, "%-36s %-6s %7ld %9s %9s %8s %8s   %s\n", o.name.c_str(), o.ok ? "ok" : "FAILED",
                  o.increments, fixed(o.summary.peak_stress_ratio, 3).c_str(), fixed(o.summary.final_stress_ratio, 3).c_str(),
                  fixed(o.summary.final_axial_strain_pct, 2).c_str(), fixed(o.summary.final_volumetric_strain_pct, 2).c_str(),
                  lab.c_str());
    out << buf;
  }
}

// Runs one scene, writing its CSV as the rows come, then its figure or its failure files; the
// outcome is not ok when the run failed or its results could not be written.
Outcome run_and_write(const ElementScene& s, int index, Progress& progress, std::ostream& err) {
  const auto t0 = WallClock::now();
  Outcome o;
  o.name = s.output.name;
  // The lab curves were read when the scene was checked; one that cannot be read now is left
  // out of the comparison, as it is out of the figure.
  std::vector<LabComparer> labs;
  for (const auto& lab : s.lab_data) {
    try {
      labs.emplace_back(read_lab_curve(lab));
    } catch (const std::exception&) {
    }
  }
  const fs::path dir(s.output.directory);
  std::optional<CsvStream> csv;
  fs::path base;
  try {
    fs::create_directories(dir);
    base = fs::absolute(dir / s.output.name);
    csv.emplace(s, base.string() + ".csv");
  } catch (const std::exception& e) {
    err << s.source << ": cannot write the results: " << e.what() << "\n";
    progress.finished(index, s.output.name, 0, false, 0.0);
    return o;
  }
  // Rows go to the CSV and the summaries as they come; none is kept.
  Summariser summary;
  PlotRanges ranges;
  const RunResult r = stream_scene(
      s,
      [&](const Record& rec) {
        csv->add(rec);
        summary.add(rec);
        ranges.add(rec);
        for (LabComparer& l : labs) l.add(rec);
      },
      [&](long done, long) { progress.update(index, s.output.name, done); });
  o.ok = r.ok;
  o.increments = r.increments;
  o.summary = summary.summary();
  try {
    if (r.ok) {
      o.csv = base.string() + ".csv";
      csv->publish();
      if (s.output.plot) {
        const std::string w = write_figure(s, ranges, o.csv, base.string() + ".png", base.string() + ".gp");
        if (!w.empty()) err << s.source << ": warning: " << w << "\n";
      }
    } else {
      err << s.source << ": run failed: " << r.message << "\n";
      csv->publish_failed(base.string() + ".failed.csv", r.message);
      if (r.reproducer) {
        common::write_file_atomically(base.string() + ".reproducer.json", r.reproducer->dump(2) + "\n");
        err << s.source << ": wrote " << base.string() << ".reproducer.json (replays the failing increment) and "
            << base.string() << ".failed.csv (the rows up to it)\n";
      }
    }
  } catch (const std::exception& e) {
    o.ok = false;
    err << s.source << ": cannot write the results: " << e.what() << "\n";
  }
  for (const LabComparer& l : labs) o.labs.push_back(l.comparison());
  progress.finished(index, s.output.name, r.increments, o.ok,
                    std::chrono::duration<double>(WallClock::now() - t0).count());
  return o;
}

}  // namespace

int element_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::ostringstream help;
  usage(help);
  common::CliSpec spec("acst_element", "scene file");
  spec.many_inputs = true;
  common::CliArgs cli;
  const int early = common::parse_command_line(spec, args, help.str(), out, err, cli);
  if (early >= 0) return early;
  const bool quiet = cli.quiet, plot = cli.plot;
  const std::string& output_dir = cli.output;
  const std::vector<std::string>& files = cli.inputs;
  // Read and validate everything first: an invalid scene means nothing is written.
  std::vector<ElementScene> scenes;
  int invalid = 0;
  for (const auto& f : files) {
    try {
      scenes.push_back(read_scene(f));
      if (!output_dir.empty()) scenes.back().output.directory = output_dir;
      if (!plot) scenes.back().output.plot = false;
    } catch (const std::exception& e) {
      err << f << ": " << e.what() << "\n";
      ++invalid;
    }
  }
  std::map<std::string, std::string> targets;
  for (const ElementScene& s : scenes) {
    const std::string target = (fs::path(s.output.directory) / s.output.name).lexically_normal().string();
    const auto [it, fresh] = targets.emplace(target, s.source);
    if (!fresh) {
      err << s.source << ": /output/name: writes to " << target << " as " << it->second
          << " does; give one of them another output name\n";
      ++invalid;
    }
  }
  if (invalid > 0) {
    err << "acst_element: " << invalid << " invalid scene" << (invalid > 1 ? "s" : "") << "; nothing was run or written\n";
    return 2;
  }
  long planned = 0;
  for (const ElementScene& s : scenes) planned += static_cast<long>(scene_size(s.blocks, 1).increments);
  Progress progress(err, !quiet, static_cast<int>(scenes.size()), planned);
  std::vector<Outcome> outcomes;
  int failed = 0;
  for (std::size_t i = 0; i < scenes.size(); ++i) {
    outcomes.push_back(run_and_write(scenes[i], static_cast<int>(i), progress, err));
    failed += outcomes.back().ok ? 0 : 1;
  }
  if (!quiet) {
    print_summary(out, outcomes);
    out << "\n" << scenes.size() - failed << " of " << scenes.size() << " scenes ran in " << common::duration_text(progress.elapsed())
        << "; results in " << (output_dir.empty() ? "each scene's output directory" : output_dir) << "\n";
  }
  return failed > 0 ? 1 : 0;
}

}  // namespace acst::driver
