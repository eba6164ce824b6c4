#pragma once
#include <cstddef>
#include <vector>

namespace acst::mpm {

// Particle data in flat arrays (structure of arrays). A step feature keeps its own per-particle
// fields in its unit (MicropolarRotations, Regulariser; README, "Add a step feature").
struct Particles {
  std::size_t n = 0;
  int state_size = 0;
  std::vector<double> x, y, x_initial, y_initial, vx, vy;
  std::vector<double> mass, weight_mass, volume_initial;  // mass = inertial (scaled) mass
  std::vector<double> density;                             // initial density, kg/m^3
  std::vector<double> F;        // deformation gradient, 4 per particle (xx xy yx yy)
  std::vector<double> stress;   // 6 per particle, kPa, tension positive
  std::vector<double> strain;   // accumulated small strain, 3 per particle (xx yy xy tensor)
  std::vector<double> statev;   // state_size per particle
  std::vector<double> surcharge_length;  // top-edge length loaded by the surcharge (0: none)
  // Side length loaded by the confining pressure (undeformed; + on a left side, pushed toward +x,
  // - on a right one; 0: none).
  std::vector<double> side_length;
  std::vector<double> wave_speed;
  std::vector<int> material;    // index into Simulation::materials
  std::vector<int> stress_free;  // 1 while the material holds it at its pressure floor (docs/mpm.md)
  // Particles whose history is recorded (output/particle_histories), and per each its material
  // frame: material_frame_size values (material_frame.hpp), checkpointed with the rest.
  std::vector<int> tracked;
  std::vector<double> track_frame;

  void resize(std::size_t count, int state_size);
  double volume(std::size_t p) const;
};

}  // namespace acst::mpm
