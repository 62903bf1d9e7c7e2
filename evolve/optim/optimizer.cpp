// SPDX-License-Identifier: MIT
// make_optimizer: checks the problem (bounds, x0) once, then each optimiser checks its settings.
#include "evolve/optim/optimizer.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "evolve/optim/cmaes.hpp"
#include "evolve/optim/ga.hpp"
#include "evolve/optim/nlopt_adapter.hpp"
#include "evolve/optim/random_search.hpp"

namespace swarmpath::evolve {
namespace {

std::string joined_names() {
  std::string s;
  for (const auto& n : optimizer_names()) s += (s.empty() ? "" : ", ") + n;
  return s;
}

}  // namespace

void check_problem(const Bounds& b, const Vector& x0) {
  if (b.lower.empty()) throw std::invalid_argument("bounds: dimension is 0");
  if (b.upper.size() != b.lower.size()) {
    throw std::invalid_argument("bounds: " + std::to_string(b.lower.size()) + " lower but " +
                                std::to_string(b.upper.size()) + " upper values");
  }
  for (std::size_t i = 0; i < b.dim(); ++i) {
    if (!std::isfinite(b.lower[i]) || !std::isfinite(b.upper[i]) || !(b.lower[i] < b.upper[i])) {
      throw std::invalid_argument("bounds: need finite lower < upper, coordinate " + std::to_string(i) +
                                  " has [" + std::to_string(b.lower[i]) + ", " + std::to_string(b.upper[i]) +
                                  "]");
    }
  }
  if (x0.size() != b.dim()) {
    throw std::invalid_argument("x0 has dimension " + std::to_string(x0.size()) + ", bounds " +
                                std::to_string(b.dim()));
  }
  for (std::size_t i = 0; i < b.dim(); ++i) {
    if (!(x0[i] >= b.lower[i] && x0[i] <= b.upper[i])) {
      throw std::invalid_argument("x0 outside the bounds at coordinate " + std::to_string(i) + ": " +
                                  std::to_string(x0[i]) + " not in [" + std::to_string(b.lower[i]) + ", " +
                                  std::to_string(b.upper[i]) + "]");
    }
  }
}

std::vector<std::string> optimizer_names() {
  std::vector<std::string> names = {"cmaes", "ga", "random"};
  for (const auto& a : NloptAdapter::algorithms()) names.push_back("nlopt:" + a);
  return names;
}

std::unique_ptr<Optimizer> make_optimizer(const OptimizerSettings& s, const Bounds& b, const Vector& x0,
                                          std::uint64_t seed) {
  check_problem(b, x0);
  if (s.name == "cmaes") return std::make_unique<Cmaes>(s, b, x0, seed);
  if (s.name == "ga") return std::make_unique<GeneticAlgorithm>(s, b, x0, seed);
  if (s.name == "random") return std::make_unique<RandomSearch>(s, b, x0, seed);
  if (s.name.rfind("nlopt:", 0) == 0) return std::make_unique<NloptAdapter>(s, b, x0, seed);
  throw std::invalid_argument("unknown optimizer '" + s.name + "' (known: " + joined_names() + ")");
}

}  // namespace swarmpath::evolve
