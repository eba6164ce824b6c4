// The size of a scene's run (see scene.hpp), and the check against the caps.
#include "acst_common/json_fields.hpp"
#include "acst_driver/scene.hpp"

namespace acst::driver {

ElementSceneSize scene_size(const std::vector<Block>& blocks, int every) {
  ElementSceneSize size;
  double segment_ends = 0.0;
  for (const Block& b : blocks) {
    double increments = 0.0, segments = 0.0;
    for (const Step& s : b.steps)
      for (const Segment& g : s.segments) {
        increments += g.increments;
        segments += 1.0;
      }
    size.increments += increments * b.cycles;
    segment_ends += segments * b.cycles;
  }
  size.rows = size.increments / every + segment_ends;
  return size;
}

void check_scene_size(const std::vector<Block>& blocks, int every) {
  namespace f = common::fields;
  const ElementSceneSize size = scene_size(blocks, every);
  if (size.increments > max_total_increments) {
    // Name the block that asks for the most.
    const Block* largest = nullptr;
    double most = -1.0, per_cycle_of_largest = 0.0;
    for (const Block& b : blocks) {
      const double per_cycle = scene_size({b}, 1).increments / b.cycles;
      if (per_cycle * b.cycles > most) most = per_cycle * b.cycles, largest = &b, per_cycle_of_largest = per_cycle;
    }
    std::string share = largest->path + ": " + f::shown(per_cycle_of_largest) + " increments";
    if (largest->repeat) share += " per cycle x " + std::to_string(largest->cycles) + " cycles";
    f::fail("/steps", "the scene asks for " + f::shown(size.increments) + " increments in all (most of them " + share +
                          "), more than the " + f::shown(max_total_increments) + " a run may have");
  }
  if (size.rows > max_csv_rows)
    f::fail("/output/every", "the run would write about " + f::shown(size.rows) + " CSV rows (" +
                                 f::shown(size.increments) + " increments, every " + std::to_string(every) +
                                 "-th written, and every step's end), more than the " + f::shown(max_csv_rows) +
                                 " allowed; write fewer rows with a larger output.every");
}

}  // namespace acst::driver
