// SPDX-License-Identifier: MIT
// The paper's "Test Results (average) for eight different environments" (SPEC §5.1) and its
// headline claims (SPEC §5.2), printed beside ours.
#pragma once

#include <optional>
#include <string>

namespace swarmpath::app {

struct PaperRow {
  int env;
  double time_without;  ///< ticks
  double time_with;     ///< ticks
  double astar_tu;
  double path_without_tu;
  double path_with_tu;
  double resource_reduction_pct;
};

// clang-format off
inline constexpr PaperRow kPaperTable[8] = {
    {1,  4677,  5047, 100.0, 131.4, 100.3, 77.1},
    {2,  7348,  2389, 112.8, 147.5, 104.4, 75.4},
    {3,  5977,  5026, 132.9, 149.5, 118.6, 75.4},
    {4,  9754,  8383, 144.3, 197.6, 158.2, 52.5},
    {5, 10124,  8164, 158.9, 150.3, 146.2, 49.2},
    {6, 14471, 15280, 172.5, 201.0, 183.1, 47.1},
    {7, 10464,  7679, 143.1, 142.3, 145.9, 76.2},
    {8, 20123, 19770, 191.2, 211.4, 209.2, 42.9},
};
// clang-format on

/// SPEC §5.2: success without TA 80 % of 40 cases; 25 % of the no-TA paths shorter than A*;
/// with TA 61.93 % resource reduction, 40 % shorter than A*, 87.5 % faster, all 40 shorter than
/// without TA.
inline constexpr double kPaperSuccessRatePf = 80.0;
inline constexpr double kPaperPctPfShorterThanAstar = 25.0;
inline constexpr double kPaperMeanResourceReduction = 61.93;
inline constexpr double kPaperPctTaShorterThanAstar = 40.0;
inline constexpr double kPaperPctTaFaster = 87.5;
inline constexpr double kPaperPctTaShorterThanPf = 100.0;  ///< "in all 40 test cases"

/// The paper's row for a scenario named "env1" ... "env8".
inline std::optional<PaperRow> paper_row(const std::string& scenario_name) {
  for (const PaperRow& r : kPaperTable) {
    if (scenario_name == "env" + std::to_string(r.env)) return r;
  }
  return std::nullopt;
}

}  // namespace swarmpath::app
