#include "acst_mpm/dilation_averaging.hpp"

namespace acst::mpm {

void average_dilation_over_cells(std::vector<double>& L, const std::vector<std::size_t>& cell,
                                 const std::vector<double>& volume, std::size_t cells, std::vector<double>& sum,
                                 std::vector<double>& weight) {
  const std::size_t n = cell.size();
  sum.assign(cells, 0.0);
  weight.assign(cells, 0.0);
  for (std::size_t p = 0; p < n; ++p) {
    sum[cell[p]] += volume[p] * (L[4 * p] + L[4 * p + 3]);
    weight[cell[p]] += volume[p];
  }
  for (std::size_t p = 0; p < n; ++p) {
    double* l = &L[4 * p];
    const double c = 0.5 * (sum[cell[p]] / weight[cell[p]] - (l[0] + l[3]));
    l[0] += c;
    l[3] += c;
  }
}

}  // namespace acst::mpm
