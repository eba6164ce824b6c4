#include "acst_mpm/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <type_traits>

#include "acst_common/double_pair.hpp"
#include "acst_mpm/material_update.hpp"
#include "acst_mpm/units.hpp"

namespace acst::mpm {

using common::DoublePair;

Simulation::Simulation(Grid grid, Boundaries boundaries, Settings settings,
                       std::vector<std::shared_ptr<const AbiMaterial>> materials, Particles particles,
                       double particle_half_width)
    : grid_(grid),
      boundaries_(boundaries),
      settings_(settings),
      materials_(std::move(materials)),
      particles_(std::move(particles)),
      weights_(particle_half_width),
      rows_(settings_.grid_follows_footing, grid_, boundaries_.walls, boundaries_.footing),
      regulariser_(settings_.regularisation, particles_, materials_,
                   boundaries_.symmetric_half ? std::optional<double>(boundaries_.walls.left) : std::nullopt,
                   settings_.threads),
      micropolar_(settings_.micropolar, particles_.n) {
  prepare();
}

void Simulation::restore(Particles particles, FeatureState features, const Clock& clock,
                         const Footing::Motion& motion, std::vector<double> friction) {
  particles_ = std::move(particles);
  regulariser_.state() = std::move(features.regularisation);
  micropolar_.state() = std::move(features.micropolar);
  clock_ = clock;
  boundaries_.footing.motion() = motion;
  boundaries_.footing.friction() = std::move(friction);
  prepare();
}

bool Simulation::is_xpic_step(long long step) const {
  if (settings_.update == ParticleUpdate::PIC) return true;
  if (settings_.update == ParticleUpdate::FLIP) return false;
  return (step + 1) % settings_.xpic_every == 0;
}

void Simulation::prepare() {
  rows_.follow(grid_, boundaries_.footing, clock_.step);  // for the footing's motion (a checkpoint's, on restore)
  StepScratch& w = work_;
  const std::size_t N = grid_.nodes(), n = particles_.n;
  for (auto* v : {&w.mass, &w.vx, &w.vy, &w.fx, &w.fy, &w.ax, &w.ay, &w.ux, &w.uy, &w.xpx, &w.xpy}) v->assign(N, 0.0);
  w.constraints.resize(N);
  micropolar_.prepare(N);
  w.first_i.assign(n, 0);
  w.first_j.assign(n, 0);
  for (auto* v : {&w.wx, &w.wy, &w.dwx, &w.dwy}) v->assign(4 * n, 0.0);
  w.pvx.assign(n, 0.0);
  w.pvy.assign(n, 0.0);
  w.nx = grid_.nx;
  w.scatter.configure(settings_.threads, N);
  weights_.prepare(grid_, particles_);
  if (clock_.step == 0 || particles_.wave_speed.empty() ||
      std::all_of(particles_.wave_speed.begin(), particles_.wave_speed.end(), [](double c) { return c == 0.0; }))
    refresh_wave_speeds();
}

void Simulation::refresh_wave_speeds() {
  Particles& P = particles_;
  const std::size_t n = P.n;
  std::vector<std::string> errors(work_.scatter.threads());
  parallel_for(work_.scatter.threads(), n, [&](int t, std::size_t p) {
    try {
      const double J = P.volume(p) / P.volume_initial[p];
      P.wave_speed[p] = materials_[P.material[p]]->wave_speed(&P.stress[6 * p],
                                                             P.statev.data() + P.state_size * p, P.density[p] / J);
    } catch (const std::exception& e) {
      if (errors[t].empty()) errors[t] = "particle " + std::to_string(p) + ": " + e.what();
    }
  });
  for (const auto& e : errors)
    if (!e.empty()) throw SimulationError("step " + std::to_string(clock_.step) + ", " + e);
}

// The largest wave speed of the particles (refreshed with the time step).
double Simulation::stiffest_wave_speed() const {
  return particles_.wave_speed.empty() ? 0.0 : *std::max_element(particles_.wave_speed.begin(), particles_.wave_speed.end());
}

double Simulation::stable_time_step() const {
  const Particles& P = particles_;
  const double scale = 1.0 / std::sqrt(settings_.mass_scaling);
  const bool contact = boundaries_.footing.uses_contact();
  // Every step, so over the threads; a maximum is the same in any order. omega^2's maximum
  // gives omega's (the square root is monotonic and correctly rounded) at one root per step.
  struct alignas(64) Largest {  // one cache line per thread
    double fastest = 0.0, omega2 = 0.0;
  };
  // A particle's exact term (hypot, divisions) is worked out only where a bound says it could
  // pass the thread's largest so far; the bounds hold with a margin far above the terms' rounding,
  // so the maxima are the same numbers (a NaN fails every test and goes to the exact term, which
  // std::max ignores as before).
  constexpr double margin = 1.0 + 1e-12;
  const Footing::SpringRate spring =
      boundaries_.footing.spring_rate(grid_.h, weights_.half_width(), stiffest_wave_speed(), margin);
  std::vector<Largest> of(work_.scatter.threads());
  parallel_for(work_.scatter.threads(), P.n, [&](int t, std::size_t p) {
    const double c = P.wave_speed[p] * scale;
    if (!(c + (std::fabs(P.vx[p]) + std::fabs(P.vy[p])) * margin <= of[t].fastest))  // hypot <= |vx| + |vy|
      of[t].fastest = std::max(of[t].fastest, c + std::hypot(P.vx[p], P.vy[p]));
    if (contact && spring.may_exceed(P, p, of[t].omega2)) of[t].omega2 = std::max(of[t].omega2, spring.omega2(P, p));
  });
  double fastest = 0.0, omega2 = 0.0;
  for (const Largest& m : of) fastest = std::max(fastest, m.fastest), omega2 = std::max(omega2, m.omega2);
  const double omega = std::sqrt(omega2);
  if (!(fastest > 0.0) || !std::isfinite(fastest))
    throw SimulationError("step " + std::to_string(clock_.step) + ": no finite wave speed for the time step");
  double dt = settings_.cfl * std::min(grid_.h, grid_.hy) / fastest;
  // The stiffest contact spring (a whole particle width pressed) on its particle: dt <= 2 cfl /
  // omega keeps it stable with the CFL bound's margin (no restriction at one particle per cell
  // and factor <= 4).
  if (omega > 0.0) dt = std::min(dt, 2.0 * settings_.cfl / omega);
  return std::min(dt, micropolar_.stable_time_step(stiffest_wave_speed() * scale, grid_, settings_.cfl));
}

double Simulation::kinetic_energy() const {
  double k = 0.0;
  for (std::size_t p = 0; p < particles_.n; ++p)
    k += 0.5 * particles_.mass[p] * (particles_.vx[p] * particles_.vx[p] + particles_.vy[p] * particles_.vy[p]);
  return boundaries_.symmetric_half ? 2.0 * k : k;
}

void Simulation::fail_at(long long particle, const char* what) const {
  if (particle >= 0) fail(static_cast<std::size_t>(particle), what);
}

void Simulation::fail(std::size_t p, const std::string& what, const std::string& reproducer) const {
  char where[96];
  std::snprintf(where, sizeof where, "step %lld, particle %zu at (%.4g, %.4g) m: ", clock_.step, p, particles_.x[p],
                particles_.y[p]);
  throw SimulationError(where + what, reproducer);
}

void Simulation::compute_shape_functions() {
  fail_at(weights_.compute(grid_, particles_, work_), "left the grid (the grid must reach two cells past every particle)");
}

void Simulation::apply_constraints() {
  work_.constraints.clear();
  boundaries_.footing.constrain(grid_, work_.constraints);
  nodal_velocity(work_.ax.data(), work_.ay.data(), work_.vx.data(), work_.vy.data());
}

void Simulation::nodal_velocity(const double* px, const double* py, double* vx, double* vy) {
  const StepScratch& w = work_;
  for (std::size_t i = 0; i < grid_.nodes(); ++i) {
    const double m = w.mass[i];
    const DoublePair v = m > 0.0 ? DoublePair{px[i], py[i]} / DoublePair{m, m} : DoublePair{0.0, 0.0};
    vx[i] = w.constraints.set_x[i] != free_node ? w.constraints.vx[i] : v[0];
    vy[i] = w.constraints.set_y[i] != free_node ? w.constraints.vy[i] : v[1];
  }
}

void Simulation::update_stress(const double* vx, const double* vy, double dt) {
  const bool averaged = settings_.volumetric_averaging == VolumetricAveraging::cell;
  const MaterialFailure failure =
      update_material_points(particles_, materials_, regulariser_, grid_, averaged, work_, vx, vy, dt);
  if (failure.particle >= 0) fail(static_cast<std::size_t>(failure.particle), failure.message, failure.reproducer);
}

void Simulation::xpic_velocity(int order) {
  StepScratch& w = work_;
  Particles& P = particles_;
  const std::size_t N = grid_.nodes();
  // v(m) = sum_k dv(k), dv(1) = v_L, dv(k) = dv(k-1) - S+S dv(k-1), constrained parts of dv(k>1) zero.
  std::vector<double> dvx(w.vx), dvy(w.vy);
  w.xpx = w.vx;
  w.xpy = w.vy;
  for (int k = 2; k <= order; ++k) {
    parallel_for(w.scatter.threads(), P.n, [&](int, std::size_t p) {
      double sx = 0.0, sy = 0.0;
      w.stencil(p, [&](std::size_t i, double S, double, double) {
        sx += S * dvx[i];
        sy += S * dvy[i];
      });
      w.pvx[p] = sx;
      w.pvy[p] = sy;
    });
    // The force is already consumed: its fields are reused as scratch.
    w.map_to_grid<2>({w.fx.data(), w.fy.data()}, P.n,
                     [&](std::size_t p) { return std::array<double, 2>{P.mass[p] * w.pvx[p], P.mass[p] * w.pvy[p]}; });
    fold(w.fx.data(), FieldKind::x);
    fold(w.fy.data(), FieldKind::y);
    for (std::size_t i = 0; i < N; ++i) {
      const double m = w.mass[i];
      dvx[i] = (m > 0.0 && w.constraints.set_x[i] == free_node) ? dvx[i] - w.fx[i] / m : 0.0;
      dvy[i] = (m > 0.0 && w.constraints.set_y[i] == free_node) ? dvy[i] - w.fy[i] / m : 0.0;
      w.xpx[i] += dvx[i];
      w.xpy[i] += dvy[i];
    }
  }
}

// One step (docs/mpm.md, "One step"): the phases in their order; the stress is updated in two
// halves (update-stress-average), or once before the internal force or after the re-map.
void Simulation::step() {
  PhaseClock phase(phase_seconds_);
  boundaries_.footing.at_time(clock_.time);
  regulariser_.regularise(particles_, materials_, clock_.step, work_.scatter.threads());
  rows_.follow(grid_, boundaries_.footing, clock_.step);
  phase.lap(StepPhase::regularisation);
  refresh_time_step();
  phase.lap(StepPhase::time_step);
  compute_shape_functions();
  phase.lap(StepPhase::shape_functions);
  map_mass_and_momentum();
  phase.lap(StepPhase::map_to_grid);
  apply_constraints();
  phase.lap(StepPhase::constraints);
  fail_at(micropolar_.update_stress(particles_, work_, work_.vx.data(), work_.vy.data(), clock_.dt),
          "the micropolar stresses are not finite");
  phase.lap(StepPhase::micropolar_stress);
  const StressUpdate when = settings_.stress_update;
  const double part = when == StressUpdate::average ? 0.5 * clock_.dt : clock_.dt;  // of dt per update
  if (when != StressUpdate::last) update_stress(work_.vx.data(), work_.vy.data(), part);  // with v_L
  phase.lap(StepPhase::stress_update);
  footing_contact();
  phase.lap(StepPhase::footing_contact);
  internal_force_and_reactions();
  phase.lap(StepPhase::internal_force);
  update_particles();
  phase.lap(StepPhase::particle_update);
  if (when != StressUpdate::first) {
    remap_momentum();
    phase.lap(StepPhase::remap);
    update_stress(work_.ux.data(), work_.uy.data(), part);  // with the re-mapped v
    phase.lap(StepPhase::stress_update);
  }
  advance_boundaries();
  phase.lap(StepPhase::advance);
}

void Simulation::refresh_time_step() {
  if (clock_.step > 0 && clock_.step % settings_.wave_speed_every == 0) refresh_wave_speeds();
  clock_.dt = stable_time_step();
}

// Mass and momentum to the grid (with the micropolar rotations' inertia and angular momentum in
// the same pass), the walls' mirror images folded in.
void Simulation::map_mass_and_momentum() {
  StepScratch& w = work_;
  Particles& P = particles_;
  const auto momentum = [&](std::size_t p) {
    const double m = P.mass[p];
    return std::array<double, 3>{m, m * P.vx[p], m * P.vy[p]};
  };
  if (micropolar_.active()) {
    const MicropolarRotations::MapTerms rotation = micropolar_.map_terms(P, grid_);
    w.map_to_grid<5>({w.mass.data(), w.ax.data(), w.ay.data(), rotation.inertia, rotation.momentum}, P.n,
                     [&](std::size_t p) {
                       const std::array<double, 3> m = momentum(p);
                       const std::array<double, 2> r = rotation(p);
                       return std::array<double, 5>{m[0], m[1], m[2], r[0], r[1]};
                     });
  } else {
    w.map_to_grid<3>({w.mass.data(), w.ax.data(), w.ay.data()}, P.n, momentum);
  }
  w.mass_body = w.mass;
  fold(w.mass.data(), FieldKind::scalar);
  fold(w.ax.data(), FieldKind::x);
  fold(w.ay.data(), FieldKind::y);
  micropolar_.finish_map(boundaries_.walls, grid_);
}

// The footing's contact force on every particle that touches it; the footing's reaction is their
// sum, and internal_force_and_reactions applies them to the grid.
void Simulation::footing_contact() {
  Footing& f = boundaries_.footing;
  if (!f.uses_contact()) return;
  f.touch(particles_, grid_, weights_.half_width(), stiffest_wave_speed(), clock_.dt, work_.scatter.threads());
  reaction_[reaction_footing] = f.reaction();
}

// Internal force, weight, surcharge and confining pressure; the walls' and the constraints'
// reactions; a = f/m.
void Simulation::internal_force_and_reactions() {
  StepScratch& w = work_;
  Particles& P = particles_;
  const std::size_t n = P.n;
  const double g = settings_.gravity, q = boundaries_.surcharge, sigma3 = boundaries_.confining_pressure;
  // Instantiated with and without the sides' pressure (without it, the loop is the one it was) and
  // with and without the micropolar rotations' forces and couples (fields 2-4 of the same pass).
  const auto scatter = [&](auto confined, auto rotations) {
    constexpr bool with_rotations = decltype(rotations)::value;
    const MicropolarRotations::ForceTerms couples = micropolar_.force_terms();
    double* out[5] = {w.fx.data(), w.fy.data(), couples.fields[0], couples.fields[1], couples.fields[2]};
    w.scatter.run(with_rotations ? 5 : 2, out, n, [&](std::size_t p, double* const* f) {
      const double V = kilo * P.volume(p);
      const double* s = &P.stress[6 * p];
      const double sxx = V * s[0], syy = V * s[1], sxy = V * s[3];
      const double by = -P.weight_mass[p] * g - kilo * q * P.surcharge_length[p];
      MicropolarRotations::ParticleCouples c{};
      if constexpr (with_rotations) c = couples(p, V);
      if constexpr (decltype(confined)::value) {
        // On the side's current length: the particle's height stretched by F_yy.
        const double bx = kilo * sigma3 * P.side_length[p] * std::fabs(P.F[4 * p + 3]);
        w.stencil(p, [&](std::size_t i, double S, double gx, double gy) {
          f[0][i] += bx * S - (sxx * gx + sxy * gy);
          f[1][i] += by * S - (sxy * gx + syy * gy);
          if constexpr (with_rotations) c.add(f + 2, i, S, gx, gy);
        });
      } else {
        w.stencil(p, [&](std::size_t i, double S, double gx, double gy) {
          f[0][i] -= sxx * gx + sxy * gy;
          f[1][i] += by * S - (sxy * gx + syy * gy);
          if constexpr (with_rotations) c.add(f + 2, i, S, gx, gy);
        });
      }
    });
  };
  const bool rotations = micropolar_.active();
  if (sigma3 != 0.0 && rotations)
    scatter(std::true_type{}, std::true_type{});
  else if (sigma3 != 0.0)
    scatter(std::true_type{}, std::false_type{});
  else if (rotations)
    scatter(std::false_type{}, std::true_type{});
  else
    scatter(std::false_type{}, std::false_type{});
  micropolar_.finish_forces(w, boundaries_.walls, grid_, settings_.grid_damping, clock_.dt);
  if (boundaries_.footing.uses_contact()) boundaries_.footing.spread(grid_, w.mass.data(), w.fx.data(), w.fy.data());
  // Reactions: the body's share m_body/m of a node's folded force f drives its particles, so a
  // wall's mirror image adds (m_body/m) f - f_body there and a footing node takes -(m_body/m) f.
  const Reaction contact = reaction_[reaction_footing];
  reaction_.fill(Reaction{});
  if (boundaries_.footing.uses_contact()) reaction_[reaction_footing] = contact;
  w.fx_body = w.fx;
  w.fy_body = w.fy;
  fold(w.fx.data(), FieldKind::x);
  fold(w.fy.data(), FieldKind::y);
  // Row by row (no division to find a node's row), the share only where a reaction takes it,
  // and the acceleration's two divisions in one instruction (the same quotients).
  const Walls::Lines wall_lines = boundaries_.walls.lines(grid_);
  for (int j = 0; j < grid_.ny; ++j) {
    for (int column = 0; column < grid_.nx; ++column) {
      const std::size_t i = static_cast<std::size_t>(j) * grid_.nx + column;
      const double m = w.mass[i];
      if (m <= 0.0) {
        w.ax[i] = w.ay[i] = 0.0;
        continue;
      }
      const int wall = boundaries_.walls.wall_of(column, j, wall_lines);
      const int set_x = w.constraints.set_x[i], set_y = w.constraints.set_y[i];
      if (wall != free_node || set_x != free_node || set_y != free_node) {
        const double share = w.mass_body[i] / m;
        if (wall != free_node) {
          reaction_[wall].fx += share * w.fx[i] - w.fx_body[i];
          reaction_[wall].fy += share * w.fy[i] - w.fy_body[i];
        }
        // The constraint force keeps the (already prescribed) velocity: it cancels the net force.
        if (set_x != free_node) {
          reaction_[set_x].fx -= share * w.fx[i];
          w.fx[i] = 0.0;
        }
        if (set_y != free_node) {
          reaction_[set_y].fy -= share * w.fy[i];
          w.fy[i] = 0.0;
        }
      }
      const DoublePair a = DoublePair{w.fx[i], w.fy[i]} / DoublePair{m, m};
      w.ax[i] = a[0];
      w.ay[i] = a[1];
    }
  }
}

// Particle velocities and positions: FLIP, or XPIC(m) (PIC = XPIC(1)), with damping. A particle
// the material holds at its pressure floor takes the grid's velocity (PIC) in every step: it has
// no stiffness, so the velocity FLIP keeps for it from step to step is bounded by nothing
// (docs/mpm.md, "Stress-free particles"; what FLIP did to them beside the footing's corners:
// docs/footing-study.md, "Particles at the pressure floor take PIC").
void Simulation::update_particles() {
  StepScratch& w = work_;
  Particles& P = particles_;
  const std::size_t n = P.n;
  const int T = w.scatter.threads();
  const bool xpic = is_xpic_step(clock_.step);
  if (xpic) xpic_velocity(settings_.update == ParticleUpdate::PIC ? 1 : settings_.xpic_order);
  const double ag = settings_.grid_damping, ap = settings_.particle_damping;
  // With the micropolar rotations the particles' spin is mapped in the same walk of the stencil.
  const auto update = [&](auto rotations) {
    constexpr bool with_rotations = decltype(rotations)::value;
    parallel_for(T, n, [&](int, std::size_t p) {
      double svx = 0, svy = 0, sax = 0, say = 0, smx = 0, smy = 0, spin = 0;
      w.stencil(p, [&](std::size_t i, double S, double, double) {
        svx += S * w.vx[i];
        svy += S * w.vy[i];
        sax += S * w.ax[i];
        say += S * w.ay[i];
        if (xpic) {
          smx += S * w.xpx[i];
          smy += S * w.xpy[i];
        }
        if constexpr (with_rotations) spin += S * micropolar_.spin_at(i);
      });
      const double vx0 = P.vx[p], vy0 = P.vy[p];
      double vx1, vy1;
      const bool pic = P.stress_free[p] != 0;  // nothing in the particle can hold a velocity of its own
      if (pic || xpic) {  // the grid's velocity: S v_L for PIC, the XPIC(m) field otherwise
        const double bx = pic ? svx : smx, by = pic ? svy : smy;
        vx1 = bx + sax * clock_.dt - (ag * svx + ap * vx0) * clock_.dt;
        vy1 = by + say * clock_.dt - (ag * svy + ap * vy0) * clock_.dt;
      } else {
        vx1 = vx0 + (sax - ag * svx - ap * vx0) * clock_.dt;
        vy1 = vy0 + (say - ag * svy - ap * vy0) * clock_.dt;
      }
      P.vx[p] = vx1;
      P.vy[p] = vy1;
      P.x[p] += (svx + 0.5 * (vx1 - vx0)) * clock_.dt;
      P.y[p] += (svy + 0.5 * (vy1 - vy0)) * clock_.dt;
      if constexpr (with_rotations) micropolar_.set_spin(p, spin, clock_.dt, ap);
    });
  };
  if (micropolar_.active())
    update(std::true_type{});
  else
    update(std::false_type{});
}

// Momentum re-extrapolated from the new particle velocities; the constrained velocity field.
void Simulation::remap_momentum() {
  StepScratch& w = work_;
  Particles& P = particles_;
  w.map_to_grid<2>({w.ux.data(), w.uy.data()}, P.n,
                   [&](std::size_t p) { return std::array<double, 2>{P.mass[p] * P.vx[p], P.mass[p] * P.vy[p]}; });
  fold(w.ux.data(), FieldKind::x);
  fold(w.uy.data(), FieldKind::y);
  nodal_velocity(w.ux.data(), w.uy.data(), w.ux.data(), w.uy.data());
}

// The footing moves on (and counts its work); then the clock.
void Simulation::advance_boundaries() {
  boundaries_.footing.advance(reaction_[reaction_footing], clock_.dt);
  clock_.time += clock_.dt;
  ++clock_.step;
}

}  // namespace acst::mpm
