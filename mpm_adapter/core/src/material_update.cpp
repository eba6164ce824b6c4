#include "acst_mpm/material_update.hpp"

#include <algorithm>
#include <type_traits>

#include "acst_mpm/dilation_averaging.hpp"
#include "acst_mpm/material_frame.hpp"

namespace acst::mpm {

namespace {

// Every particle's velocity gradient into the scratch, then each dilation rate replaced by the
// mean over the particles in its cell (docs/mpm.md, "Volumetric locking").
void velocity_gradients_averaged(const Particles& P, const Grid& grid, StepScratch& w, const double* vx,
                                 const double* vy) {
  w.L.resize(4 * P.n);
  w.cell.resize(P.n);
  w.volume.resize(P.n);
  parallel_for(w.scatter.threads(), P.n, [&](int, std::size_t p) {
    const std::array<double, 4> L = w.velocity_gradient(p, vx, vy);
    std::copy(L.begin(), L.end(), &w.L[4 * p]);
    const auto i = static_cast<std::size_t>(grid.place_x(P.x[p]).cell);
    const auto j = static_cast<std::size_t>(grid.place_y(P.y[p]).cell);
    w.cell[p] = j * static_cast<std::size_t>(grid.nx) + i;
    w.volume[p] = P.volume(p);
  });
  average_dilation_over_cells(w.L, w.cell, w.volume, grid.nodes(), w.cell_sum, w.cell_weight);
}

}  // namespace

MaterialFailure update_material_points(Particles& P, const std::vector<std::shared_ptr<const AbiMaterial>>& materials,
                                       const Regulariser& regulariser, const Grid& grid, bool cell_averaged,
                                       StepScratch& w, const double* vx, const double* vy, double dt_half) {
  const int T = w.scatter.threads();
  std::vector<long long> failed(T, -1);
  std::vector<std::string> messages(T), reproducers(T);
  const auto offset_of = [&](const AbiMaterial& mat, std::size_t p) { return regulariser.offset(mat, p); };
  if (cell_averaged) velocity_gradients_averaged(P, grid, w, vx, vy);
  // The loop is instantiated once per setting and chosen here: a branch inside it cost the
  // default 1-2 %.
  auto update_all = [&](auto averaged_gradients) -> MaterialFailure {
    const auto gradient = [&](std::size_t p) {  // L_ij = dv_i/dx_j: xx xy yx yy
      std::array<double, 4> L;
      if constexpr (decltype(averaged_gradients)::value)
        std::copy_n(&w.L[4 * p], 4, L.begin());
      else
        L = w.velocity_gradient(p, vx, vy);
      return L;
    };
    // In runs of AbiMaterial::batch_size particles: one call updates a run of one material (the
    // library updates points of the common kind together, with the same numbers).
    constexpr std::size_t run = AbiMaterial::batch_size;
    parallel_for(T, (P.n + run - 1) / run, [&](int t, std::size_t r) {
      const std::size_t first = r * run, n = std::min(P.n, first + run) - first;
      std::array<double, 4 * run> Ls;
      bool one_material = true;
      for (std::size_t p = first; p < first + n; ++p) {
        const std::array<double, 4> L = gradient(p);
        std::copy(L.begin(), L.end(), &Ls[4 * (p - first)]);
        one_material = one_material && P.material[p] == P.material[first];
        double* F = &P.F[4 * p];
        const double F0 = F[0], F1 = F[1], F2 = F[2], F3 = F[3];
        F[0] += dt_half * (L[0] * F0 + L[1] * F2);
        F[1] += dt_half * (L[0] * F1 + L[1] * F3);
        F[2] += dt_half * (L[2] * F0 + L[3] * F2);
        F[3] += dt_half * (L[2] * F1 + L[3] * F3);
        double* e = &P.strain[3 * p];
        e[0] += L[0] * dt_half;
        e[1] += L[3] * dt_half;
        e[2] += 0.5 * (L[1] + L[2]) * dt_half;
      }
      const auto note_failure = [&](std::size_t p, const acst_status& st) {
        failed[t] = static_cast<long long>(p);
        messages[t] = "material '" + materials[P.material[p]]->name() + "': " + st.message;
      };
      if (one_material) {
        std::string* reproducer = failed[t] < 0 ? &reproducers[t] : nullptr;  // only the first failure's
        acst_status failure;
        const AbiMaterial& mat = *materials[P.material[first]];
        const std::size_t bad =
            mat.update_batch(n, &P.stress[6 * first], P.statev.data() + P.state_size * first, Ls.data(), dt_half,
                             &P.stress_free[first], failure, reproducer, offset_of(mat, first));
        if (bad < n && failed[t] < 0) note_failure(first + bad, failure);
        return;
      }
      for (std::size_t p = first; p < first + n; ++p) {
        std::string* reproducer = failed[t] < 0 ? &reproducers[t] : nullptr;
        bool free = false;
        const AbiMaterial& mat = *materials[P.material[p]];
        const acst_status st = mat.update(&P.stress[6 * p], P.statev.data() + P.state_size * p, &Ls[4 * (p - first)],
                                          dt_half, free, reproducer, offset_of(mat, p));
        P.stress_free[p] = free;
        if (st.code != ACST_OK && failed[t] < 0) note_failure(p, st);
      }
    });
    for (int t = 0; t < T; ++t)
      if (failed[t] >= 0) return {failed[t], messages[t], reproducers[t]};
    // The followed particles' frames (a handful: outside the loop above, which stays as it was).
    for (std::size_t k = 0; k < P.tracked.size(); ++k)
      turn_material_frame(&P.track_frame[material_frame_size * k], gradient(static_cast<std::size_t>(P.tracked[k])).data(),
                          dt_half);
    return {};
  };
  return cell_averaged ? update_all(std::true_type{}) : update_all(std::false_type{});
}

}  // namespace acst::mpm
