// SPDX-License-Identifier: MIT
// NLopt (callback-driven) as an ask/tell optimiser by replay. The state is the seed plus the
// history of (x, f) told so far. To find the next candidate, NLopt runs again from scratch
// (nlopt::srand(seed) right before optimize): the objective callback answers its first k calls
// from the history, checking that NLopt asks for exactly the recorded x (else std::logic_error:
// the run is not deterministic), and stops NLopt at call k + 1, whose x is the next candidate.
// One candidate per ask(); a replay costs k callback calls, so a run of N evaluations costs
// O(N^2) NLopt steps: negligible next to simulations for budgets of a few thousand.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "evolve/optim/batch.hpp"
#include "evolve/optim/normalise.hpp"
#include "evolve/optim/optimizer.hpp"

namespace swarmpath::evolve {

/// nlopt:<algorithm>, the search in [0,1]^n. done() once NLopt returns by itself (xtol_rel,
/// maxeval, roundoff) or fails.
class NloptAdapter final : public Optimizer {
 public:
  /// The algorithms after "nlopt:", e.g. "bobyqa".
  static std::vector<std::string> algorithms();

  NloptAdapter(const OptimizerSettings& s, const Bounds& b, const Vector& x0, std::uint64_t seed);

  std::string name() const override { return "nlopt:" + algorithm_; }

  std::vector<Vector> ask() override;
  void tell(const std::vector<Vector>& candidates, const std::vector<double>& fitness) override;

  bool done() const override { return done_; }

  Vector best_x() const override { return best_.x; }

  double best_f() const override { return best_.f; }

  nlohmann::json state() const override;
  void restore(const nlohmann::json& state) override;

  /// How NLopt ended ("" while it runs): success, xtol_reached, maxeval_reached, roundoff_limited, failure.
  const std::string& result() const { return result_; }

  /// One told evaluation, x in [0,1]^n.
  struct Told {
    Vector x;
    double f;
  };

 private:
  void replay();

  // fixed by construction
  UnitBox box_;
  std::string algorithm_;
  unsigned population_;
  unsigned max_evaluations_;
  double xtol_rel_;
  double initial_step_;
  Vector x0_unit_;
  std::uint64_t seed_;

  // serialised: the history (plus the best, for convenience)
  std::vector<Told> history_;
  BestSoFar best_;

  // derived by replay()
  Vector next_unit_;    ///< the next candidate in [0,1]^n
  bool asked_ = false;  ///< next_unit_ was handed out by ask() (serialised)
  bool done_ = false;
  std::string result_;
};

}  // namespace swarmpath::evolve
