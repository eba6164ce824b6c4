#include <exception>
#include <filesystem>
#include <ostream>

#include "acst_common/cli.hpp"
#include "acst_common/gnuplot.hpp"
#include "acst_common/input_error.hpp"
#include "acst_sweep/sweep_budget.hpp"
#include "acst_sweep/sweep_runner.hpp"

namespace acst::mpm {

namespace {

const char* const usage =
    "usage: acst_sweep [--help] [--quiet] [--no-plot] [--output DIR] [--threads N] [--retry-failed] [--list] [--replot] [--report FILE]\n"
    "                  [--set '{\"/POINTER\": VALUE, ...}'] [--budget MINUTES] [--shard K/N] [--only NAME[,NAME...]] SWEEP.json\n"
    "       acst_sweep --gather DIR [DIR...] --output DIR SWEEP.json\n"
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
    "  --budget MINUTES  start no case not expected to end within MINUTES (from the rate of the cases\n"
    "                    run whole in DIR); near the end, checkpoint the running ones, write the table\n"
    "                    and report, and exit 75: run the same command again to go on\n"
    "  --shard K/N       run shard K of N: the cases split longest first, the same for one description\n"
    "  --only NAMES      run only these cases (comma-separated names or shell patterns: 'V*')\n"
    "  --gather DIR...   run nothing: merge the kept results of these folders of the sweep (shards run\n"
    "                    apart) into --output, with one table, report and figures\n"
    "  --quiet           no progress lines\n"
    "  --no-plot         no PNG figures\n"
    "Run it again to go on: finished cases are kept, an interrupted case resumes from its checkpoint.\n"
    "Writes DIR/cases/NAME (acst_mpm's files and sweep_case.json, each folder published whole),\n"
    "DIR/table.csv, table.md, table.json (one row per case), DIR/report.md (the description's\n"
    "findings judged on the table), DIR/figures/GROUP.png and the panel figures, and DIR/kept/NAME\n"
    "(what gather/keep names).\n"
    "Exit status: 0 every case done, 1 a case failed (the others ran), 2 bad input, 75 the budget\n"
    "ended with cases waiting.\n";

}  // namespace

int sweep_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err, CaseDistributor* where,
              int default_threads) {
  common::CliSpec spec("acst_sweep", "sweep description");
  spec.threads = true;
  spec.many_inputs = true;  // --gather's folders before the description
  spec.flag_options = {"--retry-failed", "--list", "--replot", "--gather"};
  spec.value_options = {"--set", "--report", "--budget", "--shard", "--only"};
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
  SweepRunOptions opt;
  std::vector<std::string> gathered;
  if (early < 0) {
    try {
      const bool gather = cli.flags.count("--gather") > 0;
      if (!gather && cli.inputs.size() != 1)
        throw common::InputError("one sweep description expected, " + std::to_string(cli.inputs.size()) +
                                 " inputs given (several folders go with --gather)");
      if (gather && cli.inputs.size() < 2)
        throw common::InputError("--gather: expected the folders to gather, then the sweep description");
      if (gather && cli.output.empty()) throw common::InputError("--gather: --output DIR names the folder to gather into");
      for (const char* flag : {"--budget", "--shard", "--only", "--replot", "--retry-failed", "--list"})
        if (gather && (cli.values.count(flag) || cli.flags.count(flag)))
          throw common::InputError(std::string("--gather runs nothing: ") + flag + " does not go with it");
      gathered.assign(cli.inputs.begin(), cli.inputs.end() - 1);
      if (cli.values.count("--budget")) opt.budget_minutes = parse_budget_minutes(cli.values.at("--budget"));
      if (cli.values.count("--shard")) opt.shard = parse_shard(cli.values.at("--shard"));
      if (cli.values.count("--only")) opt.only = parse_only(cli.values.at("--only"));
      sweep = read_sweep(cli.inputs.back(), cli.values.count("--set") ? cli.values.at("--set") : "");
      require_only_names_cases(sweep, opt.only);
    } catch (const std::exception& x) {
      problem = x.what();
      early = common::exit_bad_input;
    }
  }
  if (!dist.all(early < 0)) {
    if (!problem.empty()) e << "acst_sweep: " << problem << "\n";
    return early < 0 ? common::exit_bad_input : early;
  }
  if (cli.flags.count("--list")) {  // with --shard and --only, the cases they select
    std::vector<bool> chosen(sweep.cases.size(), true);
    try {
      std::vector<std::size_t> every(sweep.cases.size());
      for (std::size_t i = 0; i < every.size(); ++i) every[i] = i;
      if (opt.shard.n > 1 || !opt.only.empty())
        chosen = selected_cases(sweep, opt.shard.n > 1 ? expected_case_work(sweep, every) : std::vector<double>(every.size(), 0.0),
                                opt.shard, opt.only);
    } catch (const std::exception& x) {
      e << "acst_sweep: " << x.what() << "\n";
      return common::exit_bad_input;
    }
    for (std::size_t i = 0; i < sweep.cases.size(); ++i) {
      if (!chosen[i]) continue;
      const SweepCase& c = sweep.cases[i];
      o << c.name << "  group";
      for (const std::string& g : c.groups) o << " " << g;
      o << "  from " << c.origin << "\n";
    }
    return common::exit_done;
  }
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
    if (cli.flags.count("--gather")) return dist.coordinator() ? gather_sweeps(sweep, gathered, opt, o, e) : common::exit_done;
    return run_sweep(sweep, opt, dist, o, e);
  } catch (const std::exception& x) {
    e << "acst_sweep: " << x.what() << "\n";
    return common::exit_failed;
  }
}

}  // namespace acst::mpm
