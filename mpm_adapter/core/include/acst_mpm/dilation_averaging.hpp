#pragma once
// Volumetric locking and the cell-averaged dilation rate (docs/mpm.md, "Volumetric locking").
// With several particles per cell, every particle's plastic flow at constant volume (Tresca; sand
// at its critical state) is one more constraint on the few nodal velocities of its cell, and the
// grid locks: at h = B/10 a Tresca footing on 2 x 2 particles per cell carries 4-7 % more than on
// one. Giving every particle its cell's mean dilation rate, weighted by the particles' current
// volumes, leaves one volumetric constraint per cell, as one particle per cell has: a B-bar in rate
// form, the incremental counterpart of the F-bar of Coombs, Charlton, Cortis and Augarde,
// "Overcoming volumetric locking in material point methods", CMAME 333 (2018) 1-21.
#include <cstddef>
#include <vector>

namespace acst::mpm {

// L: each particle's velocity gradient, 4 per particle (L_ij = dv_i/dx_j: xx xy yx yy); cell: each
// particle's cell index (< cells); volume: each particle's current volume. Adds half the
// difference between the cell's mean tr(L) and the particle's own to L_xx and to L_yy (plane
// strain: the out-of-plane rate stays zero), so tr(L) becomes the cell's mean; L_xx - L_yy and the
// shear are kept. The sums run in particle order: the result does not depend on the threads.
// sum and weight are scratch (resized here).
void average_dilation_over_cells(std::vector<double>& L, const std::vector<std::size_t>& cell,
                                 const std::vector<double>& volume, std::size_t cells, std::vector<double>& sum,
                                 std::vector<double>& weight);

}  // namespace acst::mpm
