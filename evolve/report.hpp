// SPDX-License-Identifier: MIT
// The files an evolution run leaves behind: log.csv (one row per generation), fitness.svg (best
// and mean over the generations), best.toml (a params file with a provenance header) and
// run.json (config, seeds, versions, git commit, finalists).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/checkpoint.hpp"
#include "evolve/evolve_config.hpp"
#include "evolve/runner.hpp"

namespace swarmpath::evolve {

/// What built this binary (from CMake at configure time).
struct BuildInfo {
  std::string version;
  std::string git_commit;  ///< `git rev-parse --short HEAD`, or "unknown"
  std::string compiler;
  std::string box2d;
  std::string build_type;
};

BuildInfo build_info();

/// Shortest text that reads back to the same double ("nan"/"inf" as such).
std::string exact(double v);

/// generation,best,mean,std,best_so_far,best_success_rate,evaluations,seconds; with `validation`
/// also validation_fitness,validation_success_rate (the generation's best on the validation set)
void write_log_csv(std::ostream& out, const std::vector<GenerationRecord>& history, bool validation = false);

/// Best, mean and best-so-far fitness over the generations, as plain SVG.
void write_fitness_svg(std::ostream& out, const std::string& title,
                       const std::vector<GenerationRecord>& history);  // with the validation line when logged

/// best.toml: write_params_toml of the pick (the best finalist, or the base params kept by keep_base)
/// under a comment saying where it came from and, with keep_base, the paired test's figures.
std::string best_toml(const EvolveConfig& c, const RunResult& r);

/// The part of run.json every run has: tool, versions, config and its hash, every seed, threads,
/// counts, wall time and stop reason.
nlohmann::ordered_json run_json_common(const EvolveConfig& c, const RunState& st,
                                       const std::vector<EvalSetting>& settings,
                                       const std::vector<EvalCase>& cases,
                                       const std::vector<EvalCase>& reevaluation_cases, double seconds,
                                       const std::string& stop_reason, int threads);

/// run.json: the config, the seeds, the build, the stop reason and the finalists.
nlohmann::ordered_json run_json(const EvolveConfig& c, const RunResult& r, int threads);

}  // namespace swarmpath::evolve
