// SPDX-License-Identifier: MIT
#include "step.hpp"

#include "controller.hpp"

namespace swarmpath::sim {

SensorView sensor_view(const Scenario& s, const Params& p, const World& w) {
  SensorView view;
  view.poses = w.poses;
  view.leds = w.leds;
  view.tags = w.tags;
  view.rab_sending = w.rab_sending;
  view.rab_out = w.rab_out;
  view.rab_kinds = w.rab_kinds;
  view.rab_cell_kinds = w.rab_cell_kinds;
  view.rab_row_kinds = w.rab_row_kinds;
  view.grid = &w.grid;
  view.shapes = w.shapes;
  view.touch_bins = &w.touch_bins;
  view.camera_bins = &w.camera_bins;
  view.rab_bins = &w.rab_bins;
  view.nest = s.nest;
  view.goal = s.goal;
  view.camera_range = p.r_vis / 100.0;
  view.occlude_by_robots = s.sim.occlude_by_robots;
  view.led_ring = p.led_ring;
  return view;
}

namespace {

// Robot i's readings: the Percept's fixed part, its blobs and RAB messages appended to the buffers
// (its spans are set by the caller, once the buffers have stopped growing); with noise on, as the
// fault model distorts them, from robot i's own noise streams.
void sense_robot(const SensorView& view, const Params& p, World& w, std::size_t i, Percept& in,
                 std::vector<Blob>& blobs, std::vector<RabMessage>& inbox) {
  const int id = static_cast<int>(i);
  in.tick = w.tick;
  in.id = id;
  in.pose = w.poses[i];
  const std::size_t blobs_from = blobs.size();
  const std::size_t inbox_from = inbox.size();
  if (w.needs.proximity) sense_proximity(view, id, in.proximity);
  if (w.needs.camera) sense_camera(view, id, blobs);
  // the kinds of message it reads this tick (rab_interest), or every kind when the medium hands
  // every message to every robot that listens (World::rab_by_kind)
  const bool listens = w.needs.rab && robot_listens(w.mode, p, w.memory[i], w.tick);
  const RabKinds interest = !listens        ? 0
                            : w.rab_by_kind ? rab_interest(w.mode, p, w.memory[i], w.tick)
                                            : kEveryRabKind;
  if (interest != 0) sense_rab(view, id, interest, inbox);
  if (!w.faults.noisy) return;
  RobotNoise& noise = w.faults.noise[i];
  in.pose = pose_noise(w.faults.model, noise.pose, w.poses[i]);
  if (w.needs.camera) camera_noise(w.faults.model, noise.camera, view.camera_range, blobs, blobs_from);
  if (listens) rab_noise(w.faults.model, noise.rab, inbox, inbox_from);
}

// World::rab_cell_kinds and rab_row_kinds from this tick's grid and last tick's messages.
void tally_rab_cells(World& w) {
  if (!w.needs.rab) return;
  w.rab_cell_kinds.assign(w.grid.cells(), 0);
  w.rab_row_kinds.assign(w.grid.cells() / w.grid.columns(), 0);
  for (std::size_t i = 0; i < w.rab_kinds.size(); ++i) {
    const auto cell = static_cast<std::size_t>(w.grid.cell_of(static_cast<int>(i)));
    w.rab_cell_kinds[cell] |= w.rab_kinds[i];
    w.rab_row_kinds[cell / w.grid.columns()] |= w.rab_kinds[i];
  }
}

}  // namespace

void sense_all(const Scenario& s, const Params& p, World& w) {
  tally_rab_cells(w);
  const SensorView view = sensor_view(s, p, w);
  const std::size_t n = w.poses.size();
  w.percepts.resize(n);
  w.blob_begin.resize(n + 1);
  w.rab_begin.resize(n + 1);
  w.blobs.clear();
  w.rab_inbox.clear();
  for (std::size_t i = 0; i < n; ++i) {
    w.blob_begin[i] = w.blobs.size();
    w.rab_begin[i] = w.rab_inbox.size();
    if (w.faults.failed[i] == 0) sense_robot(view, p, w, i, w.percepts[i], w.blobs, w.rab_inbox);
  }
  w.blob_begin[n] = w.blobs.size();
  w.rab_begin[n] = w.rab_inbox.size();
  // spans only once the buffers have stopped growing
  for (std::size_t i = 0; i < n; ++i) {
    w.percepts[i].blobs = {w.blobs.data() + w.blob_begin[i], w.blob_begin[i + 1] - w.blob_begin[i]};
    w.percepts[i].rab = {w.rab_inbox.data() + w.rab_begin[i], w.rab_begin[i + 1] - w.rab_begin[i]};
  }
}

void control_all(const Params& p, World& w) {
  for (std::size_t i = 0; i < w.poses.size(); ++i) {
    if (w.faults.failed[i] == 0) w.commands[i] = control(w.mode, w.percepts[i], p, w.memory[i]);
  }
}

void sense_and_control_all(const Scenario& s, const Params& p, World& w) {
  tally_rab_cells(w);
  const SensorView view = sensor_view(s, p, w);
  Percept in;
  for (std::size_t i = 0; i < w.poses.size(); ++i) {
    if (w.faults.failed[i] != 0) continue;  // a failed robot's command stays stopped and dark
    w.blobs.clear();
    w.rab_inbox.clear();
    sense_robot(view, p, w, i, in, w.blobs, w.rab_inbox);
    in.blobs = w.blobs;
    in.rab = w.rab_inbox;
    w.commands[i] = control(w.mode, in, p, w.memory[i]);
  }
}

void act_all(World& w) {
  for (std::size_t i = 0; i < w.poses.size(); ++i) {
    const Command& c = w.commands[i];
    double left = c.left_cm_s / 100.0;
    double right = c.right_cm_s / 100.0;
    if (w.faults.noisy) wheel_noise(w.faults.model, w.faults.noise[i].wheels, left, right);
    w.physics->set_wheels(static_cast<int>(i), left, right);
    w.leds[i] = c.led;
    w.tags[i] = c.tag;
    w.rab_sending[i] = c.rab_send ? 1 : 0;
    w.rab_out[i] = c.rab;
    w.rab_kinds[i] = !c.rab_send ? 0 : w.rab_by_kind ? rab_kinds(w.mode, c.rab) : kEveryRabKind;
  }
}

void integrate(const Scenario& s, World& w, MetricsAccumulator& m) {
  w.physics->step(s.sim.dt(), s.sim.velocity_iterations, s.sim.position_iterations);
  w.physics->read_poses(w.poses);
  for (std::size_t i = 0; i < w.poses.size(); ++i) {
    m.add_distance(dist(w.positions[i], w.poses[i].p));
    w.positions[i] = w.poses[i].p;
  }
  w.grid.build(w.positions);
  ++w.tick;
}

void fail_due(World& w) {
  FaultState& f = w.faults;
  while (f.next < f.schedule.size() && f.schedule[f.next].tick <= w.tick) {
    int victim = f.schedule[f.next].robot;
    if (victim < 0) {
      // FailTarget::kChain: one of the robots showing a chain link's light now; none: wait
      int lit = 0;
      for (std::size_t i = 0; i < w.leds.size(); ++i) lit += f.failed[i] == 0 && is_chain_light(w.leds[i]);
      if (lit == 0) return;
      auto k = static_cast<int>(f.victims.below(static_cast<std::uint64_t>(lit)));
      for (std::size_t i = 0; i < w.leds.size() && victim < 0; ++i) {
        if (f.failed[i] == 0 && is_chain_light(w.leds[i]) && k-- == 0) victim = static_cast<int>(i);
      }
    }
    fail_robot(w, victim);
    ++f.next;
  }
}

void step(const Scenario& s, const Params& p, World& w, MetricsAccumulator& m) {
  // robots whose failure is due stop (faults)
  fail_due(w);
  // sense and control, robot by robot in id order: every robot reads the same pre-step snapshot
  sense_and_control_all(s, p, w);
  // act: wheels, LEDs and the RAB outbox (heard by the others next tick)
  act_all(w);
  // physics, then the post-step snapshot the next tick senses
  integrate(s, w, m);
  // measure
  m.observe(s, w);
}

Metrics run(const Params& p, const Scenario& s, Mode mode, std::uint64_t seed, const TickObserver& observe,
            World* final_world) {
  World w = make_world(s, p, mode, seed);
  MetricsAccumulator m;
  m.begin(w.robot_count());
  while (w.tick < s.sim.max_ticks) {
    step(s, p, w, m);
    if (observe && observe(w)) break;
    if (s.sim.stop_when_complete && m.complete()) break;
  }
  Metrics out = m.finish(w.tick, s.sim.dt(), state_hash(w));
  out.failures = w.faults.failures;
  out.chain_failures = w.faults.chain_failures;
  if (final_world != nullptr) *final_world = std::move(w);
  return out;
}

Metrics evaluate(const Params& p, const Scenario& s, Mode mode, std::uint64_t seed) {
  return run(p, s, mode, seed, {});
}

}  // namespace swarmpath::sim
