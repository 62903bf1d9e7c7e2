// SPDX-License-Identifier: MIT
#include "channel.hpp"

#include <algorithm>
#include <csignal>
#include <cstdlib>
#include <stdexcept>

#include <climits>

#include "evolve/stopwatch.hpp"

namespace swarmpath::mpi {

std::optional<Message> try_receive(int source) {
  int flag = 0;
  MPI_Status status;
  MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
  if (!flag) return std::nullopt;
  int size = 0;
  MPI_Get_count(&status, MPI_BYTE, &size);
  Message m{status.MPI_SOURCE, status.MPI_TAG, Bytes(static_cast<std::size_t>(size))};
  MPI_Recv(m.bytes.data(), size, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return m;
}

void Outbox::send(int dest, int tag, std::shared_ptr<const Bytes> bytes) {
  if (bytes->size() > static_cast<std::size_t>(INT_MAX)) {
    throw std::runtime_error("a message of " + std::to_string(bytes->size()) + " bytes is too large for MPI");
  }
  Pending p{MPI_REQUEST_NULL, std::move(bytes)};
  // MPI reads the buffer, never writes it: the const_cast only satisfies MPI's C signature
  MPI_Isend(const_cast<char*>(p.bytes->data()), static_cast<int>(p.bytes->size()), MPI_BYTE, dest, tag,
            MPI_COMM_WORLD, &p.request);
  pending_.push_back(std::move(p));
}

bool Outbox::progress() {
  std::erase_if(pending_, [](Pending& p) {
    int done = 0;
    MPI_Test(&p.request, &done, MPI_STATUS_IGNORE);
    return done != 0;
  });
  return pending_.empty();
}

void Outbox::flush() {
  Backoff wait;
  while (!progress()) std::this_thread::sleep_for(wait.next());
}

std::chrono::microseconds Backoff::next() {
  wait_ = std::clamp(wait_ * 2, std::chrono::microseconds(20), std::chrono::microseconds(2000));
  return wait_;
}

TaskThreads::TaskThreads(const evolve::SimBatch& batch, int threads, TaskRunner runner, Next next,
                         Done done) {
  for (int i = 0; i < threads; ++i) {
    threads_.emplace_back([&batch, runner, next, done] {
      while (const std::optional<std::uint32_t> k = next()) {
        const evolve::Stopwatch clock;
        Outcome o;
        try {
          o.metrics = runner(batch, *k);
        } catch (const std::exception& e) {
          o.error = e.what();
        }
        o.seconds = clock.seconds();
        done(*k, std::move(o));
      }
    });
  }
}

TaskThreads::~TaskThreads() {
  for (std::thread& t : threads_) t.join();
}

void maybe_die(int rank, std::uint64_t batch) {
  const char* fault = std::getenv("SWARMPATH_MPI_FAULT");
  if (!fault) return;
  const std::string f(fault);
  const auto colon = f.find(':');
  if (colon == std::string::npos) return;
  try {
    if (std::stoi(f.substr(0, colon)) == rank && std::stoull(f.substr(colon + 1)) == batch)
      std::raise(SIGKILL);
  } catch (const std::logic_error&) {
    // not "R:B": no fault
  }
}

}  // namespace swarmpath::mpi
