// Throwaway diagnostic: micropolar skew/couple stresses carried by particles at the pressure floor.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include "acst_footing_tool/build_simulation.hpp"
using namespace acst::mpm;
int main(int argc, char** argv) {
  const double h = argc > 1 ? std::atof(argv[1]) : 0.18, stop = argc > 2 ? std::atof(argv[2]) : 0.3;
  const std::string mat = argc > 3 ? argv[3] : "toyoura_isotropic_calibrated";
  const std::string json = R"({"name": "diag", "grid": {"cell_size": )" + std::to_string(h) + R"(, "cells_above": 8},
    "materials": {"toyoura": ")" + std::string(ACST_SOURCE_DIR) + "/data/parameters/" + mat + R"(.json"},
    "bodies": [{"material": "toyoura", "x_range": [0, 12.6], "y_range": [0, 6.3], "density": 1600,
                "relative_density_pct": 85.6, "bedding_angle_deg": 0}],
    "gravity": 9.8, "initial_stress": {"type": "geostatic", "K0": 0.4},
    "walls": {"base": "fixed", "sides": "smooth"}, "micropolar": {"acceleration_level": 30},
    "footing": {"width": 0.9, "centre_x": 6.3, "speed": 0.045, "interface": "rough", "inclination_deg": -30},
    "solver": {"threads": 1}, "stop": {"S_over_B": 1}})";
  Simulation s = build_simulation(parse_scene(json));
  const double l = 0.0051;
  double next = 0.0;
  double vmax_all = 0, fsum = 0; long nsum = 0;
  while (s.footing().settlement() < stop * 0.9) {
    s.step();
    fsum += s.reaction(reaction_footing).fy; ++nsum;
    const Particles& P = s.particles();
    const auto& M = s.micropolar().state();
    int nf = 0;
    double skew_f = 0, couple_f = 0, skew_s = 0, vmax_f = 0, ymax = 0;
    for (std::size_t p = 0; p < P.n; ++p) {
      const double v = std::hypot(P.vx[p], P.vy[p]);
      if (P.stress_free[p]) {
        ++nf;
        skew_f = std::max(skew_f, std::fabs(M.skew_stress[p]));
        couple_f = std::max(couple_f, std::hypot(M.couple_x[p], M.couple_y[p]) / l);
        vmax_f = std::max(vmax_f, v);
      } else
        skew_s = std::max(skew_s, std::fabs(M.skew_stress[p]));
      ymax = std::max(ymax, P.y[p]);
    }
    vmax_all = std::max(vmax_all, vmax_f);
    const double sb = s.footing().settlement() / 0.9;
    if (sb >= next) {
      std::printf("S/B %.3f free %d  max|A| free %.2f kPa  max|m|/l free %.2f kPa  max|A| stressed %.1f  vmax free %.3f  ymax %.3f  q %.1f\n", sb, nf,
                  skew_f, couple_f, skew_s, vmax_f, ymax, -fsum / nsum / 900.0);
      fsum = 0; nsum = 0;
      std::fflush(stdout);
      next += 0.01;
    }
  }
  std::printf("fastest floor particle over the run %.3f m/s\n", vmax_all);
}
