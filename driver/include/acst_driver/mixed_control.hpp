#pragma once
// One increment of a mixed stress/strain-controlled element test: find the strain increment
// d_eps that satisfies six linear constraints  A d_sigma + B d_eps = c  (row by row), by Newton
// iteration with the material's tangent. Strain control is A = 0, B = I; stress control A = I,
// B = 0; undrained is a row B = (1, 1, 1, 0, 0, 0), c = 0. Model convention: compression positive,
// tensor shear strain.
#include "acst/material.hpp"

namespace acst::driver {

struct LinearControl {
  Mat6 A = Mat6::Zero();  // on the stress increment
  Mat6 B = Mat6::Zero();  // on the strain increment
  Sym c = Sym::Zero();
};

struct NewtonOptions {
  int max_iterations = 25;
  double stress_tolerance = 1e-8;  // residual of a stress row, relative to max(p, pa)
  double strain_tolerance = 1e-12; // residual of a pure strain row, and absolute strain correction
};

// Why an increment did not converge.
enum class IncrementFailure {
  none,
  material,           // the material update failed (its report says why)
  singular_jacobian,  // A D + B is singular: the control leaves a component free at this state
  not_converged,      // max_iterations reached
  non_finite,         // the strain iterate became NaN or inf
};
const char* failure_text(IncrementFailure f);

struct IncrementResult {
  bool converged = false;
  int iterations = 0;
  IncrementFailure failure = IncrementFailure::none;
  integration::Report material;  // report of the last material call (counters summed over iterations)
  Sym strain_increment = Sym::Zero();
  Mat6 tangent = Mat6::Zero();   // material tangent at the accepted state (a predictor for the next increment)
};

// Advances `state` by one increment; `guess` is the starting strain increment (for example the
// previous one). Converged only when every row's residual is below its tolerance AND the last
// Newton correction is below the strain tolerance (plus 1e-8 of the increment). On failure the
// state is unchanged. `void_ratio_offset`: a nonlocal offset every material update takes.
IncrementResult solve_increment(const Material& material, State& state, const LinearControl& control,
                                const Sym& guess, const NewtonOptions& options = {}, double void_ratio_offset = 0.0);

// Presets in the test frame (1 = axial): the control of one increment of d_eps_axial.
LinearControl drained_triaxial(double axial_strain_increment);    // sigma_2, sigma_3 held, no shear
LinearControl undrained_triaxial(double axial_strain_increment);  // eps_v = 0, sigma_2 = sigma_3

}  // namespace acst::driver
