// SPDX-License-Identifier: MIT
// Where every random seed of an evolution run comes from: mix_seed of the master seed, a
// purpose tag and indices, never a thread id or the clock, so that a run is reproducible on any
// number of threads and across resumes.
#pragma once

#include <cstdint>

#include "sim/rng.hpp"

namespace swarmpath::evolve {

/// Purpose tags: they keep the streams apart ("gen", "reev", "opt" in ASCII).
inline constexpr std::uint64_t kTagGeneration = 0x67656eULL;
inline constexpr std::uint64_t kTagReevaluation = 0x72656576ULL;
inline constexpr std::uint64_t kTagOptimizer = 0x6f7074ULL;

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
