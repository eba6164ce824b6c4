// One model handle shared by many threads (acst.h: a handle is immutable after creation): each
// thread passes its own stress and state arrays and must get bit-for-bit the numbers of a
// single-threaded run. Any hidden shared mutable state (a cache, a static scratch buffer, a
// counter) would show up as a difference or, under the sanitizers, as a crash.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <string>
#include <thread>
#include <vector>

#include "acst.h"
#include "test_materials.hpp"

namespace c_abi_threads_test {

namespace {

constexpr int thread_count = 4;
constexpr int path_steps = 3000;

struct ModelHandle {
  acst_model* model = nullptr;
  ModelHandle() {
    const std::string json = acst::test::read_text("data/parameters/toyoura_acst_guide.json");
    const acst_status st = acst_model_create(&model, json.c_str());
    EXPECT_EQ(st.code, ACST_OK) << st.message;
  }
  ~ModelHandle() { acst_model_destroy(model); }
};

// ABI strain increment of step k (tension positive, engineering shear): cyclic triaxial-like
// shearing with a shear component, reversed every 250 steps, on a slow volumetric compression, so
// the path loads, unloads and reloads many times (plastic, elastic and crossing branches).
void path_increment(int k, double scale, double* d) {
  const double sign = (k / 250) % 2 == 0 ? 1.0 : -1.0;
  const double base[6] = {-2e-5, 1e-5, 0.8e-5, 0.6e-5, -0.2e-5, 0.1e-5};
  for (int i = 0; i < 6; ++i) d[i] = scale * sign * base[i] + (i < 3 ? -1e-6 : 0.0);
}

struct PathResult {
  std::vector<double> stress_history;  // 6 per step
  std::vector<double> tangent_last;
  std::vector<double> statev;
  std::vector<int> codes;
  long substeps = 0;
  int plastic_steps = 0;
};

PathResult run_path(const acst_model* model) {
  PathResult r;
  double stress[6], statev[ACST_NSTATV], tangent[36];
  const double s0[6] = {-100, -100, -100, 0, 0, 0}, b[3] = {0.3, 1.0, 0.2};
  r.codes.push_back(acst_initial_state(statev, stress, model, s0, 0.72, b).code);
  r.stress_history.reserve(6 * path_steps);
  for (int k = 0; k < path_steps; ++k) {
    double d[6];
    path_increment(k, 1.0, d);
    acst_counters c;
    const acst_status st = acst_update(stress, statev, tangent, &c, model, d);
    if (st.code != ACST_OK) r.codes.push_back(st.code);
    r.substeps += c.substeps_accepted + c.substeps_rejected;
    r.plastic_steps += c.plastic;
    r.stress_history.insert(r.stress_history.end(), stress, stress + 6);
  }
  r.tangent_last.assign(tangent, tangent + 36);
  r.statev.assign(statev, statev + ACST_NSTATV);
  return r;
}

void expect_identical(const PathResult& a, const PathResult& ref, const std::string& who) {
  ASSERT_EQ(a.codes, ref.codes) << who;
  ASSERT_EQ(a.stress_history.size(), ref.stress_history.size()) << who;
  // Bit-identical: EXPECT_EQ on doubles, no tolerance. Report the first difference only.
  for (size_t i = 0; i < a.stress_history.size(); ++i) {
    if (a.stress_history[i] != ref.stress_history[i]) {
      ADD_FAILURE() << who << ": stress differs at step " << i / 6 << " component " << i % 6 << ": "
                    << a.stress_history[i] << " vs " << ref.stress_history[i];
      break;
    }
  }
  EXPECT_EQ(a.statev, ref.statev) << who;
  EXPECT_EQ(a.tangent_last, ref.tangent_last) << who;
  EXPECT_EQ(a.substeps, ref.substeps) << who;
  EXPECT_EQ(a.plastic_steps, ref.plastic_steps) << who;
}

TEST(CAbiThreads, OneHandleManyThreadsBitIdenticalToSerialRun) {
  ModelHandle h;
  const PathResult serial = run_path(h.model);
  ASSERT_EQ(serial.codes, std::vector<int>{ACST_OK}) << "the path itself must run without failures";
  // The path must visit both branches: plastic loading and elastic unloading, each on at least
  // a tenth of the increments.
  EXPECT_GT(serial.plastic_steps, path_steps / 10);
  EXPECT_LT(serial.plastic_steps, path_steps - path_steps / 10);
  std::printf("serial path: %d of %d increments plastic, %ld substeps\n", serial.plastic_steps, path_steps, serial.substeps);

  std::vector<PathResult> results(thread_count);
  std::atomic<int> ready{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < thread_count; ++t)
    threads.emplace_back([&, t] {
      ++ready;
      while (ready.load() < thread_count) std::this_thread::yield();  // start together
      results[t] = run_path(h.model);
    });
  for (auto& th : threads) th.join();
  for (int t = 0; t < thread_count; ++t) expect_identical(results[t], serial, "thread " + std::to_string(t));
}

// The batch function from several threads on disjoint slices of shared arrays (with strides wider
// than a point) equals one serial batch over all points.
TEST(CAbiThreads, BatchOnDisjointSlicesFromThreadsEqualsSerialBatch) {
  ModelHandle h;
  constexpr size_t points_per_thread = 6, n = thread_count * points_per_thread;
  constexpr size_t ss = 7, sv = ACST_NSTATV + 1, ds = 6;
  constexpr int steps = 300;
  auto initial = [&](std::vector<double>& stress, std::vector<double>& statev, std::vector<double>& dstrain) {
    stress.assign(n * ss, -1.0);
    statev.assign(n * sv, -1.0);
    dstrain.assign(n * ds, 0.0);
    for (size_t k = 0; k < n; ++k) {
      const double p = 50.0 + 10.0 * k;  // each point its own pressure, density and path scale
      const double s0[6] = {-p, -p, -p, 0, 0, 0}, b[3] = {1.0, 0.1 * k, 0.0};
      ASSERT_EQ(acst_initial_state(&statev[k * sv], &stress[k * ss], h.model, s0, 0.65 + 0.005 * k, b).code, ACST_OK);
    }
  };
  auto fill_strain = [&](int step, size_t first, size_t count, std::vector<double>& dstrain) {
    for (size_t k = first; k < first + count; ++k) path_increment(step, 0.5 + 0.05 * k, &dstrain[k * ds]);
  };

  std::vector<double> s_ref, q_ref, d_ref;
  initial(s_ref, q_ref, d_ref);
  for (int step = 0; step < steps; ++step) {
    fill_strain(step, 0, n, d_ref);
    std::vector<int> codes(n, -1);
    const acst_status st =
        acst_update_batch(s_ref.data(), ss, q_ref.data(), sv, codes.data(), nullptr, h.model, n, d_ref.data(), ds);
    ASSERT_EQ(st.code, ACST_OK) << st.message;
  }

  std::vector<double> s, q, d;
  initial(s, q, d);
  std::vector<int> failures(thread_count, 0);
  std::atomic<int> ready{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < thread_count; ++t)
    threads.emplace_back([&, t] {
      const size_t first = t * points_per_thread;
      ++ready;
      while (ready.load() < thread_count) std::this_thread::yield();
      for (int step = 0; step < steps; ++step) {
        fill_strain(step, first, points_per_thread, d);  // each thread writes only its own slice
        const acst_status st = acst_update_batch(&s[first * ss], ss, &q[first * sv], sv, nullptr, nullptr, h.model,
                                                 points_per_thread, &d[first * ds], ds);
        if (st.code != ACST_OK) ++failures[t];
      }
    });
  for (auto& th : threads) th.join();
  EXPECT_EQ(failures, std::vector<int>(thread_count, 0));
  EXPECT_EQ(s, s_ref) << "stress (including the untouched padding) bit-identical to the serial batch";
  EXPECT_EQ(q, q_ref) << "state bit-identical to the serial batch";
}

}  // namespace

}  // namespace c_abi_threads_test
