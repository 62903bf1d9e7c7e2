// SPDX-License-Identifier: MIT
#include "registry.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "draw_support.hpp"
#include "family_list.hpp"
#include "sim/astar.hpp"
#include "sim/config_error.hpp"
#include "sim/hash.hpp"
#include "sim/scenario_writer.hpp"

namespace swarmpath::sim::arenas {

namespace {

// clang-format off
constexpr FamilyParam kCommon[] = {
    {"width", 24.0, 10.0, 25.0, false, "m", "arena side along x (SPEC §3.3: 24)"},
    {"height", 14.0, 8.0, 25.0, false, "m", "arena side along y (SPEC §3.3: 14)"},
    {"robots", 100, 1, 120, true, "", "the arena's robot count; its deployment region must hold them"},
};
// clang-format on

constexpr double kBeaconClearance = 0.35;  // nest and goal to the nearest obstacle [m]
constexpr double kGoalToDeployment = 0.5;  // the goal outside the deployment region grown by this [m]

std::string fmt(double v) { return toml_number(v); }

std::string range_text(const FamilyParam& q) { return "[" + fmt(q.lo) + ", " + fmt(q.hi) + "]"; }

// "" when v suits q, else why not
std::string value_problem(const FamilyParam& q, double v) {
  if (!std::isfinite(v) || v < q.lo || v > q.hi)
    return "must lie in " + range_text(q) + " (got " + fmt(v) + ")";
  if (q.integer && v != std::floor(v)) return "must be a whole number (got " + fmt(v) + ")";
  return {};
}

std::string param_list(const Family& f) {
  std::string s;
  for (const FamilyParam& q : all_params(f)) s += (s.empty() ? "" : ", ") + std::string(q.name);
  return s;
}

std::size_t index_of(const std::vector<FamilyParam>& params, std::string_view name) {
  for (std::size_t i = 0; i < params.size(); ++i) {
    if (params[i].name == name) return i;
  }
  return params.size();
}

// yaw in whole tenths of a degree, in [0, 180)
double mirrored_yaw(double yaw) {
  const double deg = std::round(rad2deg(yaw) * 10.0) / 10.0;
  double m = std::fmod(180.0 - deg, 180.0);
  if (m < 0.0) m += 180.0;
  return deg2rad(m);
}

// the draft mirrored in x and / or y (the families draw west to east; mirrors vary that)
void mirror(Draft& d, bool flip_x, bool flip_y) {
  // + 0.0 turns the -0 of a flipped 0 into 0
  const auto flip = [&](Vec2 v) { return Vec2{(flip_x ? -v.x : v.x) + 0.0, (flip_y ? -v.y : v.y) + 0.0}; };
  d.nest = flip(d.nest);
  d.goal = flip(d.goal);
  d.deployment.center = flip(d.deployment.center);
  for (BoxObstacle& b : d.boxes) {
    b.center = flip(b.center);
    if (b.yaw != 0.0 && flip_x != flip_y) b.yaw = mirrored_yaw(b.yaw);
  }
  for (CylinderObstacle& c : d.cylinders) c.center = flip(c.center);
}

std::string header(const ArenaSpec& spec, std::uint64_t seed, const Draft& d, const Scenario& s,
                   double astar8_m, int draws) {
  std::string h = "# Arena \"" + s.name + "\": family " + std::string(spec.family->name) + ", seed " +
                  std::to_string(seed) + ", drawn by the swarmpath arena generator (version " +
                  std::to_string(kGeneratorVersion) + "; draw " + std::to_string(draws) + " of at most " +
                  std::to_string(kMaxDraws) + ").\n";
  h += "#   " + spec.command_line(seed) + "\n";
  if (!d.note.empty()) h += "# " + d.note + ".\n";
  const double ratio = astar8_m / empty_arena_astar8(s);
  h += "# A*-8 on the 1 cm grid with 8.5 cm inflation (SPEC §4.5): " +
       fmt(std::round(to_tu(astar8_m) * 10) / 10) + " TU (1 TU = 10 cm), " +
       fmt(std::round(ratio * 100) / 100) + " x its length without obstacles; class " +
       std::string(to_string(s.env_class)) + " (no obstacles: open; from " + fmt(kComplexDetour) +
       " x: complex).\n";
  return h;
}

}  // namespace

double ParamValues::operator()(std::string_view name) const {
  const std::size_t i = index_of(params_, name);
  if (i >= values_.size()) throw std::logic_error("arena family has no parameter " + std::string(name));
  return values_[i];
}

std::string ordered(const ParamValues& p, std::string_view a, std::string_view b, std::string& key) {
  if (p(a) <= p(b)) return {};
  key = std::string(a);
  return std::string(a) + " (" + fmt(p(a)) + ") must be <= " + std::string(b) + " (" + fmt(p(b)) + ")";
}

std::span<const Family> families() {
  static const std::array<Family, 8> kAll = {open_family(),   clutter_family(),  wall_gap_family(),
                                             u_trap_family(), corridor_family(), serpentine_family(),
                                             rooms_family(),  mixed_family()};
  return kAll;
}

const Family* find_family(std::string_view name) {
  for (const Family& f : families()) {
    if (f.name == name) return &f;
  }
  return nullptr;
}

std::string family_names() {
  std::string s;
  for (const Family& f : families()) s += (s.empty() ? "" : ", ") + std::string(f.name);
  return s;
}

std::vector<FamilyParam> all_params(const Family& f) {
  std::vector<FamilyParam> out(std::begin(kCommon), std::end(kCommon));
  out.insert(out.end(), f.params.begin(), f.params.end());
  return out;
}

ParamValues ArenaSpec::param_values() const { return ParamValues(all_params(*family), values); }

std::string ArenaSpec::settings_text() const {
  std::string s;
  const std::vector<FamilyParam> params = all_params(*family);
  for (std::size_t i = 0; i < params.size(); ++i) {
    if (values[i] != params[i].fallback)
      s += (s.empty() ? "" : " ") + std::string(params[i].name) + "=" + fmt(values[i]);
  }
  return s;
}

std::string ArenaSpec::command_line(std::uint64_t seed) const {
  std::string s =
      "swarmpath arena generate --family " + std::string(family->name) + " --seed " + std::to_string(seed);
  const std::vector<FamilyParam> params = all_params(*family);
  for (std::size_t i = 0; i < params.size(); ++i) {
    if (values[i] != params[i].fallback) s += " --set " + std::string(params[i].name) + "=" + fmt(values[i]);
  }
  return s;
}

std::vector<std::pair<std::string, double>> ArenaSpec::sorted_params() const {
  std::vector<std::pair<std::string, double>> out;
  const std::vector<FamilyParam> params = all_params(*family);
  for (std::size_t i = 0; i < params.size(); ++i) out.emplace_back(std::string(params[i].name), values[i]);
  std::sort(out.begin(), out.end());
  return out;
}

ArenaSpec default_spec(std::string_view family, const std::string& where) {
  const Family* f = find_family(family);
  if (f == nullptr) {
    throw ConfigError(
        where, 0, "family",
        "unknown arena family \"" + std::string(family) + "\" (families: " + family_names() + ")");
  }
  ArenaSpec spec{f, {}};
  for (const FamilyParam& q : all_params(*f)) spec.values.push_back(q.fallback);
  return spec;
}

std::string check_spec(const ArenaSpec& spec, std::string& key) {
  const std::vector<FamilyParam> params = all_params(*spec.family);
  if (spec.values.size() != params.size()) {
    key = "family";
    return "expected " + std::to_string(params.size()) + " parameter values";
  }
  for (std::size_t i = 0; i < params.size(); ++i) {
    const std::string e = value_problem(params[i], spec.values[i]);
    if (!e.empty()) {
      key = std::string(params[i].name);
      return e;
    }
  }
  return spec.family->check != nullptr ? spec.family->check(spec.param_values(), key) : std::string();
}

ArenaSpec spec_from_settings(std::string_view family, const std::vector<std::string>& settings,
                             const std::string& where) {
  ArenaSpec spec = default_spec(family, where);
  const std::vector<FamilyParam> params = all_params(*spec.family);
  std::vector<bool> set(params.size(), false);
  for (const std::string& s : settings) {
    const auto eq = s.find('=');
    const std::string key = s.substr(0, eq);
    if (eq == std::string::npos) throw ConfigError(where, 0, key, "expected key=value, e.g. walls=2");
    const std::size_t i = index_of(params, key);
    if (i == params.size()) {
      throw ConfigError(where, 0, key,
                        "unknown parameter of family " + std::string(family) +
                            " (its parameters: " + param_list(*spec.family) + ")");
    }
    if (set[i]) throw ConfigError(where, 0, key, "set twice");
    set[i] = true;
    const std::string text = s.substr(eq + 1);
    double v = 0.0;
    const auto r = std::from_chars(text.data(), text.data() + text.size(), v);
    if (text.empty() || r.ec != std::errc() || r.ptr != text.data() + text.size()) {
      throw ConfigError(where, 0, key, "expected a number, got \"" + text + "\"");
    }
    spec.values[i] = v;
  }
  std::string key;
  const std::string e = check_spec(spec, key);
  if (!e.empty()) throw ConfigError(where, 0, key, e);
  return spec;
}

ArenaSpec read_spec(const TableReader& t, std::string_view family_key, std::string_view params_key) {
  const std::string name = t.string(family_key);
  const Family* f = find_family(name);
  if (f == nullptr) {
    t.fail(family_key, "unknown arena family \"" + name + "\" (families: " + family_names() + ")");
  }
  ArenaSpec spec = default_spec(name, t.file());
  const std::vector<FamilyParam> params = all_params(*f);
  std::optional<TableReader> table = t.table(params_key);
  if (table) {
    for (const std::string& key : table->keys()) {
      const std::size_t i = index_of(params, key);
      if (i == params.size()) {
        table->fail(key, "unknown parameter of family " + name + " (its parameters: " + param_list(*f) + ")");
      }
      const double v = table->number(key);
      const std::string e = value_problem(params[i], v);
      if (!e.empty()) table->fail(key, e);
      spec.values[i] = v;
    }
    table->finish();
  } else {
    t.allow(params_key);
  }
  std::string key;
  const std::string e = check_spec(spec, key);
  if (!e.empty()) {
    if (table && table->has(key)) table->fail(key, e);
    t.fail(table ? params_key : family_key, key + ": " + e);
  }
  return spec;
}

double empty_arena_astar8(const Scenario& s) {
  const double dx = std::abs(s.goal.x - s.nest.x), dy = std::abs(s.goal.y - s.nest.y);
  return std::max(dx, dy) + (std::sqrt(2.0) - 1.0) * std::min(dx, dy);
}

EnvClass classify(const Scenario& s, double astar8_m) {
  if (s.boxes.empty() && s.cylinders.empty()) return EnvClass::kOpen;
  return astar8_m >= kComplexDetour * empty_arena_astar8(s) ? EnvClass::kComplex : EnvClass::kObstacle;
}

std::string arena_problem(const Scenario& s, double& astar8_m) {
  const std::vector<Shape> shapes = obstacle_shapes(s);
  for (const auto& [what, p] : {std::pair<const char*, Vec2>{"nest", s.nest}, {"goal", s.goal}}) {
    for (const Shape& sh : shapes) {
      if (signed_distance(sh, p) < kBeaconClearance) {
        return std::string("the ") + what + " lies within " + fmt(kBeaconClearance) + " m of an obstacle";
      }
    }
  }
  const Aabb dep = s.deployment.bounds();
  const Aabb near = {dep.lo - Vec2{kGoalToDeployment, kGoalToDeployment},
                     dep.hi + Vec2{kGoalToDeployment, kGoalToDeployment}};
  if (near.contains(s.goal))
    return "the goal lies within " + fmt(kGoalToDeployment) + " m of the deployment region";
  // no obstacle inside the deployment region: a 10 cm lattice over it
  std::vector<Shape> inside;
  for (std::size_t i = 4; i < shapes.size(); ++i) {  // the boundary walls first (obstacle_shapes)
    if (shapes[i].bounds.overlaps(dep)) inside.push_back(shapes[i]);
  }
  const int nx = std::max(2, static_cast<int>(std::ceil(s.deployment.size.x / 0.1)));
  const int ny = std::max(2, static_cast<int>(std::ceil(s.deployment.size.y / 0.1)));
  for (int j = 0; j <= ny && !inside.empty(); ++j) {
    for (int i = 0; i <= nx; ++i) {
      const Vec2 p{dep.lo.x + s.deployment.size.x * i / nx, dep.lo.y + s.deployment.size.y * j / ny};
      for (const Shape& sh : inside) {
        if (signed_distance(sh, p) <= 0.0) return "an obstacle reaches into the deployment region";
      }
    }
  }
  const AStarResult a = astar(s);
  if (!a.found) return "the goal cannot be reached (no 8-connected A* path with the robot's inflation)";
  astar8_m = a.length_m;
  return {};
}

GeneratedArena generate_arena(const ArenaSpec& spec, std::uint64_t seed) {
  const std::string where = "arena " + std::string(spec.family->name);
  if (seed > kMaxArenaSeed) throw ConfigError(where, 0, "seed", "arena seeds must lie in [0, 2^63 - 1]");
  std::string key;
  if (const std::string e = check_spec(spec, key); !e.empty()) throw ConfigError(where, 0, key, e);
  const ParamValues p = spec.param_values();
  Fnv1a tag;
  tag.add_bytes(spec.family->name.data(), spec.family->name.size());
  const std::string name = std::string(spec.family->name) + "-" + std::to_string(seed);
  std::string last;
  for (int k = 0; k < kMaxDraws; ++k) {
    Rng rng(mix_seed(seed, tag.value(), static_cast<std::uint64_t>(k)));
    Draft d;
    d.arena_size = {p("width"), p("height")};
    if (!spec.family->draw(p, rng, d)) {
      last = "the family found no room for its layout";
      continue;
    }
    mirror(d, rng.bernoulli(0.5), rng.bernoulli(0.5));
    Scenario s;
    s.name = name;
    s.arena_size = d.arena_size;
    s.wall_thickness = kBoundary;
    s.boxes = d.boxes;
    s.cylinders = d.cylinders;
    s.nest = d.nest;
    s.goal = d.goal;
    s.deployment = d.deployment;
    s.robots = p.integer("robots");
    s.origin = ArenaOrigin{std::string(spec.family->name), seed, kGeneratorVersion, spec.sorted_params()};
    Scenario read;
    try {
      read = parse_scenario(write_scenario_toml(s), name + ".toml");
    } catch (const ConfigError& e) {
      last = e.what();
      continue;
    }
    double astar8_m = 0.0;
    last = arena_problem(read, astar8_m);
    if (!last.empty()) continue;
    s.env_class = classify(read, astar8_m);
    GeneratedArena out;
    out.toml = write_scenario_toml(s, header(spec, seed, d, s, astar8_m, k + 1));
    out.scenario = parse_scenario(out.toml, name + ".toml");
    out.astar8_m = astar8_m;
    out.draws = k + 1;
    return out;
  }
  throw ConfigError(
      where, 0, "seed",
      "no valid arena in " + std::to_string(kMaxDraws) + " draws of seed " + std::to_string(seed) +
          " (the last: " + last + "); the parameters may be impossible together (" +
          (spec.settings_text().empty() ? std::string("defaults") : spec.settings_text()) + ")");
}

}  // namespace swarmpath::sim::arenas
