// acst_update_rotated_batch against acst_update_rotated called point by point: the same codes,
// the same bits in stress and state, the same counters, the first failure named, the failed
// points left as they came. The points follow plane-strain paths as an MPM host's particles do
// (where the library updates them in SIMD lanes) with bad points mixed in.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include "abi_model.hpp"
#include "acst.h"
#include "test_materials.hpp"

namespace c_abi_update_rotated_batch_test {

using acst::test::AbiModel;

bool same_bits(const double* a, const double* b, int n) { return std::memcmp(a, b, sizeof(double) * n) == 0; }

bool same_counters(const acst_counters& a, const acst_counters& b) {
  return a.substeps_accepted == b.substeps_accepted && a.substeps_rejected == b.substeps_rejected &&
         a.rate_evaluations == b.rate_evaluations && a.crossing_iterations == b.crossing_iterations &&
         a.unload_reload == b.unload_reload && a.guard_pressure_floor == b.guard_pressure_floor &&
         a.guard_small_R == b.guard_small_R && a.guard_lode_clamp == b.guard_lode_clamp &&
         a.guard_h_floor == b.guard_h_floor && a.guard_uniqueness == b.guard_uniqueness &&
         a.pressure_floor_resets == b.pressure_floor_resets && a.plastic == b.plastic;
}

struct Points {
  int n;
  std::vector<double> stress, statev, rotation, dstrain;
  explicit Points(int count)
      : n(count), stress(6 * count), statev(ACST_NSTATV * count), rotation(9 * count), dstrain(6 * count) {}
};

// n sand points at geostatic stresses with shear (ABI convention: tension positive).
Points start(const acst_model* m, int n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  Points P(n);
  for (int i = 0; i < n; ++i) {
    const double p = 10.0 + 300.0 * u(rng), K0 = 0.4 + 0.4 * u(rng);
    const double s0[6] = {-K0 * p, -p, -0.5 * (1.0 + K0) * p, (u(rng) - 0.5) * 0.3 * p, 0.0, 0.0};
    double b[3];
    EXPECT_EQ(acst_bedding_direction(b, 90.0 * u(rng), 1, 0, -1.0).code, ACST_OK);
    const acst_status st = acst_initial_state(&P.statev[ACST_NSTATV * i], &P.stress[6 * i], m, s0, 0.6 + 0.2 * u(rng), b);
    EXPECT_EQ(st.code, ACST_OK) << st.message;
  }
  return P;
}

// A step's rotations (about axis 3, as a plane-strain host's; every fifth point's about a tilted
// axis, the general turn) and plane-strain increments (engineering shear), mostly compressing
// the points vertically.
void step(Points& P, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < P.n; ++i) {
    const double a = 1e-5 * u(rng), c = std::cos(a), s = std::sin(a);
    if (i % 5 == 2) {  // Rodrigues' formula about the unit axis k
      const double k[3] = {0.48, 0.6, 0.64}, t = 1.0 - c;
      const double Q[9] = {c + t * k[0] * k[0],        t * k[0] * k[1] - s * k[2], t * k[0] * k[2] + s * k[1],
                           t * k[1] * k[0] + s * k[2], c + t * k[1] * k[1],        t * k[1] * k[2] - s * k[0],
                           t * k[2] * k[0] - s * k[1], t * k[2] * k[1] + s * k[0], c + t * k[2] * k[2]};
      std::memcpy(&P.rotation[9 * i], Q, sizeof Q);
    } else {
      const double Q[9] = {c, s, 0.0, -s, c, 0.0, 0.0, 0.0, 1.0};
      std::memcpy(&P.rotation[9 * i], Q, sizeof Q);
    }
    const double size = std::pow(10.0, -6.5 + 2.0 * (0.5 * (u(rng) + 1.0)));
    const double e[6] = {size * (0.4 + 0.5 * u(rng)), -size * (1.0 + 0.5 * u(rng)), 0.0, size * u(rng), 0.0, 0.0};
    std::memcpy(&P.dstrain[6 * i], e, sizeof e);
  }
}

