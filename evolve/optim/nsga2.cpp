// SPDX-License-Identifier: MIT
// NSGA-II after Deb, Pratap, Agarwal & Meyarivan, "A fast and elitist multiobjective genetic
// algorithm: NSGA-II", IEEE TEC 6(2), 2002, with the variation operators of Deb's reference code.
#include "evolve/optim/nsga2.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "evolve/optim/hypervolume.hpp"
#include "evolve/optim/state_json.hpp"
#include "evolve/optim/state_reader.hpp"
#include "evolve/optim/variation.hpp"

namespace swarmpath::evolve {

bool constrained_dominates(const Vector& fa, double violation_a, const Vector& fb, double violation_b) {
  const bool feasible_a = violation_a <= 0.0;
  const bool feasible_b = violation_b <= 0.0;
  if (feasible_a && feasible_b) return dominates(fa, fb);
  if (feasible_a != feasible_b) return feasible_a;
  return violation_a < violation_b;
}

std::vector<std::vector<std::size_t>> non_dominated_fronts(const std::vector<Vector>& objectives,
                                                           const std::vector<double>& violation) {
  if (objectives.size() != violation.size()) {
    throw std::invalid_argument("non_dominated_fronts: " + std::to_string(objectives.size()) +
                                " objective vectors but " + std::to_string(violation.size()) + " violations");
  }
  // Deb et al. 2002, III-A: S_p (whom p dominates) and n_p (how many dominate p); front 1 is n_p = 0,
  // each next front the points whose n_p drops to 0 when the previous front is removed
  const std::size_t n = objectives.size();
  std::vector<std::vector<std::size_t>> dominated_by(n);
  std::vector<std::size_t> count(n, 0);
  for (std::size_t p = 0; p < n; ++p) {
    for (std::size_t q = p + 1; q < n; ++q) {
      if (constrained_dominates(objectives[p], violation[p], objectives[q], violation[q])) {
        dominated_by[p].push_back(q);
        ++count[q];
      } else if (constrained_dominates(objectives[q], violation[q], objectives[p], violation[p])) {
        dominated_by[q].push_back(p);
        ++count[p];
      }
    }
  }
  std::vector<std::vector<std::size_t>> fronts;
  std::vector<std::size_t> current;
  for (std::size_t p = 0; p < n; ++p) {
    if (count[p] == 0) current.push_back(p);
  }
  while (!current.empty()) {
    std::vector<std::size_t> next;
    for (const std::size_t p : current) {
      for (const std::size_t q : dominated_by[p]) {
        if (--count[q] == 0) next.push_back(q);
      }
    }
    std::sort(next.begin(), next.end());
    fronts.push_back(std::move(current));
    current = std::move(next);
  }
  return fronts;
}

std::vector<double> crowding_distances(const std::vector<Vector>& objectives,
                                       const std::vector<std::size_t>& front) {
  const std::size_t n = front.size();
  std::vector<double> distance(n, 0.0);
  if (n == 0) return distance;
  const double inf = std::numeric_limits<double>::infinity();
  const std::size_t m = objectives[front[0]].size();
  std::vector<std::size_t> order(n);
  for (std::size_t k = 0; k < m; ++k) {
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      const double fa = objectives[front[a]][k];
      const double fb = objectives[front[b]][k];
      return fa < fb || (fa == fb && a < b);
    });
    distance[order.front()] = inf;
    distance[order.back()] = inf;
    const double range = objectives[front[order.back()]][k] - objectives[front[order.front()]][k];
    if (!(range > 0.0 && std::isfinite(range))) continue;
    for (std::size_t i = 1; i + 1 < n; ++i) {
      distance[order[i]] += (objectives[front[order[i + 1]]][k] - objectives[front[order[i - 1]]][k]) / range;
    }
  }
  return distance;
}

