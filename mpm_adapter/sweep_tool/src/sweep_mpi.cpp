#include "sweep_mpi.hpp"

#include <mpi.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <deque>
#include <iostream>
#include <string>
#include <thread>

#include "acst_common/cli.hpp"
#include "acst_sweep/sweep_runner.hpp"

namespace acst::mpm {

namespace {

constexpr int tag_ready = 1;   // worker -> rank 0: "" (first call) or "INDEX\nROW" (the case it ran)
constexpr int tag_assign = 2;  // rank 0 -> worker: the case to run, -1 for none left

// Open MPI's blocking calls spin; a rank that waits for a long time (rank 0 for its workers, a
// worker at the end for the others) polls and sleeps instead, leaving the cores to the cases.
void nap() { std::this_thread::sleep_for(std::chrono::milliseconds(20)); }

void wait_sleeping(MPI_Request& request) {
  for (int done = 0;;) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (done) return;
    nap();
  }
}

class MpiRanks : public CaseDistributor {
 public:
  MpiRanks() {
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  bool coordinator() const override { return rank_ == 0; }
  int workers() const override { return size_; }
  bool all(bool ok) override {
    int mine = ok ? 1 : 0, every = 0;
    MPI_Allreduce(&mine, &every, 1, MPI_INT, MPI_LAND, MPI_COMM_WORLD);
    return every != 0;
  }
  void distribute(const std::vector<std::size_t>& pending, const RunOne& run_one, const Finished& finished,
                  const MayStart& may_start) override {
    if (rank_ == 0)
      coordinate(pending, run_one, finished, may_start);
    else
      work(run_one);
    MPI_Request barrier;
    MPI_Ibarrier(MPI_COMM_WORLD, &barrier);
    wait_sleeping(barrier);
  }

 private:
  int rank_ = 0, size_ = 1;

  void work(const RunOne& run_one) {
    std::string report;
    for (;;) {
      MPI_Send(report.data(), static_cast<int>(report.size()), MPI_CHAR, 0, tag_ready, MPI_COMM_WORLD);
      int next = -1;
      MPI_Request request;
      MPI_Irecv(&next, 1, MPI_INT, 0, tag_assign, MPI_COMM_WORLD, &request);
      wait_sleeping(request);
      if (next < 0) return;
      report = std::to_string(next) + "\n" + run_one(static_cast<std::size_t>(next));
    }
  }

  // Rank 0 runs cases in a thread of its own while this thread (the only one that calls MPI)
  // answers the workers. A worker that asks while no case may start (the budget) waits for its
  // answer as long as a case runs anywhere: that case's end measures the rate, and a refused case
  // may fit then. Once nothing runs and nothing may start, every waiting worker is told so.
  void coordinate(const std::vector<std::size_t>& pending, const RunOne& run_one, const Finished& finished,
                  const MayStart& may_start) {
    std::deque<std::size_t> queue(pending.begin(), pending.end());
    const auto take_startable = [&](int& next) {
      for (auto it = queue.begin(); it != queue.end(); ++it)
        if (may_start(*it)) {
          next = static_cast<int>(*it);
          queue.erase(it);
          return true;
        }
      return false;
    };
    int remote_left = size_ - 1;  // workers not yet told that there is nothing left
    int remote_busy = 0;          // workers running a case
    std::deque<int> waiting;      // workers that asked and have no answer yet
    std::thread local;
    std::atomic<bool> local_done{false};
    std::size_t local_case = 0;
    std::string local_row;
    for (;;) {
      bool moved = false;
      if (local.joinable() && local_done) {
        local.join();
        finished(local_case, local_row);
        moved = true;
      }
      int next = -1;
      if (!local.joinable() && take_startable(next)) {
        local_case = static_cast<std::size_t>(next);
        local_done = false;
        local = std::thread([&, i = local_case] {
          local_row = run_one(i);
          local_done = true;
        });
        moved = true;
      }
      int asking = 0;
      MPI_Status status;
      MPI_Iprobe(MPI_ANY_SOURCE, tag_ready, MPI_COMM_WORLD, &asking, &status);
      if (asking) {
        int length = 0;
        MPI_Get_count(&status, MPI_CHAR, &length);
        std::string report(static_cast<std::size_t>(length), '\0');
        MPI_Recv(report.data(), length, MPI_CHAR, status.MPI_SOURCE, tag_ready, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        const std::size_t newline = report.find('\n');
        if (newline != std::string::npos) {
          finished(std::stoul(report.substr(0, newline)), report.substr(newline + 1));
          --remote_busy;
        }
        waiting.push_back(status.MPI_SOURCE);
        moved = true;
      }
      while (!waiting.empty()) {
        int assigned = -1;
        const bool runs_elsewhere = local.joinable() || remote_busy > 0;
        if (!take_startable(assigned) && runs_elsewhere && !queue.empty()) break;  // wait for a case to end
        MPI_Send(&assigned, 1, MPI_INT, waiting.front(), tag_assign, MPI_COMM_WORLD);
        waiting.pop_front();
        if (assigned >= 0) {
          ++remote_busy;
        } else {
          --remote_left;
        }
        moved = true;
      }
      if (!local.joinable() && remote_left == 0) {
        if (!take_startable(next)) return;
        queue.push_front(static_cast<std::size_t>(next));  // a case's end made it fit: run it here
        continue;
      }
      if (!moved) nap();
    }
  }
};

// Threads per case when --threads is not given: the machine's cores shared among its ranks.
int threads_per_rank() {
  MPI_Comm node;
  MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
  int on_node = 1;
  MPI_Comm_size(node, &on_node);
  MPI_Comm_free(&node);
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::max(1, cores / on_node);
}

}  // namespace

int sweep_over_mpi(int argc, char** argv, const std::vector<std::string>& args) {
  int provided = 0;
  if (MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
    std::cerr << "acst_sweep: MPI_Init_thread failed\n";
    return common::exit_failed;
  }
  int status = common::exit_failed;
  {
    MpiRanks ranks;
    status = sweep_cli(args, std::cout, std::cerr, &ranks, threads_per_rank());
  }
  MPI_Finalize();
  return status;
}

}  // namespace acst::mpm
