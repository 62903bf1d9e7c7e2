// SPDX-License-Identifier: MIT
#include "experiment.hpp"

#include <algorithm>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <ostream>
#include <utility>

#include "common.hpp"
#include "evolve/path_collision.hpp"
#include "sim/astar.hpp"
#include "sim/config_error.hpp"
#include "sim/scenario_identity.hpp"

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

std::vector<sim::Mode> path_modes(const std::string& mode) {
  if (mode == "both") return {sim::Mode::kPathFormation, sim::Mode::kTaskAllocation};
  const sim::Mode m = mode_from_option(mode);
  if (m == sim::Mode::kDiffusion)
    throw sim::ConfigError("--mode", 0, "", "needs pf, ta or both (diffusion forms no path)");
  return {m};
}

GridProgress grid_progress(std::ostream& err, bool terminal) {
  auto clock = std::make_shared<Stopwatch>();
  auto last_line = std::make_shared<std::size_t>(0);
  return [&err, terminal, clock, last_line](std::size_t done, std::size_t total) {
    const double t = clock->seconds();
    const double eta = done > 0 ? t * static_cast<double>(total - done) / static_cast<double>(done) : 0.0;
    if (terminal) {
      err << "\r  " << done << " / " << total << " runs, " << fixed(t, 0) << " s, ETA " << fixed(eta, 0)
          << " s   " << std::flush;
    } else if (done == total || done >= *last_line + std::max<std::size_t>(1, total / 10)) {
      *last_line = done;
      err << "  " << done << " / " << total << " runs, " << fixed(t, 0) << " s\n";
    }
  };
}

std::vector<std::vector<GridRun>> run_grid(const std::vector<sim::Scenario>& scenarios,
                                           const std::vector<GridCase>& grid,
                                           const std::vector<sim::Params>& params,
                                           evolve::BatchEvaluator& evaluator, const GridProgress& progress) {
  // each (scenario, robots) once, checked before any work so that errors come out first
  evolve::SimBatch batch;
  std::map<std::pair<std::size_t, int>, std::uint32_t> index;
  std::vector<std::uint32_t> scenario_of;
  scenario_of.reserve(grid.size());
  for (const GridCase& c : grid) {
    const auto key = std::make_pair(c.scenario, c.robots);
    auto it = index.find(key);
    if (it == index.end()) {
      const auto s = std::make_shared<const sim::Scenario>(sim::with_robots(scenarios[c.scenario], c.robots));
      it = index.emplace(key, batch.add_scenario(s)).first;
    }
    scenario_of.push_back(it->second);
  }
  for (const sim::Params& p : params) {
    const std::uint32_t pi = batch.add_params(p);
    for (std::size_t k = 0; k < grid.size(); ++k)
      batch.tasks.push_back({pi, scenario_of[k], grid[k].mode, grid[k].seed});
  }
  const std::vector<sim::Metrics> metrics = evaluator.run(batch, progress);

  std::vector<std::vector<GridRun>> out(params.size());
  for (std::size_t i = 0; i < params.size(); ++i) {
    out[i].reserve(grid.size());
    for (std::size_t k = 0; k < grid.size(); ++k) out[i].push_back({grid[k], metrics[i * grid.size() + k]});
  }
  return out;
}

std::vector<GridRun> run_grid(const std::vector<sim::Scenario>& scenarios, const std::vector<GridCase>& grid,
                              const sim::Params& p, evolve::BatchEvaluator& evaluator,
                              const GridProgress& progress) {
  return std::move(run_grid(scenarios, grid, std::vector<sim::Params>{p}, evaluator, progress).front());
}

void check_distinct_scenarios(const std::string& option, const std::vector<std::string>& files,
                              const std::vector<sim::Scenario>& scenarios) {
  for (std::size_t i = 0; i < scenarios.size(); ++i) {
    for (std::size_t k = 0; k < i; ++k) {
      const auto fail = [&](const std::string& why) {
        throw sim::ConfigError(option, 0, "", files[k] + " and " + files[i] + " " + why);
      };
      if (evolve::same_file(files[k], files[i])) fail("are one file, listed twice");
      if (sim::experiment_fingerprint(scenarios[k]) == sim::experiment_fingerprint(scenarios[i])) {
        fail("are the same scenario (the same arena, robots and settings): each would count twice");
      }
      if (scenarios[k].name == scenarios[i].name) {
        fail("are two scenarios of one name, \"" + scenarios[i].name +
             "\": their rows would merge; give one of them another name");
      }
    }
  }
}

void check_distinct_robots(const std::string& option, const std::vector<int>& robots) {
  for (std::size_t i = 0; i < robots.size(); ++i) {
    for (std::size_t k = 0; k < i; ++k) {
      if (robots[k] == robots[i]) {
        throw sim::ConfigError(option, 0, "", std::to_string(robots[i]) + " robots listed twice");
      }
    }
  }
}

std::vector<double> astar8_lengths(const std::vector<sim::Scenario>& scenarios) {
  std::vector<double> out;
  for (const sim::Scenario& s : scenarios) out.push_back(sim::astar8_baseline_tu(s, s.file));
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
