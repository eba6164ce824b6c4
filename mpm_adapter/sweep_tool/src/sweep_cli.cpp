#include <exception>
#include <filesystem>
#include <ostream>

#include "acst_common/cli.hpp"
#include "acst_common/gnuplot.hpp"
#include "acst_common/input_error.hpp"
#include "acst_sweep/sweep_runner.hpp"

namespace acst::mpm {

namespace {

const char* const usage =
    "usage: acst_sweep [--help] [--quiet] [--no-plot] [--output DIR] [--threads N] [--retry-failed] [--list] [--replot] [--report FILE]\n"
    "                  [--set '{\"/POINTER\": VALUE, ...}'] SWEEP.json\n"
    "       mpirun -n RANKS acst_sweep [options] SWEEP.json\n"
    "\n"
    "Runs the cases of a footing sweep (docs/sweeps.md): a base scene of acst_mpm and named cases,\n"
    "each the base with values replaced. Under mpirun, rank 0 hands out whole cases and gathers\n"
    "their rows, and every rank runs cases (with --threads threads each; default: the cores of its\n"
    "machine shared among the ranks on it); without mpirun the cases run in turn.\n"
    "  --output DIR      the sweep's folder (default results/sweeps/<sweep name>)\n"
    "  --threads N       OpenMP threads per case\n"
    "  --retry-failed    run the cases that failed before again (default: keep their rows)\n"
    "  --list            print the cases (name, groups, origin) and stop\n"
    "  --replot          run nothing: draw the figures and write the report again from DIR's\n"
    "                    table.json and kept results (a recorded study without its case folders)\n"
    "  --report FILE     also write the report (findings, table, figures) to FILE\n"
    "  --set JSON        values put into every case after the description's own \"set\" (a JSON\n"
    "                    object of JSON pointers and values), e.g. '{\"/grid/cell_size\": 0.18}'\n"
    "                    for a coarse preview in another --output folder\n"
    "  --quiet           no progress lines\n"
    "  --no-plot         no PNG figures\n"
    "Run it again to go on: finished cases are kept, an interrupted case resumes from its checkpoint.\n"
    "Writes DIR/cases/NAME (acst_mpm's files and sweep_case.json, each folder published whole),\n"
    "DIR/table.csv, table.md, table.json (one row per case), DIR/report.md (the description's\n"
    "findings judged on the table), DIR/figures/GROUP.png and the panel figures, and DIR/kept/NAME\n"
    "(what gather/keep names).\n"
    "Exit status: 0 every case done, 1 a case failed (the others ran), 2 bad input.\n";

}  // namespace

int sweep_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, CaseDistributor* where,
              int default_threads) {
  common::CliSpec spec("acst_sweep", "sweep description");
  spec.threads = true;
  spec.flag_options = {"--retry-failed", "--list", "--replot"};
  spec.value_options = {"--set", "--report"};
  InTurn in_turn;
  CaseDistributor& dist = where ? *where : in_turn;
  // Only the coordinator speaks; every rank reads the same command line and description.
  std::ostream null_stream(nullptr);
  std::ostream& o = dist.coordinator() ? out : null_stream;
  std::ostream& e = dist.coordinator() ? err : null_stream;
  common::CliArgs cli;
  int early = common::parse_command_line(spec, args, usage, o, e, cli);
  SweepSpec sweep;
  std::string problem;
  if (early < 0) {
    try {
      sweep = read_sweep(cli.inputs.front(), cli.values.count("--set") ? cli.values.at("--set") : "");
    } catch (const std::exception& x) {
      problem = x.what();
      early = common::exit_bad_input;
    }
  }
  if (!dist.all(early < 0)) {
    if (!problem.empty()) e << "acst_sweep: " << problem << "\n";
    return early < 0 ? common::exit_bad_input : early;
  }
  if (cli.flags.count("--list")) {
    for (const SweepCase& c : sweep.cases) {
      o << c.name << "  group";
      for (const std::string& g : c.groups) o << " " << g;
      o << "  from " << c.origin << "\n";
    }
    return common::exit_done;
  }
  SweepRunOptions opt;
  opt.output_dir = cli.output.empty() ? "results/sweeps/" + sweep.name : cli.output;
  opt.threads = cli.threads > 0 ? cli.threads : default_threads;
  opt.plot = cli.plot;
  opt.quiet = cli.quiet;
  opt.retry_failed = cli.flags.count("--retry-failed") > 0;
  if (cli.values.count("--report")) {
    opt.report = cli.values.at("--report");
    if (std::filesystem::is_directory(opt.report)) {
      e << "acst_sweep: --report " << opt.report << ": is a folder; name the markdown file to write\n";
      return common::exit_bad_input;  // the same on every rank: all read the same file system
    }
  }
  opt.command = (dist.workers() > 1 ? "mpirun -n " + std::to_string(dist.workers()) + " " : std::string()) + "acst_sweep";
  for (const std::string& a : args)
    opt.command += " " + (a.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-./=") ==
                                  std::string::npos
                              ? a
                              : common::shell_quoted(a));
  try {
    if (cli.flags.count("--replot")) return dist.coordinator() ? replot_sweep(sweep, opt, o, e) : common::exit_done;
    return run_sweep(sweep, opt, dist, o, e);
  } catch (const std::exception& x) {
    e << "acst_sweep: " << x.what() << "\n";
    return common::exit_failed;
  }
}

}  // namespace acst::mpm
