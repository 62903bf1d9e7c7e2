// SPDX-License-Identifier: MIT
// Bookkeeping every ask/tell optimiser shares: checking that tell() answers the last ask(),
// NaN fitness as +inf, and the best point told so far.
#pragma once

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evolve/optim/optimizer.hpp"
#include "evolve/optim/state_json.hpp"
#include "evolve/optim/state_reader.hpp"

namespace swarmpath::evolve {

/// Checks that (candidates, fitness) answer `asked` exactly; returns the fitness with NaN as +inf.
inline std::vector<double> checked_fitness(const std::vector<Vector>& asked,
                                           const std::vector<Vector>& candidates,
                                           const std::vector<double>& fitness) {
  if (asked.empty()) throw std::logic_error("tell() without a pending ask()");
  if (candidates.size() != asked.size() || fitness.size() != asked.size()) {
    throw std::invalid_argument("tell(): expected " + std::to_string(asked.size()) +
                                " candidates and fitness values, got " + std::to_string(candidates.size()) +
                                " and " + std::to_string(fitness.size()));
  }
  if (candidates != asked) throw std::invalid_argument("tell(): the candidates differ from the last ask()");
  std::vector<double> f = fitness;
  for (double& v : f) {
    if (std::isnan(v)) v = std::numeric_limits<double>::infinity();
  }
  return f;
}

/// The best candidate told so far (the first of equals wins).
struct BestSoFar {
  Vector x;
  double f = std::numeric_limits<double>::infinity();

  void update(const std::vector<Vector>& candidates, const std::vector<double>& fitness) {
    for (std::size_t i = 0; i < candidates.size(); ++i) {
      if (fitness[i] < f || x.empty()) {
        f = fitness[i];
        x = candidates[i];
      }
    }
  }

  nlohmann::json to_json() const { return {{"x", vector_to_json(x)}, {"f", number_to_json(f)}}; }

  /// Read strictly: x empty (nothing told yet, f = inf) or a point inside `b`.
  static BestSoFar from_state(const StateReader& r, const Bounds& b) {
    const StateReader best = r.object("best");
    const double f = best.extended("f", -StateReader::kInf, StateReader::kInf);
    if (best.at("x").is_array() && best.at("x").empty()) {
      if (f != StateReader::kInf) best.fail("f", "no point told yet, so the best value must be inf");
      return {{}, f};
    }
    return {best.point("x", b), f};
  }
};

}  // namespace swarmpath::evolve
