#pragma once
// A failing (or any) stress update turned into an element-test scene that `acst_element`
// replays (docs/element-tests.md, "Cut-back and reproducers"): the material written out in
// full, the whole start state, and the strain increment as six strain-controlled rows of one
// increment without cut-back. Every host writes the same: the element driver, the MPM and any
// C or umat_ host through acst_reproducer / acst_umat_reproducer (docs/c-abi.md).
#include <nlohmann/json.hpp>
#include <string>

#include "acst/material.hpp"

namespace acst {

// {"model", "parameters" (every row of the parameter table), "integrator" (every option)}:
// Material::from_json of it gives the same material (doubles round-trip exactly).
nlohmann::json material_document(const Material& material);

// The one-increment scene; `strain_increment` in the model's convention (compression positive,
// tensor shear); a nonlocal update's offset (Material::update) goes into the initial state.
nlohmann::json update_reproducer(const Material& material, const State& start, const Sym& strain_increment,
                                 const std::string& description, double void_ratio_offset = 0.0);

}  // namespace acst
