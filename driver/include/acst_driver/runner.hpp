#pragma once
// Runs a scene: every step's increments by Newton iteration on the six control rows, with
// cut-back (halving) on failure, exit conditions located inside the crossing increment (to 1e-9
// of the quantity's change over it; the earliest crossing wins), and a one-increment reproducer
// scene when an increment fails at the smallest cut-back.
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "acst_driver/record.hpp"
#include "acst_driver/scene.hpp"

namespace acst::driver {

struct RunResult {
  bool ok = false;
  std::string message;          // on failure: where (step path, increment) and why
  std::vector<Record> records;  // the output rows (the initial state first); empty when streamed
  std::optional<nlohmann::json> reproducer;  // one-increment scene that replays the failure
  long increments = 0;          // accepted increments
  long iterations = 0, substeps = 0, cutbacks = 0;
};

// Called now and then with the accepted and the planned number of increments.
using ProgressFn = std::function<void(long done, long planned)>;

// Called with each output row as it is produced (the initial state first).
using RecordFn = std::function<void(const Record&)>;

// Runs the scene, handing each row to `on_record` and keeping none: the memory a run needs does
// not grow with its number of increments (acst_element writes the rows as they come).
RunResult stream_scene(const ElementScene& scene, const RecordFn& on_record, const ProgressFn& progress = {});

// The same with every row kept in the result's records (short runs: tests, calibration).
RunResult run_scene(const ElementScene& scene, const ProgressFn& progress = {});

// The quantity an exit condition watches, at a given stress, strain and excess pore pressure.
double exit_quantity(ExitQuantity q, const Sym& stress, const Sym& strain, double u_excess);

}  // namespace acst::driver
