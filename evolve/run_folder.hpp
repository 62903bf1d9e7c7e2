// SPDX-License-Identifier: MIT
// The output folder of an evolve run, guarded so that a week-long run is never lost: the files a
// run writes there, the check that none of them is an input of the run, and what happens to an
// earlier run found in the folder (refused unless resumed; with --force moved aside, not deleted).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "evolve/evolve_config.hpp"

namespace swarmpath::evolve {

/// The files and folders run_evolution and run_pareto write into their folder.
const std::vector<std::string>& run_file_names();

/// Throws sim::ConfigError (exit 2) when one of the run's files in `folder` would be an input of
/// the run (the config, its params file, a scenario), naming both.
void check_run_inputs(const EvolveConfig& c, const std::string& folder);

/// Before a fresh run (not a resume) in `folder`: when it holds an earlier run's files, throws
/// sim::ConfigError saying how far that run got and how to go on (--resume, --force, another
/// folder); with `force`, moves those files into folder/replaced/<UTC time>/ instead and tells
/// `note` where. Either way, removes the temporary files a kill left behind. Call it with the
/// folder locked.
void prepare_run_folder(const std::string& folder, bool resume, bool force,
                        const std::function<void(const std::string&)>& note);

/// True when `folder` holds what a run killed during its first generation leaves: progress files
/// (log.csv, fitness.svg, hypervolume.svg, written before the checkpoint) but no checkpoint.json,
/// run.json or best.toml. Such a run has nothing to continue from: a resume starts it again.
bool stopped_before_first_checkpoint(const std::string& folder);

}  // namespace swarmpath::evolve
