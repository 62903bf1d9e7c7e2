// SPDX-License-Identifier: MIT
#include "scenario.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

#include "config_error.hpp"
#include "reachability.hpp"
#include "robot_model.hpp"
#include "toml_reader.hpp"

namespace swarmpath::sim {

std::string_view to_string(EnvClass c) {
  switch (c) {
    case EnvClass::kOpen:
      return "open";
    case EnvClass::kObstacle:
      return "obstacle";
    case EnvClass::kComplex:
      return "complex";
  }
  return "?";
}

std::vector<BoxObstacle> boundary_walls(const Scenario& s) {
  const double t = s.wall_thickness;
  if (t <= 0.0) return {};
  const double w = s.arena_size.x;
  const double h = s.arena_size.y;
  return {
      {{0.0, 0.5 * h - 0.5 * t}, {w, t}, 0.0},   // north
      {{0.0, -0.5 * h + 0.5 * t}, {w, t}, 0.0},  // south
      {{0.5 * w - 0.5 * t, 0.0}, {t, h}, 0.0},   // east
      {{-0.5 * w + 0.5 * t, 0.0}, {t, h}, 0.0},  // west
  };
}

std::vector<Shape> obstacle_shapes(const Scenario& s) {
  std::vector<Shape> shapes;
  shapes.reserve(4 + s.boxes.size() + s.cylinders.size());
  for (const BoxObstacle& b : boundary_walls(s)) shapes.push_back(Shape::box(b.center, b.size, b.yaw));
  for (const BoxObstacle& b : s.boxes) shapes.push_back(Shape::box(b.center, b.size, b.yaw));
  for (const CylinderObstacle& c : s.cylinders) shapes.push_back(Shape::circle(c.center, c.radius));
  return shapes;
}

namespace {

// the arena interior: inside the boundary walls
Aabb interior(const Scenario& s) {
  const Aabb a = s.arena_bounds();
  const double t = std::max(s.wall_thickness, 0.0);
  return {{a.lo.x + t, a.lo.y + t}, {a.hi.x - t, a.hi.y - t}};
}

std::string fmt(double v, int digits = 6) {
  std::ostringstream o;
  o << std::setprecision(digits) << v;
  return o.str();
}

std::string fmt(Vec2 v) { return "(" + fmt(v.x) + ", " + fmt(v.y) + ")"; }

EnvClass parse_class(const TableReader& t) {
  const std::string c = t.string("class");
  if (c == "open") return EnvClass::kOpen;
  if (c == "obstacle") return EnvClass::kObstacle;
  if (c == "complex") return EnvClass::kComplex;
  t.fail("class", "must be \"open\", \"obstacle\" or \"complex\", got \"" + c + "\"");
}

void require_positive(const TableReader& t, std::string_view key, double v, const std::string& what) {
  if (!(v > 0.0)) t.fail(key, what + " must be > 0 (got " + fmt(v) + ")");
}

void require_range(const TableReader& t, std::string_view key, double v, double lo, double hi) {
  if (v < lo || v > hi) t.fail(key, "must lie in [" + fmt(lo) + ", " + fmt(hi) + "] (got " + fmt(v) + ")");
}

// a named point (nest or goal) must be inside the arena interior and outside every obstacle
void check_point(const Scenario& s, const TableReader& root, std::string_view key, Vec2 p,
                 const std::vector<Shape>& shapes, const std::vector<std::string>& shape_names) {
  const Aabb in = interior(s);
  if (!(p.x > in.lo.x && p.x < in.hi.x && p.y > in.lo.y && p.y < in.hi.y)) {
    root.fail(key, std::string(key) + " " + fmt(p) + " lies outside the arena interior [" + fmt(in.lo.x) +
                       ", " + fmt(in.hi.x) + "] x [" + fmt(in.lo.y) + ", " + fmt(in.hi.y) + "]");
  }
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    if (signed_distance(shapes[i], p) <= 0.0) {
      root.fail(key, std::string(key) + " " + fmt(p) + " lies inside " + shape_names[i]);
    }
  }
  // a robot's centre can come no closer to an obstacle than its radius
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    if (signed_distance(shapes[i], p) < kRobotRadius) {
      root.fail(key, std::string(key) + " " + fmt(p) + " lies within " + fmt(100.0 * kRobotRadius, 2) +
                         " cm of " + shape_names[i] + ": no robot can reach it (a robot's radius is " +
                         fmt(100.0 * kRobotRadius, 2) + " cm)");
    }
  }
}

}  // namespace

