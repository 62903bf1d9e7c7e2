// SPDX-License-Identifier: MIT
#include "worker.hpp"

#include <condition_variable>
#include <deque>
#include <mutex>
#include <utility>

#include "evolve/mpi/channel.hpp"
#include "evolve/task_codec.hpp"

namespace swarmpath::mpi {

namespace {

Bytes result_message(std::uint64_t batch, std::uint32_t task, const Outcome& o) {
  evolve::ByteWriter w;
  w.u64(batch);
  w.u32(task);
  w.f64(o.seconds);
  w.u8(o.error.empty() ? 1 : 0);
  if (o.error.empty()) {
    evolve::write_metrics(w, o.metrics);
  } else {
    w.text(o.error);
  }
  return w.take();
}

// runs batch `id` until rank 0 ends it; true when rank 0 said stop instead
bool serve_batch(std::uint64_t id, const evolve::SimBatch& batch, int threads, TaskRunner runner,
                 Outbox& outbox) {
  std::mutex mutex;
  std::condition_variable work, ready;
  std::deque<std::uint32_t> queue;                      // under mutex
  bool ended = false;                                   // under mutex
  std::vector<std::pair<std::uint32_t, Outcome>> done;  // under mutex
  const auto next = [&]() -> std::optional<std::uint32_t> {
    std::unique_lock<std::mutex> lock(mutex);
    work.wait(lock, [&] { return ended || !queue.empty(); });
    if (ended) return std::nullopt;
    const std::uint32_t k = queue.front();
    queue.pop_front();
    return k;
  };
  const auto finish = [&](std::uint32_t k, Outcome&& o) {
    {
      const std::lock_guard<std::mutex> lock(mutex);
      done.emplace_back(k, std::move(o));
    }
    ready.notify_one();
  };

  bool stop = false;
  const TaskThreads pool(batch, threads, runner, next, finish);
  Backoff backoff;
  for (bool over = false; !over;) {
    bool any = false;
    // finished tasks back to rank 0
    std::vector<std::pair<std::uint32_t, Outcome>> out;
    {
      const std::lock_guard<std::mutex> lock(mutex);
      out.swap(done);
    }
    for (const auto& [k, o] : out) outbox.send(0, kResult, result_message(id, k, o));
    any = !out.empty();
    outbox.progress();
    // tasks in; the end of the batch (or of the job)
    while (!over) {
      const std::optional<Message> m = try_receive(0);
      if (!m) break;
      any = true;
      evolve::ByteReader r(m->bytes);
      if (m->tag == kTask && r.u64() == id) {
        const std::uint32_t k = r.u32();
        if (k >= batch.tasks.size()) throw std::runtime_error("corrupt message: task " + std::to_string(k));
        {
          const std::lock_guard<std::mutex> lock(mutex);
          queue.push_back(k);
        }
        work.notify_one();
      } else if (m->tag == kEndBatch || m->tag == kStop) {
        stop = m->tag == kStop;
        over = true;
        {
          const std::lock_guard<std::mutex> lock(mutex);
          ended = true;
          queue.clear();
        }
        work.notify_all();
      }
    }
    if (any) {
      backoff.reset();
    } else {
      std::unique_lock<std::mutex> lock(mutex);
      ready.wait_for(lock, backoff.next());
    }
  }
  // the pool joins here: a task still running (a batch given up on) finishes and is dropped
  return stop;
}

}  // namespace

void serve(int rank, TaskRunner runner) {
  Outbox outbox;
  Backoff backoff;
  for (;;) {
    outbox.progress();
    const std::optional<Message> m = try_receive(0);
    if (!m) {
      std::this_thread::sleep_for(backoff.next());
      continue;
    }
    backoff.reset();
    if (m->tag == kStop) break;
    if (m->tag != kBatch) continue;  // a late task or end of a batch given up on
    evolve::ByteReader r(m->bytes);
    const std::uint64_t id = r.u64();
    const auto threads = static_cast<int>(r.u32());
    const evolve::SimBatch batch = evolve::read_batch(r);
    maybe_die(rank, id);
    if (serve_batch(id, batch, threads, runner, outbox)) break;
  }
  outbox.flush();
}

}  // namespace swarmpath::mpi
