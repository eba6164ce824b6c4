#pragma once
// The MPM solver's settings (the scene's /solver, /gravity, /grid/follow_footing and
// /regularisation; docs/mpm.md).
#include "acst_mpm/nonlocal_average.hpp"

namespace acst::mpm {

enum class ParticleUpdate { FLIP, PIC, XPIC };

// When the material is called in a step (docs/mpm.md, "One step"): two halves around the particle
// update (update-stress-average, the default), or once with the whole step before the internal
// force (update-stress-first) or after the momentum is re-mapped (modified update-stress-last):
// half the material calls.
enum class StressUpdate { average, first, last };

// The particles' dilation rates as the velocity field gives them, or each cell's mean (against
// volumetric locking at several particles per cell; docs/mpm.md, "Volumetric locking").
enum class VolumetricAveraging { none, cell };

// What the sand's regularisation averages (docs/mpm.md, "Nonlocal regularisation"): the changes
// of the void ratio between averagings, summed into each particle's nonlocal void ratio (its
// initial value its own), or the void ratio itself.
enum class NonlocalQuantity { void_ratio_increments, void_ratio };

// The sand's nonlocal regularisation: its internal length l (m; 0: the local model), the kernel,
// what is averaged, the over-nonlocal factor m (the state parameter takes (1 - m) e + m e_mean:
// m = 1 the plain average, m > 1 Vermeer & Brinkgreve's over-nonlocal form) and every how many
// steps.
struct Regularisation {
  double internal_length = 0.0;
  NonlocalKernel kernel = NonlocalKernel::galavi_schweiger;
  NonlocalQuantity quantity = NonlocalQuantity::void_ratio_increments;
  double over_nonlocal = 1.0;
  int every = 20;
};

// Micropolar (Cosserat) rotations of the soil (docs/mpm.md, "Micropolar rotations"): every
// particle carries a micro-rotation besides its motion, with an elastic energy density
// 1/2 k (theta_M - theta)^2 + 1/2 k l^2 |grad theta|^2 (theta_M the continuum's rotation,
// k = modulus_ratio rho c^2 from the material's wave speed c) and a micro-inertia l^2 per unit
// mass (at least a finest cell's square). The material's stress stays the symmetric part; length
// 0 (the default) is the classical continuum, to the bit.
struct Micropolar {
  double length = 0.0;         // l, m
  double modulus_ratio = 0.5;  // k / (rho c^2)
  bool active() const { return length > 0.0; }
};

struct Settings {
  double cfl = 0.5;
  ParticleUpdate update = ParticleUpdate::XPIC;
  StressUpdate stress_update = StressUpdate::average;
  VolumetricAveraging volumetric_averaging = VolumetricAveraging::none;
  int xpic_order = 4;   // m of XPIC(m)
  int xpic_every = 20;  // XPIC on every k-th step, FLIP between
  double grid_damping = 0.5;      // alpha_g, 1/s
  double particle_damping = 0.0;  // alpha_p, 1/s
  int wave_speed_every = 100;     // steps between refreshes of the particles' wave speeds
  bool grid_follows_footing = false;  // grid/follow_footing: a node row stays on the footing's base
  double mass_scaling = 1.0;      // inertial mass x this factor (weight unchanged)
  double gravity = 0.0;           // m/s^2, acting in -y
  int threads = 0;                // 0: OpenMP default
  Regularisation regularisation;
  Micropolar micropolar;
};

}  // namespace acst::mpm