double deployment_free_area(const Scenario& s) {
  const Aabb region = s.deployment.bounds();
  const Aabb in = interior(s);
  const std::vector<Shape> all = obstacle_shapes(s);
  std::vector<Shape> near;
  const Aabb grown = {region.lo - Vec2{kRobotRadius, kRobotRadius},
                      region.hi + Vec2{kRobotRadius, kRobotRadius}};
  for (const Shape& sh : all) {
    if (sh.bounds.overlaps(grown)) near.push_back(sh);
  }
  // a lattice of at most 100 x 100 points, at least 2 cm apart
  const double area = s.deployment.size.x * s.deployment.size.y;
  const double step = std::max(0.02, std::sqrt(area / 1.0e4));
  const int nx = std::max(1, static_cast<int>(std::floor(s.deployment.size.x / step)));
  const int ny = std::max(1, static_cast<int>(std::floor(s.deployment.size.y / step)));
  int free = 0;
  for (int iy = 0; iy < ny; ++iy) {
    for (int ix = 0; ix < nx; ++ix) {
      const Vec2 p{region.lo.x + (ix + 0.5) * s.deployment.size.x / nx,
                   region.lo.y + (iy + 0.5) * s.deployment.size.y / ny};
      if (p.x - kRobotRadius < in.lo.x || p.x + kRobotRadius > in.hi.x || p.y - kRobotRadius < in.lo.y ||
          p.y + kRobotRadius > in.hi.y) {
        continue;
      }
      bool clear = true;
      for (const Shape& sh : near) {
        if (signed_distance(sh, p) < kRobotRadius) {
          clear = false;
          break;
        }
      }
      free += clear ? 1 : 0;
    }
  }
  return area * free / (static_cast<double>(nx) * ny);
}

int deployment_capacity(const Scenario& s) {
  const double disk = kPi * 0.25 * s.min_spacing * s.min_spacing;
  return static_cast<int>(std::floor(0.45 * deployment_free_area(s) / disk));
}

std::string check_robot_count(const Scenario& s, std::int64_t n) {
  if (n < 1) return "the robot count must be at least 1 (got " + std::to_string(n) + ")";
  if (n > kMaxRobots) {
    return std::to_string(n) + " robots exceed the limit of " + std::to_string(kMaxRobots);
  }
  const int cap = deployment_capacity(s);
  if (n > cap) {
    return "the deployment region " + fmt(s.deployment.size.x) + " x " + fmt(s.deployment.size.y) + " m at " +
           fmt(s.deployment.center) + " with min_spacing " + fmt(s.min_spacing) + " m cannot hold " +
           std::to_string(n) + " robots (at most " + std::to_string(cap) + ")";
  }
  return {};
}

Scenario with_robots(const Scenario& s, std::int64_t n, const std::string& what) {
  const std::string err = check_robot_count(s, n);
  if (!err.empty()) throw ConfigError(what, 0, "", err);
  Scenario out = s;
  out.robots = static_cast<int>(n);
  return out;
}

Scenario with_max_ticks(const Scenario& s, std::int64_t ticks, const std::string& what) {
  if (ticks < 1 || ticks > kMaxTicks) {
    throw ConfigError(
        what, 0, "",
        "ticks must lie in [1, " + std::to_string(kMaxTicks) + "] (got " + std::to_string(ticks) + ")");
  }
  Scenario out = s;
  out.sim.max_ticks = ticks;
  return out;
}

Scenario with_faults(const Scenario& s, const FaultModel& f, const std::string& what) {
  if (const std::string err = check_faults(f); !err.empty()) throw ConfigError(what, 0, "", err);
  Scenario out = s;
  out.faults = f;
  return out;
}

