// SPDX-License-Identifier: MIT
// The fitness of one simulation run (minimised) and its summary over a candidate's cases. A
// failed run is never a missing value: it counts as a censored time (max_ticks), a stated path
// penalty ratio and every robot used, plus the failure weight.
#pragma once

#include <cstdint>
#include <limits>
#include <span>

#include "sim/controller.hpp"
#include "sim/metrics.hpp"

namespace swarmpath::evolve {

/// Weights of the fitness terms ([fitness] table of an evolve config).
struct FitnessWeights {
  double w_fail = 1.0;           ///< weight of (1 - success)
  double w_time = 1.0;           ///< weight of ticks_to_form / max_ticks (max_ticks on failure)
  double w_path = 1.0;           ///< weight of path length / A* (fail_path_ratio on failure)
  double w_robots = 0.0;         ///< weight of robots used / N (N on failure)
  double fail_path_ratio = 3.0;  ///< the path/A* ratio a failed run counts as
};

/// What the fitness of one run needs to know about its case.
struct CaseInfo {
  std::int64_t max_ticks = 1;                                  ///< the scenario's T_max, the censoring time
  double astar_tu = std::numeric_limits<double>::quiet_NaN();  ///< A* (8-connected) length [TU]
  int robots = 1;                                              ///< N
  sim::Mode mode = sim::Mode::kPathFormation;
};

/// One run's score and the parts it is made of.
struct RunScore {
  double fitness = 0.0;  ///< lower is better
  bool success = false;
  double ticks = 0.0;  ///< ticks_to_form, or max_ticks when the path never formed (censored)
  double path_ratio = std::numeric_limits<double>::quiet_NaN();  ///< path / A*; NaN on failure
  double robots_used =
      0.0;  ///< ta_robots_used (ta, once allocated, failures too) or path_robots (pf); else N
  double robots_fraction = 1.0;  ///< robots_used / N
};

/// The robots a task-allocation run used: those allocated, or the chain's robots when more (scouts
/// that were still exploring when the founder allocated can end up in the chain; allocated alone
/// would not count them).
int ta_robots_used(const sim::Metrics& m);

/// fitness = w_fail (1 - success) + w_time t / max_ticks + w_path r + w_robots u / N, where on
/// success t = ticks_to_form, r = path / A*, u = allocated (ta) or path_robots (pf), and on
/// failure t = max_ticks, r = fail_path_ratio, u = N. A success whose path or A* length is
/// unknown counts r = fail_path_ratio. The fitness of a failure is penalty_score's; its robots_used
/// is what it committed: ta_robots_used for a task-allocation run that allocated, else N.
RunScore score_run(const sim::Metrics& m, const CaseInfo& c, const FitnessWeights& w);

/// The score of a run that was not simulated because the candidate breaks a constraint: a
/// failure in every term (the worst score a simulated run can get).
RunScore penalty_score(const CaseInfo& c, const FitnessWeights& w);

/// A candidate's summary over its cases.
struct CandidateStats {
  double fitness = std::numeric_limits<double>::infinity();  ///< mean run fitness
  double success_rate = 0.0;
  double mean_ticks = 0.0;                                            ///< mean censored ticks, over all runs
  double mean_path_ratio = std::numeric_limits<double>::quiet_NaN();  ///< over successful runs
  double mean_robots = 0.0;                                           ///< over all runs
  double mean_robots_fraction = 1.0;  ///< mean of robots used / N, over all runs
  int runs = 0;
};

/// Means in index order (so that the sums do not depend on the thread count).
CandidateStats summarise(std::span<const RunScore> runs);

}  // namespace swarmpath::evolve
