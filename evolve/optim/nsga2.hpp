// SPDX-License-Identifier: MIT
// NSGA-II (Deb, Pratap, Agarwal & Meyarivan 2002) in the unit cube: fast non-dominated sorting,
// crowding distance, binary tournaments by (rank, crowding), constrained domination, SBX and
// polynomial mutation, (mu + lambda) elitist survival.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "evolve/optim/multi_objective.hpp"
#include "evolve/optim/normalise.hpp"
#include "sim/rng.hpp"

namespace swarmpath::evolve {

/// Constrained domination (Deb et al. 2002, section VI): a feasible point beats an infeasible one,
/// of two infeasible points the smaller violation wins, of two feasible points Pareto domination
/// decides.
bool constrained_dominates(const Vector& fa, double violation_a, const Vector& fb, double violation_b);

/// Fast non-dominated sorting (Deb et al. 2002, section III-A) under constrained domination:
/// the fronts in order, each a list of indices in ascending order.
std::vector<std::vector<std::size_t>> non_dominated_fronts(const std::vector<Vector>& objectives,
                                                           const std::vector<double>& violation);

/// Crowding distance (Deb et al. 2002, section III-B) of each member of `front` (same order):
/// per objective, the boundary points get +inf and the others the normalised gap between their
/// neighbours, summed over the objectives. Objectives with zero or non-finite range add nothing
/// to the inner points.
std::vector<double> crowding_distances(const std::vector<Vector>& objectives,
                                       const std::vector<std::size_t>& front);

/// The first ask() is the whole population (x0 and uniform points); each later ask() is as many
/// offspring, and survival keeps the best of parents and offspring together.
class Nsga2 final : public MultiObjectiveOptimizer {
 public:
  static constexpr int kDefaultPopulation = 40;
  static constexpr double kSbxEta = 20.0;       ///< SBX distribution index (Deb et al. 2002 use 20)
  static constexpr double kMutationEta = 20.0;  ///< polynomial mutation index (Deb et al. 2002 use 20)

  Nsga2(const OptimizerSettings& s, const Bounds& b, const Vector& x0, std::size_t n_objectives,
        std::uint64_t seed);

  std::string name() const override { return "nsga2"; }

  std::size_t n_objectives() const override { return n_objectives_; }

  std::vector<Vector> ask() override;
  void tell(const std::vector<Vector>& candidates, const std::vector<Vector>& objectives,
            const std::vector<double>& constraint_violation) override;
  std::vector<ParetoPoint> front() const override;
  std::vector<ParetoPoint> population() const override;

  nlohmann::json state() const override;
  void restore(const nlohmann::json& state) override;

 private:
  void assess();
  std::size_t tournament();

  // fixed by construction
  UnitBox box_;
  std::size_t n_objectives_;
  std::size_t size_;
  double crossover_rate_;
  double mutation_rate_;
  Vector x0_;

  // serialised
  sim::Rng rng_;
  std::vector<Vector> population_;    ///< in [0,1]^n; empty before the first tell
  std::vector<Vector> population_x_;  ///< the same in the caller's units, exactly as told
  std::vector<Vector> objectives_;
  std::vector<double> violation_;
  std::vector<Vector> asked_unit_;  ///< the pending offspring in [0,1]^n
  std::vector<Vector> asked_;       ///< the same in the caller's units (x0 exactly as given)

  // derived from the population by assess()
  std::vector<std::size_t> rank_;
  std::vector<double> crowding_;
};

}  // namespace swarmpath::evolve
