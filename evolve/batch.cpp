// SPDX-License-Identifier: MIT
#include "batch.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <stdexcept>

#include <omp.h>

#include "evolve/stopwatch.hpp"
#include "sim/step.hpp"

namespace swarmpath::evolve {

namespace {

std::string rate_text(std::size_t tasks, double seconds) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "%zu simulations in %.1f s (%.2f per s)", tasks, seconds,
                seconds > 0 ? static_cast<double>(tasks) / seconds : 0.0);
  return buf;
}

}  // namespace

std::uint32_t SimBatch::add_scenario(std::shared_ptr<const sim::Scenario> s) {
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    if (scenarios[i] == s) return static_cast<std::uint32_t>(i);
  }
  scenarios.push_back(std::move(s));
  return static_cast<std::uint32_t>(scenarios.size() - 1);
}

std::uint32_t SimBatch::add_params(const sim::Params& p) {
  params.push_back(p);
  return static_cast<std::uint32_t>(params.size() - 1);
}

double expected_cost(const sim::Scenario& s, sim::Mode mode) {
  // the cost of a robot-tick relative to path formation's, from whole runs on one core
  // (docs/speed.md, bench/speed_report): task allocation 1.23x since the range-and-bearing medium
  // hands each robot only what it reads (3.4x before); diffusion runs no controller logic to speak of
  const double per_robot_tick = mode == sim::Mode::kTaskAllocation ? 1.25
                                : mode == sim::Mode::kDiffusion    ? 0.5
                                                                   : 1.0;
  return static_cast<double>(s.robots) * static_cast<double>(s.sim.max_ticks) * per_robot_tick;
}

std::vector<std::uint32_t> handout_order(const SimBatch& b) {
  std::vector<double> cost(b.tasks.size());
  for (std::size_t k = 0; k < b.tasks.size(); ++k) {
    cost[k] = expected_cost(*b.scenarios[b.tasks[k].scenario], b.tasks[k].mode);
  }
  std::vector<std::uint32_t> order(b.tasks.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = static_cast<std::uint32_t>(k);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t c) { return cost[a] > cost[c]; });
  return order;
}

sim::Metrics run_task(const SimBatch& b, std::size_t k) {
  const SimTask& t = b.tasks[k];
  return sim::evaluate(b.params[t.params], *b.scenarios[t.scenario], t.mode, t.seed);
}

void throw_first_error(const SimBatch& b, const std::vector<std::string>& errors) {
  for (std::size_t k = 0; k < errors.size(); ++k) {
    if (errors[k].empty()) continue;
    const SimTask& t = b.tasks[k];
    const sim::Scenario& s = *b.scenarios[t.scenario];
    throw std::runtime_error("evaluation failed (" + s.name + ", " + std::to_string(s.robots) + " robots, " +
                             std::string(sim::to_string(t.mode)) + ", seed " + std::to_string(t.seed) +
                             "): " + errors[k]);
  }
}

ThreadPool::ThreadPool(int threads) : threads_(std::max(1, threads)) {}

std::vector<sim::Metrics> ThreadPool::run(const SimBatch& b, const BatchProgress& progress) {
  const Stopwatch clock;
  const std::size_t total = b.tasks.size();
  const std::vector<std::uint32_t> order = handout_order(b);
  std::vector<sim::Metrics> out(total);
  std::vector<std::string> errors(total);
  std::vector<double> busy(static_cast<std::size_t>(threads_), 0.0);
  std::atomic<std::size_t> done{0};
  const auto n = static_cast<std::int64_t>(total);
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads_)
  for (std::int64_t i = 0; i < n; ++i) {
    const std::size_t k = order[static_cast<std::size_t>(i)];
    const Stopwatch task;
    try {
      out[k] = run_task(b, k);  // slot k: the same whichever thread runs it
    } catch (const std::exception& e) {
      errors[k] = e.what();
    }
    busy[static_cast<std::size_t>(omp_get_thread_num())] += task.seconds();
    const std::size_t finished = ++done;
    if (progress && omp_get_thread_num() == 0) progress(finished, total);
  }
  tasks_ += total;
  seconds_ += clock.seconds();
  for (const double s : busy) busy_seconds_ += s;
  throw_first_error(b, errors);
  if (progress) progress(total, total);
  return out;
}

std::string ThreadPool::describe() const {
  return std::to_string(threads_) + (threads_ == 1 ? " thread" : " threads");
}

std::string ThreadPool::summary() const {
  if (tasks_ == 0) return "";
  char busy[64];
  std::snprintf(busy, sizeof busy, "; threads busy %.0f %%",
                seconds_ > 0 ? 100.0 * busy_seconds_ / (seconds_ * threads_) : 0.0);
  return rate_text(tasks_, seconds_) + " on " + describe() + busy;
}

EvaluatorFactory thread_pool_factory() {
  return [](int threads) { return std::make_unique<ThreadPool>(threads); };
}

}  // namespace swarmpath::evolve
