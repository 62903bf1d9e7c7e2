// SPDX-License-Identifier: MIT
// Uniform random search: the baseline every other optimiser must beat.
#pragma once

#include <cstdint>

#include "evolve/optim/batch.hpp"
#include "evolve/optim/normalise.hpp"
#include "evolve/optim/optimizer.hpp"
#include "sim/rng.hpp"

namespace swarmpath::evolve {

/// Batches of `population` points drawn uniformly in the bounds; the first batch starts with x0.
class RandomSearch final : public Optimizer {
 public:
  static constexpr int kDefaultPopulation = 10;

  RandomSearch(const OptimizerSettings& s, const Bounds& b, const Vector& x0, std::uint64_t seed);

  std::string name() const override { return "random"; }

  std::vector<Vector> ask() override;
  void tell(const std::vector<Vector>& candidates, const std::vector<double>& fitness) override;

  Vector best_x() const override { return best_.x; }

  double best_f() const override { return best_.f; }

  nlohmann::json state() const override;
  void restore(const nlohmann::json& state) override;

 private:
  UnitBox box_;
  std::size_t population_;
  sim::Rng rng_;
  Vector x0_;
  bool started_ = false;  ///< false until the first batch (which holds x0) was drawn
  std::vector<Vector> asked_;
  BestSoFar best_;
};

}  // namespace swarmpath::evolve
