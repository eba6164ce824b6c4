#pragma once
// The element-test presets as six control rows each (test frame: 1 = axial, 2 = intermediate,
// 3 = minor lateral; model convention: compression positive, tensor shear strain as a fraction).
// Changes are totals over a step; "target" rows are absolute values to reach.
#include "acst_driver/scene.hpp"

namespace acst::driver {

// Voigt slot names in the test frame, for messages: sigma_11 ... sigma_23, eps_11 ... eps_23.
const char* component_name(int i);  // "11", "22", "33", "12", "13", "23"

// Row builders: stress or strain of one component; value = change (or target if absolute).
void set_stress_row(ControlRows& rows, int row, int component, double value, bool absolute = false);
void set_strain_row(ControlRows& rows, int row, int component, double value, bool absolute = false);

// Triaxial compression (axial_change > 0) or extension (< 0). Drained: sigma_22, sigma_33 held.
// Undrained: eps_v = 0 and sigma_22 = sigma_33 (with the total lateral stress held, the excess
// pore pressure is minus the change of the effective lateral stress). Shear stresses held.
ControlRows triaxial_rows(double axial_change, bool drained);

// Plane strain: eps_11 changes, eps_22 = 0, sigma_33 held, shear stresses held.
ControlRows plane_strain_rows(double axial_change);

// Equal changes of the three normal stresses until p reaches p_target; shear stresses held.
ControlRows isotropic_rows(double p_target);

// Oedometric (K0): lateral strains zero, shear stresses held; axial strain change, or an axial
// stress target when `axial_stress_target` is true (then `value` is sigma_11 at the end).
ControlRows oedometric_rows(double value, bool axial_stress_target);

// Axial strain change with b = (sigma_2 - sigma_3)/(sigma_1 - sigma_3) kept in the increments
// (d sigma_2 - d sigma_3 = b (d sigma_1 - d sigma_3)), and either p or sigma_33 held.
ControlRows true_triaxial_rows(double axial_change, double b, bool hold_p);

// Roscoe p-q path, axisymmetric (sigma_22 = sigma_33 in the increments), q = sigma_11 - sigma_33:
// p and q each a change or a target.
ControlRows pq_rows(double p_value, bool p_absolute, double q_value, bool q_absolute);

// Every strain component controlled (change of the tensor components).
ControlRows strain_rows(const Sym& change);

}  // namespace acst::driver
