#pragma once
// The names a reader of the reference study knows its cases by, in its symbols: relative density
// Dr, bedding angle alpha, load inclination beta, footing width B, soil width L and the model
// (isotropic or anisotropic), read from each case's scene. A figure's title gives what its cases
// share and each legend what sets its case apart.
#include <string>
#include <vector>

#include "acst_sweep/sweep.hpp"

namespace acst::mpm {

// The quantities of one case, each as "symbol = value unit" (UTF-8), in a fixed order.
std::vector<std::string> case_quantities(const SweepCase& c);

struct CaseLabels {
  std::string shared;                // what every case has, joined with ", "
  std::vector<std::string> legends;  // per case, what differs; the case's name where nothing does
};

CaseLabels case_labels(const std::vector<const SweepCase*>& cases);

}  // namespace acst::mpm
