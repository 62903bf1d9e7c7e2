// SPDX-License-Identifier: MIT
// make_multi_objective: checks the problem (bounds, x0, objectives) once, then NSGA-II its settings.
#include "evolve/optim/multi_objective.hpp"

#include <stdexcept>
#include <string>

#include "evolve/optim/nsga2.hpp"

namespace swarmpath::evolve {
std::vector<std::string> multi_objective_names() { return {"nsga2"}; }

std::unique_ptr<MultiObjectiveOptimizer> make_multi_objective(const OptimizerSettings& s, const Bounds& b,
                                                              const Vector& x0, std::size_t n_objectives,
                                                              std::uint64_t seed) {
  check_problem(b, x0);
  if (n_objectives < 2) {
    throw std::invalid_argument("multi-objective: needs at least 2 objectives, got " +
                                std::to_string(n_objectives));
  }
  if (s.name == "nsga2") return std::make_unique<Nsga2>(s, b, x0, n_objectives, seed);
  throw std::invalid_argument("unknown multi-objective optimizer '" + s.name + "' (known: nsga2)");
}

}  // namespace swarmpath::evolve
