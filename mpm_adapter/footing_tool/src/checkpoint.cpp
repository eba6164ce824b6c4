#include "acst_footing_tool/checkpoint.hpp"
#include "acst_mpm/material_frame.hpp"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "acst_common/checksum.hpp"
#include "acst_common/files.hpp"
#include "acst_common/input_error.hpp"

namespace acst::mpm {
namespace {

constexpr std::uintmax_t max_checkpoint_bytes = std::uintmax_t{16} << 30;

// Layout (docs/mpm.md, "Checkpoints"): magic, scene text, material records, particle arrays, run
// fields, then the FNV-1a checksum of everything before it.
constexpr char magic[8] = {'A', 'C', 'S', 'T', 'M', 'P', 'M', '8'};
constexpr std::size_t checksum_bytes = sizeof(std::uint64_t);

struct Writer {
  std::string out;
  template <class T>
  void pod(const T& v) {
    static_assert(std::is_trivially_copyable<T>::value, "plain data only");
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
  void flag(const bool& v) { pod<std::uint8_t>(v ? 1 : 0); }
  template <class T>
  void vec(const std::vector<T>& v) {
    pod<std::uint64_t>(v.size());
    out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  void str(const std::string& s) {
    pod<std::uint64_t>(s.size());
    out += s;
  }
};

// Every refusal is the user's bad input (exit 2): a damaged file, or one of another run.
struct Reader {
  const std::string& in;
  std::size_t end;  // where the checksum starts
  std::string file;
  std::size_t at = sizeof magic;
  [[noreturn]] void refuse(const std::string& why) const {
    throw CheckpointError("--resume: the checkpoint '" + file + "' " + why);
  }
  void need(std::size_t n) {
    if (n > end - at) refuse("is truncated");
  }
  template <class T>
  void pod(T& v) {
    need(sizeof v);
    std::memcpy(&v, in.data() + at, sizeof v);
    at += sizeof v;
  }
  void flag(bool& v) {  // a byte other than 0 or 1 is no bool: reading it as one is undefined
    std::uint8_t b = 0;
    pod(b);
    if (b > 1) refuse("holds a flag that is neither 0 nor 1");
    v = b == 1;
  }
  template <class T>
  void vec(std::vector<T>& v) {
    std::uint64_t n = 0;
    pod(n);
    if (n > (end - at) / sizeof(T)) refuse("is truncated");
    v.resize(n);
    if (n > 0) std::memcpy(v.data(), in.data() + at, n * sizeof(T));  // data() may be null when empty
    at += n * sizeof(T);
  }
  std::string str() {
    std::uint64_t n = 0;
    pod(n);
    need(n);
    std::string s = in.substr(at, n);
    at += n;
    return s;
  }
};

// One list of the evolving particle arrays, the step features' among them, shared by writer
// (const) and reader; in the order of the format's first version, when the features' fields were
// the particles'.
template <class P, class S, class F>
void particle_arrays(P& particles, S& features, F&& f) {
  auto& p = particles;
  auto& r = features.regularisation;
  auto& m = features.micropolar;
  for (auto* v : {&p.x, &p.y, &p.x_initial, &p.y_initial, &p.vx, &p.vy, &p.mass, &p.weight_mass, &p.volume_initial,
                  &p.density, &p.F, &p.stress, &p.strain, &p.statev, &p.surcharge_length, &p.side_length,
                  &p.wave_speed, &r.offset, &r.averaged, &p.track_frame, &m.spin, &m.skew_stress, &m.couple_x,
                  &m.couple_y})
    f(*v);
  f(p.material);
  f(p.stress_free);
  f(p.tracked);
}

// Plain values in the order given (a fold over the comma is sequenced left to right).
template <class IO, class... T>
void pods(IO& io, T&... values) {
  (io.pod(values), ...);
}

template <class IO, class C, class M, class V, class State>
void run_fields(IO& io, C& clock, M& motion, V& friction, State& st) {
  pods(io, clock.step, clock.time, clock.dt, motion.dx, motion.dy, motion.work);
  io.flag(motion.unloading);
  io.vec(friction);
  io.vec(st.history);
  io.vec(st.every_step);
  pods(io, st.sum_V, st.sum_H, st.sum_M, st.max_penetration, st.period_steps, st.vtk_frames);
  io.vec(st.vtk_times);
  io.vec(st.contours_done);
  pods(io, st.peak.S_over_B, st.peak.V_kN_per_m);
  for (auto* v : {&st.peak.x, &st.peak.y, &st.peak.shear_strain, &st.peak.displacement}) io.vec(*v);
  io.vec(st.tracks);
}

bool all_finite(const std::vector<double>& v) {
  for (const double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

// A step count a run can go on from: a forged one at the type's largest value would overflow at
// the next step.
bool step_in_range(long long step) { return step >= 0 && step <= max_checkpoint_steps; }

// A strain no soil reaches (1000 = 100 000 %): past it a followed particle's frame is not a run's.
constexpr double max_frame_strain = 1e3;

bool track_finite(const TrackRecord& t) {
  bool finite = std::isfinite(t.time) && std::isfinite(t.S_over_B) && std::isfinite(t.x) && std::isfinite(t.y) &&
                std::isfinite(t.rotation_rad) && std::isfinite(t.void_ratio) && std::isfinite(t.H) &&
                std::isfinite(t.fabric_norm) && std::isfinite(t.A) && step_in_range(t.step);
  for (const double* v : {t.strain, t.strain + 1, t.strain + 2}) finite = finite && std::isfinite(*v);
  for (int i = 0; i < 6; ++i) finite = finite && std::isfinite(t.stress[i]) && std::isfinite(t.fabric[i]);
  return finite;
}

bool record_finite(const LoadRecord& r) {
  for (const double x : {r.time, r.settlement, r.S_over_B, r.V_kN_per_m, r.H_kN_per_m, r.M_kNm_per_m, r.q_kPa,
                         r.penetration_m, r.kinetic_J_per_m, r.footing_work_J_per_m})
    if (!std::isfinite(x)) return false;
  return step_in_range(r.step);
}

// What the checksum cannot promise for a file that was written so (a bug, or made by hand): every
// number a run goes on with is finite and in its range, every index points into its array.
void check_restored(const Reader& r, const Scene& scene, const Simulation& sim, const Particles& P,
                    const FeatureState& features, const Clock& clock,
                    const Footing::Motion& motion, const std::vector<double>& friction, const RunState& st) {
  if (!step_in_range(clock.step) || !std::isfinite(clock.time) || clock.time < 0 || !std::isfinite(clock.dt) || clock.dt < 0)
    r.refuse("holds an impossible clock (step " + std::to_string(clock.step) + ", time " + std::to_string(clock.time) + ")");
  if (!std::isfinite(motion.dx) || !std::isfinite(motion.dy) || !std::isfinite(motion.work))
    r.refuse("holds a non-finite footing motion");
  if ((!friction.empty() && friction.size() != P.n) || !all_finite(friction))
    r.refuse("holds an impossible friction of the footing's base");
  particle_arrays(P, features, [&](const auto& v) {
    if constexpr (std::is_same_v<std::decay_t<decltype(v)>, std::vector<double>>)
      if (!all_finite(v)) r.refuse("holds a non-finite particle value");
  });
  if (P.tracked != sim.particles().tracked) r.refuse("follows other particles than the scene's particle_histories");
  // A followed particle's frame: the cosine and sine of a rotation (a unit pair, to the rounding
  // of many turns) and its strain (a 1e300 under a good checksum gave non-finite histories).
  if (P.track_frame.size() != static_cast<std::size_t>(material_frame_size) * P.tracked.size())
    r.refuse("holds particle-history frames of the wrong size");
  for (std::size_t k = 0; k < P.tracked.size(); ++k) {
    const double* frame = &P.track_frame[static_cast<std::size_t>(material_frame_size) * k];
    const bool turn = std::fabs(frame[0] * frame[0] + frame[1] * frame[1] - 1.0) <= 1e-6;
    const bool strain = std::fabs(frame[2]) <= max_frame_strain && std::fabs(frame[3]) <= max_frame_strain &&
                        std::fabs(frame[4]) <= max_frame_strain;
    if (!turn || !strain) r.refuse("holds an impossible particle-history frame (followed particle " + std::to_string(k) + ")");
  }
  const Grid& g = sim.grid();
  const double x_lo = g.node_x(0), y_lo = g.node_y(0), x_max = g.node_x(g.nx - 1), y_max = g.node_y(g.ny - 1);
  for (std::size_t p = 0; p < P.n; ++p) {
    if (P.material[p] < 0 || static_cast<std::size_t>(P.material[p]) >= sim.materials().size())
      r.refuse("gives particle " + std::to_string(p) + " a material index out of range");
    if (!(P.mass[p] > 0 && P.volume_initial[p] > 0 && P.density[p] > 0 && P.volume(p) > 0))
      r.refuse("gives particle " + std::to_string(p) + " a mass, density or volume that is not positive");
    if (P.x[p] < x_lo || P.x[p] > x_max || P.y[p] < y_lo || P.y[p] > y_max)
      r.refuse("puts particle " + std::to_string(p) + " off the grid");
  }
  for (const auto* records : {&st.history, &st.every_step})
    for (const LoadRecord& rec : *records)
      if (!record_finite(rec)) r.refuse("holds an impossible load record");
  if (!std::isfinite(st.sum_V) || !std::isfinite(st.sum_H) || !std::isfinite(st.sum_M) ||
      !std::isfinite(st.max_penetration) || !step_in_range(st.period_steps))
    r.refuse("holds an impossible running sum");
  if (st.vtk_frames < 0 || static_cast<std::size_t>(st.vtk_frames) != st.vtk_times.size() || !all_finite(st.vtk_times))
    r.refuse("holds an impossible frame count");
  if (st.contours_done.size() != scene.output.contours_at_S_over_B.size())
    r.refuse("holds a contour list of the wrong length");
  for (const int done : st.contours_done)
    if (done != 0 && done != 1) r.refuse("holds a contour flag that is neither 0 nor 1");
  const std::size_t m = st.peak.x.size();
  if ((m != 0 && m != P.n) || st.peak.y.size() != m || st.peak.shear_strain.size() != m ||
      st.peak.displacement.size() != m)
    r.refuse("holds a peak snapshot of the wrong size");
  if (!std::isfinite(st.peak.S_over_B) || !std::isfinite(st.peak.V_kN_per_m))
    r.refuse("holds a non-finite peak");
  for (const auto* v : {&st.peak.x, &st.peak.y, &st.peak.shear_strain, &st.peak.displacement})
    if (!all_finite(*v)) r.refuse("holds a non-finite peak snapshot");
  for (const TrackRecord& t : st.tracks)
    if (t.track < 0 || static_cast<std::size_t>(t.track) >= P.tracked.size() || !track_finite(t))
      r.refuse("holds an impossible particle-history row");
}

}  // namespace

void write_checkpoint(const std::string& path, const Scene& scene, const Simulation& sim, const RunState& state) {
  Writer w;
  w.out.append(magic, sizeof magic);
  w.str(scene.text);
  // The scene names its material files; their parameters are recorded, so that a resume after
  // one of them was edited is refused instead of mixing two materials in one run.
  w.pod<std::uint64_t>(scene.materials.size());
  for (const MaterialSpec& m : scene.materials) {
    w.str(m.name);
    w.str(m.json_text);
  }
  w.pod<std::uint64_t>(sim.particles().n);
  const FeatureState features = sim.feature_state();
  particle_arrays(sim.particles(), features, [&](const auto& v) { w.vec(v); });
  run_fields(w, sim.clock(), sim.footing().motion(), sim.footing().friction(), state);
  w.pod<std::uint64_t>(common::fnv1a64(w.out));
  acst::common::write_file_atomically(path, w.out);
}

void read_checkpoint(const std::string& path, const Scene& scene, Simulation& sim, RunState& state) {
  std::string data;
  try {
    // A checkpoint grows with the particles and the load record, beyond the cap of the small
    // inputs; its own cap only stops a file that cannot be one (the reader checks the rest).
    data = common::read_input_file(path, max_checkpoint_bytes);
  } catch (const common::InputError& e) {
    throw CheckpointError(std::string("--resume: the checkpoint ") + e.what());
  }
  Reader r{data, 0, path};
  if (data.size() < sizeof magic || std::memcmp(data.data(), magic, sizeof magic - 1) != 0)
    r.refuse("is not an acst_mpm checkpoint");
  if (data[sizeof magic - 1] != magic[sizeof magic - 1])
    r.refuse("was written by another version of acst_mpm (format " + std::string(1, data[sizeof magic - 1]) +
             ", this one reads " + magic[sizeof magic - 1] + "): run the scene again");
  if (data.size() < sizeof magic + checksum_bytes) r.refuse("is truncated");
  r.end = data.size() - checksum_bytes;
  std::uint64_t stored = 0;
  std::memcpy(&stored, data.data() + r.end, checksum_bytes);
  if (stored != common::fnv1a64(std::string_view(data.data(), r.end)))
    r.refuse("is damaged (its checksum does not match): it was cut, changed or not written completely");
  if (r.str() != scene.text) r.refuse("was written for a different scene");
  std::uint64_t materials = 0;
  r.pod(materials);
  if (materials != scene.materials.size()) r.refuse("was written with another list of materials");
  for (const MaterialSpec& m : scene.materials)
    if (r.str() != m.name || r.str() != m.json_text)
      r.refuse("was written with other parameters for material '" + m.name +
               "' (its file was changed since): run the scene again");
  std::uint64_t n = 0;
  r.pod(n);
  if (n != sim.particles().n) r.refuse("holds a different number of particles");
  Particles P = sim.particles();
  FeatureState features = sim.feature_state();
  particle_arrays(P, features, [&](auto& v) {
    const std::size_t expected = v.size();
    r.vec(v);
    if (v.size() != expected) r.refuse("has an array of the wrong size");
  });
  RunState st;
  Clock clock;
  Footing::Motion motion;
  std::vector<double> friction;
  run_fields(r, clock, motion, friction, st);
  if (r.at != r.end) r.refuse("has trailing data");
  check_restored(r, scene, sim, P, features, clock, motion, friction, st);
  sim.restore(std::move(P), std::move(features), clock, motion, std::move(friction));
  state = std::move(st);
}

}  // namespace acst::mpm
