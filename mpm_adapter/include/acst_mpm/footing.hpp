#pragma once
// The rigid strip footing as one boundary unit: a rough (or smooth) footing driven at a
// constant speed at `inclination` (rad) from the downward vertical, toward +x for positive
// angles: velocity = speed (sin b, -cos b). Grid nodes inside its footprint and at or above its
// base (nearest node row) move with it. A contact formulation replaces this unit alone.
#include "acst_mpm/grid.hpp"

namespace acst::mpm {

class Footing {
 public:
  struct Spec {
    double centre_x = 0.0, width = 0.0, base_y = 0.0;  // base_y: the soil surface under it
    double speed = 0.0, inclination = 0.0;
    bool rough = true;
  };
  // How far it has moved and the work it has done on the soil (checkpointed).
  struct Motion {
    double dx = 0.0, dy = 0.0, work = 0.0;  // m, m, J/m
  };

  Footing() = default;
  explicit Footing(const Spec& spec) : spec_(spec), active_(true) {}

  bool active() const { return active_; }
  const Spec& spec() const { return spec_; }
  Motion& motion() { return motion_; }
  const Motion& motion() const { return motion_; }
  double base_y() const { return spec_.base_y + motion_.dy; }
  double settlement() const { return -motion_.dy; }

  // Prescribes its velocity on the nodes it covers (reaction set reaction_footing).
  void constrain(const Grid& grid, NodeConstraints& c) const;
  // Moves on by its velocity over dt; `on_soil` is the force it exerts on the soil (N/m).
  void advance(const Reaction& on_soil, double dt);

 private:
  double vx() const;
  double vy() const;
  Spec spec_;
  Motion motion_;
  bool active_ = false;
};

}  // namespace acst::mpm
