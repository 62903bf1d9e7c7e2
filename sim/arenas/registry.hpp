// SPDX-License-Identifier: MIT
// The arena families and the one way to draw an arena: generate_arena(spec, seed) is a pure
// function of the family, its parameter values and the seed. It draws with our own random
// streams, mirrors the draw at random, checks it (nest and goal clear of obstacles, the goal
// outside the deployment region, the deployment region able to hold the robots, the goal
// reachable by the 8-connected A* of SPEC §4.5 with the robot's inflation), sets the class that
// selects delta, and draws again (deterministically) when the draw is impossible. The arena
// comes back as the scenario file's text and as what load_scenario reads from that text.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "family.hpp"
#include "sim/scenario.hpp"
#include "sim/toml_reader.hpp"

namespace swarmpath::sim::arenas {

/// Changes whenever any family would draw a different arena from the same spec and seed; a
/// benchmark records the version its arenas were drawn with.
inline constexpr int kGeneratorVersion = 1;

/// Draws tried before a spec is declared impossible.
inline constexpr int kMaxDraws = 100;

/// Arena seeds are integers in [0, kMaxArenaSeed] (a TOML integer holds them).
inline constexpr std::uint64_t kMaxArenaSeed = 0x7fffffffffffffffULL;

/// Seeds [kBenchmarkSeedLo, kBenchmarkSeedHi) are the benchmarks' own: never screen or tune on them.
inline constexpr std::uint64_t kBenchmarkSeedLo = 1'000'000;
inline constexpr std::uint64_t kBenchmarkSeedHi = 2'000'000;

constexpr bool is_benchmark_seed(std::uint64_t seed) {
  return seed >= kBenchmarkSeedLo && seed < kBenchmarkSeedHi;
}

/// An arena is "complex" when its A* path is at least this many times the A* path of the same
/// arena without obstacles (the octile distance); so are the paper's complex arenas (env7 1.19,
/// env8 1.37) and none of its obstacle arenas (env4 1.11, env5 1.04, env6 1.08). Without
/// obstacles it is "open", else "obstacle".
inline constexpr double kComplexDetour = 1.15;

/// Every family, in the order `arena families` lists them.
std::span<const Family> families();

/// The family called `name`, or nullptr.
const Family* find_family(std::string_view name);

/// The names of all families, comma-separated (for messages).
std::string family_names();

/// The parameters every family has (arena size, robots), then the family's own.
std::vector<FamilyParam> all_params(const Family& f);

/// A family and a value for each of its parameters (all_params order).
struct ArenaSpec {
  const Family* family = nullptr;
  std::vector<double> values;

  ParamValues param_values() const;

  /// The parameters that differ from their defaults, as "key=value" joined by spaces.
  std::string settings_text() const;

  /// "swarmpath arena generate --family F --seed S --set key=value ...": the command that draws it.
  std::string command_line(std::uint64_t seed) const;

  /// Every parameter as (name, value), sorted by name (a scenario's ArenaOrigin::params).
  std::vector<std::pair<std::string, double>> sorted_params() const;

  friend bool operator==(const ArenaSpec& a, const ArenaSpec& b) {
    return a.family == b.family && a.values == b.values;
  }
};

/// The family's defaults; throws ConfigError(where, 0, "family", ...) for an unknown family.
ArenaSpec default_spec(std::string_view family, const std::string& where);

/// Checks every value (range, whole numbers, the family's cross-parameter rules). An empty string
/// when the spec is sound, else the message, and `key` names the parameter to blame.
std::string check_spec(const ArenaSpec& spec, std::string& key);

/// The spec from `key=value` settings (the command line's --set): unknown keys, values that are
/// not numbers, out-of-range values and broken cross rules throw ConfigError(where, 0, key, ...).
ArenaSpec spec_from_settings(std::string_view family, const std::vector<std::string>& settings,
                             const std::string& where);

/// The spec from a config table: `family_key` names the family, the optional table `params_key`
/// its parameters; errors are ConfigErrors at file:line: key.
ArenaSpec read_spec(const TableReader& t, std::string_view family_key, std::string_view params_key);

/// A drawn arena: what the file says and what the loader reads back from it.
struct GeneratedArena {
  Scenario scenario;    ///< parse_scenario(toml): identical to loading the file
  std::string toml;     ///< the scenario file, with a header saying how it was drawn
  double astar8_m = 0;  ///< the 8-connected A* length [m] (SPEC §4.5)
  int draws = 0;        ///< draws it took (1: the first was valid)
};

/// Draws the arena of `spec` and `seed` (pure: the same inputs give the same file, on any thread).
/// Throws ConfigError naming the family when kMaxDraws draws were all impossible.
GeneratedArena generate_arena(const ArenaSpec& spec, std::uint64_t seed);

/// The 8-connected A* length of the arena without obstacles: the octile nest-goal distance [m].
double empty_arena_astar8(const Scenario& s);

/// The environment class of an arena from its obstacles and its A* length (kComplexDetour).
EnvClass classify(const Scenario& s, double astar8_m);

/// Why a loaded arena is unusable ("" when it is usable): nest or goal within 0.35 m of an
/// obstacle, the goal inside the deployment region grown by 0.5 m, an obstacle in the deployment
/// region, or no 8-connected A* path. Sets `astar8_m` when a path exists.
std::string arena_problem(const Scenario& s, double& astar8_m);

}  // namespace swarmpath::sim::arenas
