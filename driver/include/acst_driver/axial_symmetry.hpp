#pragma once
// Symmetry of an element test about the axial direction 1: the mirror that swaps axes 2 and 3.
// A triaxial test on a specimen whose state has that symmetry (isotropic, or bedded normal to
// axis 1) keeps it in exact arithmetic. The explicit stress update does not: near the critical
// state, with a Lode function pointed at compression, the mode sigma_22 - sigma_33 is so stiff
// that the update's error in it (within STOL) is far above Newton's tolerance, and the iteration
// on that mode alone can take most of a fit's time (docs/element-tests.md, "Mixed control on
// the axis of symmetry").
#include "acst/state.hpp"
#include "acst_driver/mixed_control.hpp"

namespace acst::driver {

// Voigt order 11, 22, 33, 12, 13, 23: swaps 22 with 33 and 12 with 13.
Sym mirrored_23(const Sym& a);

// (a + mirrored_23(a)) / 2: exactly symmetric (floating-point addition commutes).
Sym symmetrized_23(const Sym& a);

bool symmetric_23(const Sym& a);  // exactly equal to its mirror image
bool symmetric_23(const State& s);  // stress and fabric

// The mirrored constraints (rows with their values) are those of the control: each mirrored row
// lies in the span of the rows, with the value the same combination gives.
bool symmetric_23(const LinearControl& control);

}  // namespace acst::driver
