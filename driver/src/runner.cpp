// Runs the blocks and steps of a scene increment by increment (see runner.hpp).
#include "acst_driver/runner.hpp"

#include <Eigen/LU>
#include <cmath>

#include "acst_driver/presets.hpp"
#include "acst/scene_units.hpp"

namespace acst::driver {

using nlohmann::json;

double exit_quantity(ExitQuantity q, const Sym& stress, const Sym& strain, double u_excess) {
  switch (q) {
    case ExitQuantity::q: return signed_q(stress);
    case ExitQuantity::stress_ratio: return stress_ratio_of(stress);
    case ExitQuantity::p: return mean_stress(stress);
    case ExitQuantity::axial_strain_pct: return axial_strain_pct(strain);
    case ExitQuantity::volumetric_strain_pct: return volumetric_strain_pct(strain);
    case ExitQuantity::excess_pore_pressure: return u_excess;
  }
  return 0.0;
}

namespace {

// Where the test is: material state, strain since the start, excess pore pressure.
struct Point {
  State state;
  Sym strain = Sym::Zero();
  double u_excess = 0.0;
};

struct Work {
  int iterations = 0, substeps = 0, cutbacks = 0;
};

// What a failed increment leaves for the message and the reproducer.
struct Failure {
  State state;
  LinearControl control;
  Sym guess;
  IncrementResult result;
  double piece = 1.0;
  bool over_budget = false;  // stopped by solver/max_cutbacks, not by max_halvings
};

double signed_margin(const ExitCondition& c, const Point& pt) {  // >= 0 when the condition is met
  const double v = exit_quantity(c.quantity, pt.state.stress, pt.strain, pt.u_excess);
  return c.above ? v - c.threshold : c.threshold - v;
}

class Runner {
 public:
  Runner(const ElementScene& scene, const RecordFn& on_record, const ProgressFn& progress)
      : scene_(scene), mat_(*scene.material), on_record_(on_record), progress_(progress) {}

  RunResult run() {
    const InitialState& is = scene_.initial;
    pt_.state = mat_.initial_state(is.stress, is.void_ratio, is.deposition_direction);
    if (is.fabric) pt_.state.fabric = *is.fabric;
    if (is.H) pt_.state.H = *is.H;
    if (is.substep_hint) pt_.state.substep_hint = *is.substep_hint;
    planned_ = static_cast<long>(scene_size(scene_.blocks, 1).increments);  // below max_total_increments
    record("start", {}, 0, 1, 0);
    result_.ok = true;
    for (std::size_t i = 0; i < scene_.blocks.size() && result_.ok; ++i) run_block(scene_.blocks[i], static_cast<int>(i));
    if (progress_) progress_(result_.increments, planned_);
    return std::move(result_);
  }

 private:
  enum class End { completed, exit_step, exit_block, failed };

  const ElementScene& scene_;
  const Material& mat_;
  const RecordFn& on_record_;
  const ProgressFn& progress_;
  RunResult result_;
  Point pt_;
  Sym guess_unit_ = Sym::Zero();  // last converged strain increment per unit of increment
  double time_ = 0.0;
  long planned_ = 0;

  void run_block(const Block& b, int index) {
    for (int cycle = 1; cycle <= b.cycles; ++cycle) {
      for (std::size_t k = 0; k < b.steps.size(); ++k) {
        const End e = run_step(b.steps[k], b, index, cycle, b.repeat ? static_cast<int>(k) : 0);
        if (e == End::failed || e == End::exit_block) return;
      }
    }
  }

  // The exit conditions watched during a step: its own, then its block's.
  std::vector<std::pair<const ExitCondition*, bool>> watched(const Step& s, const Block& b) const {
    std::vector<std::pair<const ExitCondition*, bool>> w;
    for (const auto& c : s.exits) w.emplace_back(&c, false);
    for (const auto& c : b.exits) w.emplace_back(&c, true);
    return w;
  }

