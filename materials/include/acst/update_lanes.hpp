#pragma once
// Several points' stress updates at once, lane by lane in SIMD registers, for the two updates an
// MPM host asks for most (measured on the Kimura footing): a start on the yield surface loaded outwards with
// one modified-Euler substep accepted, and an elastic increment that one Heun step integrates. Each lane computes, operation for operation, what
// Material::update computes for its point, so a lane's result is the same to the last bit
// (tests/materials/update_lanes_test.cpp); a lane whose update takes any other route (a crossing of the
// surface, a rejected substep, a guard, a failure) is left for Material::update.
#include "acst/material.hpp"

namespace acst {

// Up to `width` points in the model's convention (compression positive, tensor shear), one
// array entry per lane.
struct UpdateLanes {
  static constexpr int width = 8;
  int n = 0;  // lanes in use, 0..width
  // In, and out where done:
  double stress[6][width];
  double fabric[6][width];
  double void_ratio[width];
  double H[width];
  double substep_hint[width];
  // In:
  double strain_increment[6][width];
  double void_ratio_offset[width];  // the host's nonlocal offset (Material::update), 0 where local
  // Out: 1 where the lane holds Material::update's result (status OK, no tangent), 0 where the
  // lane is as it came and Material::update must be called for it.
  int done[width];
  // The route of a done lane: 1 plastic (3 rate evaluations, 1 accepted substep and the guard
  // counts below), 0 elastic (2 rate evaluations, nothing else counted).
  int plastic[width];
  int guard_lode_clamp[width];
  int guard_h_floor[width];
};

// A point's state and strain increment into lane l, and lane l's state back out (all of State
// but the floor-reset count, which a lane never changes).
void put_lane(UpdateLanes& lanes, int l, const State& state, const Sym& strain_increment, double void_ratio_offset = 0.0);
void take_lane(const UpdateLanes& lanes, int l, State& state);

// The report Material::update gives for done lane l (status OK and the counters of its route);
// inline, so that a caller's copy of it is built in place.
inline integration::Report lane_report(const UpdateLanes& lanes, int l) {
  integration::Report rep;
  if (lanes.plastic[l]) {
    rep.plastic = true;
    rep.counters.rate_evaluations = 3;  // the elastic trial's rate and the two stages'
    rep.counters.substeps_accepted = 1;
    rep.counters.guard_lode_clamp = lanes.guard_lode_clamp[l];
    rep.counters.guard_h_floor = lanes.guard_h_floor[l];
  } else {
    rep.counters.rate_evaluations = 2;  // Heun's two elastic rates
  }
  return rep;
}

// Whether update_lanes can do anything for this material (ME without tangent, isotropic
// elasticity) in this build (x86-64 without ACST_NATIVE: materials/CMakeLists.txt); where not,
// every lane comes back not done.
bool lanes_apply(const Material& material);

// The kernel's builds: the best the CPU runs (AVX2 and FMA where it has them, on x86-64), or
// the one for any CPU of the architecture (for tests: both give the same numbers).
enum class LaneBuild { best, generic };

// Updates the lanes it can (done = 1) and leaves the others as they came (done = 0).
void update_lanes(const Material& material, UpdateLanes& lanes, LaneBuild build = LaneBuild::best);

}  // namespace acst
