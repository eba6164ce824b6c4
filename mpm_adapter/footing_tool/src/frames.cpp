#include "acst_footing_tool/frames.hpp"

#include <cmath>
#include <cstdio>
#include <string>

#include "acst_common/files.hpp"
#include "acst_footing_tool/fields.hpp"
#include "acst_footing_tool/output.hpp"

namespace acst::mpm {

bool frame_due(const RunContext& run) {
  const OutputSpec& out = run.scene.output;
  const int k = run.state.vtk_frames;
  if (out.vtk_every_time) return run.sim.time() >= k * *out.vtk_every_time;
  if (run.scene.footing && out.vtk_every_S_over_B > 0) return run.S_over_B() >= k * out.vtk_every_S_over_B;
  return false;
}

void write_frame(RunContext& run) {
  RunState& st = run.state;
  char name[64];
  std::snprintf(name, sizeof name, "particles_%04d.vtp", st.vtk_frames);
  common::write_file_atomically(run.path(name), vtp_text(run.sim));
  st.vtk_times.push_back(run.sim.time());
  ++st.vtk_frames;
  common::write_file_atomically(run.path("particles.pvd"), pvd_text("particles", st.vtk_times));
}

void contours_at_requested(RunContext& run) {
  const Scene& scene = run.scene;
  const auto& targets = scene.output.contours_at_S_over_B;
  for (std::size_t k = 0; k < targets.size(); ++k) {
    if (run.state.contours_done[k] || run.S_over_B() < targets[k]) continue;
    run.state.contours_done[k] = 1;
    if (!run.options.plot) continue;
    const ParticleFields f = particle_fields(run.sim);
    char tag[48];
    const bool three = std::fabs(targets[k] * 1000.0 - std::round(targets[k] * 1000.0)) < 1e-9;
    std::snprintf(tag, sizeof tag, three ? "SB%.3f" : "SB%.4f", targets[k]);  // SB0.500, SB0.0125
    const std::string when = " at S/B = " + std::to_string(run.S_over_B()).substr(0, 6);
    for (ContourField field : scene.output.contour_fields) {
      const auto map = [&](const char* stem, const std::string& what, const char* label, const std::vector<double>& v) {
        const std::string w = write_contour_figure(run.options.output_dir, stem + std::string("_") + tag,
                                                   scene.name + ": " + what + when, label, scene.cell_size,
                                                   run.sim.particles().x, run.sim.particles().y, v,
                                                   field == ContourField::N);
        if (!w.empty()) std::fprintf(stderr, "warning: %s\n", w.c_str());
      };
      switch (field) {
        case ContourField::shear_strain: map("shear_strain", "shear strain", "max shear strain (engineering)", f.shear_strain); break;
        case ContourField::displacement: map("displacement", "displacement", "|u| [m]", f.displacement); break;
        case ContourField::fabric_norm: map("fabric_norm", "fabric norm |F|", "|F|", f.fabric_norm); break;
        case ContourField::N: map("N", "N = F:n / |F| (fabric against loading direction)", "N", f.N); break;
        case ContourField::void_ratio: map("void_ratio", "void ratio", "e", f.void_ratio); break;
      }
    }
  }
}

}  // namespace acst::mpm
