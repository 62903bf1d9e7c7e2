// SPDX-License-Identifier: MIT
// Exact hypervolume (the Lebesgue measure dominated by a point set, minimisation) in 2 and 3
// objectives, and the non-dominated subset of a point set.
#pragma once

#include <cstddef>
#include <vector>

#include "evolve/optim/optimizer.hpp"

namespace swarmpath::evolve {

/// The volume of the region dominated by `points` and bounded above by `reference` (all
/// objectives minimised). Points not strictly better than the reference in every objective
/// contribute nothing. 2 objectives: sort and sweep, O(n log n); 3 objectives: slices along the
/// third axis with a 2D sweep per slice, O(n^2 log n) (both exact up to rounding).
/// Throws std::invalid_argument unless the reference has 2 or 3 finite coordinates and every
/// point has as many.
double hypervolume(const std::vector<Vector>& points, const Vector& reference);

/// True when a dominates b: a <= b in every objective and a < b in at least one (minimisation).
bool dominates(const Vector& a, const Vector& b);

/// Indices (ascending) of the points no other point dominates; equal points are all kept.
/// Throws std::invalid_argument when the points differ in dimension.
std::vector<std::size_t> non_dominated(const std::vector<Vector>& points);

}  // namespace swarmpath::evolve
