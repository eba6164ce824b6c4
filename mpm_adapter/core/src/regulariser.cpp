#include "acst_mpm/regulariser.hpp"

#include "acst_common/parallel_for.hpp"

namespace acst::mpm {

Regulariser::Regulariser(const Regularisation& settings, const Particles& P, const Materials& materials,
                         std::optional<double> mirror_x, int threads)
    : settings_(settings) {
  state_.offset.assign(P.n, 0.0);
  state_.averaged.assign(P.n, 0.0);
  if (!(settings_.internal_length > 0.0)) return;
  std::vector<int> takes_part(P.n);
  for (std::size_t p = 0; p < P.n; ++p) takes_part[p] = materials[P.material[p]]->nonlocal_size() > 0;
  average_ = NonlocalAverage(settings_.internal_length, settings_.kernel, std::move(takes_part), mirror_x);
  local_void_ratios(P, materials, state_.averaged, threads);
}

// Every particle's local void ratio (0 for the particles of a material that takes nothing
// nonlocally).
void Regulariser::local_void_ratios(const Particles& P, const Materials& materials, std::vector<double>& out,
                                    int threads) const {
  out.assign(P.n, 0.0);
  common::parallel_for(threads, P.n, [&](int, std::size_t p) {
    const AbiMaterial& m = *materials[P.material[p]];
    if (m.nonlocal_size() > 0) m.nonlocal_local(&out[p], &P.stress[6 * p], P.statev.data() + P.state_size * p);
  });
}

// The nonlocal void ratio of every sand particle and its offset from the particle's own, which the
// material takes for its state parameter until the next averaging.
void Regulariser::regularise(const Particles& P, const Materials& materials, long long step, int threads) {
  if (!active() || step % settings_.every != 0) return;
  const double m = settings_.over_nonlocal;
  local_void_ratios(P, materials, value_, threads);
  mean_ = value_;
  if (settings_.quantity == NonlocalQuantity::void_ratio) {
    average_.average(P, value_.data(), mean_.data(), threads);
    for (std::size_t p = 0; p < P.n; ++p) state_.offset[p] = m * (mean_[p] - value_[p]);
    return;
  }
  // The changes since the last averaging, averaged: the nonlocal void ratio (the particle's own
  // plus its offset) moves by the mean change of its neighbourhood instead of its own.
  std::vector<double>& change = value_;
  for (std::size_t p = 0; p < P.n; ++p) {
    const double e = change[p];
    change[p] = e - state_.averaged[p];
    state_.averaged[p] = e;
  }
  average_.average(P, change.data(), mean_.data(), threads);
  for (std::size_t p = 0; p < P.n; ++p) state_.offset[p] += m * (mean_[p] - change[p]);
}

}  // namespace acst::mpm
