#include "acst_mpm/material_frame.hpp"

#include "acst_mpm/material_adapter.hpp"

namespace acst::mpm {

void to_material_frame(double c, double s, double xx, double yy, double xy, double* out) {
  out[0] = c * c * xx - 2.0 * c * s * xy + s * s * yy;
  out[1] = s * s * xx + 2.0 * c * s * xy + c * c * yy;
  out[2] = c * s * (xx - yy) + (c * c - s * s) * xy;
}

void turn_material_frame(double* frame, const double* L, double dt) {
  const PlaneRotation q = hughes_winget_rotation(L, dt);
  const double c = frame[0], s = frame[1];
  frame[0] = q.c * c - q.s * s;  // R <- Q R: in the plane, angles add
  frame[1] = q.s * c + q.c * s;
  double de[3];
  to_material_frame(frame[0], frame[1], L[0] * dt, L[3] * dt, 0.5 * (L[1] + L[2]) * dt, de);
  for (int k = 0; k < 3; ++k) frame[2 + k] += de[k];
}

}  // namespace acst::mpm
