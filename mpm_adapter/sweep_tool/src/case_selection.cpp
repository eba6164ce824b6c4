#include "acst_sweep/case_selection.hpp"

#include <fnmatch.h>

#include <algorithm>
#include <charconv>
#include <numeric>

#include "acst_common/input_error.hpp"
#include "acst_footing_tool/build_simulation.hpp"
#include "acst_footing_tool/scene_size.hpp"

namespace acst::mpm {

namespace {

constexpr std::size_t max_shards = 10000;

bool whole_number(const std::string& text, std::size_t& value) {
  if (text.empty() || text.size() > 6 || text.find_first_not_of("0123456789") != std::string::npos) return false;
  const auto r = std::from_chars(text.data(), text.data() + text.size(), value);
  return r.ec == std::errc() && r.ptr == text.data() + text.size();
}

}  // namespace

std::vector<double> expected_case_work(const SweepSpec& sweep, const std::vector<std::size_t>& which) {
  std::string problems;
  std::vector<double> work(sweep.cases.size(), 0.0);
  for (std::size_t i : which) {
    try {
      const Simulation sim = build_simulation(sweep.cases[i].scene);
      work[i] = expected_particle_steps(sweep.cases[i].scene, sim.stable_time_step());
    } catch (const std::exception& e) {
      problems += "\n  case '" + sweep.cases[i].name + "' (" + sweep.cases[i].origin + "): " + e.what();
    }
  }
  if (!problems.empty()) throw common::InputError("cases that cannot start:" + problems);
  return work;
}

Shard parse_shard(const std::string& text) {
  const std::size_t slash = text.find('/');
  Shard s;
  if (slash == std::string::npos || !whole_number(text.substr(0, slash), s.k) ||
      !whole_number(text.substr(slash + 1), s.n) || s.n < 1 || s.n > max_shards || s.k < 1 || s.k > s.n)
    throw common::InputError("--shard '" + text + "': expected K/N with whole numbers 1 <= K <= N <= " +
                             std::to_string(max_shards) + " (shard K of N, e.g. 1/2)");
  return s;
}

std::vector<std::string> parse_only(const std::string& text) {
  std::vector<std::string> names;
  std::size_t from = 0;
  for (;;) {
    const std::size_t comma = text.find(',', from);
    const std::string name = text.substr(from, comma == std::string::npos ? std::string::npos : comma - from);
    if (name.empty())
      throw common::InputError("--only '" + text + "': an empty name; expected NAME[,NAME...] (case names or shell patterns)");
    names.push_back(name);
    if (comma == std::string::npos) return names;
    from = comma + 1;
  }
}

std::vector<std::size_t> shard_of_cases(const std::vector<double>& work, std::size_t shards) {
  std::vector<std::size_t> order(work.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return work[a] > work[b]; });
  std::vector<double> load(shards, 0.0);
  std::vector<std::size_t> shard(work.size(), 0);
  for (std::size_t i : order) {
    const std::size_t least = static_cast<std::size_t>(std::min_element(load.begin(), load.end()) - load.begin());
    shard[i] = least;
    load[least] += work[i];
  }
  return shard;
}

namespace {

bool matches(const std::string& pattern, const std::string& name) { return fnmatch(pattern.c_str(), name.c_str(), 0) == 0; }

}  // namespace

void require_only_names_cases(const SweepSpec& sweep, const std::vector<std::string>& only) {
  for (const std::string& pattern : only)
    if (std::none_of(sweep.cases.begin(), sweep.cases.end(), [&](const SweepCase& c) { return matches(pattern, c.name); }))
      throw common::InputError("--only: '" + pattern + "' names no case of sweep '" + sweep.name +
                               "' (acst_sweep --list shows them)");
}

std::vector<bool> selected_cases(const SweepSpec& sweep, const std::vector<double>& work, const Shard& shard,
                                 const std::vector<std::string>& only) {
  const std::vector<std::size_t> of = shard_of_cases(work, shard.n);
  std::vector<bool> chosen(sweep.cases.size(), false);
  for (std::size_t i = 0; i < sweep.cases.size(); ++i) {
    const bool named = only.empty() || std::any_of(only.begin(), only.end(), [&](const std::string& p) {
                         return matches(p, sweep.cases[i].name);
                       });
    chosen[i] = named && of[i] == shard.k - 1;
  }
  return chosen;
}

}  // namespace acst::mpm
