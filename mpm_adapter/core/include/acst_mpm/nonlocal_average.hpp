#pragma once
// The nonlocal average of a particle field over a neighbourhood of the internal length l (docs/mpm.md,
// "Nonlocal regularisation"): the host's half of the sand's regularisation. The material takes
// the averaged quantity through the C ABI (acst.h, "Nonlocal regularisation"); what is averaged
// and how often is the Regulariser's (regulariser.hpp).
//
//   mean_i = sum_j w(|x_i - x_j|) V_j v_j / sum_j w(|x_i - x_j|) V_j
//
// over the particles that take part (the sand's), V_j their current volumes. The sum is
// normalised, so a particle near a free surface, a wall or the footing averages over the soil it
// has (Bazant & Jirasek 2002); across the symmetry line of a half domain the mirror image of the
// soil counts as soil, so that the half gives the whole domain's averages. The sums run over
// each particle's neighbours in a fixed order: the result does not depend on the threads.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "acst_mpm/particles.hpp"

namespace acst::mpm {

enum class NonlocalKernel {
  gauss,             // w = exp(-(r/l)^2)
  galavi_schweiger,  // w = (r/l) exp(-(r/l)^2), Galavi & Schweiger (2010): nothing from the point itself
};

// The kernels' reach: pairs further apart than this many l are left out (there w is 0.2 % of the
// Gaussian's largest and 1.1 % of Galavi & Schweiger's).
inline constexpr double nonlocal_reach = 2.5;

// w(r) of a kernel for the internal length l.
double nonlocal_weight(NonlocalKernel kernel, double r, double l);

// The kernel tabulated in s = r/l over [0, reach], read by linear interpolation: the averaging's
// pairs take it instead of an exp each (within 2e-7 of nonlocal_weight's largest value, tested).
class KernelTable {
 public:
  KernelTable() = default;
  explicit KernelTable(NonlocalKernel kernel);
  double operator()(double s) const {
    if (!(s < nonlocal_reach)) return 0.0;
    const double u = s * scale_;
    const std::size_t i = static_cast<std::size_t>(u);
    const double t = u - static_cast<double>(i);
    return values_[i] + t * (values_[i + 1] - values_[i]);
  }
  static constexpr std::size_t intervals = 4096;

 private:
  std::vector<double> values_;
  double scale_ = 0.0;
};

class NonlocalAverage {
 public:
  NonlocalAverage() = default;
  // `takes_part[p]` non-zero for the particles that are averaged over and get a mean;
  // `mirror_x`: the symmetry line of a half domain (the soil's mirror image beyond it counts).
  NonlocalAverage(double length, NonlocalKernel kernel, std::vector<int> takes_part, std::optional<double> mirror_x);

  bool active() const { return length_ > 0.0; }
  double length() const { return length_; }

  // mean[p] for every particle that takes part (the others keep theirs), from value[p]. Finds
  // the neighbours again where a particle has moved more than the lists' skin since they were
  // found.
  void average(const Particles& P, const double* value, double* mean, int threads);

  // Neighbour-list builds so far (for tests and the run's summary).
  long long builds() const { return builds_; }

 private:
  void find_neighbours(const Particles& P, int threads);
  double weight(double dx, double dy) const { return table_(std::sqrt(dx * dx + dy * dy) * inverse_length_); }

  double length_ = 0.0, inverse_length_ = 0.0, skin_ = 0.0;
  KernelTable table_;
  std::vector<double> volume_;  // the particles' current volumes, of the averaging at hand
  std::vector<int> takes_part_;
  std::optional<double> mirror_x_;
  // Neighbours of each particle within (reach + skin) l of it or of its mirror image, in
  // particle order (compressed rows: first_[p] .. first_[p + 1]).
  std::vector<std::size_t> first_;
  std::vector<std::uint32_t> neighbour_;
  std::vector<double> x_found_, y_found_;  // positions when the lists were found
  long long builds_ = 0;
};

}  // namespace acst::mpm
