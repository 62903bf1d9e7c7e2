// SPDX-License-Identifier: MIT
// Where every random seed of an evolution run comes from: mix_seed of the master seed, a
// purpose tag and indices, never a thread id or the clock, so that a run is reproducible on any
// number of threads and across resumes.
#pragma once

#include <cstdint>

#include "sim/arenas/registry.hpp"
#include "sim/rng.hpp"

namespace swarmpath::evolve {

/// Purpose tags: they keep the streams apart ("gen", "reev", "opt" in ASCII).
inline constexpr std::uint64_t kTagGeneration = 0x67656eULL;
inline constexpr std::uint64_t kTagReevaluation = 0x72656576ULL;
inline constexpr std::uint64_t kTagOptimizer = 0x6f7074ULL;
inline constexpr std::uint64_t kTagArena = 0x6172656e61ULL;   ///< "arena": training arenas
inline constexpr std::uint64_t kTagValidation = 0x76616cULL;  ///< "val": validation arenas
inline constexpr std::uint64_t kTagVerify = 0x766572ULL;      ///< "ver": `swarmpath verify`

/// Arena seeds by purpose, in disjoint ranges below 2^63 (a TOML integer holds them), all above
/// the benchmarks' own seeds: training arenas [2^61, 2^62), validation [2^62, 2^62 + 2^61),
/// verification [2^62 + 2^61, 2^63). No tuning run can draw a benchmark arena or a validation
/// arena as a training one.
inline constexpr std::uint64_t kTrainingArenaSeeds = 1ULL << 61;
inline constexpr std::uint64_t kValidationArenaSeeds = 1ULL << 62;
inline constexpr std::uint64_t kVerifyArenaSeeds = (1ULL << 62) + (1ULL << 61);
static_assert(sim::arenas::kBenchmarkSeedHi <= kTrainingArenaSeeds);
static_assert(kVerifyArenaSeeds + ((1ULL << 61) - 1) == sim::arenas::kMaxArenaSeed);

enum class ArenaUse : std::uint8_t { kTraining, kValidation, kVerify, kOther };

/// Which range an arena seed lies in.
constexpr ArenaUse arena_use(std::uint64_t seed) {
  if (seed >= kVerifyArenaSeeds && seed <= sim::arenas::kMaxArenaSeed) return ArenaUse::kVerify;
  if (seed >= kValidationArenaSeeds && seed < kVerifyArenaSeeds) return ArenaUse::kValidation;
  if (seed >= kTrainingArenaSeeds && seed < kValidationArenaSeeds) return ArenaUse::kTraining;
  return ArenaUse::kOther;
}

/// The seed of training arena `arena` of family entry `entry` in `generation`: the same for
/// every candidate and every robot count of the generation (common random arenas), new in every
/// generation (unless `fixed_seeds`: generation 0's).
constexpr std::uint64_t training_arena_seed(std::uint64_t master, std::int64_t generation,
                                            std::uint64_t entry, std::uint64_t arena,
                                            bool fixed_seeds = false) {
  const auto g = static_cast<std::uint64_t>(fixed_seeds ? 0 : generation);
  return kTrainingArenaSeeds + (sim::mix_seed(master, kTagArena, g, entry, arena) >> 3);
}

/// The seed of validation arena `arena` of family entry `entry` (the same all run long).
constexpr std::uint64_t validation_arena_seed(std::uint64_t master, std::uint64_t entry,
                                              std::uint64_t arena) {
  return kValidationArenaSeeds + (sim::mix_seed(master, kTagValidation, entry, arena) >> 3);
}

/// The seed of `swarmpath verify`'s arena `arena` of family entry `entry`.
constexpr std::uint64_t verify_arena_seed(std::uint64_t master, std::uint64_t entry, std::uint64_t arena) {
  return kVerifyArenaSeeds + (sim::mix_seed(master, kTagVerify, entry, arena) >> 3);
}

/// The simulation seed of `swarmpath verify`'s case `case_index`.
constexpr std::uint64_t verify_seed(std::uint64_t master, std::uint64_t case_index) {
  return sim::mix_seed(master, kTagVerify, case_index);
}

/// The simulation seed of evaluation case `case_index` in `generation`.
///
/// The candidate index is deliberately NOT an input: every candidate of a generation meets
/// the same seeds (common random numbers), so differences between candidates within a
/// generation come from their parameters, not from luckier deployments. With `fixed_seeds`
/// the generation is replaced by 0, so every generation reuses generation 0's seeds.
constexpr std::uint64_t generation_seed(std::uint64_t master, std::int64_t generation,
                                        std::uint64_t case_index, bool fixed_seeds = false) {
  const auto g = static_cast<std::uint64_t>(fixed_seeds ? 0 : generation);
  return sim::mix_seed(master, kTagGeneration, g, case_index);
}

/// The seed of re-evaluation case `case_index` (fresh: never one a generation used, up to a
/// 64-bit hash collision). The same for every finalist, again for common random numbers.
constexpr std::uint64_t reevaluation_seed(std::uint64_t master, std::uint64_t case_index) {
  return sim::mix_seed(master, kTagReevaluation, case_index);
}

/// The optimiser's own seed.
constexpr std::uint64_t optimizer_seed(std::uint64_t master) { return sim::mix_seed(master, kTagOptimizer); }

}  // namespace swarmpath::evolve
