// SPDX-License-Identifier: MIT
// An arena family: a named, parameterised way of drawing arenas (open field, clutter, walls with
// doorways, U-traps, corridors, serpentines, rooms, a mixture). A family draws the geometry of
// one arena from its parameter values and a random stream; the registry (registry.hpp) fills in
// the rest, checks the arena and draws again when it is impossible.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "sim/rng.hpp"
#include "sim/scenario.hpp"

namespace swarmpath::sim::arenas {

/// One parameter of a family: a number in [lo, hi] (whole when `integer`).
struct FamilyParam {
  std::string_view name;
  double fallback = 0.0;  ///< the value when not set
  double lo = 0.0;
  double hi = 0.0;
  bool integer = false;
  std::string_view unit;  ///< "m", "deg", "" ...
  std::string_view help;
};

/// The parameter values of one family, in the order of its parameter list (common ones first).
class ParamValues {
 public:
  ParamValues(std::vector<FamilyParam> params, std::vector<double> values)
      : params_(std::move(params)), values_(std::move(values)) {}

  /// The value of `name`; throws std::logic_error for a name the family does not have.
  double operator()(std::string_view name) const;

  int integer(std::string_view name) const { return static_cast<int>((*this)(name)); }

  const std::vector<FamilyParam>& params() const { return params_; }

  const std::vector<double>& values() const { return values_; }

 private:
  std::vector<FamilyParam> params_;
  std::vector<double> values_;
};

/// What a family draws: the geometry of one arena. The registry adds the boundary walls, the
/// robot count, the class, the name and the origin, then checks it.
struct Draft {
  Vec2 arena_size;
  std::vector<BoxObstacle> boxes;
  std::vector<CylinderObstacle> cylinders;
  Vec2 nest;
  Vec2 goal;
  RectRegion deployment;
  std::string note;  ///< one line for the file's header (e.g. which family a mixture drew)
};

/// Draws one arena; may leave it impossible (the registry checks and draws again). Returns
/// false when the draw already knows it failed.
using DrawFn = bool (*)(const ParamValues& p, Rng& rng, Draft& out);

/// A cross-parameter check: an empty message when the values are consistent, else the message and
/// (through `key`) the parameter to blame.
using CheckFn = std::string (*)(const ParamValues& p, std::string& key);

struct Family {
  std::string_view name;
  std::string_view description;
  std::span<const FamilyParam> params;  ///< the family's own parameters (the common ones come first)
  DrawFn draw = nullptr;
  CheckFn check = nullptr;  ///< optional
};

}  // namespace swarmpath::sim::arenas
