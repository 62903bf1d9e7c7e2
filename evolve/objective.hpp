// SPDX-License-Identifier: MIT
// What a candidate is evaluated on: settings (scenario x robot count), cases (setting x seed),
// and the objective that scores one candidate on one case: which simulation the case is, and the
// score of its Metrics. The runner hands the simulations to a BatchEvaluator (threads or MPI
// ranks) and scores what comes back. SwarmObjective is the simulator with the fitness of
// fitness.hpp; tests put fakes in its place.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "evolve/evolve_config.hpp"
#include "evolve/fitness.hpp"
#include "sim/controller.hpp"
#include "sim/metrics.hpp"
#include "sim/params.hpp"
#include "sim/scenario.hpp"

namespace swarmpath::evolve {

/// One scenario at one robot count, or one family entry's drawn arenas at one robot count.
struct EvalSetting {
  std::string scenario;   ///< the scenario's name (a family's name for drawn arenas)
  int robots = 0;         ///< N
  bool held_out = false;  ///< a held-out scenario (re-evaluation only)
  int family = -1;        ///< drawn arenas: the index of its [[evaluation.family]] entry; -1: a scenario file
  int arenas = 0;         ///< drawn arenas: fresh arenas per generation
  int seeds = 0;          ///< drawn arenas: runs per arena
  int validation_arenas = 0;  ///< drawn arenas: arenas of the validation set
};

/// One simulation of a candidate: a setting, a seed and, for drawn arenas, the arena's seed.
/// (setting, arena_seed) is all it takes to draw the arena again, on any thread or process:
/// sim::arenas::generate_arena(config.evaluation.families[setting.family].spec, arena_seed).
struct EvalCase {
  std::size_t setting = 0;       ///< index into the objective's settings()
  int replicate = 0;             ///< k-th seed of this setting (of this arena)
  std::uint64_t seed = 0;        ///< the simulation's seed
  int arena = -1;                ///< drawn arenas: the k-th arena of the setting; -1: a scenario file
  std::uint64_t arena_seed = 0;  ///< drawn arenas: the arena's seed
};

/// The simulation a case stands for. The scenario is shared, never changed, and carries all
/// it needs (no file is read to run it), so that any process of an MPI job can run the case.
struct CaseSimulation {
  std::shared_ptr<const sim::Scenario> scenario;
  sim::Mode mode = sim::Mode::kPathFormation;
  std::uint64_t seed = 0;
};

/// Scores candidates case by case: simulation(c) says what to run, score() turns its Metrics
/// into the run's score. All three must be const, pure and thread-safe.
class CaseObjective {
 public:
  virtual ~CaseObjective() = default;

  /// Training settings first, then held-out ones.
  virtual const std::vector<EvalSetting>& settings() const = 0;

  /// What case c simulates (the same for every candidate: common random numbers).
  virtual CaseSimulation simulation(const EvalCase& c) const = 0;

  /// The score of candidate p's run of case c.
  virtual RunScore score(const sim::Params& p, const EvalCase& c, const sim::Metrics& m) const = 0;

  /// The score of a candidate that breaks a constraint (not simulated).
  virtual RunScore penalty(const EvalCase& c) const = 0;

  /// Called before a batch on `cases` (evaluate_batch does): an objective that draws arenas draws
  /// the batch's ones here, once each and in parallel, instead of one by one in simulation().
  /// Logically const and thread-safe like the others; no result depends on whether it was called.
  virtual void prepare(const std::vector<EvalCase>& cases) const { (void)cases; }

  /// Adaptive capping (evolve/capping.hpp): the lowest score case c's run can still get once it
  /// has run `ticks` ticks without forming its path; nullopt (the default): no bound, never capped.
  virtual std::optional<double> score_floor(const EvalCase& c, std::int64_t ticks) const {
    (void)c;
    (void)ticks;
    return std::nullopt;
  }

  /// simulation(c), run here, then score(): one case in this thread.
  RunScore evaluate(const sim::Params& p, const EvalCase& c) const;
};

/// The cases of one generation: every training scenario setting x `seeds` seeds, then every drawn
/// arena setting x its arenas x its seeds, setting-major; case i has seed generation_seed(master,
/// generation, i, fixed_seeds), arena k of family entry f the seed training_arena_seed(master,
/// generation, f, k, fixed_seeds) (the same at every robot count).
std::vector<EvalCase> generation_cases(const std::vector<EvalSetting>& settings, int seeds,
                                       std::uint64_t master, std::int64_t generation, bool fixed_seeds);

/// The re-evaluation cases, which are the validation set: every scenario setting (held-out ones
/// too) x `seeds` fresh seeds, then every drawn arena setting x its validation arenas x its seeds;
/// case i has seed reevaluation_seed(master, i), validation arena k of family entry f the seed
/// validation_arena_seed(master, f, k).
std::vector<EvalCase> reevaluation_cases(const std::vector<EvalSetting>& settings, int seeds,
                                         std::uint64_t master);

/// The simulator as the objective: scenarios loaded once (robot counts and max_ticks applied),
/// A* computed once per scenario, scored by score_run. Drawn arenas are drawn (with their A*) once
/// per arena, by prepare() or on demand, and simulated as shared scenarios like any other.
class SwarmObjective final : public CaseObjective {
 public:
  explicit SwarmObjective(const EvolveConfig& c);

  const std::vector<EvalSetting>& settings() const override { return settings_; }

  CaseSimulation simulation(const EvalCase& c) const override;
  RunScore score(const sim::Params& p, const EvalCase& c, const sim::Metrics& m) const override;
  RunScore penalty(const EvalCase& c) const override;
  /// w_time ticks / T_max + w_path |nest - goal| / A*: what a later success still pays.
  std::optional<double> score_floor(const EvalCase& c, std::int64_t ticks) const override;
  void prepare(const std::vector<EvalCase>& cases) const override;

  /// The scenario of a scenario-file setting.
  const sim::Scenario& scenario(std::size_t setting) const { return *scenarios_[setting]; }

  /// The A* (8-connected) length of a scenario-file setting's scenario [TU].
  double astar_tu(std::size_t setting) const { return infos_[setting].astar_tu; }

  /// The A* length of a case's arena, drawn or not [TU].
  double astar_tu(const EvalCase& c) const { return info(c).astar_tu; }

 private:
  struct Drawn {  // one drawn arena at each robot count of its family entry
    std::vector<std::pair<int, std::shared_ptr<const sim::Scenario>>> scenarios;
    double astar_tu = 0.0;
    std::int64_t max_ticks = 0;
  };

  using ArenaKey = std::pair<int, std::uint64_t>;  // (family entry, arena seed)

  std::shared_ptr<const Drawn> draw(int family, std::uint64_t seed) const;
  std::shared_ptr<const Drawn> drawn(int family, std::uint64_t seed) const;
  CaseInfo info(const EvalCase& c) const;

  std::vector<EvalSetting> settings_;
  std::vector<std::shared_ptr<const sim::Scenario>> scenarios_;  // one per setting (null for drawn arenas)
  std::vector<CaseInfo> infos_;                                  // one per setting
  std::vector<FamilyEntry> families_;
  std::optional<std::int64_t> max_ticks_;
  sim::Mode mode_;
  FitnessWeights weights_;
  mutable std::mutex mutex_;                                         // guards arenas_
  mutable std::map<ArenaKey, std::shared_ptr<const Drawn>> arenas_;  // this batch's and the validation set's
};

}  // namespace swarmpath::evolve