TEST(UpdateRotatedBatch, EveryPointIsUpdateRotatedToTheBit) {
  const AbiModel model(acst::test::read_text("data/parameters/toyoura_acst_calibrated.json"));
  std::mt19937_64 rng(11);
  const int n = 37;  // not a multiple of the library's blocks or lanes
  Points P = start(model.get(), n, rng);
  int plastic_one_substep = 0, total = 0;
  for (int round = 0; round < 60; ++round) {
    step(P, rng);
    Points bad = P;
    // Points the update refuses or fails: not a rotation, a NaN state, a tensile blow-up. And a
    // floor-reset count that is not a whole number (every update writes back what it read).
    if (round % 3 == 0) {
      bad.rotation[9 * 5] = 2.0;
      bad.statev[ACST_NSTATV * 11 + 6] = std::numeric_limits<double>::quiet_NaN();
      bad.dstrain[6 * 20 + 1] = 0.5;
    } else if (round % 3 == 1) {
      bad.statev[ACST_NSTATV * 9 + 9] = 2.5;
    }
    Points one = bad, batch = bad;
    std::vector<int> codes(n);
    std::vector<acst_counters> counters(n);
    const acst_status st = acst_update_rotated_batch(batch.stress.data(), 6, batch.statev.data(), ACST_NSTATV,
                                                     codes.data(), counters.data(), model.get(), n,
                                                     batch.rotation.data(), batch.dstrain.data());
    int first_failure = -1;
    for (int i = 0; i < n; ++i) {
      acst_counters c{};
      const acst_status s = acst_update_rotated(&one.stress[6 * i], &one.statev[ACST_NSTATV * i], nullptr, &c,
                                                model.get(), &one.rotation[9 * i], &one.dstrain[6 * i]);
      ASSERT_EQ(codes[i], s.code) << "round " << round << " point " << i;
      if (s.code != ACST_OK && first_failure < 0) first_failure = i;
      if (s.code == ACST_OK) {
        EXPECT_TRUE(same_counters(counters[i], c)) << "round " << round << " point " << i;
      }
      ASSERT_TRUE(same_bits(&batch.stress[6 * i], &one.stress[6 * i], 6)) << "round " << round << " point " << i;
      ASSERT_TRUE(same_bits(&batch.statev[ACST_NSTATV * i], &one.statev[ACST_NSTATV * i], ACST_NSTATV))
          << "round " << round << " point " << i;
      if (s.code != ACST_OK) {  // left as it came
        EXPECT_TRUE(same_bits(&batch.stress[6 * i], &bad.stress[6 * i], 6));
        EXPECT_TRUE(same_bits(&batch.statev[ACST_NSTATV * i], &bad.statev[ACST_NSTATV * i], ACST_NSTATV));
      }
      plastic_one_substep += s.code == ACST_OK && c.plastic && c.substeps_accepted == 1 && c.rate_evaluations == 3;
      ++total;
    }
    if (first_failure < 0) {
      EXPECT_EQ(st.code, ACST_OK) << st.message;
    } else {
      EXPECT_EQ(st.code, codes[first_failure]);
      EXPECT_EQ(std::string(st.message).rfind("point " + std::to_string(first_failure) + ": ", 0), 0u) << st.message;
    }
    // The good points go on from the batch's results, a failed one from where it was.
    for (int i = 0; i < n; ++i)
      if (codes[i] == ACST_OK) {
        std::memcpy(&P.stress[6 * i], &batch.stress[6 * i], 6 * sizeof(double));
        std::memcpy(&P.statev[ACST_NSTATV * i], &batch.statev[ACST_NSTATV * i], ACST_NSTATV * sizeof(double));
      }
  }
  // The paths load most points plastically in one substep: the lanes' kind was exercised.
  EXPECT_GT(plastic_one_substep, total / 3) << plastic_one_substep << " of " << total;
}

TEST(UpdateRotatedBatch, RefusesMissingPointersAndShortStrides) {
  const AbiModel model(acst::test::read_text("data/parameters/toyoura_acst_calibrated.json"));
  double stress[6] = {-100, -100, -100, 0, 0, 0}, statev[ACST_NSTATV] = {}, Q[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1},
         de[6] = {};
  EXPECT_EQ(acst_update_rotated_batch(stress, 6, statev, ACST_NSTATV, nullptr, nullptr, nullptr, 1, Q, de).code,
            ACST_INVALID_INPUT);
  EXPECT_EQ(acst_update_rotated_batch(stress, 6, statev, ACST_NSTATV, nullptr, nullptr, model.get(), 1, nullptr, de).code,
            ACST_INVALID_INPUT);
  EXPECT_EQ(acst_update_rotated_batch(stress, 5, statev, ACST_NSTATV, nullptr, nullptr, model.get(), 1, Q, de).code,
            ACST_INVALID_INPUT);
  EXPECT_EQ(acst_update_rotated_batch(stress, 6, statev, ACST_NSTATV - 1, nullptr, nullptr, model.get(), 1, Q, de).code,
            ACST_INVALID_INPUT);
  EXPECT_EQ(acst_update_rotated_batch(nullptr, 6, nullptr, ACST_NSTATV, nullptr, nullptr, model.get(), 0, nullptr,
                                      nullptr).code,
            ACST_OK);
}

}  // namespace c_abi_update_rotated_batch_test
