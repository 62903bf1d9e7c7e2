// SPDX-License-Identifier: MIT
#include "mpi_evaluator.hpp"

#include <algorithm>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <stdexcept>

#include "evolve/mpi/channel.hpp"
#include "evolve/stopwatch.hpp"
#include "evolve/task_codec.hpp"

namespace swarmpath::mpi {

namespace {

std::string percent(double busy_seconds, double wall_seconds, int threads) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.0f %%",
                wall_seconds > 0 ? 100.0 * busy_seconds / (wall_seconds * threads) : 0.0);
  return buf;
}

Bytes header(std::uint64_t batch, std::uint32_t task) {
  evolve::ByteWriter w;
  w.u64(batch);
  w.u32(task);
  return w.take();
}

}  // namespace

MpiEvaluator::MpiEvaluator(int ranks, int threads, TaskRunner runner, int local_threads)
    : ranks_(ranks),
      threads_(std::max(1, threads)),
      runner_(runner),
      local_threads_(std::max(0, local_threads)),
      busy_(static_cast<std::size_t>(ranks), 0.0),
      ran_(static_cast<std::size_t>(ranks), 0) {
  if (ranks_ < 2 && local_threads_ == 0)
    throw std::invalid_argument("MpiEvaluator: no rank would run the tasks");
}

std::vector<sim::Metrics> MpiEvaluator::run(const evolve::SimBatch& b,
                                            const evolve::BatchProgress& progress) {
  const evolve::Stopwatch clock;
  const std::uint64_t id = ++batches_;
  maybe_die(0, id);
  const std::size_t n = b.tasks.size();
  std::vector<sim::Metrics> out(n);
  std::vector<std::string> errors(n);
  if (n == 0) return out;

  // the batch to every other rank: params, scenarios and tasks, once
  Outbox outbox;
  {
    evolve::ByteWriter w;
    w.u64(id);
    w.u32(static_cast<std::uint32_t>(threads_));
    evolve::write_batch(w, b);
    const auto bytes = std::make_shared<const Bytes>(w.take());
    for (int r = 1; r < ranks_; ++r) outbox.send(r, kBatch, bytes);
  }

  // one list, longest expected first, shared by this rank's threads and the other ranks
  const std::vector<std::uint32_t> order = evolve::handout_order(b);
  std::mutex mutex;
  std::condition_variable finished;
  std::size_t next = 0, done = 0;  // under mutex
  const auto take = [&]() -> std::optional<std::uint32_t> {
    const std::lock_guard<std::mutex> lock(mutex);
    if (next == n) return std::nullopt;
    return order[next++];
  };
  const auto store = [&](std::uint32_t k, Outcome&& o, int rank) {
    {
      const std::lock_guard<std::mutex> lock(mutex);
      out[k] = std::move(o.metrics);  // slot k, whoever ran it
      errors[k] = std::move(o.error);
      busy_[static_cast<std::size_t>(rank)] += o.seconds;
      ++ran_[static_cast<std::size_t>(rank)];
      ++done;
    }
    finished.notify_one();
  };
  // a rank holds one task per thread, plus one queued while plenty are left (so that its threads
  // never wait for a message), but none queued near the end (where a queued task could wait
  // behind a long one while another rank idles)
  const auto all_threads = static_cast<std::size_t>(local_threads_ + (ranks_ - 1) * threads_);
  std::vector<int> held(static_cast<std::size_t>(ranks_), 0);
  const auto top_up = [&](int rank) {
    for (;;) {
      std::optional<std::uint32_t> k;
      {
        const std::lock_guard<std::mutex> lock(mutex);
        const int want = threads_ + (n - next > all_threads ? 1 : 0);
        if (held[static_cast<std::size_t>(rank)] >= want || next == n) return;
        k = order[next++];
      }
      outbox.send(rank, kTask, header(id, *k));
      ++held[static_cast<std::size_t>(rank)];
    }
  };

  // this thread: hand tasks to the other ranks and collect what they send back
  const auto coordinate = [&] {
    for (int r = 1; r < ranks_; ++r) {
      top_up(r);
    }
    Backoff backoff;
    std::size_t reported = 0;
    for (;;) {
      bool any = false;
      // results from the other ranks; each frees a thread there, which gets the next task
      while (const std::optional<Message> m = try_receive(MPI_ANY_SOURCE)) {
        any = true;
        if (m->tag != kResult) continue;
        evolve::ByteReader r(m->bytes);
        if (r.u64() != id) continue;  // a late result of a batch given up on
        const std::uint32_t k = r.u32();
        if (k >= n) throw std::runtime_error("corrupt message: result of task " + std::to_string(k));
        Outcome o;
        o.seconds = r.f64();
        if (r.u8() != 0) {
          o.metrics = evolve::read_metrics(r);
        } else {
          o.error = r.text();
        }
        store(k, std::move(o), m->source);
        --held[static_cast<std::size_t>(m->source)];
        top_up(m->source);
      }
      outbox.progress();
      std::size_t now = 0;
      {
        const std::lock_guard<std::mutex> lock(mutex);
        now = done;
      }
      if (now != reported) {
        reported = now;
        any = true;
        if (progress) progress(now, n);
      }
      if (now == n) break;
      if (any) {
        backoff.reset();
      } else {
        std::unique_lock<std::mutex> lock(mutex);
        finished.wait_for(lock, backoff.next());
      }
    }
  };

  std::exception_ptr failure;
  {
    const TaskThreads local(b, local_threads_, runner_, take,
                            [&](std::uint32_t k, Outcome&& o) { store(k, std::move(o), 0); });
    try {
      coordinate();
    } catch (...) {
      // give the batch up: nothing more is handed out (the threads here stop after their task)
      failure = std::current_exception();
      const std::lock_guard<std::mutex> lock(mutex);
      next = n;
    }
  }
  // every rank leaves the batch; results still on their way are dropped (their batch id is old)
  for (int r = 1; r < ranks_; ++r) outbox.send(r, kEndBatch, header(id, 0));
  outbox.flush();
  if (failure) std::rethrow_exception(failure);
  tasks_ += n;
  seconds_ += clock.seconds();
  evolve::throw_first_error(b, errors);
  return out;
}

std::string MpiEvaluator::describe() const {
  return std::to_string(ranks_) + " MPI ranks x " + std::to_string(threads_) +
         (threads_ == 1 ? " thread" : " threads");
}

std::string MpiEvaluator::summary() const {
  if (tasks_ == 0) return "";
  char rate[160];
  std::snprintf(rate, sizeof rate, "%zu simulations in %.1f s (%.2f per s) on ", tasks_, seconds_,
                seconds_ > 0 ? static_cast<double>(tasks_) / seconds_ : 0.0);
  std::string s = rate + describe() + "; busy: ";
  if (local_threads_ > 0) s += "rank 0 " + percent(busy_[0], seconds_, local_threads_) + ", ";
  if (ranks_ > 1) {
    double sum = 0.0;
    std::size_t low = 1;
    for (std::size_t r = 1; r < busy_.size(); ++r) {
      sum += busy_[r];
      if (busy_[r] < busy_[low]) low = r;
    }
    s += "other ranks " + percent(sum / static_cast<double>(ranks_ - 1), seconds_, threads_) +
         " on average, lowest " + percent(busy_[low], seconds_, threads_) + " (rank " + std::to_string(low) +
         ")";
  }
  return s;
}

}  // namespace swarmpath::mpi
