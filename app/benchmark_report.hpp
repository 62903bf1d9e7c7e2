// SPDX-License-Identifier: MIT
// The generalisation benchmark's report: per arena family, over all families and over the paper
// arenas, with and without task allocation: success, time to form the path, path / A* and the
// resource reduction; for two params files on the same runs, their differences and whether the
// first beats the second. Built from the runs of the table machinery (experiment.hpp).
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "experiment.hpp"

namespace swarmpath::app {

/// One mode's figures over a group of runs.
struct ModeFigures {
  int runs = 0;
  int successes = 0;
  double success_rate = 0.0;        ///< [0, 1]
  double ticks = 0.0;               ///< mean ticks to form, over the successful runs (NaN: none)
  double ticks_censored = 0.0;      ///< mean over all runs, a failure counting its max_ticks
  double path_ratio = 0.0;          ///< mean path / A*, over the successful runs (NaN: none)
  double resource_reduction = 0.0;  ///< TA: mean %, over the runs that allocated (NaN: none)
};

/// One row: a family's arenas (or all families', or the paper arenas) for one params file.
struct BenchmarkRow {
  std::string group;
  int arenas = 0;
  ModeFigures pf, ta;
};

/// The rows of one params file: each group in `groups` order, then "all families" over every
/// group but "paper", then "paper arenas" when there are paper runs. group_of[s] names scenario
/// s's group ("paper" for a paper arena); astar8_tu[s] is its A* length.
std::vector<BenchmarkRow> benchmark_rows(const std::vector<std::string>& groups,
                                         const std::vector<std::string>& group_of,
                                         const std::vector<double>& astar8_tu,
                                         const std::vector<GridRun>& runs);

/// Two params files on the same runs, paired.
struct PairedFigures {
  int both = 0;          ///< runs both formed the path in
  double ticks_a = 0.0;  ///< mean ticks to form of A over those runs (NaN: none)
  double ticks_b = 0.0;
  int only_a = 0, only_b = 0;
};

struct BenchmarkDifference {
  std::string group;
  PairedFigures pf, ta;
};

/// Per row, A against B over the same runs (runs_a[i] and runs_b[i] are the same case).
std::vector<BenchmarkDifference> benchmark_differences(const std::vector<std::string>& groups,
                                                       const std::vector<std::string>& group_of,
                                                       const std::vector<GridRun>& runs_a,
                                                       const std::vector<GridRun>& runs_b);

/// "A beats B": over all families, a higher success rate in every mode run, and a mean time to
/// form (paired: over the runs both formed the path in) no higher.
struct Verdict {
  bool wins = false;
  std::string text;
};

Verdict benchmark_verdict(const BenchmarkRow& all_a, const BenchmarkRow& all_b,
                          const BenchmarkDifference& all, bool pf, bool ta);

/// The table of one params file.
void write_benchmark_markdown(std::ostream& out, const std::vector<BenchmarkRow>& rows, bool pf, bool ta);

/// The differences A - B.
void write_difference_markdown(std::ostream& out, const std::vector<BenchmarkRow>& a,
                               const std::vector<BenchmarkRow>& b, const std::vector<BenchmarkDifference>& d,
                               bool pf, bool ta);

nlohmann::ordered_json benchmark_rows_json(const std::vector<BenchmarkRow>& rows);
nlohmann::ordered_json benchmark_differences_json(const std::vector<BenchmarkDifference>& d);

/// Success per group and mode as grouped bars (one colour per params file and mode).
struct BarSet {
  std::string label;
  std::string color;
  std::vector<double> values;  ///< one per group, [0, 1]
};

void write_success_svg(std::ostream& out, const std::string& title, const std::string& subtitle,
                       const std::vector<std::string>& groups, const std::vector<BarSet>& bars);

}  // namespace swarmpath::app
