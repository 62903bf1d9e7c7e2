// SPDX-License-Identifier: MIT
#include "recorder.hpp"

#include <algorithm>
#include <optional>
#include <set>
#include <sstream>

#include "astar.hpp"
#include "config_error.hpp"
#include "robot_model.hpp"

namespace swarmpath::sim {

namespace {

constexpr int kTaCodeStride = 16;  // task_allocation_step's state code: TaState * 16 + PfState

std::string length_text(double metres) {
  std::ostringstream s;
  s.setf(std::ios::fixed);
  s.precision(1);
  s << to_tu(metres) << " TU";
  return s.str();
}

void add_path(Recording& r, const std::string& name, const std::string& what, const PathSnapshot& snap) {
  if (snap.tick < 0) return;
  r.paths.push_back({name,
                     what + ": " + length_text(snap.length_m) + ", " + std::to_string(snap.robots.size()) +
                         " robots, tick " + std::to_string(snap.tick),
                     snap.tick, snap.points, snap.robots, snap.length_m});
}

void add_milestone(Recording& r, const std::string& name, const std::string& label, std::int64_t tick) {
  if (tick >= 0) r.milestones.push_back({name, label, tick});
}

}  // namespace

Recorder::Recorder(const Params& p, const Scenario& s, Mode mode, std::uint64_t seed, std::int64_t every)
    : scenario_(&s) {
  if (every < 1) throw ConfigError("--record-every", 0, "", "must be at least 1 tick");
  r_.scenario_name = s.name;
  r_.scenario_file = s.file;
  r_.env_class = s.env_class;
  r_.mode = mode;
  r_.seed = seed;
  r_.ticks_per_second = s.sim.ticks_per_second;
  r_.max_ticks = s.sim.max_ticks;
  r_.every = every;
  r_.arena_size = s.arena_size;
  r_.obstacles = obstacle_shapes(s);
  r_.nest = s.nest;
  r_.goal = s.goal;
  r_.deployment = s.deployment;
  r_.robot_radius = kRobotRadius;
  std::ostringstream params;
  write_params_toml(params, p, "# the params of the recorded run");
  r_.params_toml = params.str();
  // 1 mm steps over the arena and a metre round it (coarser only past 63 m)
  constexpr double kMargin = 1.0;
  r_.origin = s.arena_bounds().lo - Vec2{kMargin, kMargin};
  const double extent = std::max(s.arena_size.x, s.arena_size.y) + 2.0 * kMargin;
  r_.quantum = std::max(0.001, extent / 65535.0);
  for (int c = 0; c < kLedCount; ++c) {
    const Led l = static_cast<Led>(c);
    r_.leds.push_back({std::string(name(l)), rgb(l)});
  }
  for (const PfTransition& t : pf_transitions())
    r_.pf_rows.push_back({std::string(t.row), std::string(t.label)});
  for (const TaTransition& t : ta_transitions())
    r_.ta_rows.push_back({std::string(t.row), std::string(t.label)});

  // frame 0: the world as sim::run starts it (make_world is a pure function of these inputs)
  const World w0 = make_world(s, p, mode, seed);
  r_.robots = w0.robot_count();
  const auto n = static_cast<std::size_t>(r_.robots);
  // room for the frames of a whole run, up to 4096 of them (longer runs grow the buffers)
  const std::size_t frames =
      std::min<std::size_t>(static_cast<std::size_t>(s.sim.max_ticks / every) + 2, 4096);
  for (auto* v : {&r_.qx, &r_.qy}) v->reserve(frames * n);
  for (auto* v : {&r_.heading, &r_.led, &r_.state}) v->reserve(frames * n);
  for (auto* v : {&r_.parent, &r_.child}) v->reserve(frames * n);
  r_.frame_ticks.reserve(frames);
  last_state_.resize(n);
  last_done_.assign(n, -1);
  last_refounder_.assign(n, 0);
  for (std::size_t i = 0; i < n; ++i) last_state_[i] = w0.memory[i].state;
  add_frame(w0);
}

void Recorder::add_frame(const World& w) {
  r_.frame_ticks.push_back(w.tick);
  for (std::size_t i = 0; i < w.poses.size(); ++i) {
    const Pose& q = w.poses[i];
    r_.qx.push_back(quantise(q.p.x, r_.origin.x, r_.quantum));
    r_.qy.push_back(quantise(q.p.y, r_.origin.y, r_.quantum));
    r_.heading.push_back(heading_code(q.yaw()));
    r_.led.push_back(static_cast<std::uint8_t>(w.leds[i]));
    r_.state.push_back(w.memory[i].state);
    r_.parent.push_back(w.memory[i].pf.parent.id);
    r_.child.push_back(w.memory[i].pf.child.id);
  }
}

void Recorder::note_allocation(const World& w, std::size_t i) {
  const RobotMemory& m = w.memory[i];
  const int robot = static_cast<int>(i);
  const std::uint8_t code = m.state;
  const std::uint8_t was = last_state_[i];
  if (code / kTaCodeStride != was / kTaCodeStride) {
    const auto row = [&] {
      const auto rows = ta_transitions();
      return m.ta.fired_tick == w.tick - 1 && m.ta.last_row > 0 && m.ta.last_row <= rows.size()
                 ? " (row " + std::string(rows[m.ta.last_row - 1].row) + ")"
                 : std::string();
    };
    if (m.ta.state == TaState::kGoalFounder) r_.notes.push_back({w.tick, robot, "goal founder" + row()});
    if (m.ta.state == TaState::kPathFormation) r_.notes.push_back({w.tick, robot, "allocated" + row()});
  }
  if (m.ta.alloc_done_tick >= 0 && last_done_[i] != m.ta.alloc_done_tick) {
    last_done_[i] = m.ta.alloc_done_tick;
    r_.notes.push_back({w.tick, robot,
                        "DONE: n = " + std::to_string(m.ta.n) + ", " + std::to_string(m.ta.allocated) +
                            " robots allocated"});
  }
  if (m.ta.refounder != (last_refounder_[i] != 0)) {
    last_refounder_[i] = m.ta.refounder ? 1 : 0;
    if (m.ta.refounder) r_.notes.push_back({w.tick, robot, "chain end goes home to allocate more robots"});
  }
}

void Recorder::observe(const World& w) {
  const bool ta = r_.mode == Mode::kTaskAllocation;
  for (std::size_t i = 0; i < w.memory.size(); ++i) {
    const RobotMemory& m = w.memory[i];
    if (ta) note_allocation(w, i);
    if (m.state == last_state_[i]) continue;
    const std::int64_t fired = w.tick - 1;  // the rows fired during the tick just simulated
    r_.changes.push_back({static_cast<std::int32_t>(w.tick), static_cast<std::int32_t>(i), last_state_[i],
                          m.state, m.pf.fired_tick == fired ? m.pf.last_row : std::uint8_t{0},
                          m.ta.fired_tick == fired ? m.ta.last_row : std::uint8_t{0}});
    last_state_[i] = m.state;
  }
  if (w.tick % r_.every == 0) add_frame(w);
}

Recording Recorder::finish(const World& final_world, const Metrics& m, const AStarResult* astar) {
  if (r_.frame_ticks.back() != final_world.tick) add_frame(final_world);
  r_.success = m.success;
  r_.ticks = m.ticks;
  r_.state_hash = m.state_hash;
  r_.allocated = m.allocated;
  add_milestone(r_, "goal", "goal in view (a robot within 1 m)", m.ticks_to_goal);
  add_milestone(r_, "alloc", "allocation done (T_alloc)", m.ticks_to_allocate);
  add_milestone(r_, "chain", "chain reaches the nest (T_chain)", m.ticks_to_chain);
  add_milestone(r_, "opt1", "optimisation 1 done (T_opt1)", m.ticks_to_opt1);
  add_milestone(r_, "form", "path complete (T_form)", m.ticks_to_form);
  std::stable_sort(r_.milestones.begin(), r_.milestones.end(),
                   [](const Milestone& a, const Milestone& b) { return a.tick < b.tick; });
  std::optional<AStarResult> computed;
  if (astar == nullptr) {
    try {
      computed = sim::astar(*scenario_, {Connectivity::kEight});
      astar = &*computed;
    } catch (const ConfigError&) {
      // arenas too large for the A* grid have no baseline
    }
  }
  if (astar != nullptr && astar->found) {
    r_.paths.push_back(
        {"astar", "A* (8-connected): " + length_text(astar->length_m), -1, astar->path, {}, astar->length_m});
  }
  add_path(r_, "subgoal", "subgoal path", m.subgoal_path);
  add_path(r_, "opt1", "optimisation-1 path", m.opt1_path);
  add_path(r_, "final", "optimisation-2 (final) path", m.final_path);
  // the names of every code the frames and changes hold
  std::set<int> codes(r_.state.begin(), r_.state.end());
  for (const StateChange& c : r_.changes) codes.insert({c.from, c.to});
  for (const int c : codes)
    r_.state_names.emplace_back(c, state_code_name(r_.mode, static_cast<std::uint8_t>(c)));
  return std::move(r_);
}

Recording record_run(const Params& p, const Scenario& s, Mode mode, std::uint64_t seed, std::int64_t every,
                     Metrics* metrics, const TickObserver& also) {
  Recorder rec(p, s, mode, seed, every);
  World w;
  const Metrics m = run(
      p, s, mode, seed,
      [&](const World& now) {
        rec.observe(now);
        return also ? also(now) : false;
      },
      &w);
  if (metrics != nullptr) *metrics = m;
  return rec.finish(w, m);
}

}  // namespace swarmpath::sim
