// SPDX-License-Identifier: MIT
// The messages between rank 0 and the other ranks, and the plumbing both sides share: polling
// receives and non-blocking sends (nobody spins a core waiting: Open MPI's blocking calls poll
// at full speed, which would steal a core from the simulations when ranks share cores), and the
// threads that run a rank's tasks.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <mpi.h>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "evolve/batch.hpp"
#include "evolve/mpi/job.hpp"
#include "sim/metrics.hpp"

namespace swarmpath::mpi {

/// Message tags. Rank 0 sends kBatch (batch id, threads, the batch), then kTask (batch id, task)
/// one per free thread, and kEndBatch (batch id) once every result is in; a rank answers each
/// task with kResult (batch id, task, seconds, ok, Metrics or the error). kStop ends a rank.
enum Tag : int { kBatch = 11, kTask = 12, kResult = 13, kEndBatch = 14, kStop = 15 };

using Bytes = std::vector<char>;

struct Message {
  int source = 0;
  int tag = 0;
  Bytes bytes;
};

/// The next waiting message from `source` (MPI_ANY_SOURCE for any), without waiting.
std::optional<Message> try_receive(int source);

/// Sends that do not block: each buffer lives until MPI has sent it.
class Outbox {
 public:
  Outbox() = default;
  Outbox(const Outbox&) = delete;
  Outbox& operator=(const Outbox&) = delete;

  void send(int dest, int tag, std::shared_ptr<const Bytes> bytes);

  void send(int dest, int tag, Bytes bytes) {
    send(dest, tag, std::make_shared<const Bytes>(std::move(bytes)));
  }

  /// Lets go of the finished sends; true when none is left.
  bool progress();

  /// Polls until every send has finished.
  void flush();

 private:
  struct Pending {
    MPI_Request request;
    std::shared_ptr<const Bytes> bytes;
  };

  std::vector<Pending> pending_;
};

/// How long to wait before polling again: 20 us after something happened, doubling to 2 ms.
class Backoff {
 public:
  std::chrono::microseconds next();

  void reset() { wait_ = std::chrono::microseconds(0); }

 private:
  std::chrono::microseconds wait_{0};
};

/// One task's outcome on the rank that ran it.
struct Outcome {
  sim::Metrics metrics;
  std::string error;     ///< empty: it ran
  double seconds = 0.0;  ///< wall time, for the busy fraction
};

/// Threads that run tasks of one batch: each asks `next` for a task (nullopt: stop), runs it and
/// hands the outcome to `done`. Joined by the destructor.
class TaskThreads {
 public:
  using Next = std::function<std::optional<std::uint32_t>()>;
  using Done = std::function<void(std::uint32_t task, Outcome&& outcome)>;

  TaskThreads(const evolve::SimBatch& batch, int threads, TaskRunner runner, Next next, Done done);
  TaskThreads(const TaskThreads&) = delete;
  TaskThreads& operator=(const TaskThreads&) = delete;
  ~TaskThreads();

 private:
  std::vector<std::thread> threads_;
};

/// SWARMPATH_MPI_FAULT="R:B" (a test hook): rank R kills itself (SIGKILL) as batch B (1-based)
/// begins, as a crashed node or a scheduler's kill would.
void maybe_die(int rank, std::uint64_t batch);

}  // namespace swarmpath::mpi
