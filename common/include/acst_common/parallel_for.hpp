#pragma once
// The one parallel loop of the project. OpenMP where the including target is built with it,
// a plain loop otherwise.
//   static chunks (default): index i always runs on the same thread for a given thread count,
//     so per-thread partial sums combined in thread order give results that depend on the
//     thread count only (the MPM's scatters rely on this);
//   dynamic: indices handed out one at a time in order, for work of very different lengths
//     sorted longest first (the calibration's element tests).
// The first exception thrown by the body is rethrown after the loop (the others are dropped).
#include <cstddef>
#include <exception>
#include <mutex>
#ifdef _OPENMP
#include <omp.h>
#endif

namespace acst::common {

enum class Schedule { static_chunks, dynamic };

// Threads a loop will use: `requested` when positive, else every hardware thread (1 without OpenMP).
inline int thread_count(int requested) {
#ifdef _OPENMP
  return requested > 0 ? requested : omp_get_max_threads();
#else
  (void)requested;
  return 1;
#endif
}

// f(thread, index) for index in [0, n).
template <class F>
void parallel_for(int threads, std::size_t n, F&& f, Schedule schedule = Schedule::static_chunks) {
  std::exception_ptr error;
  std::mutex error_mutex;
  auto guarded = [&](int t, std::size_t i) {
    try {
      f(t, i);
    } catch (...) {
      std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) error = std::current_exception();
    }
  };
#ifdef _OPENMP
  if (schedule == Schedule::dynamic) {
#pragma omp parallel for schedule(dynamic, 1) num_threads(thread_count(threads))
    for (std::size_t i = 0; i < n; ++i) guarded(omp_get_thread_num(), i);
  } else {
#pragma omp parallel num_threads(thread_count(threads))
    {
      const int t = omp_get_thread_num();
      // nowait: the region's own end is the one barrier (a second, the loop's, cost about a
      // quarter of a short loop's fork and join).
#pragma omp for schedule(static) nowait
      for (std::size_t i = 0; i < n; ++i) guarded(t, i);
    }
  }
#else
  (void)threads;
  (void)schedule;
  for (std::size_t i = 0; i < n; ++i) guarded(0, i);
#endif
  if (error) std::rethrow_exception(error);
}

}  // namespace acst::common
