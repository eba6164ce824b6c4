#include "acst_mpm/checkpoint.hpp"

#include <cstdint>
#include <cstring>
#include <type_traits>

#include "acst_common/files.hpp"
#include "acst_common/gnuplot.hpp"
#include "acst_common/input_error.hpp"

namespace acst::mpm {
namespace {

constexpr std::uintmax_t max_checkpoint_bytes = std::uintmax_t{16} << 30;

constexpr char magic[8] = {'A', 'C', 'S', 'T', 'M', 'P', 'M', '2'};

struct Writer {
  std::string out;
  template <class T>
  void pod(const T& v) {
    static_assert(std::is_trivially_copyable<T>::value, "plain data only");
    out.append(reinterpret_cast<const char*>(&v), sizeof v);
  }
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

struct Reader {
  const std::string& in;
  std::size_t at = 0;
  std::string file;
  void need(std::size_t n) {
    if (at + n > in.size()) throw SimulationError("checkpoint '" + file + "' is truncated");
  }
  template <class T>
  void pod(T& v) {
    need(sizeof v);
    std::memcpy(&v, in.data() + at, sizeof v);
    at += sizeof v;
  }
  template <class T>
  void vec(std::vector<T>& v) {
    std::uint64_t n = 0;
    pod(n);
    if (n > (in.size() - at) / sizeof(T)) throw SimulationError("checkpoint '" + file + "' is truncated");
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

// One list of the evolving particle arrays, shared by writer (const) and reader.
template <class P, class F>
void particle_arrays(P& particles, F&& f) {
  auto& p = particles;
  for (auto* v : {&p.x, &p.y, &p.x_initial, &p.y_initial, &p.vx, &p.vy, &p.mass, &p.weight_mass, &p.volume_initial,
                  &p.density, &p.F, &p.stress, &p.strain, &p.statev, &p.surcharge_length, &p.wave_speed, &p.contact_friction})
    f(*v);
  f(p.material);
}

template <class IO, class C, class M, class State>
void run_fields(IO& io, C& clock, M& motion, State& st) {
  io.pod(clock.step);
  io.pod(clock.time);
  io.pod(clock.dt);
  io.pod(motion.dx);
  io.pod(motion.dy);
  io.pod(motion.work);
  io.pod(motion.unloading);
  io.vec(st.history);
  io.vec(st.every_step);
  io.pod(st.sum_V);
  io.pod(st.sum_H);
  io.pod(st.sum_M);
  io.pod(st.max_penetration);
  io.pod(st.period_steps);
  io.pod(st.vtk_frames);
  io.vec(st.vtk_times);
  io.vec(st.contours_done);
  io.pod(st.peak.S_over_B);
  io.pod(st.peak.V_kN_per_m);
  for (auto* v : {&st.peak.x, &st.peak.y, &st.peak.shear_strain, &st.peak.displacement}) io.vec(*v);
}

}  // namespace

void write_checkpoint(const std::string& path, const Scene& scene, const Simulation& sim, const RunState& state) {
  Writer w;
  w.out.append(magic, sizeof magic);
  w.str(scene.text);
  w.pod<std::uint64_t>(sim.particles().n);
  particle_arrays(sim.particles(), [&](const auto& v) { w.vec(v); });
  run_fields(w, sim.clock(), sim.footing().motion(), state);
  acst::common::write_file_atomically(path, w.out);
}

void read_checkpoint(const std::string& path, const Scene& scene, Simulation& sim, RunState& state) {
  std::string data;
  try {
    // A checkpoint grows with the particles and the load record, beyond the cap of the small
    // inputs; its own cap only stops a file that cannot be one (the reader checks the rest).
    data = common::read_input_file(path, max_checkpoint_bytes);
  } catch (const common::InputError& e) {
    throw common::InputError(std::string("--resume: cannot read the checkpoint: ") + e.what());  // the user's bad input: exit 2
  }
  Reader r{data, 0, path};
  r.need(sizeof magic);
  if (std::memcmp(data.data(), magic, sizeof magic) != 0) throw SimulationError("'" + path + "' is not an acst_mpm checkpoint");
  r.at = sizeof magic;
  if (r.str() != scene.text) throw SimulationError("checkpoint '" + path + "' was written for a different scene");
  std::uint64_t n = 0;
  r.pod(n);
  if (n != sim.particles().n) throw SimulationError("checkpoint '" + path + "' holds a different number of particles");
  Particles P = sim.particles();
  particle_arrays(P, [&](auto& v) {
    const std::size_t expected = v.size();
    r.vec(v);
    if (v.size() != expected) throw SimulationError("checkpoint '" + path + "' has an array of the wrong size");
  });
  RunState st;
  Clock clock;
  Footing::Motion motion;
  run_fields(r, clock, motion, st);
  if (r.at != data.size()) throw SimulationError("checkpoint '" + path + "' has trailing data");
  sim.restore(std::move(P), clock, motion);
  state = std::move(st);
}

}  // namespace acst::mpm
