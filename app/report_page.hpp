// SPDX-License-Identifier: MIT
// The page of a tuning run (`swarmpath report`): the files an evolve run leaves (run.json,
// checkpoint.json, best.toml or front/, the SVGs, evaluate.json when `evaluate --json` wrote one)
// read and laid out as one self-contained HTML page with the best genome's replays.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/checkpoint.hpp"
#include "web_page.hpp"

namespace swarmpath::app {

struct ReportInputs {
  std::string dir;
  nlohmann::json run;                      ///< run.json
  evolve::RunState state;                  ///< checkpoint.json: the history
  std::optional<nlohmann::json> evaluate;  ///< evaluate.json, when there is one
  std::string genome_file;                 ///< best.toml, or front/000.toml for NSGA-II
  std::string genome_toml;                 ///< its text
  std::string progress_svg;                ///< fitness.svg or hypervolume.svg ("" when missing)
  std::string pareto_svg;                  ///< pareto.svg (NSGA-II)
  bool pareto = false;                     ///< a multi-objective run

  std::string name() const;
};

/// Reads an evolve run's folder; throws ConfigError naming the file when run.json or
/// checkpoint.json is missing or malformed.
ReportInputs read_report_inputs(const std::string& dir);

/// A mean with its 95 % interval (Student's t), over the finite values.
struct MeanInterval {
  double mean = 0.0;
  double half_width = 0.0;  ///< +inf when fewer than two values
  int n = 0;
};

MeanInterval mean_interval(const std::vector<double>& values);

/// Wilson's 95 % interval of a proportion k / n: {low, high}.
std::pair<double, double> wilson_interval(int k, int n);

/// The whole page; `replays` are the best genome's recorded runs, `notes` lines said at the top.
std::string report_page(const ReportInputs& in, const std::vector<PageRecording>& replays,
                        const std::vector<std::string>& notes);

}  // namespace swarmpath::app
