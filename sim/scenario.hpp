// SPDX-License-Identifier: MIT
// The immutable description of one experiment arena (SPEC §3.3): arena, walls, obstacles,
// nest and goal beacons, deployment region, environment class and simulation settings.
// Loaded from TOML and validated once; shared read-only by every thread afterwards.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "faults.hpp"
#include "geometry.hpp"
#include "vec2.hpp"

namespace swarmpath::sim {

/// The paper's three environment types; they select the delta of Eq. (3).
enum class EnvClass : std::uint8_t { kOpen, kObstacle, kComplex };

std::string_view to_string(EnvClass c);

struct BoxObstacle {
  Vec2 center;     ///< [m]
  Vec2 size;       ///< full side lengths [m]
  double yaw = 0;  ///< [rad], CCW from +x
};

struct CylinderObstacle {
  Vec2 center;        ///< [m]
  double radius = 0;  ///< [m]
};

/// An axis-aligned rectangle given by centre and full size [m].
struct RectRegion {
  Vec2 center;
  Vec2 size;

  Aabb bounds() const { return {center - 0.5 * size, center + 0.5 * size}; }
};

struct SimSettings {
  int ticks_per_second = 10;       ///< one physics step per tick (SPEC §1.2)
  std::int64_t max_ticks = 36000;  ///< T_max (SPEC §1.4)
  int velocity_iterations = 8;     ///< Box2D solver iterations
  int position_iterations = 3;
  bool occlude_by_robots = false;  ///< robot bodies block the camera (SPEC §1.3)
  bool stop_when_complete = true;  ///< end a path-formation run once the path is complete
  double grid_cell = 1.0;          ///< neighbour-grid cell size [m]
  int physics_regions_x = 1;       ///< Box2D worlds across x (see PhysicsLayout)
  int physics_regions_y = 1;       ///< and along y

  double dt() const { return 1.0 / ticks_per_second; }
};

/// How a generated arena was drawn (a scenario file's [generator] table): the family, its
/// parameters and the seed, from which the arena generator (sim/arenas) draws it again.
struct ArenaOrigin {
  std::string family;
  std::uint64_t seed = 0;
  int version = 0;                                     ///< the arena generator's version
  std::vector<std::pair<std::string, double>> params;  ///< every family parameter, sorted by name
};

struct Scenario {
  std::string name;  ///< e.g. "env4"
  std::string file;  ///< the file it came from, for messages ("<memory>" otherwise)
  EnvClass env_class = EnvClass::kOpen;

  Vec2 arena_size{24.0, 14.0};  ///< centred at the origin [m]
  double wall_thickness = 0.1;  ///< boundary walls inside the arena edge, >= kMinWallThickness [m]
  std::vector<BoxObstacle> boxes;
  std::vector<CylinderObstacle> cylinders;

  Vec2 nest;  ///< nest beacon (BLUE light) [m]
  Vec2 goal;  ///< goal beacon (YELLOW light) [m]

  RectRegion deployment;     ///< robots start uniformly in here
  double min_spacing = 0.2;  ///< minimum centre distance at deployment [m]
  int robots = 100;          ///< default robot count

  SimSettings sim;
  std::optional<ArenaOrigin> origin;  ///< set for a generated arena
  FaultModel faults;                  ///< `[faults]`: failures and sensor noise, off by default [R]

  Aabb arena_bounds() const { return {-0.5 * arena_size, 0.5 * arena_size}; }
};

/// Upper limits that catch absurd inputs before they exhaust memory or time.
inline constexpr int kMaxRobots = 100000;
inline constexpr std::int64_t kMaxTicks = 10000000;
inline constexpr double kMaxArenaSide = 2000.0;  // [m]
inline constexpr std::size_t kMaxObstacles = 200000;
inline constexpr int kMaxPhysicsRegions = 16;             // per axis (each Box2D world holds a 100 KiB stack)
inline constexpr std::int64_t kMaxGridCells = 4'000'000;  // arena cells of the neighbour grid (~130 MB)
inline constexpr double kMinWallThickness = 0.01;         // [m]: the boundary walls are never removed

/// Loads and validates a scenario file. Throws ConfigError ("file:line: key: message").
Scenario load_scenario(const std::string& path);

/// Same, from TOML text; `name` stands for the file in messages.
Scenario parse_scenario(std::string_view text, const std::string& name);

/// All static shapes: the four boundary walls first, then boxes, then cylinders.
std::vector<Shape> obstacle_shapes(const Scenario& s);

/// The boundary walls as boxes (SPEC §3.3: 0.10 m thick, inside the arena edge).
std::vector<BoxObstacle> boundary_walls(const Scenario& s);

/// Free area of the deployment region [m^2]: points whose robot body would not touch an
/// obstacle, estimated on a 2 cm lattice.
double deployment_free_area(const Scenario& s);

/// The most robots the deployment region can hold at random with min_spacing (45 % of the
/// random-sequential-adsorption packing of its free area).
int deployment_capacity(const Scenario& s);

/// Returns an error message when `n` robots cannot be used with `s` (too many, too few,
/// region too small), or an empty string when they can.
std::string check_robot_count(const Scenario& s, std::int64_t n);

/// A copy of `s` with another robot count / tick limit; throws ConfigError naming `what`
/// (the command-line option) when the value is not acceptable.
Scenario with_robots(const Scenario& s, std::int64_t n, const std::string& what = "--robots");
Scenario with_max_ticks(const Scenario& s, std::int64_t ticks, const std::string& what = "--ticks");
/// A copy of `s` with another fault model; throws ConfigError naming `what` when it is invalid.
Scenario with_faults(const Scenario& s, const FaultModel& f, const std::string& what = "--faults");

}  // namespace swarmpath::sim
