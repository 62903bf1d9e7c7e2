// SPDX-License-Identifier: MIT
// The optimisers work in the unit cube [0,1]^n: one scale for every parameter, so that step
// sizes and tolerances mean "a fraction of the bound's width" (Hansen's 2016 tutorial advises
// scaling the variables so that one sigma suits all). Only the edges of an optimiser see the
// caller's units.
#pragma once

#include <algorithm>
#include <cstddef>

#include "evolve/optim/optimizer.hpp"

namespace swarmpath::evolve {

/// Maps Bounds to [0,1]^n and back.
class UnitBox {
 public:
  explicit UnitBox(Bounds bounds) : bounds_(std::move(bounds)) {}

  std::size_t dim() const { return bounds_.dim(); }

  const Bounds& bounds() const { return bounds_; }

  Vector to_unit(const Vector& x) const {
    Vector u(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      u[i] = std::clamp((x[i] - bounds_.lower[i]) / width(i), 0.0, 1.0);
    }
    return u;
  }

  /// The point in the caller's units; clamped so that rounding never leaves the bounds.
  Vector from_unit(const Vector& u) const {
    Vector x(u.size());
    for (std::size_t i = 0; i < u.size(); ++i) {
      const double t = std::clamp(u[i], 0.0, 1.0);
      x[i] = std::clamp(bounds_.lower[i] + t * width(i), bounds_.lower[i], bounds_.upper[i]);
    }
    return x;
  }

 private:
  double width(std::size_t i) const { return bounds_.upper[i] - bounds_.lower[i]; }

  Bounds bounds_;
};

}  // namespace swarmpath::evolve
