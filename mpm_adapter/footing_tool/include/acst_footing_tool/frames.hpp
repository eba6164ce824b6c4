#pragma once
// What a run writes while it goes: VTK frames of the particles (particles_NNNN.vtp and the .pvd
// listing them) and the contour maps at the requested S/B (docs/mpm.md, "Outputs").
#include "acst_footing_tool/run_context.hpp"

namespace acst::mpm {

// Whether the next VTK frame is due (output/vtk_every_time, or vtk_every_S_over_B of a footing).
bool frame_due(const RunContext& run);
void write_frame(RunContext& run);
// The contour maps of output/contour_fields at each output/contours_at_S_over_B the footing has
// passed since the last call (each once; drawn only with plots on).
void contours_at_requested(RunContext& run);

}  // namespace acst::mpm