Nsga2::Nsga2(const OptimizerSettings& s, const Bounds& b, const Vector& x0, std::size_t n_objectives,
             std::uint64_t seed)
    : box_(b), n_objectives_(n_objectives), x0_(x0), rng_(seed) {
  if (n_objectives < 2) {
    throw std::invalid_argument("nsga2: needs at least 2 objectives, got " + std::to_string(n_objectives));
  }
  if (s.population < 0 || (s.population > 0 && (s.population < 4 || s.population % 2 != 0))) {
    throw SettingError("population", "nsga2: population must be even and >= 4 (or 0 for the default " +
                                         std::to_string(kDefaultPopulation) + "), got " +
                                         std::to_string(s.population));
  }
  size_ = static_cast<std::size_t>(s.population > 0 ? s.population : kDefaultPopulation);
  if (!(s.crossover_rate >= 0.0 && s.crossover_rate <= 1.0)) {
    throw SettingError("crossover_rate",
                       "nsga2: crossover_rate must be in [0, 1], got " + std::to_string(s.crossover_rate));
  }
  if (!(s.mutation_rate >= 0.0 && s.mutation_rate <= 1.0)) {
    throw SettingError("mutation_rate", "nsga2: mutation_rate must be in [0, 1] (0: 1/n), got " +
                                            std::to_string(s.mutation_rate));
  }
  crossover_rate_ = s.crossover_rate;
  mutation_rate_ = s.mutation_rate > 0.0 ? s.mutation_rate : 1.0 / static_cast<double>(b.dim());
}

void Nsga2::assess() {
  rank_.assign(population_.size(), 0);
  crowding_.assign(population_.size(), 0.0);
  const auto fronts = non_dominated_fronts(objectives_, violation_);
  for (std::size_t r = 0; r < fronts.size(); ++r) {
    const auto d = crowding_distances(objectives_, fronts[r]);
    for (std::size_t i = 0; i < fronts[r].size(); ++i) {
      rank_[fronts[r][i]] = r;
      crowding_[fronts[r][i]] = d[i];
    }
  }
}

std::size_t Nsga2::tournament() {
  // binary tournament by the crowded-comparison operator (Deb et al. 2002, III-B): lower rank,
  // then larger crowding distance; a tie is decided by a coin
  const std::size_t a = rng_.below(population_.size());
  const std::size_t b = rng_.below(population_.size());
  if (rank_[a] != rank_[b]) return rank_[a] < rank_[b] ? a : b;
  if (crowding_[a] != crowding_[b]) return crowding_[a] > crowding_[b] ? a : b;
  return rng_.bernoulli(0.5) ? a : b;
}

std::vector<Vector> Nsga2::ask() {
  if (!asked_.empty()) return asked_;
  if (population_.empty()) {
    first_generation(box_, x0_, size_, rng_, asked_unit_, asked_);
    return asked_;
  }
  while (asked_unit_.size() < size_) {  // size_ is even
    Vector a = population_[tournament()];
    Vector b = population_[tournament()];
    if (rng_.bernoulli(crossover_rate_)) sbx_crossover(a, b, kSbxEta, rng_);
    polynomial_mutation(a, mutation_rate_, kMutationEta, rng_);
    polynomial_mutation(b, mutation_rate_, kMutationEta, rng_);
    asked_unit_.push_back(std::move(a));
    asked_unit_.push_back(std::move(b));
  }
  for (const auto& u : asked_unit_) asked_.push_back(box_.from_unit(u));
  return asked_;
}

void Nsga2::tell(const std::vector<Vector>& candidates, const std::vector<Vector>& objectives,
                 const std::vector<double>& constraint_violation) {
  if (asked_.empty()) throw std::logic_error("nsga2: tell() without a pending ask()");
  if (candidates.size() != asked_.size() || objectives.size() != asked_.size() ||
      constraint_violation.size() != asked_.size()) {
    throw std::invalid_argument("nsga2: tell() expected " + std::to_string(asked_.size()) +
                                " candidates, objective vectors and violations, got " +
                                std::to_string(candidates.size()) + ", " + std::to_string(objectives.size()) +
                                " and " + std::to_string(constraint_violation.size()));
  }
  if (candidates != asked_)
    throw std::invalid_argument("nsga2: tell(): the candidates differ from the last ask()");
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<Vector> f = objectives;
  std::vector<double> cv = constraint_violation;
  for (std::size_t i = 0; i < f.size(); ++i) {
    if (f[i].size() != n_objectives_) {
      throw std::invalid_argument("nsga2: tell(): candidate " + std::to_string(i) + " has " +
                                  std::to_string(f[i].size()) + " objectives, expected " +
                                  std::to_string(n_objectives_));
    }
    for (double& v : f[i]) {
      if (std::isnan(v)) v = inf;
    }
    if (std::isnan(cv[i])) cv[i] = inf;
    if (cv[i] < 0.0) {
      throw std::invalid_argument("nsga2: tell(): candidate " + std::to_string(i) +
                                  " has a negative constraint violation " + std::to_string(cv[i]));
    }
  }
  // (mu + lambda) survival (Deb et al. 2002, III-C): parents and offspring together, whole fronts
  // while they fit, then the least crowded of the front that does not
  std::vector<Vector> pool = std::move(population_);
  std::vector<Vector> pool_x = std::move(population_x_);
  std::vector<Vector> pool_f = std::move(objectives_);
  std::vector<double> pool_cv = std::move(violation_);
  for (std::size_t i = 0; i < asked_.size(); ++i) {
    pool.push_back(std::move(asked_unit_[i]));
    pool_x.push_back(std::move(asked_[i]));
    pool_f.push_back(std::move(f[i]));
    pool_cv.push_back(cv[i]);
  }
  std::vector<std::size_t> chosen;
  for (const auto& front : non_dominated_fronts(pool_f, pool_cv)) {
    if (chosen.size() + front.size() <= size_) {
      chosen.insert(chosen.end(), front.begin(), front.end());
      if (chosen.size() == size_) break;
      continue;
    }
    const auto d = crowding_distances(pool_f, front);
    std::vector<std::size_t> order(front.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return d[a] > d[b]; });
    for (std::size_t i = 0; chosen.size() < size_; ++i) chosen.push_back(front[order[i]]);
    break;
  }
  population_.clear();
  population_x_.clear();
  objectives_.clear();
  violation_.clear();
  for (const std::size_t i : chosen) {
    population_.push_back(std::move(pool[i]));
    population_x_.push_back(std::move(pool_x[i]));
    objectives_.push_back(std::move(pool_f[i]));
    violation_.push_back(pool_cv[i]);
  }
  asked_.clear();
  asked_unit_.clear();
  assess();
}

