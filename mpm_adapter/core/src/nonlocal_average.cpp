#include "acst_mpm/nonlocal_average.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "acst_common/parallel_for.hpp"

namespace acst::mpm {

namespace {

// The kernel's formula at s = r/l, without the reach.
double kernel_formula(NonlocalKernel kernel, double s) {
  const double g = std::exp(-s * s);
  return kernel == NonlocalKernel::gauss ? g : s * g;
}

}  // namespace

double nonlocal_weight(NonlocalKernel kernel, double r, double l) {
  const double s = r / l;
  return s < nonlocal_reach ? kernel_formula(kernel, s) : 0.0;
}

KernelTable::KernelTable(NonlocalKernel kernel) : values_(intervals + 2), scale_(intervals / nonlocal_reach) {
  for (std::size_t i = 0; i <= intervals; ++i) values_[i] = kernel_formula(kernel, i / scale_);
  values_[intervals + 1] = values_[intervals];  // read by s just under the reach, at t near 1
}

NonlocalAverage::NonlocalAverage(double length, NonlocalKernel kernel, std::vector<int> takes_part,
                                 std::optional<double> mirror_x)
    : length_(length),
      inverse_length_(1.0 / length),
      skin_(0.25 * length),
      table_(kernel),
      takes_part_(std::move(takes_part)),
      mirror_x_(mirror_x) {
  if (!(length > 0.0) || !std::isfinite(length)) throw std::invalid_argument("the internal length must be positive");
}

void NonlocalAverage::find_neighbours(const Particles& P, int threads) {
  const std::size_t n = P.n;
  if (n > UINT32_MAX) throw std::length_error("too many particles for the nonlocal lists");
  const double radius = nonlocal_reach * length_ + skin_;
  // Particles that take part, binned in squares of the radius: a neighbour lies in the 3 x 3
  // squares around a point (its own or its mirror image).
  double x_min = INFINITY, y_min = INFINITY, x_max = -INFINITY, y_max = -INFINITY;
  for (std::size_t p = 0; p < n; ++p)
    if (takes_part_[p]) {
      x_min = std::min(x_min, P.x[p]), x_max = std::max(x_max, P.x[p]);
      y_min = std::min(y_min, P.y[p]), y_max = std::max(y_max, P.y[p]);
    }
  first_.assign(n + 1, 0);
  neighbour_.clear();
  x_found_ = P.x;
  y_found_ = P.y;
  ++builds_;
  if (!(x_min <= x_max)) return;
  // Counted in double before any becomes an integer: a vanishing length must not overflow them.
  const double bins_x = std::floor((x_max - x_min) / radius) + 1.0, bins_y = std::floor((y_max - y_min) / radius) + 1.0;
  if (!(bins_x * bins_y <= 4.0 * static_cast<double>(n) + 16.0))
    throw std::length_error("the internal length (" + std::to_string(length_) +
                            " m) is too short for the soil's extent: the nonlocal bins would outnumber the particles");
  const long long bx = static_cast<long long>(bins_x), by = static_cast<long long>(bins_y);
  std::vector<std::size_t> bin_first(static_cast<std::size_t>(bx * by) + 1, 0), in_bin;
  const auto bin_of = [&](double x, double y, long long& i, long long& j) {
    i = static_cast<long long>(std::floor((x - x_min) / radius));
    j = static_cast<long long>(std::floor((y - y_min) / radius));
  };
  for (std::size_t p = 0; p < n; ++p)
    if (takes_part_[p]) {
      long long i, j;
      bin_of(P.x[p], P.y[p], i, j);
      ++bin_first[static_cast<std::size_t>(j * bx + i) + 1];
    }
  for (std::size_t b = 1; b < bin_first.size(); ++b) bin_first[b] += bin_first[b - 1];
  in_bin.resize(bin_first.back());
  {
    std::vector<std::size_t> fill(bin_first.begin(), bin_first.end() - 1);
    for (std::size_t p = 0; p < n; ++p)  // in particle order within each bin
      if (takes_part_[p]) {
        long long i, j;
        bin_of(P.x[p], P.y[p], i, j);
        in_bin[fill[static_cast<std::size_t>(j * bx + i)]++] = p;
      }
  }
  // The neighbours of p: every particle within the radius of p or of p's mirror image, once, in
  // particle order. Counted first, then written: compressed rows without per-particle vectors.
  const double r2 = radius * radius;
  const auto for_neighbours = [&](std::size_t p, auto&& take) {
    std::vector<std::size_t> found;
    const auto scan = [&](double x, double y) {
      long long i0, j0;
      bin_of(x, y, i0, j0);
      for (long long j = std::max(0LL, j0 - 1); j <= std::min(by - 1, j0 + 1); ++j)
        for (long long i = std::max(0LL, i0 - 1); i <= std::min(bx - 1, i0 + 1); ++i) {
          const std::size_t b = static_cast<std::size_t>(j * bx + i);
          for (std::size_t k = bin_first[b]; k < bin_first[b + 1]; ++k) {
            const std::size_t q = in_bin[k];
            const double dx = P.x[q] - x, dy = P.y[q] - y;
            if (dx * dx + dy * dy <= r2) found.push_back(q);
          }
        }
    };
    scan(P.x[p], P.y[p]);
    if (mirror_x_) scan(2.0 * *mirror_x_ - P.x[p], P.y[p]);
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    take(found);
  };
  common::parallel_for(threads, n, [&](int, std::size_t p) {
    if (takes_part_[p]) for_neighbours(p, [&](const std::vector<std::size_t>& f) { first_[p + 1] = f.size(); });
  });
  for (std::size_t p = 0; p < n; ++p) first_[p + 1] += first_[p];
  neighbour_.resize(first_[n]);
  common::parallel_for(threads, n, [&](int, std::size_t p) {
    if (takes_part_[p])
      for_neighbours(p, [&](const std::vector<std::size_t>& f) {
        std::copy(f.begin(), f.end(), neighbour_.begin() + static_cast<std::ptrdiff_t>(first_[p]));
      });
  });
}

void NonlocalAverage::average(const Particles& P, const double* value, double* mean, int threads) {
  // The lists hold every pair within reach + skin: good while no particle has moved half the
  // skin since they were found (two particles then close by at most the skin).
  bool stale = x_found_.size() != P.n;
  for (std::size_t p = 0; p < P.n && !stale; ++p)
    stale = takes_part_[p] && std::hypot(P.x[p] - x_found_[p], P.y[p] - y_found_[p]) > 0.5 * skin_;
  if (stale) find_neighbours(P, threads);
  volume_.resize(P.n);
  common::parallel_for(threads, P.n, [&](int, std::size_t p) { volume_[p] = P.volume(p); });
  common::parallel_for(threads, P.n, [&](int, std::size_t p) {
    if (!takes_part_[p]) return;
    double sum = 0.0, weight_sum = 0.0;
    for (std::size_t k = first_[p]; k < first_[p + 1]; ++k) {
      const std::size_t q = neighbour_[k];
      double w = weight(P.x[q] - P.x[p], P.y[q] - P.y[p]);
      if (mirror_x_) w += weight(2.0 * *mirror_x_ - P.x[q] - P.x[p], P.y[q] - P.y[p]);
      const double wV = w * volume_[q];
      sum += wV * value[q];
      weight_sum += wV;
    }
    mean[p] = weight_sum > 0.0 ? sum / weight_sum : value[p];
  });
}

}  // namespace acst::mpm
