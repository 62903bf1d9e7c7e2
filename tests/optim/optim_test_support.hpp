// SPDX-License-Identifier: MIT
// Test problems (ensmallen's problems/ habit) and drivers for ask/tell loops.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "evolve/optim/optimizer.hpp"

namespace swarmpath::evolve::test {

using Objective = std::function<double(const Vector&)>;

constexpr std::size_t kDim = 10;

inline double sphere(const Vector& x) {
  double s = 0.0;
  for (const double v : x) s += v * v;
  return s;
}

/// Rosenbrock: minimum 0 at (1, ..., 1); a local minimum near (-1, 1, ..., 1) (f ~ 3.99) for n >= 4.
inline double rosenbrock(const Vector& x) {
  double s = 0.0;
  for (std::size_t i = 0; i + 1 < x.size(); ++i) {
    const double a = x[i + 1] - x[i] * x[i];
    const double b = 1.0 - x[i];
    s += 100.0 * a * a + b * b;
  }
  return s;
}

/// The test box [-3, 7]^10: neither optimum (0 or 1) is its centre, which DIRECT samples first.
inline Bounds test_box() { return {Vector(kDim, -3.0), Vector(kDim, 7.0)}; }

/// The far start (5, ..., 5): sphere 250, Rosenbrock 360144.
inline Vector far_start() { return Vector(kDim, 5.0); }

/// The classic Rosenbrock start (-1.2, 1, -1.2, 1, ...) (More, Garbow & Hillstrom 1981): f = 2057.
inline Vector classic_start() {
  Vector x(kDim);
  for (std::size_t i = 0; i < kDim; ++i) x[i] = i % 2 == 0 ? -1.2 : 1.0;
  return x;
}

inline OptimizerSettings settings_named(const std::string& name) {
  OptimizerSettings s;
  s.name = name;
  return s;
}

/// The outcome of an ask/tell loop.
struct RunResult {
  double best_f = std::numeric_limits<double>::infinity();
  long evaluations = 0;  ///< evaluations spent until the target was reached (or in all)
  bool reached = false;  ///< best_f <= target within the budget
};

/// Runs `opt` on f until an evaluation <= target, `budget` evaluations, or done().
inline RunResult run(Optimizer& opt, const Objective& f, long budget,
                     double target = -std::numeric_limits<double>::infinity()) {
  RunResult r;
  while (!opt.done() && r.evaluations < budget && !r.reached) {
    const auto batch = opt.ask();
    std::vector<double> fit;
    fit.reserve(batch.size());
    for (const auto& x : batch) {
      fit.push_back(f(x));
      if (!r.reached) ++r.evaluations;
      if (fit.back() <= target) r.reached = true;
    }
    opt.tell(batch, fit);
    r.best_f = opt.best_f();
  }
  return r;
}

/// Every candidate of `rounds` ask/tell rounds (fewer if the optimiser is done), in order.
inline std::vector<Vector> candidates_of(Optimizer& opt, const Objective& f, int rounds) {
  std::vector<Vector> all;
  for (int i = 0; i < rounds && !opt.done(); ++i) {
    const auto batch = opt.ask();
    std::vector<double> fit;
    for (const auto& x : batch) fit.push_back(f(x));
    opt.tell(batch, fit);
    all.insert(all.end(), batch.begin(), batch.end());
  }
  return all;
}

inline bool is_nlopt(const std::string& name) { return name.rfind("nlopt:", 0) == 0; }

/// Rounds for about `evaluations` evaluations: NLopt asks one candidate a round, the others about ten.
inline int rounds_for(const std::string& name, int evaluations) {
  return is_nlopt(name) ? evaluations : evaluations / 10;
}

/// Bit-for-bit equality (== would equate 0.0 and -0.0).
inline bool bit_identical(const std::vector<Vector>& a, const std::vector<Vector>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i].size() != b[i].size()) return false;
    if (!a[i].empty() && std::memcmp(a[i].data(), b[i].data(), a[i].size() * sizeof(double)) != 0)
      return false;
  }
  return true;
}

/// gtest parameter names may not contain ':'.
inline std::string param_name(std::string name) {
  for (char& c : name) {
    if (c == ':') c = '_';
  }
  return name;
}

/// NLopt's local algorithms and DIRECT use no random numbers: their runs do not depend on the seed.
inline bool uses_randomness(const std::string& name) {
  return name != "nlopt:direct" && name != "nlopt:bobyqa" && name != "nlopt:sbplx" &&
         name != "nlopt:neldermead";
}

}  // namespace swarmpath::evolve::test
