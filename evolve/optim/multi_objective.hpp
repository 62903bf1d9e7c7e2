// SPDX-License-Identifier: MIT
// The multi-objective ask/tell concept: like Optimizer, but each candidate is told a vector of
// objectives (all minimised) and a constraint violation (0: feasible); the result is a front of
// non-dominated feasible points rather than one best point. State serialisable to JSON.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/optim/optimizer.hpp"

namespace swarmpath::evolve {

/// One point of a front: the candidate (caller's units) and its objectives.
struct ParetoPoint {
  Vector x;
  Vector objectives;
};

/// Minimises several objectives over Bounds by ask/tell.
class MultiObjectiveOptimizer {
 public:
  virtual ~MultiObjectiveOptimizer() = default;

  virtual std::string name() const = 0;

  virtual std::size_t n_objectives() const = 0;

  /// The next batch of candidates (at least one), each inside the bounds.
  /// Asking again before tell() returns the same batch (also after restore()).
  virtual std::vector<Vector> ask() = 0;

  /// The objectives (each of n_objectives() values, minimised; NaN counts as +inf) and the
  /// constraint violation (>= 0, 0 = feasible; NaN counts as +inf) of each candidate of the last
  /// ask(), in the same order. Throws std::invalid_argument when the batch differs from the last
  /// ask(), sizes disagree or a violation is negative; std::logic_error without a pending ask().
  virtual void tell(const std::vector<Vector>& candidates, const std::vector<Vector>& objectives,
                    const std::vector<double>& constraint_violation) = 0;

  /// True when the optimiser has nothing more to propose.
  virtual bool done() const { return false; }

  /// The current non-dominated feasible set, each candidate once (empty before the first tell or
  /// while nothing told is feasible).
  virtual std::vector<ParetoPoint> front() const = 0;

  /// The current population (what survived the last tell), feasible or not, in its order;
  /// front() is a subset of it.
  virtual std::vector<ParetoPoint> population() const = 0;

  /// The whole state (random generator included); restore() of it continues bit-identically.
  virtual nlohmann::json state() const = 0;
  virtual void restore(const nlohmann::json& state) = 0;
};

/// Builds a multi-objective optimiser ("nsga2"); x0 is a start point (inside the bounds) and seed
/// its only randomness. Throws std::invalid_argument naming the problem for unknown names, bad
/// bounds or x0, fewer than 2 objectives, or bad settings.
std::unique_ptr<MultiObjectiveOptimizer> make_multi_objective(const OptimizerSettings& s, const Bounds& b,
                                                              const Vector& x0, std::size_t n_objectives,
                                                              std::uint64_t seed);

/// The names make_multi_objective accepts.
std::vector<std::string> multi_objective_names();

}  // namespace swarmpath::evolve
