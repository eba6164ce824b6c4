#pragma once
// Which of a sweep's cases one invocation runs (docs/sweeps.md, "Pieces, shards and budgets"):
// --only NAME[,NAME...] (names or shell patterns) and --shard K/N, a split of the cases that
// depends on the description alone.
#include <cstddef>
#include <string>
#include <vector>

#include "acst_sweep/sweep.hpp"

namespace acst::mpm {

struct Shard {
  std::size_t k = 1, n = 1;  // shard k of n, 1 <= k <= n
};

// Each listed case's expected work in particle-steps at its first time step (0 for the others).
// What the reader cannot see in a scene alone (a followed particle outside the soil, a material
// that refuses its start) shows when its simulation is built: each case is built once here, so
// that such a case stops the sweep before anything runs, not hours into it (InputError naming
// every such case).
std::vector<double> expected_case_work(const SweepSpec& sweep, const std::vector<std::size_t>& which);

// "K/N" with whole numbers 1 <= K <= N <= 10000; InputError naming --shard and the text otherwise.
Shard parse_shard(const std::string& text);

// The comma-separated names or shell patterns of --only (fnmatch: *, ?, [...]); InputError for an
// empty list or an empty entry.
std::vector<std::string> parse_only(const std::string& text);

// The shard of each case: the cases taken longest first by `work` (ties in the sweep's order),
// each given to the shard with the least work so far (ties to the lowest). The same description
// and build give the same split; the shards' work differs by at most the longest case.
std::vector<std::size_t> shard_of_cases(const std::vector<double>& work, std::size_t shards);

// InputError when a pattern of `only` matches no case of the sweep, naming it and the flag.
void require_only_names_cases(const SweepSpec& sweep, const std::vector<std::string>& only);

// Whether each case is this invocation's: in `shard` and matching one of `only` (empty: all).
std::vector<bool> selected_cases(const SweepSpec& sweep, const std::vector<double>& work, const Shard& shard,
                                 const std::vector<std::string>& only);

}  // namespace acst::mpm