  End run_step(const Step& s, const Block& b, int block_index, int cycle, int stage) {
    const auto exits = watched(s, b);
    for (const auto& [c, of_block] : exits)  // already met at the start: the step does nothing
      if (signed_margin(*c, pt_) >= 0.0) return of_block ? End::exit_block : End::exit_step;
    long total = 0;
    for (const Segment& g : s.segments) total += g.increments;
    bool first = true;
    for (const Segment& g : s.segments) {
      // Each increment aims at the row values of the path (start + k/n of the change), not at
      // a fixed change per increment: Newton residuals do not accumulate over the step.
      const Sym start = row_values(g.rows, pt_);
      Sym change;
      for (int i = 0; i < 6; ++i) change[i] = g.rows.absolute[i] ? g.rows.value[i] - start[i] : g.rows.value[i];
      LinearControl inc;
      inc.A = g.rows.A;
      inc.B = g.rows.B;
      for (int k = 1; k <= g.increments; ++k) {
        const double to = k == g.increments ? 1.0 : static_cast<double>(k) / g.increments;
        inc.c = start + to * change - row_values(g.rows, pt_);
        if (first) guess_unit_ = s.newton_guess ? *s.newton_guess : elastic_prediction(inc);
        first = false;
        const Point before = pt_;
        const Sym guess_before = guess_unit_;
        Work w;
        Failure fail;
        if (!advance(pt_, inc, s.undrained, w, &fail)) {
          fail_with(s, k, g.increments, fail);
          return End::failed;
        }
        ++result_.increments;
        double fraction = 1.0;
        const ExitCondition* met = nullptr;
        End end = End::completed;
        // Conditions crossed in this increment: the step ends at the earliest crossing.
        const Point after = pt_;
        Point earliest = pt_;
        for (const auto& [c, of_block] : exits) {
          if (signed_margin(*c, after) < 0.0) continue;
          pt_ = after;
          double f = 1.0;
          locate_exit(*c, before, guess_before, inc, s.undrained, w, f);
          if (met == nullptr || f < fraction) {
            fraction = f;
            earliest = pt_;
            met = c;
            end = of_block ? End::exit_block : End::exit_step;
          }
        }
        pt_ = earliest;
        time_ += fraction / static_cast<double>(total);
        result_.iterations += w.iterations;
        result_.substeps += w.substeps;
        result_.cutbacks += w.cutbacks;
        const bool last = k == g.increments || end != End::completed;
        if (last || w.cutbacks > 0 || result_.increments % scene_.output.every == 0)
          record(met ? "exit:" + met->key : w.cutbacks > 0 ? "cutback" : "ok", w, block_index, cycle, stage);
        if (progress_ && (result_.increments & 255) == 0) progress_(result_.increments, planned_);
        if (end != End::completed) return end;
      }
    }
    return End::completed;
  }

  static Sym row_values(const ControlRows& rows, const Point& pt) { return rows.A * pt.state.stress + rows.B * pt.strain; }

  // First Newton guess of a step: the strain increment an elastic stiffness gives.
  Sym elastic_prediction(const LinearControl& inc) const {
    const Mat6 D = mat_.tangent(pt_.state, false, Sym::Zero());
    const Eigen::FullPivLU<Mat6> lu(inc.A * D + inc.B);
    return lu.isInvertible() ? Sym(lu.solve(inc.c)) : Sym(Sym::Zero());
  }

  // One increment (all of inc.c) with cut-back: on failure the remaining part is halved, up to
  // max_halvings times; after a success the piece grows back by doubling. Each piece aims at the
  // row values of its end point along the increment, so piece residuals do not add up.
  bool advance(Point& pt, const LinearControl& inc, bool undrained, Work& w, Failure* fail) {
    const int max_level = scene_.solver.max_halvings;
    const Sym start = inc.A * pt.state.stress + inc.B * pt.strain;  // pieces aim along the increment
    double done = 0.0, piece = 1.0;
    int level = 0;
    while (done < 1.0) {
      piece = std::min(piece, 1.0 - done);
      LinearControl c = inc;
      c.c = start + (done + piece) * inc.c - (inc.A * pt.state.stress + inc.B * pt.strain);
      const Sym guess = guess_unit_ * piece;
      State s = pt.state;
      const IncrementResult r = solve_increment(mat_, s, c, guess, scene_.solver.newton, scene_.initial.void_ratio_offset);
      w.iterations += r.iterations;
      w.substeps += r.material.counters.substeps_accepted;
      if (r.converged) {
        if (undrained) pt.u_excess -= 0.5 * ((s.stress[1] - pt.state.stress[1]) + (s.stress[2] - pt.state.stress[2]));
        pt.state = s;
        pt.strain += r.strain_increment;
        done += piece;
        guess_unit_ = r.strain_increment / piece;
        if (level > 0) {
          --level;
          piece *= 2.0;
        }
        continue;
      }
      const long budget = scene_.solver.max_cutbacks;
      const bool over_budget = budget > 0 && result_.cutbacks + w.cutbacks >= budget;
      if (level >= max_level || over_budget) {
        if (fail) *fail = {pt.state, c, guess, r, piece, over_budget};
        return false;
      }
      ++level;
      ++w.cutbacks;
      piece *= 0.5;
    }
    return true;
  }

  // The increment crossed an exit condition: find the fraction s of it at which the condition
  // is just met (Illinois false position on its margin), and leave pt_ there.
  void locate_exit(const ExitCondition& c, const Point& before, const Sym& guess_before, const LinearControl& inc,
                   bool undrained, Work& w, double& fraction) {
    const Sym guess_after = guess_unit_;
    double a = 0.0, fa = signed_margin(c, before), b = 1.0, fb = signed_margin(c, pt_);
    Point best = pt_;
    const double tol = 1e-9 * (fb - fa);
    int side = 0;
    for (int it = 0; it < 60 && fb > tol && b - a > 1e-14; ++it) {
      double s = (a * fb - b * fa) / (fb - fa);
      if (!(s > a && s < b)) s = 0.5 * (a + b);
      Point trial = before;
      guess_unit_ = guess_before * s;
      LinearControl part = inc;
      part.c = inc.c * s;
      if (!advance(trial, part, undrained, w, nullptr)) break;  // keep the met end found so far
      const double fs = signed_margin(c, trial);
      if (fs >= 0.0) {
        b = s;
        fb = fs;
        best = trial;
        if (side == 1) fa *= 0.5;
        side = 1;
      } else {
        a = s;
        fa = fs;
        if (side == -1) fb *= 0.5;
        side = -1;
      }
    }
    pt_ = best;
    guess_unit_ = guess_after;
    fraction = b;
  }

