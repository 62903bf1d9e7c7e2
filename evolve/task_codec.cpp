// SPDX-License-Identifier: MIT
#include "task_codec.hpp"

#include <cstring>
#include <stdexcept>

namespace swarmpath::evolve {

// A field added to one of these structs must travel too: add it below (writer and reader), then
// the new size here. (Sizes of g++'s standard library on x86-64; other platforms skip the check.)
#if defined(__GLIBCXX__) && defined(__x86_64__)
static_assert(sizeof(sim::Scenario) == 432, "sim::Scenario changed: update write_scenario/read_scenario");
static_assert(sizeof(sim::ArenaOrigin) == 72,
              "sim::ArenaOrigin changed: update write_scenario/read_scenario");
static_assert(sizeof(sim::FaultModel) == 80, "sim::FaultModel changed: update write_scenario/read_scenario");
static_assert(sizeof(sim::SimSettings) == 48,
              "sim::SimSettings changed: update write_scenario/read_scenario");
static_assert(sizeof(sim::BoxObstacle) == 40 && sizeof(sim::CylinderObstacle) == 24 &&
                  sizeof(sim::RectRegion) == 32,
              "a scenario shape changed: update write_scenario/read_scenario");
static_assert(sizeof(sim::Metrics) == 352, "sim::Metrics changed: update write_metrics/read_metrics");
static_assert(sizeof(sim::PathSnapshot) == 64 && sizeof(sim::ChainStats) == 12,
              "a part of sim::Metrics changed: update write_metrics/read_metrics");
#endif

namespace {

// caps that stop a corrupt length from allocating the machine away
constexpr std::uint64_t kMaxItems = 100'000'000;

std::uint64_t count(ByteReader& r) {
  const std::uint64_t n = r.u64();
  if (n > kMaxItems) throw std::runtime_error("corrupt message: a list of " + std::to_string(n) + " items");
  return n;
}

void vec2(ByteWriter& w, sim::Vec2 v) {
  w.f64(v.x);
  w.f64(v.y);
}

sim::Vec2 vec2(ByteReader& r) {
  const double x = r.f64();
  return {x, r.f64()};
}

void int32(ByteWriter& w, int v) { w.i64(v); }

int int32(ByteReader& r) { return static_cast<int>(r.i64()); }

void flag(ByteWriter& w, bool v) { w.u8(v ? 1 : 0); }

bool flag(ByteReader& r) { return r.u8() != 0; }

void snapshot(ByteWriter& w, const sim::PathSnapshot& s) {
  w.i64(s.tick);
  w.u64(s.robots.size());
  for (const int id : s.robots) int32(w, id);
  w.u64(s.points.size());
  for (const sim::Vec2 p : s.points) vec2(w, p);
  w.f64(s.length_m);
}

sim::PathSnapshot snapshot(ByteReader& r) {
  sim::PathSnapshot s;
  s.tick = r.i64();
  s.robots.resize(count(r));
  for (int& id : s.robots) id = int32(r);
  s.points.resize(count(r));
  for (sim::Vec2& p : s.points) p = vec2(r);
  s.length_m = r.f64();
  return s;
}

}  // namespace

void ByteWriter::raw(const void* p, std::size_t n) {
  const char* c = static_cast<const char*>(p);
  bytes_.insert(bytes_.end(), c, c + n);
}

void ByteWriter::text(const std::string& s) {
  u64(s.size());
  raw(s.data(), s.size());
}

void ByteReader::raw(void* p, std::size_t n) {
  if (bytes_.size() - pos_ < n) throw std::runtime_error("corrupt message: it ends too early");
  std::memcpy(p, bytes_.data() + pos_, n);
  pos_ += n;
}

std::string ByteReader::text() {
  std::string s(count(*this), '\0');
  raw(s.data(), s.size());
  return s;
}

void write_scenario(ByteWriter& w, const sim::Scenario& s) {
  w.text(s.name);
  w.text(s.file);
  w.u8(static_cast<std::uint8_t>(s.env_class));
  vec2(w, s.arena_size);
  w.f64(s.wall_thickness);
  w.u64(s.boxes.size());
  for (const sim::BoxObstacle& b : s.boxes) {
    vec2(w, b.center);
    vec2(w, b.size);
    w.f64(b.yaw);
  }
  w.u64(s.cylinders.size());
  for (const sim::CylinderObstacle& c : s.cylinders) {
    vec2(w, c.center);
    w.f64(c.radius);
  }
  vec2(w, s.nest);
  vec2(w, s.goal);
  vec2(w, s.deployment.center);
  vec2(w, s.deployment.size);
  w.f64(s.min_spacing);
  int32(w, s.robots);
  int32(w, s.sim.ticks_per_second);
  w.i64(s.sim.max_ticks);
  int32(w, s.sim.velocity_iterations);
  int32(w, s.sim.position_iterations);
  flag(w, s.sim.occlude_by_robots);
  flag(w, s.sim.stop_when_complete);
  w.f64(s.sim.grid_cell);
  int32(w, s.sim.physics_regions_x);
  int32(w, s.sim.physics_regions_y);
  flag(w, s.origin.has_value());
  if (s.origin) {
    w.text(s.origin->family);
    w.u64(s.origin->seed);
    int32(w, s.origin->version);
    w.u64(s.origin->params.size());
    for (const auto& [key, value] : s.origin->params) {
      w.text(key);
      w.f64(value);
    }
  }
  const sim::FaultModel& f = s.faults;
  w.f64(f.fail_fraction);
  w.i64(f.fail_from);
  w.i64(f.fail_until);
  w.u8(static_cast<std::uint8_t>(f.fail_target));
  for (const double v :
       {f.camera_miss, f.camera_false, f.packet_loss, f.wheel_noise, f.position_noise, f.heading_noise})
    w.f64(v);
}

sim::Scenario read_scenario(ByteReader& r) {
  sim::Scenario s;
  s.name = r.text();
  s.file = r.text();
  s.env_class = static_cast<sim::EnvClass>(r.u8());
  s.arena_size = vec2(r);
  s.wall_thickness = r.f64();
  s.boxes.resize(count(r));
  for (sim::BoxObstacle& b : s.boxes) {
    b.center = vec2(r);
    b.size = vec2(r);
    b.yaw = r.f64();
  }
  s.cylinders.resize(count(r));
  for (sim::CylinderObstacle& c : s.cylinders) {
    c.center = vec2(r);
    c.radius = r.f64();
  }
  s.nest = vec2(r);
  s.goal = vec2(r);
  s.deployment.center = vec2(r);
  s.deployment.size = vec2(r);
  s.min_spacing = r.f64();
  s.robots = int32(r);
  s.sim.ticks_per_second = int32(r);
  s.sim.max_ticks = r.i64();
  s.sim.velocity_iterations = int32(r);
  s.sim.position_iterations = int32(r);
  s.sim.occlude_by_robots = flag(r);
  s.sim.stop_when_complete = flag(r);
  s.sim.grid_cell = r.f64();
  s.sim.physics_regions_x = int32(r);
  s.sim.physics_regions_y = int32(r);
  if (flag(r)) {
    sim::ArenaOrigin& o = s.origin.emplace();
    o.family = r.text();
    o.seed = r.u64();
    o.version = int32(r);
    o.params.resize(count(r));
    for (auto& [key, value] : o.params) {
      key = r.text();
      value = r.f64();
    }
  }
  sim::FaultModel& f = s.faults;
  f.fail_fraction = r.f64();
  f.fail_from = r.i64();
  f.fail_until = r.i64();
  f.fail_target = static_cast<sim::FailTarget>(r.u8());
  for (double* v :
       {&f.camera_miss, &f.camera_false, &f.packet_loss, &f.wheel_noise, &f.position_noise, &f.heading_noise})
    *v = r.f64();
  return s;
}

void write_params(ByteWriter& w, const sim::Params& p) {
  const auto table = sim::param_table();
  w.u64(table.size());
  for (const sim::ParamInfo& info : table) w.f64(sim::get_value(p, info));
}

sim::Params read_params(ByteReader& r) {
  const auto table = sim::param_table();
  if (r.u64() != table.size()) throw std::runtime_error("corrupt message: another parameter table");
  sim::Params p;
  for (const sim::ParamInfo& info : table) sim::set_value(p, info, r.f64());
  return p;
}

void write_metrics(ByteWriter& w, const sim::Metrics& m) {
  int32(w, m.robots);
  w.i64(m.ticks);
  w.u64(m.state_hash);
  w.f64(m.distance_m);
  w.f64(m.mean_speed_cm_s);
  flag(w, m.success);
  w.i64(m.ticks_to_form);
  w.i64(m.ticks_to_chain);
  w.i64(m.ticks_to_opt1);
  w.i64(m.ticks_to_goal);
  w.f64(m.path_length_tu);
  w.f64(m.subgoal_path_length_tu);
  w.f64(m.opt1_path_length_tu);
  int32(w, m.path_robots);
  int32(w, m.allocated);
  int32(w, m.recruited);
  w.f64(m.resource_reduction_pct);
  w.i64(m.ticks_to_allocate);
  snapshot(w, m.subgoal_path);
  snapshot(w, m.opt1_path);
  snapshot(w, m.final_path);
  int32(w, m.chain.subgoals_laid);
  int32(w, m.chain.subgoals_laid_goalward);
  int32(w, m.chain.forming_from_goal_side);
  int32(w, m.failures);
  int32(w, m.chain_failures);
}

sim::Metrics read_metrics(ByteReader& r) {
  sim::Metrics m;
  m.robots = int32(r);
  m.ticks = r.i64();
  m.state_hash = r.u64();
  m.distance_m = r.f64();
  m.mean_speed_cm_s = r.f64();
  m.success = flag(r);
  m.ticks_to_form = r.i64();
  m.ticks_to_chain = r.i64();
  m.ticks_to_opt1 = r.i64();
  m.ticks_to_goal = r.i64();
  m.path_length_tu = r.f64();
  m.subgoal_path_length_tu = r.f64();
  m.opt1_path_length_tu = r.f64();
  m.path_robots = int32(r);
  m.allocated = int32(r);
  m.recruited = int32(r);
  m.resource_reduction_pct = r.f64();
  m.ticks_to_allocate = r.i64();
  m.subgoal_path = snapshot(r);
  m.opt1_path = snapshot(r);
  m.final_path = snapshot(r);
  m.chain.subgoals_laid = int32(r);
  m.chain.subgoals_laid_goalward = int32(r);
  m.chain.forming_from_goal_side = int32(r);
  m.failures = int32(r);
  m.chain_failures = int32(r);
  return m;
}

void write_batch(ByteWriter& w, const SimBatch& b) {
  w.u64(b.params.size());
  for (const sim::Params& p : b.params) write_params(w, p);
  w.u64(b.scenarios.size());
  for (const auto& s : b.scenarios) write_scenario(w, *s);
  w.u64(b.tasks.size());
  for (const SimTask& t : b.tasks) {
    w.u32(t.params);
    w.u32(t.scenario);
    w.u8(static_cast<std::uint8_t>(t.mode));
    w.u64(t.seed);
  }
}

SimBatch read_batch(ByteReader& r) {
  SimBatch b;
  b.params.resize(count(r));
  for (sim::Params& p : b.params) p = read_params(r);
  const std::uint64_t scenarios = count(r);
  for (std::uint64_t i = 0; i < scenarios; ++i) {
    b.scenarios.push_back(std::make_shared<const sim::Scenario>(read_scenario(r)));
  }
  b.tasks.resize(count(r));
  for (SimTask& t : b.tasks) {
    t.params = r.u32();
    t.scenario = r.u32();
    t.mode = static_cast<sim::Mode>(r.u8());
    t.seed = r.u64();
    if (t.params >= b.params.size() || t.scenario >= b.scenarios.size()) {
      throw std::runtime_error("corrupt message: a task names a missing params set or scenario");
    }
  }
  return b;
}

}  // namespace swarmpath::evolve
