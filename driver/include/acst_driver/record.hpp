#pragma once
// One output row of an element test and the output-convention quantities derived from it
// (compression positive; q and the stress ratio signed, negative in extension; strains in %).
#include <cmath>
#include <string>

#include "acst/tensor.hpp"
#include "acst/yield_function.hpp"

namespace acst::driver {

struct Record {
  long increment = 0;  // accepted increments since the start
  double time = 0.0;   // each step takes one unit of time (less when an exit condition ends it)
  int step = 0;        // index in /steps
  int cycle = 1;       // cycle of a repeat block (1 for plain steps)
  int stage = 0;       // index of the step inside its repeat block (0 for plain steps)
  Sym strain = Sym::Zero();  // since the start, model convention (fraction, tensor shear)
  Sym stress = Sym::Zero();  // kPa, effective, compression positive
  double void_ratio = 0.0;
  double u_excess = 0.0;     // kPa, accumulated over undrained steps
  double psi = 0.0, zeta = 0.0, A = 0.0, fabric_norm = 0.0;
  int substeps = 0, iterations = 0, cutbacks = 0;
  std::string status;  // start | ok | cutback | exit:<condition>
};

// q = sqrt(3/2 s:s), negative when sigma_11 is below the mean of the lateral stresses (extension).
inline double signed_q(const Sym& stress) {
  const double q = std::sqrt(1.5) * norm(deviator(stress));
  return stress[0] >= 0.5 * (stress[1] + stress[2]) ? q : -q;
}
inline double stress_ratio_of(const Sym& stress) { return signed_q(stress) / mean_stress(stress); }
inline double volumetric_strain_pct(const Sym& strain) { return 100.0 * trace(strain); }
// e_q = sqrt(2/3 e:e), e the strain deviator (tensor components), in percent.
inline double deviatoric_strain_pct(const Sym& strain) { return 100.0 * std::sqrt(2.0 / 3.0) * norm(deviator(strain)); }
inline double axial_strain_pct(const Sym& strain) { return 100.0 * strain[0]; }

}  // namespace acst::driver