std::vector<ParetoPoint> Nsga2::front() const {
  std::vector<ParetoPoint> points;
  for (std::size_t i = 0; i < population_.size(); ++i) {
    if (rank_[i] != 0 || violation_[i] > 0.0) continue;
    // a child can equal its parent: each candidate once
    const bool seen = std::any_of(points.begin(), points.end(),
                                  [&](const ParetoPoint& p) { return p.x == population_x_[i]; });
    if (!seen) points.push_back({population_x_[i], objectives_[i]});
  }
  return points;
}

std::vector<ParetoPoint> Nsga2::population() const {
  std::vector<ParetoPoint> points;
  points.reserve(population_.size());
  for (std::size_t i = 0; i < population_.size(); ++i) points.push_back({population_x_[i], objectives_[i]});
  return points;
}

nlohmann::json Nsga2::state() const {
  auto j = state_header(name(), box_.dim());
  j["n_objectives"] = n_objectives_;
  j["rng"] = rng_to_json(rng_);
  j["population"] = vectors_to_json(population_);
  j["population_x"] = vectors_to_json(population_x_);
  j["objectives"] = vectors_to_json(objectives_);
  j["violation"] = vector_to_json(violation_);
  j["asked_unit"] = vectors_to_json(asked_unit_);
  j["asked"] = vectors_to_json(asked_);
  return j;
}

void Nsga2::restore(const nlohmann::json& state) {
  // every field is checked before anything changes (StateError names the field)
  const StateReader r(state, "");
  const std::size_t dim = box_.dim();
  r.header(name(), dim);
  const auto m = static_cast<std::size_t>(r.integer("n_objectives", 1, 64));
  if (m != n_objectives_) {
    r.fail("n_objectives",
           "the state has " + std::to_string(m) + " objectives, the run " + std::to_string(n_objectives_));
  }
  const sim::Rng::State rng = r.rng("rng");
  const Bounds unit{Vector(dim, 0.0), Vector(dim, 1.0)};
  // before the first tell no population, after it always `size_` members
  const bool started = r.at("population").is_array() && !r.at("population").empty();
  const std::size_t n = started ? size_ : 0;
  auto population = r.points("population", n, unit);
  auto population_x = r.points("population_x", n, box_.bounds());
  auto objectives = r.vectors("objectives", n, m, -StateReader::kInf, StateReader::kInf, true);
  auto violation = r.numbers("violation", n, 0.0, StateReader::kInf, true);
  auto asked_unit = r.points("asked_unit", StateReader::kAny, unit);
  if (!asked_unit.empty() && asked_unit.size() != size_) {
    r.fail("asked_unit",
           "expected 0 or " + std::to_string(size_) + " points, got " + std::to_string(asked_unit.size()));
  }
  auto asked = r.points("asked", asked_unit.size(), box_.bounds());
  rng_.set_state(rng);
  population_ = std::move(population);
  population_x_ = std::move(population_x);
  objectives_ = std::move(objectives);
  violation_ = std::move(violation);
  asked_unit_ = std::move(asked_unit);
  asked_ = std::move(asked);
  assess();
}

}  // namespace swarmpath::evolve