  void record(const std::string& status, const Work& w, int step, int cycle, int stage) {
    Record r;
    r.increment = result_.increments;
    r.time = time_;
    r.step = step;
    r.cycle = cycle;
    r.stage = stage;
    r.strain = pt_.strain;
    r.stress = pt_.state.stress;
    r.void_ratio = pt_.state.void_ratio;
    r.u_excess = pt_.u_excess;
    const Diagnostics d = mat_.diagnostics(pt_.state, guess_unit_);
    r.psi = d.psi;
    r.zeta = d.zeta;
    r.A = d.A;
    r.fabric_norm = d.fabric_norm;
    r.substeps = w.substeps;
    r.iterations = w.iterations;
    r.cutbacks = w.cutbacks;
    r.status = status;
    on_record_(r);
  }

  static json vector_json(const Sym& v) { return json::array({v[0], v[1], v[2], v[3], v[4], v[5]}); }

  void fail_with(const Step& s, int k, int n, const Failure& f) {
    result_.ok = false;
    std::string why = failure_text(f.result.failure);
    if (f.result.failure == IncrementFailure::material)
      why += std::string(" (") + integration::status_name(f.result.material.status) + ": " +
             integration::reason_text(f.result.material.reason) + ")";
    char piece[64];
    std::snprintf(piece, sizeof piece, "%.3g", f.piece);
    const std::string stopped_by =
        f.over_budget ? std::to_string(scene_.solver.max_cutbacks) + " cut-backs in this run (solver/max_cutbacks)"
                      : std::to_string(scene_.solver.max_halvings) + " halvings";
    result_.message = s.path + " (" + s.kind + "), increment " + std::to_string(k) + " of " + std::to_string(n) +
                      ": " + why + " after " + std::to_string(f.result.iterations) + " Newton iterations, at " +
                      piece + " of the increment after " + stopped_by + "; the state is the last converged one";
    // A one-increment scene that replays it: the full state, the failing piece as six
    // constraints in scene units, the same first Newton guess, and no cut-back.
    json rows = json::array();
    for (int i = 0; i < 6; ++i) {
      json strain = json::array();
      for (int j = 0; j < 6; ++j) strain.push_back(f.control.B(i, j) * units::scene_strain_factor(j));
      json stress = json::array();
      for (int j = 0; j < 6; ++j) stress.push_back(f.control.A(i, j));
      rows.push_back({{"stress", stress}, {"strain_pct", strain}, {"change", f.control.c[i]}});
    }
    json guess = json::array();
    for (int j = 0; j < 6; ++j) guess.push_back(units::strain_to_scene(f.guess[j], j));
    json step = {{"constraints", rows}, {"increments", 1}, {"newton_guess_strain_pct", guess}};
    if (s.undrained) step["undrained"] = true;
    const NewtonOptions& o = scene_.solver.newton;
    json repro = {
        {"description", "One-increment reproducer of a failure of " +
                            (scene_.source.empty() ? std::string("a scene") : scene_.source) + ": " + result_.message},
        {"material", scene_.material_json},
        {"initial_state",
         {{"stress", vector_json(f.state.stress)},
          {"void_ratio", f.state.void_ratio},
          {"fabric", vector_json(f.state.fabric)},
          {"H", f.state.H},
          {"substep_hint", f.state.substep_hint}}},
        {"steps", json::array({step})},
        {"solver",
         {{"max_iterations", o.max_iterations},
          {"stress_tolerance", o.stress_tolerance},
          {"strain_tolerance", o.strain_tolerance},
          {"max_halvings", 0}}},
        {"output", {{"name", scene_.output.name + "_reproducer"}, {"plot", false}}}};
    if (scene_.initial.void_ratio_offset != 0.0) repro["initial_state"]["void_ratio_offset"] = scene_.initial.void_ratio_offset;
    result_.reproducer = repro;
  }
};

}  // namespace

RunResult stream_scene(const ElementScene& scene, const RecordFn& on_record, const ProgressFn& progress) {
  return Runner(scene, on_record, progress).run();
}

RunResult run_scene(const ElementScene& scene, const ProgressFn& progress) {
  std::vector<Record> records;
  RunResult r = stream_scene(scene, [&](const Record& rec) { records.push_back(rec); }, progress);
  r.records = std::move(records);
  return r;
}

}  // namespace acst::driver
