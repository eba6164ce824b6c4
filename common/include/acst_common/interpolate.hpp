#pragma once
// Linear interpolation of sampled curves.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace acst::common {

// Linear interpolation of y(x) at `at`, x increasing (repeats allowed: the first is used); NaN
// outside [x.front(), x.back()]. Binary search: the calibration calls it per residual.
inline double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  if (x.empty() || !(at >= x.front() && at <= x.back())) return NAN;
  const auto it = std::lower_bound(x.begin(), x.end(), at);
  const std::size_t i = static_cast<std::size_t>(it - x.begin());
  if (x[i] == at || i == 0) return y[i];
  return y[i - 1] + (y[i] - y[i - 1]) * (at - x[i - 1]) / (x[i] - x[i - 1]);
}

// The samples where both x and y are numbers (lab tables leave gaps as NaN), for interpolate().
inline std::pair<std::vector<double>, std::vector<double>> finite_samples(const std::vector<double>& x,
                                                                          const std::vector<double>& y) {
  std::pair<std::vector<double>, std::vector<double>> out;
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i)
    if (!std::isnan(x[i]) && !std::isnan(y[i])) {
      out.first.push_back(x[i]);
      out.second.push_back(y[i]);
    }
  return out;
}

}  // namespace acst::common
