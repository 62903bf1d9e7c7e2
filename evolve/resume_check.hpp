// SPDX-License-Identifier: MIT
// A checkpoint against the config that resumes it: what checkpoint_from_json cannot know alone.
#pragma once

#include <cstddef>
#include <string>

#include "evolve/checkpoint.hpp"
#include "evolve/evolve_config.hpp"

namespace swarmpath::evolve {

/// Checks a checkpoint read back against its config: every elite's x has the genome's dimension and
/// decodes to its recorded values (and, single-objective, breaks no constraint, is no better than
/// its generation's best and keeps the elites' order); the elites number at most top_k
/// (single-objective) or exactly `population` (multi-objective: the optimiser's population); each
/// elite's stats cover the `cases_per_generation` cases of a generation; the runs count whole
/// generations of cases; a multi-objective history holds one front minimum per objective. Throws
/// sim::ConfigError naming `checkpoint` and the field.
void check_resumed_state(const EvolveConfig& c, const RunState& st, std::size_t cases_per_generation,
                         std::size_t population, const std::string& checkpoint);

}  // namespace swarmpath::evolve
