#pragma once
// What a run records besides the simulation: the load-settlement rows, the peak's snapshot, the
// followed particles' rows, and the run's own counters; all of it is checkpointed.
#include <vector>

#include "acst_footing_tool/particle_histories.hpp"

namespace acst::mpm {

// One row of the load-settlement record: footing loads averaged over one period of steps.
// V is the vertical load the footing applies to the soil (positive downward), H the horizontal
// one (positive toward +x), both per metre out of plane; M its moment about the centre of the
// footing's base (counter-clockwise positive); penetration the deepest overlap in the period.
struct LoadRecord {
  long long step = 0;
  double time = 0, settlement = 0, S_over_B = 0;
  double V_kN_per_m = 0, H_kN_per_m = 0, M_kNm_per_m = 0, q_kPa = 0, penetration_m = 0;
  double kinetic_J_per_m = 0, footing_work_J_per_m = 0;
};

// Particle positions and contour fields kept at the peak load.
struct Snapshot {
  double S_over_B = 0, V_kN_per_m = 0;
  std::vector<double> x, y, shear_strain, displacement;
};

// Everything besides the simulation that a checkpoint must hold to continue identically.
struct RunState {
  std::vector<LoadRecord> history;
  std::vector<LoadRecord> every_step;  // only with output.every_step_csv
  double sum_V = 0, sum_H = 0, sum_M = 0, max_penetration = 0;
  long long period_steps = 0;
  int vtk_frames = 0;
  std::vector<double> vtk_times;       // simulation time of each frame (for the .pvd)
  std::vector<int> contours_done;      // per requested S/B
  Snapshot peak;
  std::vector<TrackRecord> tracks;     // the followed particles' rows: at the start and per record row
};

}  // namespace acst::mpm
