#pragma once
// Deterministic particle-to-grid scatters: particles are split into static chunks, one per
// thread; each thread adds into its own copy of the nodal fields, and the copies are summed in
// thread order, so results depend on the thread count only.
#include <algorithm>
#include <cstddef>
#include <vector>

#include "acst_common/parallel_for.hpp"

namespace acst::mpm {

using common::parallel_for;
using common::thread_count;

class Scatter {
 public:
  void configure(int requested_threads, std::size_t nodes) {
    threads_ = thread_count(requested_threads);
    nodes_ = nodes;
  }
  int threads() const { return threads_; }

  // body(p, fields) adds particle p's contributions to fields[0..k); out[k] receives the sums.
  // The first thread adds straight into `out` and the others into buffers, then added onto it in
  // thread order: the sum 0 + f_0 + f_1 + ... of the copies, to the bit (a sum begun at +0 is
  // never -0, so 0 + f_0 is f_0), and on one thread no copy and no summing pass.
  template <class Body>
  void run(int k, double* const* out, std::size_t n, Body&& body) {
    buffer_.resize(static_cast<std::size_t>(threads_ - 1) * k * nodes_);
    parallel_for(threads_, static_cast<std::size_t>(threads_), [&](int, std::size_t t) {
      double* f[max_fields];
      for (int c = 0; c < k; ++c) {
        f[c] = t == 0 ? out[c] : field(t, c, k);
        std::fill(f[c], f[c] + nodes_, 0.0);
      }
      const std::size_t begin = n * t / threads_, end = n * (t + 1) / threads_;
      for (std::size_t p = begin; p < end; ++p) body(p, f);
    });
    if (threads_ == 1) return;
    parallel_for(threads_, nodes_, [&](int, std::size_t i) {
      for (int c = 0; c < k; ++c) {
        double s = out[c][i];
        for (int t = 1; t < threads_; ++t) s += field(t, c, k)[i];
        out[c][i] = s;
      }
    });
  }
  static constexpr int max_fields = 5;

 private:
  // Thread t's (t >= 1) copy of field c.
  double* field(std::size_t t, int c, int k) { return buffer_.data() + ((t - 1) * k + c) * nodes_; }
  int threads_ = 1;
  std::size_t nodes_ = 0;
  std::vector<double> buffer_;
};

}  // namespace acst::mpm
