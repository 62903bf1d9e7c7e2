// SPDX-License-Identifier: MIT
// The tick and the pure core: evaluate(params, scenario, mode, seed) -> Metrics.
#pragma once

#include <cstdint>
#include <functional>

#include "metrics.hpp"
#include "params.hpp"
#include "scenario.hpp"
#include "sensors.hpp"
#include "world.hpp"

namespace swarmpath::sim {

/// One tick, in a fixed phase order: failures due, sense all robots (same pre-step snapshot), control all in
/// id order, act (wheels, LEDs, RAB outbox), one physics step, then refresh poses and grid.
/// Sensing reads nothing that control writes (a robot's own memory only before its own control),
/// so step() senses and controls robot by robot, a Percept that never leaves the cache; the
/// result is that of sense_all then control_all (test Step.RobotByRobotEqualsThePhases).
void step(const Scenario& s, const Params& p, World& w, MetricsAccumulator& m);

// The phases of step(), exposed for tests that check what each one sees.

/// Phase 0: robots whose failure time has come fail-stop (Scenario::faults; fail_robot).
void fail_due(World& w);
/// What the sensors read of `w` right now.
SensorView sensor_view(const Scenario& s, const Params& p, const World& w);
/// Phase 1: every robot's Percept from the current snapshot (failed robots' are left as they were).
void sense_all(const Scenario& s, const Params& p, World& w);
/// Phase 2: every robot's Command, in id order (failed robots' stay stopped and dark).
void control_all(const Params& p, World& w);
/// Phases 1 and 2 robot by robot, as step() runs them (w.percepts is left as it was).
void sense_and_control_all(const Scenario& s, const Params& p, World& w);
/// Phase 3: wheels (with the fault model's wheel noise), LEDs and RAB outbox from the commands.
void act_all(World& w);
/// Phase 4: one physics step, then the new poses and neighbour grid.
void integrate(const Scenario& s, World& w, MetricsAccumulator& m);

/// Called after every tick; return true to stop the run early.
using TickObserver = std::function<bool(const World&)>;

/// make_world, then step until s.sim.max_ticks (or the observer says stop), then finish.
/// Pure: the same inputs give bit-identical Metrics on any thread, in any process.
Metrics evaluate(const Params& p, const Scenario& s, Mode mode, std::uint64_t seed);

/// The same run, handing the world to `observe` after each tick (pictures, traces).
Metrics run(const Params& p, const Scenario& s, Mode mode, std::uint64_t seed, const TickObserver& observe,
            World* final_world = nullptr);

}  // namespace swarmpath::sim
