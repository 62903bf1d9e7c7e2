// SPDX-License-Identifier: MIT
#include "evolve/optim/ga.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "evolve/optim/variation.hpp"

namespace swarmpath::evolve {

GeneticAlgorithm::GeneticAlgorithm(const OptimizerSettings& s, const Bounds& b, const Vector& x0,
                                   std::uint64_t seed)
    : box_(b), x0_(x0), rng_(seed) {
  if (s.population < 0 || s.population == 1) {
    throw SettingError("population", "ga: population must be >= 2 (or 0 for the default " +
                                         std::to_string(kDefaultPopulation) + "), got " +
                                         std::to_string(s.population));
  }
  size_ = static_cast<std::size_t>(s.population > 0 ? s.population : kDefaultPopulation);
  if (!(s.crossover_rate >= 0.0 && s.crossover_rate <= 1.0)) {
    throw SettingError("crossover_rate",
                       "ga: crossover_rate must be in [0, 1], got " + std::to_string(s.crossover_rate));
  }
  if (!(s.mutation_sigma > 0.0 && std::isfinite(s.mutation_sigma))) {
    throw SettingError("mutation_sigma",
                       "ga: mutation_sigma must be > 0, got " + std::to_string(s.mutation_sigma));
  }
  if (!(s.mutation_rate >= 0.0 && s.mutation_rate <= 1.0)) {
    throw SettingError("mutation_rate", "ga: mutation_rate must be in [0, 1] (0: 1/n), got " +
                                            std::to_string(s.mutation_rate));
  }
  if (s.tournament < 1) {
    throw SettingError("tournament", "ga: tournament must be >= 1, got " + std::to_string(s.tournament));
  }
  if (s.elites < 0 || static_cast<std::size_t>(s.elites) >= size_) {
    throw SettingError("elites", "ga: elites must be in [0, population - 1], got " +
                                     std::to_string(s.elites) + " with population " + std::to_string(size_));
  }
  crossover_rate_ = s.crossover_rate;
  mutation_sigma_ = s.mutation_sigma;
  mutation_rate_ = s.mutation_rate > 0.0 ? s.mutation_rate : 1.0 / static_cast<double>(b.dim());
  tournament_ = static_cast<std::size_t>(s.tournament);
  elites_ = static_cast<std::size_t>(s.elites);
}

std::vector<std::size_t> GeneticAlgorithm::ranked() const {
  std::vector<std::size_t> order(population_.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return fitness_[a] < fitness_[b]; });
  return order;
}

std::size_t GeneticAlgorithm::tournament() {
  // k contestants drawn with replacement; the fittest (then the lowest index) wins
  std::size_t winner = rng_.below(population_.size());
  for (std::size_t k = 1; k < tournament_; ++k) {
    const std::size_t c = rng_.below(population_.size());
    if (fitness_[c] < fitness_[winner] || (fitness_[c] == fitness_[winner] && c < winner)) winner = c;
  }
  return winner;
}

void GeneticAlgorithm::crossover(Vector& a, Vector& b) { sbx_crossover(a, b, kSbxEta, rng_); }

void GeneticAlgorithm::mutate(Vector& genes) {
  for (double& g : genes) {
    if (rng_.bernoulli(mutation_rate_)) g = std::clamp(g + mutation_sigma_ * rng_.normal(), 0.0, 1.0);
  }
}

std::vector<Vector> GeneticAlgorithm::ask() {
  if (!asked_.empty()) return asked_;
  if (population_.empty()) {
    first_generation(box_, x0_, size_, rng_, asked_unit_, asked_);
    return asked_;
  }
  const std::size_t children = size_ - elites_;
  while (asked_unit_.size() < children) {
    Vector a = population_[tournament()];
    Vector b = population_[tournament()];
    if (rng_.bernoulli(crossover_rate_)) crossover(a, b);
    mutate(a);
    mutate(b);
    asked_unit_.push_back(std::move(a));
    if (asked_unit_.size() < children) asked_unit_.push_back(std::move(b));
  }
  for (const auto& u : asked_unit_) asked_.push_back(box_.from_unit(u));
  return asked_;
}

void GeneticAlgorithm::tell(const std::vector<Vector>& candidates, const std::vector<double>& fitness) {
  const std::vector<double> f = checked_fitness(asked_, candidates, fitness);
  best_.update(candidates, f);
  // generational replacement: the elites survive, the children fill the rest
  std::vector<Vector> next;
  std::vector<double> next_f;
  if (!population_.empty()) {
    const auto order = ranked();
    for (std::size_t e = 0; e < elites_; ++e) {
      next.push_back(population_[order[e]]);
      next_f.push_back(fitness_[order[e]]);
    }
  }
  for (std::size_t i = 0; i < f.size(); ++i) {
    next.push_back(std::move(asked_unit_[i]));
    next_f.push_back(f[i]);
  }
  population_ = std::move(next);
  fitness_ = std::move(next_f);
  asked_.clear();
  asked_unit_.clear();
}

nlohmann::json GeneticAlgorithm::state() const {
  auto j = state_header(name(), box_.dim());
  j["rng"] = rng_to_json(rng_);
  j["population"] = vectors_to_json(population_);
  j["fitness"] = vector_to_json(fitness_);
  j["asked_unit"] = vectors_to_json(asked_unit_);
  j["asked"] = vectors_to_json(asked_);
  j["best"] = best_.to_json();
  return j;
}

void GeneticAlgorithm::restore(const nlohmann::json& state) {
  // every field is checked before anything changes (StateError names the field)
  const StateReader r(state, "");
  const std::size_t n = box_.dim();
  r.header(name(), n);
  const sim::Rng::State rng = r.rng("rng");
  const Bounds unit{Vector(n, 0.0), Vector(n, 1.0)};
  // before the first tell no population, after it always `size_` members
  const bool started = r.at("population").is_array() && !r.at("population").empty();
  std::vector<Vector> population = r.points("population", started ? size_ : 0, unit);
  Vector fitness = r.numbers("fitness", population.size(), -StateReader::kInf, StateReader::kInf, true);
  std::vector<Vector> asked_unit = r.points("asked_unit", StateReader::kAny, unit);
  const std::size_t batch = started ? size_ - elites_ : size_;
  if (!asked_unit.empty() && asked_unit.size() != batch) {
    r.fail("asked_unit",
           "expected 0 or " + std::to_string(batch) + " points, got " + std::to_string(asked_unit.size()));
  }
  std::vector<Vector> asked = r.points("asked", asked_unit.size(), box_.bounds());
  const BestSoFar best = BestSoFar::from_state(r, box_.bounds());
  rng_.set_state(rng);
  population_ = std::move(population);
  fitness_ = std::move(fitness);
  asked_unit_ = std::move(asked_unit);
  asked_ = std::move(asked);
  best_ = best;
}

}  // namespace swarmpath::evolve
