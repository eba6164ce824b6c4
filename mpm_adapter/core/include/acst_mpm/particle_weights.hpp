#pragma once
// The particles' shape functions as one unit of the step (docs/mpm.md, "One step", phase 1): the
// B2GIMP weights and slopes of every particle on the regular grid, or on the graded grid's uneven
// knots with each particle's own domain, into the step's cache (StepScratch::first_i .. dwy) that
// every later pass reads through StepScratch::stencil.
#include <cstddef>
#include <vector>

#include "acst_mpm/grid.hpp"
#include "acst_mpm/particles.hpp"
#include "acst_mpm/step_scratch.hpp"

namespace acst::mpm {

class ParticleWeights {
 public:
  ParticleWeights() = default;
  // `half_width` is l in cells: 1/(2 n) for n particles per cell and direction.
  explicit ParticleWeights(double half_width) : half_width_(half_width) {}

  double half_width() const { return half_width_; }
  // On a graded grid, every particle's domain half-widths (m), from where it was built.
  void prepare(const Grid& grid, const Particles& P);
  // Every particle's weights and slopes into w; the first particle off the grid (its stencil
  // would leave the nodes), or -1.
  long long compute(const Grid& grid, const Particles& P, StepScratch& w) const;

 private:
  long long compute_graded(const Grid& grid, const Particles& P, StepScratch& w) const;

  double half_width_ = 0.5;
  std::vector<double> domain_x_, domain_y_;  // graded grid only
};

}  // namespace acst::mpm
