// SPDX-License-Identifier: MIT
// The ask/tell optimiser concept (cf. pagmo2's population/algorithm split, ensmallen's
// callbacks): an optimiser proposes a batch of candidates inside box bounds, the caller
// evaluates them (in parallel, deterministically) and tells the fitness back. Minimisation.
// The whole state, random generator included, is serialisable to JSON so that a run can
// resume exactly.
#pragma once

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace swarmpath::evolve {

using Vector = std::vector<double>;

/// Box bounds, lower[i] < upper[i]. Candidates from ask() always lie inside.
struct Bounds {
  Vector lower;
  Vector upper;

  std::size_t dim() const { return lower.size(); }
};

/// Optimiser settings as an evolve config names them ([optimizer] table).
struct OptimizerSettings {
  std::string name = "cmaes";   ///< cmaes | ga | random | nlopt:<algorithm> (esch, crs2, isres, direct,
                                ///< bobyqa, sbplx, neldermead)
  int population = 0;           ///< 0: the optimiser's default (CMA-ES: 4 + floor(3 ln n), GA 20, random 10,
                                ///< NLopt esch/crs2/isres: NLopt's; the other NLopt algorithms ignore it)
  double sigma0 = 0.3;          ///< initial step of CMA-ES and NLopt local searches, fraction of bound width
  int ipop_restarts = 0;        ///< CMA-ES: IPOP restarts allowed (population doubles each time)
  double crossover_rate = 0.9;  ///< GA
  double mutation_sigma = 0.1;  ///< GA: Gaussian mutation, fraction of each bound's width
  double mutation_rate = 0.0;   ///< GA: per-gene probability (0: 1/n)
  int tournament = 3;           ///< GA
  int elites = 1;               ///< GA
  int max_evaluations = 0;      ///< NLopt: maxeval (0: 200 * (n + 1)); the others leave budgets to the caller
  double xtol_rel = 1e-8;       ///< NLopt: relative x tolerance, in the normalised [0,1]^n space
};

/// A bad optimiser setting: key() is its name in OptimizerSettings and in an evolve config's
/// [optimizer] table ("elites"), so that the config's error can point at that key.
class SettingError : public std::invalid_argument {
 public:
  SettingError(std::string key, const std::string& message)
      : std::invalid_argument(message), key_(std::move(key)) {}

  const std::string& key() const { return key_; }

 private:
  std::string key_;
};

/// Minimises f over Bounds by ask/tell.
class Optimizer {
 public:
  virtual ~Optimizer() = default;

  virtual std::string name() const = 0;

  /// The next batch of candidates (at least one), each inside the bounds.
  /// Asking again before tell() returns the same batch (also after restore()).
  /// Throws std::logic_error after done().
  virtual std::vector<Vector> ask() = 0;

  /// The fitness of each candidate of the last ask(), in the same order (lower is better;
  /// NaN counts as +inf). Throws std::invalid_argument when the batch differs from the last ask().
  virtual void tell(const std::vector<Vector>& candidates, const std::vector<double>& fitness) = 0;

  /// True when the optimiser has nothing more to propose (converged, budget of its own spent).
  virtual bool done() const { return false; }

  /// Best candidate told so far and its fitness (+inf before the first tell).
  virtual Vector best_x() const = 0;
  virtual double best_f() const = 0;

  /// The point the optimiser itself would return under noise, which need never have been asked
  /// (CMA-ES: its distribution mean, projected onto the bounds); empty for optimisers without one.
  virtual Vector recommended_x() const { return {}; }

  /// The whole state (random generator included); restore() of it continues bit-identically.
  virtual nlohmann::json state() const = 0;
  virtual void restore(const nlohmann::json& state) = 0;
};

/// Throws std::invalid_argument naming the problem unless the bounds are finite with lower < upper
/// in every coordinate and x0 has their dimension and lies inside them.
void check_problem(const Bounds& b, const Vector& x0);

/// Builds an optimiser; x0 is the start point (inside the bounds), seed its only randomness.
/// Throws std::invalid_argument naming the problem for unknown names or bad settings.
std::unique_ptr<Optimizer> make_optimizer(const OptimizerSettings& s, const Bounds& b, const Vector& x0,
                                          std::uint64_t seed);

/// The names make_optimizer accepts, for error messages and --help.
std::vector<std::string> optimizer_names();

}  // namespace swarmpath::evolve
