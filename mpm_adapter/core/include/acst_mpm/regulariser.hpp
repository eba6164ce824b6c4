#pragma once
// The sand's nonlocal regularisation as one step feature (docs/mpm.md, "Nonlocal
// regularisation"): every `every` steps, each sand particle's nonlocal void ratio from the
// NonlocalAverage of its neighbourhood, handed to its material with every update as an offset from
// the particle's own until the next averaging. It owns the averaged values (checkpointed as its
// ParticleState); while the model is local (no internal length) it does nothing and hands no
// offset, so the local update's numbers stay as they were.
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

#include "acst_mpm/material_adapter.hpp"
#include "acst_mpm/nonlocal_average.hpp"
#include "acst_mpm/particles.hpp"
#include "acst_mpm/settings.hpp"

namespace acst::mpm {

class Regulariser {
 public:
  // Per particle: the averaged void ratio minus the particle's own (0 while local), and its own
  // void ratio at the last averaging.
  struct ParticleState {
    std::vector<double> offset, averaged;
  };
  using Materials = std::vector<std::shared_ptr<const AbiMaterial>>;

  Regulariser() = default;
  // `mirror_x`: a half domain's symmetry line. At the start (step 0) the averaged void ratios are
  // the particles' own.
  Regulariser(const Regularisation& settings, const Particles& P, const Materials& materials,
              std::optional<double> mirror_x, int threads);

  bool active() const { return average_.active(); }
  ParticleState& state() { return state_; }
  const ParticleState& state() const { return state_; }

  // The step's hook, first in the step: the averaging, on the steps it falls on.
  void regularise(const Particles& P, const Materials& materials, long long step, int threads);
  // Particle p's offsets for a material update, or null (local model, or a material that takes none).
  const double* offset(const AbiMaterial& material, std::size_t p) const {
    return active() && material.nonlocal_size() > 0 ? &state_.offset[p] : nullptr;
  }

 private:
  void local_void_ratios(const Particles& P, const Materials& materials, std::vector<double>& out, int threads) const;

  Regularisation settings_;
  NonlocalAverage average_;  // inactive unless the regularisation has an internal length
  ParticleState state_;
  std::vector<double> value_, mean_;
};

}  // namespace acst::mpm
