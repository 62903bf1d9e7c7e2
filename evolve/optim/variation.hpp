// SPDX-License-Identifier: MIT
// Real-coded variation operators in the unit cube shared by the GA and NSGA-II: bounded SBX
// crossover and polynomial mutation (Deb & Agrawal 1995; Deb's NSGA-II code realcross/realmutate).
#pragma once

#include <algorithm>
#include <cmath>

#include "evolve/optim/normalise.hpp"
#include "evolve/optim/optimizer.hpp"
#include "sim/rng.hpp"

namespace swarmpath::evolve {

/// One side of bounded SBX: the spread factor beta_q for a child on the side with `room` to its bound.
inline double sbx_beta_q(double u, double room_over_gap, double eta) {
  const double beta = 1.0 + 2.0 * room_over_gap;
  const double alpha = 2.0 - std::pow(beta, -(eta + 1.0));
  return u <= 1.0 / alpha ? std::pow(u * alpha, 1.0 / (eta + 1.0))
                          : std::pow(1.0 / (2.0 - u * alpha), 1.0 / (eta + 1.0));
}

/// Bounded SBX on [0,1]^n (Deb & Agrawal 1995; Deb's NSGA-II realcross): each gene with probability
/// 1/2, distribution index eta (larger: children nearer the parents); children clamped to [0,1].
inline void sbx_crossover(Vector& a, Vector& b, double eta, sim::Rng& rng) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!rng.bernoulli(0.5)) continue;
    const double lo = std::min(a[i], b[i]);
    const double hi = std::max(a[i], b[i]);
    const double gap = hi - lo;
    if (gap < 1e-14) continue;
    const double u = rng.uniform();
    const double c1 = 0.5 * ((lo + hi) - sbx_beta_q(u, lo / gap, eta) * gap);
    const double c2 = 0.5 * ((lo + hi) + sbx_beta_q(u, (1.0 - hi) / gap, eta) * gap);
    const bool swap = rng.bernoulli(0.5);
    a[i] = std::clamp(swap ? c2 : c1, 0.0, 1.0);
    b[i] = std::clamp(swap ? c1 : c2, 0.0, 1.0);
  }
}

/// Bounded polynomial mutation on [0,1]^n (Deb & Goyal 1996; Deb's NSGA-II realmutate): each gene
/// with probability `rate`, distribution index eta; the perturbation never leaves [0,1].
inline void polynomial_mutation(Vector& genes, double rate, double eta, sim::Rng& rng) {
  const double power = 1.0 / (eta + 1.0);
  for (double& y : genes) {
    if (!rng.bernoulli(rate)) continue;
    const double u = rng.uniform();
    double deltaq = 0.0;
    if (u <= 0.5) {
      const double xy = 1.0 - y;  // 1 - delta1, delta1 = distance to the lower bound
      const double val = 2.0 * u + (1.0 - 2.0 * u) * std::pow(xy, eta + 1.0);
      deltaq = std::pow(val, power) - 1.0;
    } else {
      const double xy = y;  // 1 - delta2, delta2 = distance to the upper bound
      const double val = 2.0 * (1.0 - u) + 2.0 * (u - 0.5) * std::pow(xy, eta + 1.0);
      deltaq = 1.0 - std::pow(val, power);
    }
    y = std::clamp(y + deltaq, 0.0, 1.0);
  }
}

/// A first generation: x0 (exactly as given) and uniform points, up to `size` candidates, in the
/// unit box (`unit`) and in the caller's units (`caller`).
inline void first_generation(const UnitBox& box, const Vector& x0, std::size_t size, sim::Rng& rng,
                             std::vector<Vector>& unit, std::vector<Vector>& caller) {
  caller.push_back(x0);
  unit.push_back(box.to_unit(x0));
  while (unit.size() < size) {
    Vector u(box.dim());
    for (double& ui : u) ui = rng.uniform();
    unit.push_back(u);
    caller.push_back(box.from_unit(u));
  }
}

}  // namespace swarmpath::evolve
