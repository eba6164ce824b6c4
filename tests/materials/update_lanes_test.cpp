// update_lanes (acst/update_lanes.hpp) against Material::update, bit for bit: a lane that says it
// is done holds exactly Material::update's state and took the route its counters tell, a lane
// that is not done is as it came. The states come from random plane-strain paths (most updates on
// them take one of the lanes' two routes) with states of every other kind mixed in.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "acst/fabric.hpp"
#include "acst/material.hpp"
#include "acst/update_lanes.hpp"
#include "test_materials.hpp"

namespace update_lanes_test {
using namespace acst;

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

Parameters delivered() {
  return Material::from_json(acst::test::read_text("data/parameters/toyoura_acst_calibrated.json")).parameters();
}

struct Case {
  std::string name;
  Parameters parameters;
  integration::Options options;
};

std::vector<Case> cases() {
  std::vector<Case> c;
  c.push_back({"willam_warnke", delivered(), {}});
  Parameters li = delivered();
  li.lode_form = 0.0;
  li.c = 0.75;
  c.push_back({"li2002", li, {}});
  Parameters iso = delivered();
  iso.variant = Variant::isotropic;
  iso.e_A = 0.0;
  iso.F0 = 0.0;
  iso.k_f = 0.0;
  c.push_back({"isotropic", iso, {}});
  Parameters beta = delivered();
  beta.peak_pressure_exponent = 0.3;
  c.push_back({"peak_pressure_exponent", beta, {}});
  integration::Options no_reuse;
  no_reuse.reuse_last_substep = false;
  c.push_back({"no_substep_reuse", delivered(), no_reuse});
  return c;
}

// A plane-strain state (shear in the 1-2 plane) on the yield cone through its stress.
State start_state(const Material& mat, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double p = 5.0 + 400.0 * u(rng);
  const double K0 = 0.35 + 0.5 * u(rng);
  Sym s;
  s << K0 * p, p, 0.5 * (1.0 + K0) * p, (u(rng) - 0.5) * 0.4 * p, 0.0, 0.0;
  const double alpha = 90.0 * u(rng);
  return mat.initial_state(s, 0.6 + 0.3 * u(rng), bedding_direction(alpha, 1, 0, -1.0));
}

// A plane-strain increment of a random size, 1e-7 to 1e-4 (an MPM step's are 1e-6 to 1e-5).
Sym increment(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double size = std::pow(10.0, -7.0 + 3.0 * (0.5 * (u(rng) + 1.0)));
  Sym d;
  d << size * (-0.5 + 0.6 * u(rng)), size * (1.0 + 0.6 * u(rng)), 0.0, size * 0.8 * u(rng), 0.0, 0.0;
  return d;
}

// Now and then a state or increment the lanes must leave alone (or that is theirs anyway).
void perturb(State& s, Sym& d, int kind) {
  switch (kind) {
    case 0: s.H = std::numeric_limits<double>::quiet_NaN(); break;
    case 1: s.substep_hint = 0.3; break;
    case 2: s.substep_hint = std::numeric_limits<double>::quiet_NaN(); break;
    case 3: s.stress[4] = 0.01 * s.stress[1]; break;           // shear out of the plane
    case 4: s.stress = 100.0 * identity_tensor(); s.H = 0.0; break;  // R = 0
    case 5: d *= 1e3; break;                                  // a large increment
    case 6: s.void_ratio = 3.5; break;
    case 7: d[0] = std::numeric_limits<double>::infinity(); break;
    case 8: s.stress = 0.6 * identity_tensor(); break;         // at the pressure floor
    case 9: s.substep_hint = 4.0; break;
    default: break;
  }
}

// Whether lane l holds exactly state s.
::testing::AssertionResult holds(const UpdateLanes& L, int l, const State& s) {
  State t = s;
  take_lane(L, l, t);
  for (int i = 0; i < 6; ++i) {
    if (!same_bits(t.stress[i], s.stress[i]))
      return ::testing::AssertionFailure() << "stress " << i << ": " << t.stress[i] << " against " << s.stress[i];
    if (!same_bits(t.fabric[i], s.fabric[i]))
      return ::testing::AssertionFailure() << "fabric " << i << ": " << t.fabric[i] << " against " << s.fabric[i];
  }
  if (!same_bits(t.void_ratio, s.void_ratio)) return ::testing::AssertionFailure() << "void ratio";
  if (!same_bits(t.H, s.H)) return ::testing::AssertionFailure() << "H " << t.H << " against " << s.H;
  if (!same_bits(t.substep_hint, s.substep_hint)) return ::testing::AssertionFailure() << "substep hint";
  return ::testing::AssertionSuccess();
}

bool same_counters(const integration::Counters& a, const integration::Counters& b) {
  return a.substeps_accepted == b.substeps_accepted && a.substeps_rejected == b.substeps_rejected &&
         a.rate_evaluations == b.rate_evaluations && a.crossing_iterations == b.crossing_iterations &&
         a.unload_reload == b.unload_reload && a.guard_pressure_floor == b.guard_pressure_floor &&
         a.guard_small_R == b.guard_small_R && a.guard_lode_clamp == b.guard_lode_clamp &&
         a.guard_h_floor == b.guard_h_floor && a.guard_uniqueness == b.guard_uniqueness &&
         a.pressure_floor_resets == b.pressure_floor_resets;
}

// One build of the kernel on one material's paths.
void check_lanes(LaneBuild build, const Case& c) {
  SCOPED_TRACE(c.name + (build == LaneBuild::generic ? ", generic build" : ", best build"));
  const Material mat(c.parameters, c.options);
  ASSERT_TRUE(lanes_apply(mat));
  std::mt19937_64 rng(20261128);
  constexpr int W = UpdateLanes::width;
  std::vector<State> path(W);
  for (State& s : path) s = start_state(mat, rng);
  int updates = 0, done = 0, lane_route = 0, done_unperturbed = 0, elastic_lanes = 0;
  for (int round = 0; round < 400; ++round) {
    UpdateLanes L;
    L.n = 1 + round % W;  // every count of lanes in use
    std::vector<State> before(W);
    std::vector<Sym> d(W);
    std::vector<bool> perturbed(W);
    for (int l = 0; l < L.n; ++l) {
      before[l] = path[l];
      d[l] = increment(rng);
      perturbed[l] = (round * W + l) % 5 == 0;
      if (perturbed[l]) perturb(before[l], d[l], (round * W + l) / 5 % 12);
      put_lane(L, l, before[l], d[l]);
    }
    update_lanes(mat, L, build);
    for (int l = 0; l < L.n; ++l) {
      State scalar = before[l];
      const integration::Report rep = mat.update(scalar, d[l]);
      ++updates;
      // The lanes' routes, as the counters tell them: plastic from the start (one elastic and
      // two plastic rates) in one substep, or elastic in one Heun step (two elastic rates); no
      // crossing, no guard of the loading direction, no reset.
      const integration::Counters& n = rep.counters;
      const bool quiet = rep.status == integration::Status::ok && n.substeps_rejected == 0 &&
                         n.crossing_iterations == 0 && n.unload_reload == 0 && n.guard_small_R == 0 &&
                         n.pressure_floor_resets == 0;
      const bool plastic_route = quiet && rep.plastic && n.substeps_accepted == 1 && n.rate_evaluations == 3;
      const bool elastic_route = quiet && !rep.plastic && n.substeps_accepted == 0 && n.rate_evaluations == 2;
      lane_route += (plastic_route || elastic_route) && !perturbed[l];
      elastic_lanes += L.done[l] && !L.plastic[l];
      if (L.done[l]) {
        ++done;
        done_unperturbed += !perturbed[l];
        ASSERT_EQ(rep.status, integration::Status::ok) << "round " << round << " lane " << l;
        ASSERT_TRUE(holds(L, l, scalar)) << "round " << round << " lane " << l;
        EXPECT_TRUE(L.plastic[l] ? plastic_route : elastic_route);
        const integration::Report lane = lane_report(L, l);
        EXPECT_EQ(lane.plastic, rep.plastic);
        EXPECT_TRUE(same_counters(lane.counters, n)) << "round " << round << " lane " << l;
      } else {
        ASSERT_TRUE(holds(L, l, before[l])) << "round " << round << " lane " << l << " (not done, yet changed)";
      }
      path[l] = rep.status == integration::Status::ok && !perturbed[l] ? scalar : start_state(mat, rng);
    }
  }
  // On the paths (plane shear, R > 0) the lanes take every update of their route, and that
  // route is the common one.
  EXPECT_EQ(done_unperturbed, lane_route);
  EXPECT_GT(done, updates / 4) << done << " of " << updates;
  EXPECT_GT(elastic_lanes, updates / 20) << elastic_lanes << " of " << updates;
}

TEST(UpdateLanes, EveryDoneLaneIsMaterialUpdateToTheBitAndTheOthersAreUntouched) {
#if !defined(ACST_TEST_LANES_BUILT)
  GTEST_SKIP() << "this build has no lanes (not x86-64, or ACST_NATIVE: materials/CMakeLists.txt)";
#endif
  for (const LaneBuild build : {LaneBuild::best, LaneBuild::generic})
    for (const Case& c : cases()) check_lanes(build, c);
}

TEST(UpdateLanes, AMaterialTheyDoNotCoverLeavesEveryLane) {
  Parameters p = delivered();
  p.elastic_anisotropy = 0.5;
  const Material anisotropic(p, {});
  integration::Options rk;
  rk.scheme = integration::Scheme::rk23;
  const Material other_scheme(delivered(), rk);
  for (const Material* mat : {&anisotropic, &other_scheme}) {
    EXPECT_FALSE(lanes_apply(*mat));
    std::mt19937_64 rng(3);
    UpdateLanes L;
    L.n = UpdateLanes::width;
    std::vector<State> s(L.n);
    for (int l = 0; l < L.n; ++l) {
      s[l] = start_state(*mat, rng);
      put_lane(L, l, s[l], increment(rng));
    }
    update_lanes(*mat, L);
    for (int l = 0; l < L.n; ++l) {
      EXPECT_EQ(L.done[l], 0);
      EXPECT_TRUE(holds(L, l, s[l]));
    }
  }
}

}  // namespace update_lanes_test
