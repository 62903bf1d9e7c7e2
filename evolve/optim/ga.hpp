// SPDX-License-Identifier: MIT
// A real-coded generational GA in the unit cube: tournament selection, simulated binary
// crossover (SBX, Deb & Agrawal 1995, bounded form of Deb's NSGA-II code), Gaussian mutation,
// elitism, clipping to the bounds.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "evolve/optim/batch.hpp"
#include "evolve/optim/normalise.hpp"
#include "evolve/optim/optimizer.hpp"
#include "sim/rng.hpp"

namespace swarmpath::evolve {

/// The first ask() is the whole population (x0 and uniform points); each later ask() is the
/// population minus the elites, which keep their fitness (the objective is deterministic).
class GeneticAlgorithm final : public Optimizer {
 public:
  static constexpr int kDefaultPopulation = 20;
  static constexpr double kSbxEta = 15.0;  ///< SBX distribution index (larger: children nearer the parents)

  GeneticAlgorithm(const OptimizerSettings& s, const Bounds& b, const Vector& x0, std::uint64_t seed);

  std::string name() const override { return "ga"; }

  std::vector<Vector> ask() override;
  void tell(const std::vector<Vector>& candidates, const std::vector<double>& fitness) override;

  Vector best_x() const override { return best_.x; }

  double best_f() const override { return best_.f; }

  nlohmann::json state() const override;
  void restore(const nlohmann::json& state) override;

 private:
  std::vector<std::size_t> ranked() const;
  std::size_t tournament();
  void crossover(Vector& a, Vector& b);
  void mutate(Vector& genes);

  // fixed by construction
  UnitBox box_;
  std::size_t size_;
  double crossover_rate_;
  double mutation_sigma_;
  double mutation_rate_;
  std::size_t tournament_;
  std::size_t elites_;
  Vector x0_;

  // serialised
  sim::Rng rng_;
  std::vector<Vector> population_;  ///< in [0,1]^n; empty before the first tell
  std::vector<double> fitness_;
  std::vector<Vector> asked_unit_;  ///< the pending offspring in [0,1]^n
  std::vector<Vector> asked_;       ///< the same in the caller's units (x0 exactly as given)
  BestSoFar best_;
};

}  // namespace swarmpath::evolve
