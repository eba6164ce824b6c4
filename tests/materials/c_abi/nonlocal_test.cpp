// The C ABI's nonlocal regularisation (acst.h, "Nonlocal regularisation"): which quantities a
// kind takes and a point's local values; a NULL or zero offset gives the local numbers to the
// bit; an offset moves the state parameter alone (an elastic increment is untouched, a loose
// offset makes a dilating dense point contract); the batch is the single call point by point;
// offsets that are not finite or too large are refused; the reproducer holds the offset.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "abi_model.hpp"
#include "acst.h"
#include "test_materials.hpp"

namespace c_abi_nonlocal_test {

using acst::test::AbiModel;

bool same_bits(const double* a, const double* b, int n) { return std::memcmp(a, b, sizeof(double) * n) == 0; }

const std::string sand_json() { return acst::test::read_text("data/parameters/toyoura_acst_calibrated.json"); }

struct Point {
  double stress[6], statev[ACST_NSTATV];
};

// A dense sand point under plane-strain shear (ABI convention: tension positive), on its yield
// surface, and its state variables.
Point dense_point(const acst_model* m, double p, double shear, double void_ratio) {
  Point P;
  const double s0[6] = {-0.5 * p, -p, -0.75 * p, shear * p, 0.0, 0.0};
  const double b[3] = {0.0, 1.0, 0.0};
  const acst_status st = acst_initial_state(P.statev, P.stress, m, s0, void_ratio, b);
  EXPECT_EQ(st.code, ACST_OK) << st.message;
  return P;
}

TEST(NonlocalAbi, SandTakesItsVoidRatioTheVerificationKindsNothing) {
  const AbiModel sand(sand_json());
  EXPECT_EQ(acst_nonlocal_size(sand.get()), 1);
  EXPECT_STREQ(acst_nonlocal_name(sand.get(), 0), "void_ratio");
  EXPECT_EQ(acst_nonlocal_name(sand.get(), 1), nullptr);
  EXPECT_EQ(acst_nonlocal_name(sand.get(), -1), nullptr);
  const Point P = dense_point(sand.get(), 100.0, 0.1, 0.66);
  double local = 0.0;
  ASSERT_EQ(acst_nonlocal_local(&local, sand.get(), P.stress, P.statev).code, ACST_OK);
  EXPECT_EQ(local, 0.66);
  const AbiModel elastic(R"({"model": "linear_elastic", "parameters": {"E": 1000, "nu": 0.3}})");
  const AbiModel mises(R"({"model": "von_mises", "parameters": {"E": 1000, "nu": 0.3, "yield_stress": 10}})");
  EXPECT_EQ(acst_nonlocal_size(elastic.get()), 0);
  EXPECT_EQ(acst_nonlocal_size(mises.get()), 0);
  EXPECT_EQ(acst_nonlocal_size(nullptr), 0);
  EXPECT_EQ(acst_nonlocal_name(elastic.get(), 0), nullptr);
  EXPECT_EQ(acst_nonlocal_local(nullptr, sand.get(), P.stress, P.statev).code, ACST_INVALID_INPUT);
  Point bad = P;
  bad.statev[6] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(acst_nonlocal_local(&local, sand.get(), bad.stress, bad.statev).code, ACST_NONPHYSICAL_STATE);
}

// Plastic and elastic increments of many points: the nonlocal calls with a NULL offset and with
// offsets of +0 and -0 give the local calls' stress and state to the bit.
TEST(NonlocalAbi, NullOrZeroOffsetsGiveTheLocalNumbersToTheBit) {
  const AbiModel sand(sand_json());
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  for (int k = 0; k < 200; ++k) {
    const Point P = dense_point(sand.get(), 20.0 + 400.0 * u(rng), 0.3 * (u(rng) - 0.5), 0.62 + 0.25 * u(rng));
    const double size = std::pow(10.0, -6.0 + 2.0 * u(rng)), sign = k % 4 == 3 ? -1.0 : 1.0;  // some unload
    const double de[6] = {0.5 * size * sign, -size * sign, 0.0, size * (u(rng) - 0.5), 0.0, 0.0};
    const double zeros[2] = {0.0, -0.0};
    Point local = P;
    const int code = acst_update(local.stress, local.statev, nullptr, nullptr, sand.get(), de).code;
    for (const double* offset : {static_cast<const double*>(nullptr), &zeros[0], &zeros[1]}) {
      Point a = P, b = P;
      ASSERT_EQ(acst_update_nonlocal(a.stress, a.statev, nullptr, nullptr, sand.get(), de, offset).code, code);
      ASSERT_EQ(acst_update_rotated_nonlocal(b.stress, b.statev, nullptr, nullptr, sand.get(), identity, de, offset).code,
                code);
      EXPECT_TRUE(same_bits(a.stress, local.stress, 6) && same_bits(a.statev, local.statev, ACST_NSTATV)) << k;
      EXPECT_TRUE(same_bits(b.stress, local.stress, 6) && same_bits(b.statev, local.statev, ACST_NSTATV)) << k;
    }
  }
}

// The offset is where the state parameter takes the averaged void ratio: an elastic increment
// (inside the surface) does not read it, while under a plastic one at constant volume a dense
// point, which would dilate, gains mean stress, and with an offset that brings it to the critical
// state (no looser: an offset beyond gives the same numbers) loses it and carries less shear.
TEST(NonlocalAbi, AnOffsetMovesTheStateParameterAlone) {
  const AbiModel sand(sand_json());
  const Point P = dense_point(sand.get(), 100.0, 0.25, 0.66);
  const double unload[6] = {-2e-5, 4e-5, 0.0, -2e-5, 0.0, 0.0}, shear[6] = {3e-4, -3e-4, 0.0, 3e-4, 0.0, 0.0};
  const double loose = 0.35;  // e + 0.35 = 1.01, above the critical void ratio at 100 kPa
  Point a = P, b = P;
  ASSERT_EQ(acst_update(a.stress, a.statev, nullptr, nullptr, sand.get(), unload).code, ACST_OK);
  ASSERT_EQ(acst_update_nonlocal(b.stress, b.statev, nullptr, nullptr, sand.get(), unload, &loose).code, ACST_OK);
  EXPECT_TRUE(same_bits(a.stress, b.stress, 6) && same_bits(a.statev, b.statev, ACST_NSTATV)) << "elastic";
  Point dense = P, looser = P;
  acst_counters c{};
  ASSERT_EQ(acst_update(dense.stress, dense.statev, nullptr, &c, sand.get(), shear).code, ACST_OK);
  ASSERT_EQ(c.plastic, 1);
  ASSERT_EQ(acst_update_nonlocal(looser.stress, looser.statev, nullptr, nullptr, sand.get(), shear, &loose).code, ACST_OK);
  const auto p = [](const Point& x) { return -(x.stress[0] + x.stress[1] + x.stress[2]) / 3.0; };
  EXPECT_GT(p(dense), p(P) + 0.1) << "dilatant: p rises at constant volume";
  EXPECT_LT(p(looser), p(P) - 0.1) << "contractant: p falls";
  EXPECT_LT(std::fabs(looser.stress[3]), std::fabs(dense.stress[3]));
  EXPECT_EQ(looser.statev[6], dense.statev[6]) << "the void ratio follows the strain alone";
  Point further = P;
  const double much_looser = 1.0;
  ASSERT_EQ(acst_update_nonlocal(further.stress, further.statev, nullptr, nullptr, sand.get(), shear, &much_looser).code,
            ACST_OK);
  EXPECT_TRUE(same_bits(further.stress, looser.stress, 6)) << "no looser than critical";
}

// The batch with offsets against the single call point by point: the same codes and bits, with
// the lanes' kind of update among them.
TEST(NonlocalAbi, TheBatchIsTheSingleCallPointByPoint) {
  const AbiModel sand(sand_json());
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const int n = 29;
  std::vector<Point> start;
  std::vector<double> stress(6 * n), statev(ACST_NSTATV * n), Q(9 * n), de(6 * n), offset(n);
  for (int i = 0; i < n; ++i) start.push_back(dense_point(sand.get(), 50.0 + 200.0 * u(rng), 0.2 * u(rng), 0.64 + 0.1 * u(rng)));
  int plastic = 0;
  for (int round = 0; round < 30; ++round) {
    for (int i = 0; i < n; ++i) {
      std::memcpy(&stress[6 * i], start[i].stress, sizeof start[i].stress);
      std::memcpy(&statev[ACST_NSTATV * i], start[i].statev, sizeof start[i].statev);
      const double a = 1e-5 * (u(rng) - 0.5), c = std::cos(a), s = std::sin(a);
      const double q[9] = {c, s, 0, -s, c, 0, 0, 0, 1};
      std::memcpy(&Q[9 * i], q, sizeof q);
      const double size = 1e-5 * (0.2 + u(rng));
      const double e[6] = {0.5 * size, -size, 0.0, size * (u(rng) - 0.3), 0.0, 0.0};
      std::memcpy(&de[6 * i], e, sizeof e);
      offset[i] = 0.2 * (u(rng) - 0.5);
    }
    std::vector<double> s1 = stress, q1 = statev;
    std::vector<int> codes(n);
    std::vector<acst_counters> counters(n);
    acst_update_rotated_batch_nonlocal(stress.data(), 6, statev.data(), ACST_NSTATV, codes.data(), counters.data(),
                                       sand.get(), n, Q.data(), de.data(), offset.data());
    for (int i = 0; i < n; ++i) {
      const acst_status st = acst_update_rotated_nonlocal(&s1[6 * i], &q1[ACST_NSTATV * i], nullptr, nullptr, sand.get(),
                                                          &Q[9 * i], &de[6 * i], &offset[i]);
      ASSERT_EQ(codes[i], st.code) << round << " " << i;
      EXPECT_TRUE(same_bits(&stress[6 * i], &s1[6 * i], 6)) << round << " " << i;
      EXPECT_TRUE(same_bits(&statev[ACST_NSTATV * i], &q1[ACST_NSTATV * i], ACST_NSTATV)) << round << " " << i;
      plastic += st.code == ACST_OK && counters[i].plastic && counters[i].substeps_accepted == 1;
      if (st.code == ACST_OK) std::memcpy(start[i].stress, &stress[6 * i], sizeof start[i].stress);
      if (st.code == ACST_OK) std::memcpy(start[i].statev, &statev[ACST_NSTATV * i], sizeof start[i].statev);
    }
  }
  EXPECT_GT(plastic, n * 30 / 3) << "the lanes' kind of update was exercised";
}

TEST(NonlocalAbi, RefusesOffsetsThatAreNotFiniteOrTooLarge) {
  const AbiModel sand(sand_json());
  const Point P = dense_point(sand.get(), 100.0, 0.1, 0.66);
  const double de[6] = {1e-5, -2e-5, 0, 1e-5, 0, 0}, identity[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(), 2.97, -3.0}) {
    Point a = P;
    const acst_status st = acst_update_nonlocal(a.stress, a.statev, nullptr, nullptr, sand.get(), de, &bad);
    EXPECT_EQ(st.code, ACST_INVALID_INPUT);
    EXPECT_NE(std::string(st.message).find("nonlocal offset"), std::string::npos) << st.message;
    EXPECT_TRUE(same_bits(a.stress, P.stress, 6) && same_bits(a.statev, P.statev, ACST_NSTATV));
    EXPECT_EQ(acst_update_rotated_nonlocal(a.stress, a.statev, nullptr, nullptr, sand.get(), identity, de, &bad).code,
              ACST_INVALID_INPUT);
    // In a batch, that point alone: the others are updated.
    double stress[12], statev[2 * ACST_NSTATV], Q[18], strain[12];
    const double offsets[2] = {0.01, bad};
    int codes[2];
    for (int i = 0; i < 2; ++i) {
      std::memcpy(stress + 6 * i, P.stress, sizeof P.stress);
      std::memcpy(statev + ACST_NSTATV * i, P.statev, sizeof P.statev);
      std::memcpy(Q + 9 * i, identity, sizeof identity);
      std::memcpy(strain + 6 * i, de, sizeof de);
    }
    const acst_status b = acst_update_rotated_batch_nonlocal(stress, 6, statev, ACST_NSTATV, codes, nullptr, sand.get(), 2,
                                                             Q, strain, offsets);
    EXPECT_EQ(codes[0], ACST_OK);
    EXPECT_EQ(codes[1], ACST_INVALID_INPUT);
    EXPECT_EQ(std::string(b.message).rfind("point 1: ", 0), 0u) << b.message;
    EXPECT_TRUE(same_bits(stress + 6, P.stress, 6) && same_bits(statev + ACST_NSTATV, P.statev, ACST_NSTATV));
  }
  // A verification kind ignores the argument: it has nothing to average.
  const AbiModel elastic(R"({"model": "linear_elastic", "parameters": {"E": 1000, "nu": 0.3}})");
  double s[6] = {-10, -10, -10, 0, 0, 0};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(acst_update_nonlocal(s, nullptr, nullptr, nullptr, elastic.get(), de, &nan).code, ACST_OK);
}

TEST(NonlocalAbi, TheReproducerHoldsTheOffset) {
  const AbiModel sand(sand_json());
  const Point P = dense_point(sand.get(), 100.0, 0.1, 0.66);
  const double de[6] = {1e-5, -2e-5, 0, 1e-5, 0, 0}, offset = -0.0125;
  const auto text = [&](const double* o) {
    size_t length = 0;
    EXPECT_EQ(acst_reproducer_nonlocal(nullptr, &length, sand.get(), P.stress, P.statev, de, o).code, ACST_OK);
    std::string buffer(length, '\0');
    EXPECT_EQ(acst_reproducer_nonlocal(buffer.data(), &length, sand.get(), P.stress, P.statev, de, o).code, ACST_OK);
    buffer.resize(length - 1);
    return nlohmann::json::parse(buffer);
  };
  EXPECT_EQ(text(&offset)["initial_state"]["void_ratio_offset"].get<double>(), offset);
  EXPECT_FALSE(text(nullptr)["initial_state"].contains("void_ratio_offset")) << "a local update's scene is as it was";
}

}  // namespace c_abi_nonlocal_test