namespace {

Scenario parse(const TomlDoc& doc) {
  Scenario s;
  s.file = doc.name();
  const TableReader root(doc, doc.root(), "");

  // identity
  {
    std::string stem = doc.name();
    const auto slash = stem.find_last_of('/');
    if (slash != std::string::npos) stem = stem.substr(slash + 1);
    const auto dot = stem.rfind('.');
    if (dot != std::string::npos) stem = stem.substr(0, dot);
    s.name = root.string_or("name", stem);
    if (s.name.empty()) root.fail("name", "must not be empty");
  }
  s.env_class = parse_class(root);

  // arena and boundary walls
  const TableReader arena = root.required_table("arena");
  s.arena_size = arena.vec2("size");
  require_positive(arena, "size", std::min(s.arena_size.x, s.arena_size.y), "arena size");
  if (std::max(s.arena_size.x, s.arena_size.y) > kMaxArenaSide) {
    arena.fail("size",
               "arena sides must be at most " + fmt(kMaxArenaSide) + " m (got " + fmt(s.arena_size) + ")");
  }
  s.wall_thickness = arena.number_or("wall_thickness", 0.1);
  if (s.wall_thickness < kMinWallThickness) {
    arena.fail("wall_thickness", "must be at least " + fmt(kMinWallThickness) + " m (got " +
                                     fmt(s.wall_thickness) +
                                     "): without boundary walls the robots leave the arena");
  }
  if (s.wall_thickness >= 0.25 * std::min(s.arena_size.x, s.arena_size.y)) {
    arena.fail("wall_thickness",
               "must be less than a quarter of the arena's shorter side (got " + fmt(s.wall_thickness) + ")");
  }
  arena.finish();

  // obstacles
  const Aabb arena_box = s.arena_bounds();
  std::vector<std::string> names;  // for messages, in obstacle_shapes() order
  for (const char* w : {"the north wall", "the south wall", "the east wall", "the west wall"})
    names.emplace_back(w);
  const std::vector<TableReader> boxes = root.table_array("box");
  const std::vector<TableReader> cylinders = root.table_array("cylinder");
  if (boxes.size() + cylinders.size() > kMaxObstacles) {
    // the table that takes the count past the limit
    root.fail(boxes.size() > kMaxObstacles ? "box" : "cylinder",
              "too many obstacles: " + std::to_string(boxes.size()) +
                  (boxes.size() == 1 ? " box" : " boxes") + " and " + std::to_string(cylinders.size()) +
                  " cylinders (at most " + std::to_string(kMaxObstacles) + " in all)");
  }
  for (const TableReader& b : boxes) {
    BoxObstacle box;
    box.center = b.vec2("center");
    box.size = b.vec2("size");
    require_positive(b, "size", std::min(box.size.x, box.size.y), "obstacle size");
    box.yaw = deg2rad(b.number_or("yaw_deg", 0.0));
    b.finish();
    if (!Shape::box(box.center, box.size, box.yaw).bounds.overlaps(arena_box)) {
      b.fail("center", "box at " + fmt(box.center) + " lies entirely outside the arena");
    }
    s.boxes.push_back(box);
    names.push_back(b.prefix() + " (line " + std::to_string(b.line_of("center")) + ")");
  }
  for (const TableReader& c : cylinders) {
    CylinderObstacle cyl;
    cyl.center = c.vec2("center");
    cyl.radius = c.number("radius");
    require_positive(c, "radius", cyl.radius, "obstacle radius");
    c.finish();
    if (!aabb_around(cyl.center, cyl.radius).overlaps(arena_box)) {
      c.fail("center", "cylinder at " + fmt(cyl.center) + " lies entirely outside the arena");
    }
    s.cylinders.push_back(cyl);
    names.push_back(c.prefix() + " (line " + std::to_string(c.line_of("center")) + ")");
  }
  const std::vector<Shape> shapes = obstacle_shapes(s);

  // nest and goal beacons
  s.nest = root.vec2("nest");
  s.goal = root.vec2("goal");
  check_point(s, root, "nest", s.nest, shapes, names);
  check_point(s, root, "goal", s.goal, shapes, names);
  if (!robot_can_drive(s, s.nest, s.goal)) {
    root.fail("goal", "no robot can drive from the nest " + fmt(s.nest) + " to the goal " + fmt(s.goal) +
                          ": the obstacles and walls close every way (a robot is " +
                          fmt(200.0 * kRobotRadius, 3) + " cm wide)");
  }
  if (dist(s.nest, s.goal) < 2.0 * kRobotRadius) root.fail("goal", "goal and nest coincide");

  // simulation settings
  if (auto sim = root.table("simulation")) {
    const std::int64_t tps = sim->integer_or("ticks_per_second", 10);
    require_range(*sim, "ticks_per_second", static_cast<double>(tps), 1, 1000);
    s.sim.ticks_per_second = static_cast<int>(tps);
    const std::int64_t max_ticks = sim->integer_or("max_ticks", 36000);
    if (max_ticks < 1 || max_ticks > kMaxTicks) {
      sim->fail("max_ticks",
                "must lie in [1, " + std::to_string(kMaxTicks) + "] (got " + std::to_string(max_ticks) + ")");
    }
    s.sim.max_ticks = max_ticks;
    const std::int64_t vi = sim->integer_or("velocity_iterations", 8);
    require_range(*sim, "velocity_iterations", static_cast<double>(vi), 1, 100);
    s.sim.velocity_iterations = static_cast<int>(vi);
    const std::int64_t pi = sim->integer_or("position_iterations", 3);
    require_range(*sim, "position_iterations", static_cast<double>(pi), 1, 100);
    s.sim.position_iterations = static_cast<int>(pi);
    s.sim.occlude_by_robots = sim->boolean_or("occlude_by_robots", false);
    s.sim.stop_when_complete = sim->boolean_or("stop_when_complete", true);
    s.sim.grid_cell = sim->number_or("grid_cell", 1.0);
    require_range(*sim, "grid_cell", s.sim.grid_cell, 0.1, 10.0);
    // the neighbour grids hold a list per cell: their size is the product, not either factor
    const double cells = std::ceil(s.arena_size.x / s.sim.grid_cell - 1e-9) *
                         std::ceil(s.arena_size.y / s.sim.grid_cell - 1e-9);
    if (cells > static_cast<double>(kMaxGridCells)) {
      const double least = std::sqrt(s.arena_size.x * s.arena_size.y / static_cast<double>(kMaxGridCells));
      sim->fail("grid_cell", fmt(s.sim.grid_cell) + " m cells over the " + fmt(s.arena_size.x) + " x " +
                                 fmt(s.arena_size.y) + " m arena (arena.size) make " + fmt(cells, 15) +
                                 " neighbour-grid cells (limit " + std::to_string(kMaxGridCells) +
                                 "): use grid_cell >= " + fmt(std::ceil(least * 100.0) / 100.0) +
                                 " m or a smaller arena");
    }
    const Vec2 regions = sim->vec2_or("physics_regions", {1.0, 1.0});
    for (const double r : {regions.x, regions.y}) {
      if (r != std::floor(r) || r < 1.0 || r > kMaxPhysicsRegions) {
        sim->fail("physics_regions", "must be two whole numbers in [1, " +
                                         std::to_string(kMaxPhysicsRegions) + "] (got [" + fmt(regions.x) +
                                         ", " + fmt(regions.y) + "])");
      }
    }
    s.sim.physics_regions_x = static_cast<int>(regions.x);
    s.sim.physics_regions_y = static_cast<int>(regions.y);
    sim->finish();
  }

  // faults and noise [R]
  if (auto faults = root.table("faults")) s.faults = parse_faults(*faults);

  // deployment region
  const TableReader dep = root.required_table("deployment");
  s.deployment.center = dep.vec2_or("center", s.nest);
  s.deployment.size = dep.vec2("size");
  require_positive(dep, "size", std::min(s.deployment.size.x, s.deployment.size.y), "deployment size");
  s.min_spacing = dep.number_or("min_spacing", 0.2);
  if (s.min_spacing < 2.0 * kRobotRadius || s.min_spacing > 10.0) {
    dep.fail("min_spacing", "must lie in [" + fmt(2.0 * kRobotRadius) +
                                ", 10] m so that robots do not overlap (got " + fmt(s.min_spacing) + ")");
  }
  const Aabb in = interior(s);
  const Aabb region = s.deployment.bounds();
  if (region.lo.x < in.lo.x || region.hi.x > in.hi.x || region.lo.y < in.lo.y || region.hi.y > in.hi.y) {
    dep.fail(dep.has("center") ? "center" : "size",
             "deployment region [" + fmt(region.lo.x) + ", " + fmt(region.hi.x) + "] x [" + fmt(region.lo.y) +
                 ", " + fmt(region.hi.y) + "] reaches outside the arena interior");
  }
  const std::int64_t robots = dep.integer_or("robots", 100);
  dep.finish();
  if (const std::string err = check_robot_count(s, robots); !err.empty()) dep.fail("robots", err);
  s.robots = static_cast<int>(robots);

  // how a generated arena was drawn (read, not checked against the generator: sim/arenas does that)
  if (auto gen = root.table("generator")) {
    ArenaOrigin o;
    o.family = gen->string("family");
    if (o.family.empty()) gen->fail("family", "must not be empty");
    const std::int64_t seed = gen->integer("seed");
    if (seed < 0) gen->fail("seed", "must be >= 0 (got " + std::to_string(seed) + ")");
    o.seed = static_cast<std::uint64_t>(seed);
    const std::int64_t version = gen->integer("version");
    if (version < 1 || version > 1000000) gen->fail("version", "must lie in [1, 1000000]");
    o.version = static_cast<int>(version);
    if (auto params = gen->table("params")) {
      for (const std::string& key : params->keys()) o.params.emplace_back(key, params->number(key));
      params->finish();
      std::sort(o.params.begin(), o.params.end());
    } else {
      gen->allow("params");
    }
    gen->finish();
    s.origin = std::move(o);
  }

  root.finish();
  return s;
}

}  // namespace

Scenario parse_scenario(std::string_view text, const std::string& name) {
  const TomlDoc doc = TomlDoc::parse_string(text, name);
  return parse(doc);
}

Scenario load_scenario(const std::string& path) {
  const TomlDoc doc = TomlDoc::parse_file(path);
  return parse(doc);
}

}  // namespace swarmpath::sim
