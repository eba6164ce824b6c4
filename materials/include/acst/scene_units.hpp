#pragma once
// The one place where scene/CSV strain units meet the model's (element-test scenes, their CSV
// and the reproducers the library writes): the scene and the CSV give
// strains in percent with engineering shear (gamma_ij = 2 eps_ij); the model holds fractions
// with tensor shear components (slots 3-5 = 12, 13, 23).
namespace acst::units {

inline double scene_strain_factor(int component) { return component >= 3 ? 0.005 : 0.01; }
// percent (engineering shear) -> model fraction (tensor shear)
inline double strain_from_scene(double value_pct, int component) { return value_pct * scene_strain_factor(component); }
// model fraction (tensor shear) -> percent (engineering shear)
inline double strain_to_scene(double value, int component) { return value / scene_strain_factor(component); }

}  // namespace acst::units
