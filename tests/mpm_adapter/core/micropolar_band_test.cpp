// The short version of the recorded biaxial study (studies/biaxial_band.py,
// bench/results/biaxial_regularised/; docs/mpm.md, "Micropolar rotations"): plane-strain
// compression of dense Toyoura sand (0.8 x 1.6 m, sigma_3 100 kPa, a looser square at mid-height
// on the left where the band starts) with the micropolar rotations at lc = 0.005 m, on cells of
// 0.05 and 0.1/3 m. The band and the load after the peak are properties of the sand, not of the
// cell: the axial stress ratio from 6 to 12 % axial strain within 3 % RMS (the issue's bound; 1.9 %
// when this test was written) and the band's equivalent area within 10 % (0.4 %). The local model
// on the same two cells is the contrast, outside both bounds: its curves differ by 21 % RMS and
// its band narrows with the cell (by 15 %). About 40 and 30 s in Release on one core each.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "footing_runs.hpp"
#include "mpm_scenes.hpp"

namespace mpm_micropolar_band_test {

using namespace acst::mpm;

constexpr double width = 0.8, height = 1.6, sigma3 = 100.0, platen_overhang = 0.6, strain_to = 0.125;  // past the last strain compared

// A number in full precision: the cell of 0.1/3 m must tile the sample exactly.
std::string num(double v) {
  std::ostringstream s;
  s << std::setprecision(17) << v;
  return s.str();
}

// The sample as biaxial_band.py builds it: Dr 85.6 % (e 0.6517 with the delivered set's e_max
// 0.977 and e_min 0.597), the weak square 0.05 looser, a rough base, free sides under sigma_3,
// a smooth platen wider than the sample.
std::string biaxial(double h, double lc) {
  const double e0 = 0.977 - 0.856 * (0.977 - 0.597);
  auto body = [&](const char* name, double x0, double x1, double y0, double y1, double e) {
    return std::string(R"({"name": ")") + name + R"(", "material": "sand", "density": 1600, "particles_per_cell": 1,
        "bedding_angle_deg": 0, "x_range": [)" + num(x0) + ", " + num(x1) + R"(], "y_range": [)" +
           num(y0) + ", " + num(y1) + R"(], "void_ratio": )" + num(e) + "}";
  };
  const double lo = 0.5, hi = 0.6, weak = 0.1;
  const std::string sand = std::string(ACST_SOURCE_DIR) + "/data/parameters/toyoura_acst_calibrated.json";
  const double B = width + platen_overhang;
  return R"({"name": "biaxial", "grid": {"cell_size": )" + num(h) + R"(, "cells_above": 4, "cells_beside": )" +
         std::to_string(static_cast<int>(std::ceil(0.3 / h))) + R"(}, "materials": {"sand": ")" + sand +
         R"("}, "bodies": [)" + body("below", 0, width, 0, lo, e0) + ", " + body("weak", 0, weak, lo, hi, e0 + 0.05) + ", " +
         body("beside", weak, width, lo, hi, e0) + ", " + body("above", 0, width, hi, height, e0) +
         R"(], "initial_stress": {"type": "isotropic", "p_kPa": 100}, "walls": {"base": "fixed", "sides": "none"},
         "confining_pressure_kPa": 100, "footing": {"width": )" + num(B) + R"(, "centre_x": 0.4, "speed": 0.1,
         "interface": "smooth", "ramp_S_over_B": 0.002}, "solver": {"stress_update": "first", "threads": 1},
         "stop": {"S_over_B": 1})" + (lc > 0 ? R"(, "micropolar": {"length_m": )" + num(lc) + "}" : "") + "}";
}

struct Biaxial {
  std::vector<double> strain, ratio;  // axial strain and sigma_1 / sigma_3, per period of 20 steps
  double band_area = 0.0;             // m^2: the equivalent area of the shear from 6 to 10 % axial strain
};

// The engineering shear strain of a particle's strain increment (xx, yy, xy tensor).
double shear(const std::vector<double>& a, const std::vector<double>& b, std::size_t p) {
  const double dxx = b[3 * p] - a[3 * p], dyy = b[3 * p + 1] - a[3 * p + 1], dxy = b[3 * p + 2] - a[3 * p + 2];
  return std::sqrt((dxx - dyy) * (dxx - dyy) + 4.0 * dxy * dxy);
}

// Runs the sample past 12 % axial strain. The band's equivalent area (sum g A)^2 / sum g^2 A of the
// shear increment g over the particles' areas A is the band's width times its length for a band
// of uniform shear, and needs no band direction or profile.
Biaxial run(double h, double lc) {
  Simulation s = mpm_test::build(biaxial(h, lc));
  Biaxial out;
  auto load_to = [&](double strain) {
    const auto reached = [&](const Simulation& x) { return x.footing().settlement() / height >= strain; };
    for (const mpm_test::Period& r : mpm_test::run(s, 20, reached)) {
      out.strain.push_back(r.S / height);
      out.ratio.push_back(r.V / width / sigma3);
    }
  };
  load_to(0.06);
  const std::vector<double> at6 = s.particles().strain;
  load_to(0.10);
  const Particles& P = s.particles();
  double sum = 0.0, squares = 0.0;
  for (std::size_t p = 0; p < P.n; ++p) {
    const double g = shear(at6, P.strain, p);
    sum += g * P.volume(p), squares += g * g * P.volume(p);
  }
  out.band_area = sum * sum / squares;
  load_to(strain_to);
  return out;
}

double ratio_at(const Biaxial& b, double strain) {
  for (std::size_t k = 1; k < b.strain.size(); ++k)
    if (b.strain[k] >= strain) {
      const double t = (strain - b.strain[k - 1]) / (b.strain[k] - b.strain[k - 1]);
      return b.ratio[k - 1] + t * (b.ratio[k] - b.ratio[k - 1]);
    }
  return NAN;
}

// RMS of the relative gap between two runs' stress ratios at 6, 7, ... 12 % axial strain.
double rms_gap(const Biaxial& a, const Biaxial& b) {
  double sum = 0.0;
  int n = 0;
  for (double e = 0.06; e <= 0.12 + 1e-9; e += 0.01, ++n) {
    const double x = ratio_at(a, e), y = ratio_at(b, e);
    sum += (x - y) * (x - y) / (y * y);
  }
  return std::sqrt(sum / n);
}

TEST(MicropolarBiaxial, TheBandAndTheLoadAfterThePeakHoldAcrossTheCell) {
  const Biaxial coarse = run(0.05, 0.005), fine = run(0.1 / 3, 0.005);
  const double peak_coarse = *std::max_element(coarse.ratio.begin(), coarse.ratio.end());
  EXPECT_GT(peak_coarse, 1.2 * ratio_at(coarse, 0.12)) << "the sand softens after its peak";
  EXPECT_LT(rms_gap(coarse, fine), 0.03);
  EXPECT_NEAR(fine.band_area / coarse.band_area, 1.0, 0.10)
      << "band areas " << coarse.band_area << " and " << fine.band_area << " m^2";
}

TEST(MicropolarBiaxial, TheLocalModelsBandAndLoadFollowTheCell) {
  const Biaxial local_coarse = run(0.05, 0.0), local_fine = run(0.1 / 3, 0.0);
  EXPECT_GT(rms_gap(local_coarse, local_fine), 0.03) << "the local curves after the peak follow the cell";
  EXPECT_LT(local_fine.band_area / local_coarse.band_area, 0.9)
      << "the local band, " << local_coarse.band_area << " and " << local_fine.band_area << " m^2, narrows with the cell";
}

}  // namespace mpm_micropolar_band_test
