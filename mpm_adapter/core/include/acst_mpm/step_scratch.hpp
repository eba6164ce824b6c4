#pragma once
// What one MPM step works with besides the particles and the boundaries: the particles' shape
// functions, the nodal fields, the nodal constraints and per-thread scatter buffers. Rebuilt by
// Simulation::prepare; a copy is a full copy (each Simulation owns its own).
#include <array>
#include <cstddef>
#include <vector>

#include "acst_mpm/grid.hpp"
#include "acst_mpm/scatter.hpp"

namespace acst::mpm {

struct StepScratch {
  Scatter scatter;
  // Shape-function cache of every particle: first node and 4 weights/slopes per axis.
  std::vector<int> first_i, first_j;
  std::vector<double> wx, wy, dwx, dwy;
  // Nodal fields: mass, lumped velocity v_L, force, acceleration, a second velocity field.
  std::vector<double> mass, vx, vy, fx, fy, ax, ay, ux, uy, xpx, xpy;
  NodeConstraints constraints;
  // The body's own mass and force before the walls' mirror images are folded in.
  std::vector<double> mass_body, fx_body, fy_body;
  // Per-particle scratch: velocities mapped from the grid.
  std::vector<double> pvx, pvy;
  // With solver/volumetric_averaging "cell": every particle's velocity gradient (xx xy yx yy), cell
  // and current volume, and the cells' sums.
  std::vector<double> L, volume, cell_sum, cell_weight;
  std::vector<std::size_t> cell;
  int nx = 0;

  // f(node, S, dS/dx, dS/dy) over particle p's 4 x 4 stencil.
  template <class F>
  void stencil(std::size_t p, F&& f) const {
    const int fi = first_i[p], fj = first_j[p];
    for (int b = 0; b < 4; ++b) {
      const double wyb = wy[4 * p + b], dwyb = dwy[4 * p + b];
      const std::size_t row = static_cast<std::size_t>(fj + b) * nx + fi;
      for (int a = 0; a < 4; ++a) f(row + a, wx[4 * p + a] * wyb, dwx[4 * p + a] * wyb, wx[4 * p + a] * dwyb);
    }
  }

  // Particle-to-grid: adds each particle's K values (values(p), an array), weighted by its shape
  // functions, into the nodal fields out[0..K) (deterministic over the threads, scatter.hpp).
  template <std::size_t K, class Values>
  void map_to_grid(const std::array<double*, K>& out, std::size_t n, Values&& values) {
    scatter.run(static_cast<int>(K), out.data(), n, [&](std::size_t p, double* const* f) {
      const std::array<double, K> v = values(p);
      stencil(p, [&](std::size_t i, double S, double, double) {
        for (std::size_t c = 0; c < K; ++c) f[c][i] += S * v[c];
      });
    });
  }

  // Particle p's velocity gradient L_ij = dv_i/dx_j (xx xy yx yy) from the nodal velocities. Summed
  // in locals: summing into an array whose address goes on to the material made the compiler
  // store it on every node of the stencil.
  std::array<double, 4> velocity_gradient(std::size_t p, const double* vx, const double* vy) const {
    double xx = 0.0, xy = 0.0, yx = 0.0, yy = 0.0;
    stencil(p, [&](std::size_t i, double, double gx, double gy) {
      xx += vx[i] * gx;
      xy += vx[i] * gy;
      yx += vy[i] * gx;
      yy += vy[i] * gy;
    });
    return {xx, xy, yx, yy};
  }
};

}  // namespace acst::mpm
