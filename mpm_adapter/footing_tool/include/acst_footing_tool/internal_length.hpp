#pragma once
// The default internal length of the sand's regularisation (docs/mpm.md, "Nonlocal
// regularisation"), from the grains, never from a footing: the length at which the regularised
// model's shear band is as thick as a sand's measured one.
//
// Shear bands of Toyoura sand in plane-strain compression are about 10 to 20 mean grain sizes
// thick at the peak (Yoshida & Tatsuoka 1997, Proc. 14th ICSMFE Hamburg 1: 237-240; Oda & Kazama
// 1998, Geotechnique 48(4): 465-481, for sands in general): 15 d50 is taken. A centrifuge model at
// N g with unscaled grains has the band of grains N times larger in prototype units. The model's
// band is about `band_per_length` internal lengths thick (measured in the MPM's biaxial test,
// docs/footing-study.md, "The regularised biaxial test").
namespace acst::mpm {

inline constexpr double toyoura_d50_mm = 0.17;  // Toyoura sand's d50 (0.16-0.19 mm in the sources)
inline constexpr double band_thickness_in_d50 = 15.0;
inline constexpr double band_per_length = 0.9;

// l (m) for grains of d50 (mm) in a model at `acceleration_level` g.
inline double internal_length_from_grains(double d50_mm, double acceleration_level) {
  return band_thickness_in_d50 * d50_mm * 1e-3 * acceleration_level / band_per_length;
}

// The micropolar rotations' length (docs/mpm.md, "Micropolar rotations"), m: the mean grain
// diameter, as the Cosserat models of sand take it (Muhlhaus & Vardoulakis 1987, Geotechnique
// 37(3): 271-283; Tejchman & Wu 1993, Acta Mech. 99: 61-74), N times larger in prototype units at
// N g. Not matched to a band: the band the rotations then give is measured
// (docs/footing-study.md, "Micropolar rotations").
inline double micropolar_length_from_grains(double d50_mm, double acceleration_level) {
  return d50_mm * 1e-3 * acceleration_level;
}

}  // namespace acst::mpm
