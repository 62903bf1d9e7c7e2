// SPDX-License-Identifier: MIT
#include "evolve/optim/random_search.hpp"

#include <stdexcept>

namespace swarmpath::evolve {

RandomSearch::RandomSearch(const OptimizerSettings& s, const Bounds& b, const Vector& x0, std::uint64_t seed)
    : box_(b), rng_(seed), x0_(x0) {
  if (s.population < 0 || s.population == 1) {
    throw SettingError("population", "random: population must be >= 2 (or 0 for the default " +
                                         std::to_string(kDefaultPopulation) + "), got " +
                                         std::to_string(s.population));
  }
  population_ = static_cast<std::size_t>(s.population > 0 ? s.population : kDefaultPopulation);
}

std::vector<Vector> RandomSearch::ask() {
  if (!asked_.empty()) return asked_;
  std::vector<Vector> batch;
  batch.reserve(population_);
  if (!started_) batch.push_back(x0_);
  started_ = true;
  while (batch.size() < population_) {
    Vector u(box_.dim());
    for (double& ui : u) ui = rng_.uniform();
    batch.push_back(box_.from_unit(u));
  }
  asked_ = batch;
  return batch;
}

void RandomSearch::tell(const std::vector<Vector>& candidates, const std::vector<double>& fitness) {
  best_.update(candidates, checked_fitness(asked_, candidates, fitness));
  asked_.clear();
}

nlohmann::json RandomSearch::state() const {
  auto j = state_header(name(), box_.dim());
  j["rng"] = rng_to_json(rng_);
  j["started"] = started_;
  j["asked"] = vectors_to_json(asked_);
  j["best"] = best_.to_json();
  return j;
}

void RandomSearch::restore(const nlohmann::json& state) {
  // every field is checked before anything changes (StateError names the field)
  const StateReader r(state, "");
  r.header(name(), box_.dim());
  const sim::Rng::State rng = r.rng("rng");
  const bool started = r.boolean("started");
  std::vector<Vector> asked = r.points("asked", StateReader::kAny, box_.bounds());
  if (!asked.empty() && asked.size() != population_) {
    r.fail("asked",
           "expected 0 or " + std::to_string(population_) + " points, got " + std::to_string(asked.size()));
  }
  const BestSoFar best = BestSoFar::from_state(r, box_.bounds());
  rng_.set_state(rng);
  started_ = started;
  asked_ = std::move(asked);
  best_ = best;
}

}  // namespace swarmpath::evolve
