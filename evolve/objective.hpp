// SPDX-License-Identifier: MIT
// What a candidate is evaluated on: settings (scenario x robot count), cases (setting x seed),
// and the objective that scores one candidate on one case: which simulation the case is, and the
// score of its Metrics. The runner hands the simulations to a BatchEvaluator (threads or MPI
// ranks) and scores what comes back. SwarmObjective is the simulator with the fitness of
// fitness.hpp; tests put fakes in its place.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "evolve/evolve_config.hpp"
#include "evolve/fitness.hpp"
#include "sim/controller.hpp"
#include "sim/metrics.hpp"
#include "sim/params.hpp"
#include "sim/scenario.hpp"

namespace swarmpath::evolve {

/// One scenario at one robot count.
struct EvalSetting {
  std::string scenario;   ///< the scenario's name
  int robots = 0;         ///< N
  bool held_out = false;  ///< a held-out scenario (re-evaluation only)
};

/// One simulation of a candidate: a setting and a seed.
struct EvalCase {
  std::size_t setting = 0;  ///< index into the objective's settings()
  int replicate = 0;        ///< k-th seed of this setting
  std::uint64_t seed = 0;
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

  /// simulation(c), run here, then score(): one case in this thread.
  RunScore evaluate(const sim::Params& p, const EvalCase& c) const;
};

/// The cases of one generation: every training setting x `seeds` seeds, setting-major; case i
/// has seed generation_seed(master, generation, i, fixed_seeds).
std::vector<EvalCase> generation_cases(const std::vector<EvalSetting>& settings, int seeds,
                                       std::uint64_t master, std::int64_t generation, bool fixed_seeds);

/// The re-evaluation cases: every setting (held-out ones too) x `seeds` fresh seeds; case i
/// has seed reevaluation_seed(master, i).
std::vector<EvalCase> reevaluation_cases(const std::vector<EvalSetting>& settings, int seeds,
                                         std::uint64_t master);

/// The simulator as the objective: scenarios loaded once (robot counts and max_ticks applied),
/// A* computed once per scenario, sim::evaluate per case, scored by score_run.
class SwarmObjective final : public CaseObjective {
 public:
  explicit SwarmObjective(const EvolveConfig& c);

  const std::vector<EvalSetting>& settings() const override { return settings_; }

  CaseSimulation simulation(const EvalCase& c) const override;
  RunScore score(const sim::Params& p, const EvalCase& c, const sim::Metrics& m) const override;
  RunScore penalty(const EvalCase& c) const override;

  const sim::Scenario& scenario(std::size_t setting) const { return *scenarios_[setting]; }

  /// The A* (8-connected) length of a setting's scenario [TU].
  double astar_tu(std::size_t setting) const { return infos_[setting].astar_tu; }

 private:
  std::vector<EvalSetting> settings_;
  std::vector<std::shared_ptr<const sim::Scenario>> scenarios_;  // one per setting
  std::vector<CaseInfo> infos_;                                  // one per setting
  sim::Mode mode_;
  FitnessWeights weights_;
};

}  // namespace swarmpath::evolve
