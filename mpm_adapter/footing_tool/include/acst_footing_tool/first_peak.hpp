#pragma once
// The first peak of a load-settlement curve: where a dense sand footing's load first stops
// rising. Past it the path may bifurcate (soften at once, or dip and rise to a higher hump that
// a time step 10 % shorter can undo, docs/mpm.md "Loading rate"), so the largest load alone does
// not describe the curve.
#include <cstddef>
#include <optional>
#include <vector>

namespace acst::mpm {

// Loads before this settlement are the start's transient, not a peak.
inline constexpr double first_peak_from_S_over_B = 0.03;
// A first peak is the largest load within +-this of its own settlement.
inline constexpr double first_peak_window_S_over_B = 0.01;

// Index of the first point at S/B >= first_peak_from_S_over_B whose load no load within
// +-first_peak_window_S_over_B exceeds, with the curve extending a whole window past it; none if
// the load rises to the end. Only the loading branch counts: the points before S/B first
// decreases (a footing pulled back up).
inline std::optional<std::size_t> first_peak(const std::vector<double>& S_over_B, const std::vector<double>& load) {
  if (load.size() != S_over_B.size()) return std::nullopt;
  std::size_t n = S_over_B.empty() ? 0 : 1;
  while (n < S_over_B.size() && S_over_B[n] >= S_over_B[n - 1]) ++n;
  if (n == 0) return std::nullopt;
  std::size_t lo = 0;  // first point within the window of i
  for (std::size_t i = 0; i < n; ++i) {
    const double s = S_over_B[i];
    while (S_over_B[lo] < s - first_peak_window_S_over_B) ++lo;
    if (s < first_peak_from_S_over_B) continue;
    if (s + first_peak_window_S_over_B > S_over_B[n - 1]) break;
    bool highest = true;
    for (std::size_t j = lo; j < n && S_over_B[j] <= s + first_peak_window_S_over_B && highest; ++j) highest = load[j] <= load[i];
    if (highest) return i;
  }
  return std::nullopt;
}

}  // namespace acst::mpm
