// SPDX-License-Identifier: MIT
// A benchmark of generated arenas (configs/benchmarks/*.toml): for each family its parameters
// and arena seeds (all from the benchmarks' own range, which no screen or tuning run draws), the
// robot counts, the simulation seeds and the paper arenas to run beside them. Versioned: the
// arena generator's version is part of it, so that a benchmark never silently changes its arenas.
// A screen (purpose = "screen") is the same for the training side: its arena seeds lie outside the
// benchmarks' range, so that rules are chosen on it and measured on a benchmark.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "sim/arenas/registry.hpp"

namespace swarmpath::app {

struct BenchmarkFamily {
  sim::arenas::ArenaSpec spec;       ///< its robots parameter is the largest robot count
  std::vector<std::uint64_t> seeds;  ///< arena seeds, each a benchmark seed (a screen's: none is)
  std::string label;                 ///< its rows' name: `label`, else the family's name
};

struct BenchmarkConfig {
  std::string file;
  std::string name;
  int version = 1;
  bool screen = false;          ///< purpose = "screen": arena seeds outside the benchmarks' range
  std::vector<int> robots;      ///< robot counts of every arena
  int seeds = 1;                ///< runs per arena and robot count (the same seeds with and without TA)
  std::uint64_t seed_base = 1;  ///< simulation seeds seed_base .. seed_base + seeds - 1
  std::int64_t max_ticks = 36000;
  std::vector<std::string> paper;  ///< the paper arenas' files, run beside (empty: none)
  std::vector<BenchmarkFamily> families;

  /// Arenas in all.
  std::size_t arenas() const;
};

/// Reads and checks a benchmark file; errors are ConfigErrors (file:line: key: message).
BenchmarkConfig load_benchmark_config(const std::string& path);

/// The arenas of `families`, drawn in parallel (each a pure function of family, parameters, seed),
/// in order; a generator error is a runtime_error.
std::vector<sim::arenas::GeneratedArena> draw_benchmark_arenas(
    const std::vector<const BenchmarkFamily*>& families, int threads);

/// The same from text; `base_dir` resolves `paper`.
BenchmarkConfig parse_benchmark_config(std::string_view text, const std::string& name,
                                       const std::string& base_dir);

}  // namespace swarmpath::app
