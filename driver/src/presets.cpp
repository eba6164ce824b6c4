#include "acst_driver/presets.hpp"

#include <string>
#include <utility>

namespace acst::driver {

const char* component_name(int i) {
  static const char* names[] = {"11", "22", "33", "12", "13", "23"};
  return names[i];
}

namespace {

// Row `row` made a control of its own: no coefficients yet (the caller sets them), the target
// `value` (an increment, or the value to reach if `absolute`) and the name it is reported by.
void start_row(ControlRows& rows, int row, double value, bool absolute, std::string name) {
  rows.A.row(row).setZero();
  rows.B.row(row).setZero();
  rows.value[row] = value;
  rows.absolute[row] = absolute;
  rows.names[row] = std::move(name);
}

}  // namespace

void set_stress_row(ControlRows& rows, int row, int component, double value, bool absolute) {
  start_row(rows, row, value, absolute, std::string("sigma_") + component_name(component));
  rows.A(row, component) = 1.0;
}

void set_strain_row(ControlRows& rows, int row, int component, double value, bool absolute) {
  start_row(rows, row, value, absolute, std::string("eps_") + component_name(component));
  rows.B(row, component) = 1.0;
}

namespace {

void hold_shear_stresses(ControlRows& rows) {
  for (int i = 3; i < 6; ++i) set_stress_row(rows, i, i, 0.0);
}

void equal_lateral_increments(ControlRows& rows, int row) {  // d sigma_22 - d sigma_33 = 0
  start_row(rows, row, 0.0, false, "sigma_22 - sigma_33");
  rows.A(row, 1) = 1.0;
  rows.A(row, 2) = -1.0;
}

void mean_stress_row(ControlRows& rows, int row, double value, bool absolute) {
  start_row(rows, row, value, absolute, "p");
  rows.A.block<1, 3>(row, 0).setConstant(1.0 / 3.0);
}

}  // namespace

ControlRows triaxial_rows(double axial_change, bool drained) {
  ControlRows r;
  set_strain_row(r, 0, 0, axial_change);
  if (drained) {
    set_stress_row(r, 1, 1, 0.0);
    set_stress_row(r, 2, 2, 0.0);
  } else {
    r.B.row(1) << 1, 1, 1, 0, 0, 0;  // eps_v = 0
    r.names[1] = "eps_v";
    equal_lateral_increments(r, 2);
  }
  hold_shear_stresses(r);
  return r;
}

ControlRows plane_strain_rows(double axial_change) {
  ControlRows r;
  set_strain_row(r, 0, 0, axial_change);
  set_strain_row(r, 1, 1, 0.0);
  set_stress_row(r, 2, 2, 0.0);
  hold_shear_stresses(r);
  return r;
}

ControlRows isotropic_rows(double p_target) {
  ControlRows r;
  mean_stress_row(r, 0, p_target, true);
  r.A.row(1) << 1, -1, 0, 0, 0, 0;
  r.names[1] = "sigma_11 - sigma_22";
  equal_lateral_increments(r, 2);
  hold_shear_stresses(r);
  return r;
}

ControlRows oedometric_rows(double value, bool axial_stress_target) {
  ControlRows r;
  if (axial_stress_target)
    set_stress_row(r, 0, 0, value, true);
  else
    set_strain_row(r, 0, 0, value);
  set_strain_row(r, 1, 1, 0.0);
  set_strain_row(r, 2, 2, 0.0);
  hold_shear_stresses(r);
  return r;
}

ControlRows true_triaxial_rows(double axial_change, double b, bool hold_p) {
  ControlRows r;
  set_strain_row(r, 0, 0, axial_change);
  if (hold_p)
    mean_stress_row(r, 1, 0.0, false);
  else
    set_stress_row(r, 1, 2, 0.0);
  r.A.row(2) << -b, 1.0, -(1.0 - b), 0, 0, 0;  // d sigma_2 - d sigma_3 - b (d sigma_1 - d sigma_3) = 0
  r.names[2] = "b";
  hold_shear_stresses(r);
  return r;
}

ControlRows pq_rows(double p_value, bool p_absolute, double q_value, bool q_absolute) {
  ControlRows r;
  mean_stress_row(r, 0, p_value, p_absolute);
  r.A.row(1) << 1, 0, -1, 0, 0, 0;
  r.value[1] = q_value;
  r.absolute[1] = q_absolute;
  r.names[1] = "q";
  equal_lateral_increments(r, 2);
  hold_shear_stresses(r);
  return r;
}

ControlRows strain_rows(const Sym& change) {
  ControlRows r;
  for (int i = 0; i < 6; ++i) set_strain_row(r, i, i, change[i]);
  return r;
}

}  // namespace acst::driver
