// SPDX-License-Identifier: MIT
#include "experiment.hpp"

#include <algorithm>
#include <atomic>
#include <filesystem>

#include <omp.h>

#include "sim/config_error.hpp"
#include "sim/step.hpp"

namespace swarmpath::app {

std::vector<GridCase> make_grid(std::size_t scenarios, const std::vector<int>& robots,
                                const std::vector<sim::Mode>& modes, int seeds, std::uint64_t seed_base) {
  std::vector<GridCase> grid;
  for (std::size_t s = 0; s < scenarios; ++s) {
    for (const int n : robots) {
      for (const sim::Mode mode : modes) {
        for (int k = 0; k < seeds; ++k)
          grid.push_back({s, n, mode, seed_base + static_cast<std::uint64_t>(k)});
      }
    }
  }
  return grid;
}

std::vector<GridRun> runs_of(const std::vector<GridRun>& runs, sim::Mode mode) {
  std::vector<GridRun> out;
  for (const GridRun& r : runs) {
    if (r.c.mode == mode) out.push_back(r);
  }
  return out;
}

std::vector<GridRun> run_grid(const std::vector<sim::Scenario>& scenarios, const std::vector<GridCase>& grid,
                              const sim::Params& p, int threads, const GridProgress& progress) {
  // validate the robot counts first, so that errors come out before any work
  std::vector<sim::Scenario> cases;
  cases.reserve(grid.size());
  for (const GridCase& c : grid) cases.push_back(sim::with_robots(scenarios[c.scenario], c.robots));

  std::vector<GridRun> out(grid.size());
  std::atomic<std::size_t> done{0};
  const auto n = static_cast<std::int64_t>(grid.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
  for (std::int64_t i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    out[k] = {grid[k], sim::evaluate(p, cases[k], grid[k].mode, grid[k].seed)};  // slot k: thread-independent
    const std::size_t finished = ++done;
    if (progress && omp_get_thread_num() == 0) progress(finished, grid.size());
  }
  if (progress) progress(grid.size(), grid.size());
  return out;
}

std::vector<std::string> scenario_files(const std::vector<std::string>& paths) {
  std::vector<std::string> files;
  for (const std::string& path : paths) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
      std::vector<std::string> found;
      for (const auto& entry : std::filesystem::directory_iterator(path)) {
        if (entry.path().extension() == ".toml") found.push_back(entry.path().string());
      }
      std::sort(found.begin(), found.end());
      if (found.empty()) throw sim::ConfigError(path, 0, "", "no *.toml scenario files in this directory");
      files.insert(files.end(), found.begin(), found.end());
    } else {
      files.push_back(path);
    }
  }
  return files;
}

}  // namespace swarmpath::app
