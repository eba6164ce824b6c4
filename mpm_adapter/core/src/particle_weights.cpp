#include "acst_mpm/particle_weights.hpp"

#include <algorithm>
#include <cmath>

#include "acst_mpm/graded_axis.hpp"
#include "acst_mpm/shape_functions.hpp"

namespace acst::mpm {

namespace {

// The first of the threads' first particles off the grid (thread order), or -1.
long long first_off_grid(const std::vector<long long>& of_thread) {
  for (long long p : of_thread)
    if (p >= 0) return p;
  return -1;
}

}  // namespace

// The half-widths of the share of its node cell a particle was built on (half_width_ of the cell's
// width), so that the domains tile the soil and the internal force integrates a uniform stress to
// none at interior nodes; in the fine window half_width_ h, as on the regular grid (docs/mpm.md,
// "The graded grid").
void ParticleWeights::prepare(const Grid& grid, const Particles& P) {
  if (!grid.graded()) return;
  domain_x_.resize(P.n);
  domain_y_.resize(P.n);
  const auto half_width = [&](const GradedAxis& a, double at) {
    const int i = a.cell(at);
    return half_width_ * (a.node(i + 1) - a.node(i));
  };
  for (std::size_t p = 0; p < P.n; ++p) {
    domain_x_[p] = half_width(grid.graded_x, P.x_initial[p]);
    domain_y_[p] = half_width(grid.graded_y, P.y_initial[p]);
  }
}

long long ParticleWeights::compute_graded(const Grid& grid, const Particles& P, StepScratch& w) const {
  std::vector<long long> off_grid(w.scatter.threads(), -1);
  parallel_for(w.scatter.threads(), P.n, [&](int t, std::size_t p) {
    GradedWeights ax, ay;
    const GradedAxis &gx = grid.graded_x, &gy = grid.graded_y;
    // Where the particle's domain began the step before (its first node's interval is first + 2):
    // the knot intervals are looked for there first, the same intervals found faster.
    const int near_x = gx.interval(P.x[p], w.first_i[p] + 2), near_y = gy.interval(P.y[p], w.first_j[p] + 2);
    // A particle that moved onto smaller cells has its domain narrowed to cover two intervals (the
    // stencil's 4 nodes): the weights stay continuous in x, a sum of unity and linear-complete.
    if (!std::isfinite(P.x[p]) || !std::isfinite(P.y[p]) ||
        !graded_weights(gx, P.x[p], std::min(domain_x_[p], widest_domain(gx, P.x[p], near_x)), ax, near_x) ||
        !graded_weights(gy, P.y[p], std::min(domain_y_[p], widest_domain(gy, P.y[p], near_y)), ay, near_y)) {
      if (off_grid[t] < 0) off_grid[t] = static_cast<long long>(p);
      return;
    }
    w.first_i[p] = ax.first;
    w.first_j[p] = ay.first;
    std::copy_n(ax.w, 4, &w.wx[4 * p]);
    std::copy_n(ax.dw, 4, &w.dwx[4 * p]);
    std::copy_n(ay.w, 4, &w.wy[4 * p]);
    std::copy_n(ay.dw, 4, &w.dwy[4 * p]);
  });
  return first_off_grid(off_grid);
}

long long ParticleWeights::compute(const Grid& grid, const Particles& P, StepScratch& w) const {
  if (grid.graded()) return compute_graded(grid, P, w);
  const double h = grid.h, hy = grid.hy;
  const B2gimpDomain domain(half_width_);
  std::vector<long long> off_grid(w.scatter.threads(), -1);
  parallel_for(w.scatter.threads(), P.n, [&](int t, std::size_t p) {
    const DoublePair X = DoublePair{P.x[p] - grid.x0, P.y[p] - grid.y0} / DoublePair{h, hy};
    const AxisWeights ax = axis_weights(X[0], domain), ay = axis_weights(X[1], domain);
    if (!std::isfinite(P.x[p]) || !std::isfinite(P.y[p]) || ax.first < 0 || ay.first < 0 || ax.first + 3 >= grid.nx ||
        ay.first + 3 >= grid.ny) {
      if (off_grid[t] < 0) off_grid[t] = static_cast<long long>(p);
      return;
    }
    w.first_i[p] = ax.first;
    w.first_j[p] = ay.first;
    for (int k = 0; k < 4; k += 2) {
      const DoublePair gx = DoublePair{ax.dw[k], ax.dw[k + 1]} / DoublePair{h, h};
      const DoublePair gy = DoublePair{ay.dw[k], ay.dw[k + 1]} / DoublePair{hy, hy};
      w.wx[4 * p + k] = ax.w[k];
      w.wx[4 * p + k + 1] = ax.w[k + 1];
      w.dwx[4 * p + k] = gx[0];
      w.dwx[4 * p + k + 1] = gx[1];
      w.wy[4 * p + k] = ay.w[k];
      w.wy[4 * p + k + 1] = ay.w[k + 1];
      w.dwy[4 * p + k] = gy[0];
      w.dwy[4 * p + k + 1] = gy[1];
    }
  });
  return first_off_grid(off_grid);
}

}  // namespace acst::mpm
