// SPDX-License-Identifier: MIT
// The ablation of the additions beyond SPEC (sim/additions.hpp): the default controller with each
// addition switched off in turn, and the paper-literal controller with each switched on in turn, on
// the same cases (common random numbers). Each addition's effect is "with it minus without it" over
// the paired runs, with a 95 % Student-t interval, in success, time to form, path / A* and resource
// reduction; its verdict says whether any interval excludes zero, and which way.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/pareto_objectives.hpp"
#include "sim/controller.hpp"

namespace swarmpath::app {

/// What one run brings to the comparison.
struct RunOutcome {
  bool success = false;
  double ticks = std::numeric_limits<double>::quiet_NaN();       ///< T_form of a success
  double path_ratio = std::numeric_limits<double>::quiet_NaN();  ///< final path / A*-8 of a success
  double rr_pct = std::numeric_limits<double>::quiet_NaN();  ///< resource reduction (TA runs that allocated)
  std::uint64_t state_hash = 0;
};

/// The two arms of the ablation.
enum class Arm : std::uint8_t {
  kDefault,  ///< the default controller, each addition switched off in turn
  kLiteral,  ///< the paper-literal controller, each addition switched on in turn
};

std::string_view to_string(Arm a);

enum class Verdict : std::uint8_t {
  kHelps,          ///< an interval excludes zero on the good side, none on the bad side
  kHurts,          ///< an interval excludes zero on the bad side, none on the good side
  kMixed,          ///< intervals exclude zero on both sides
  kNotMeasurable,  ///< every interval includes zero (or too few pairs to tell)
};

std::string_view to_string(Verdict v);

/// One addition in one arm and one mode: its effect, with it minus without it.
struct Effect {
  int pairs = 0;
  double success_with = 0;  ///< success rate with the addition [0, 1]
  double success_without = 0;
  evolve::Interval success;     ///< difference of the success indicators [-1, 1]
  evolve::Interval ticks;       ///< T_form, over the pairs where both formed the path
  evolve::Interval path_ratio;  ///< path / A*, the same pairs
  evolve::Interval rr_pct;      ///< resource reduction [points], task-allocation pairs that allocated
  Verdict verdict = Verdict::kNotMeasurable;
};

/// The effect of an addition from paired runs: `with[i]` and `without[i]` ran the same case.
/// Throws std::invalid_argument when the sizes differ.
Effect paired_effect(std::span<const RunOutcome> with, std::span<const RunOutcome> without);

/// The verdict of an effect: higher success and resource reduction, fewer ticks and a lower path / A*
/// are better; an interval counts when it excludes zero.
Verdict verdict_of(const Effect& e);

/// One row of the ablation table.
struct AblationRow {
  Arm arm = Arm::kDefault;
  std::string addition;
  std::string title;
  std::string rule;
  sim::Mode mode = sim::Mode::kPathFormation;
  Effect effect;
};

/// What the table was measured on.
struct AblationGrid {
  std::vector<std::string> scenarios;
  std::vector<int> robots;
  int seeds = 0;
  std::uint64_t seed_base = 1;
  std::int64_t max_ticks = 0;
  std::string default_params;  ///< the files of the two arms
  std::string literal_params;
};

/// The rows as markdown: the grid, then one table per arm.
void write_ablation_markdown(std::ostream& out, const AblationGrid& grid,
                             const std::vector<AblationRow>& rows);

/// The rows as JSON.
nlohmann::ordered_json ablation_json(const AblationGrid& grid, const std::vector<AblationRow>& rows);

/// A forest plot: per arm and mode, each addition's success difference (and, for the default arm,
/// its time difference) with the 95 % interval.
void write_ablation_svg(std::ostream& out, const AblationGrid& grid, const std::vector<AblationRow>& rows);

}  // namespace swarmpath::app
