// SPDX-License-Identifier: MIT
// The files a multi-objective run leaves behind: log.csv (hypervolume per generation),
// hypervolume.svg, pareto.csv (parameters, objectives and 95 % intervals of every front point and
// the base params), front/NNN.toml (one params file per front point), pareto.svg (the front in
// every 2-D projection, fresh-seed means with their intervals, the base params marked) and run.json.
#pragma once

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/checkpoint.hpp"
#include "evolve/evolve_config.hpp"
#include "evolve/pareto_runner.hpp"

namespace swarmpath::evolve {

/// "path / A*", "ticks to form", "robots used / N": an objective as axes and tables name it.
std::string objective_title(ObjectiveKind k);

/// A value of an objective as tables print it: ticks whole, the others to 3 decimals.
std::string objective_text(ObjectiveKind k, double v);

/// "mean +- half width" (the mean alone when the width is unbounded).
std::string interval_text(ObjectiveKind k, const Interval& i);

/// generation,hypervolume,front_size,feasible,best_success_rate,min_<objective>...,evaluations,seconds
void write_pareto_log_csv(std::ostream& out, const std::vector<GenerationRecord>& history,
                          const std::vector<ObjectiveKind>& kinds);

/// The hypervolume of the feasible front per generation.
void write_hypervolume_svg(std::ostream& out, const std::string& title,
                           const std::vector<GenerationRecord>& history);

/// "000.toml", "001.toml", ...: the file of front point i in front/.
std::string front_file_name(std::size_t i);

/// One row per front point, then one for the base params: where it was found, the tuned values,
/// the generation objectives, then per objective the fresh-seed mean, interval and run count, the
/// success rate, and the flags (feasible, dominated after re-evaluation, dominates the base).
void write_pareto_csv(std::ostream& out, const EvolveConfig& c, const ParetoResult& r);

/// Front point i as a params file, its provenance and fresh-seed objectives in the header.
std::string front_point_toml(const EvolveConfig& c, const ParetoResult& r, std::size_t i);

/// Every 2-D projection of the front side by side: fresh-seed means with 95 % intervals (hollow
/// when dominated after re-evaluation), the generation values they moved from, the base params.
void write_pareto_svg(std::ostream& out, const EvolveConfig& c, const ParetoResult& r);

/// run.json of a multi-objective run: run_json_common plus the front and the base params.
nlohmann::ordered_json pareto_run_json(const EvolveConfig& c, const ParetoResult& r, int threads);

}  // namespace swarmpath::evolve
