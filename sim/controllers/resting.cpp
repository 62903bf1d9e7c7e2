// SPDX-License-Identifier: MIT
#include "resting.hpp"

#include "navigation.hpp"
#include "sim/controller.hpp"
#include "sim/motion.hpp"
#include "units.hpp"

namespace swarmpath::sim {

Command drive_to(const Percept& in, const Params& p, RobotMemory& mem, Vec2 point, double stop_within_cm,
                 Led led, bool retrace) {
  Command cmd;
  cmd.led = led;
  if (kCmPerM * dist(in.pose.p, point) <= stop_within_cm) return cmd;
  const Vec2 f = point == mem.nest ? nav_home(in, p, mem.nav, mem.rng, mem.trail, mem.nest, -1.0, nullptr,
                                              Trail::kEverywhere, retrace)
                                   : nav_toward(in, p, mem.nav, mem.rng, point);
  const Vec2 v = p.v_max * with_avoidance(in, p, mem.nav, f);
  return drive_command(v, p, mem.turn, led);
}

const RabMessage* unanswered_call(std::span<const RabMessage> inbox) {
  IdSet claimed;
  for_each_claim_heard(inbox, [&](int, int named) {
    if (named >= 0 && named <= 255) claimed.insert(static_cast<std::uint8_t>(named));
  });
  const RabMessage* best = nullptr;
  for (const RabMessage& r : inbox) {
    const TaMessage m = decode(r.data);
    if (!m.needs_link() || claimed_emitter(m) == kNobody || r.sender < 0 || r.sender > 255) continue;
    if (claimed.contains(static_cast<std::uint8_t>(r.sender))) continue;
    if (best == nullptr || r.range_cm < best->range_cm) best = &r;
  }
  return best;
}

namespace {

// give_way [R]: the resting robots stand at 20 cm spacing around the nest, a maze with gaps
// narrower than a robot; one pressed by a robot passing through (its proximity vector longer
// than when it settled) backs away from it, then drive_to brings it back.
void watch_for_pressing(const Percept& in, const Params& p, RobotMemory& mem) {
  TaMemory& m = mem.ta;
  const bool home = kCmPerM * dist(in.pose.p, mem.start) <= p.d_arrive;
  const Vec2 touch = proximity_vector(in.proximity);
  const double len = norm(touch);
  if (!m.settled) {
    m.settled = home;
    m.touch_base = len;
    return;
  }
  constexpr double kPressed = 0.1;  // growth of the reading that means a robot pressing
  if (m.give_way == 0 && p.give_way > 0.0 && len > m.touch_base + kPressed) {
    m.give_way = static_cast<std::int64_t>(p.give_way);
    m.give_dir = (-1.0 / len) * touch;
    m.settled = false;
  }
}

Command give_way(const Params& p, RobotMemory& mem) {
  --mem.ta.give_way;
  return drive_command(0.5 * p.v_max * mem.ta.give_dir, p, mem.turn, Led::kBlack);
}

}  // namespace

Command rest(const Percept& in, const Params& p, RobotMemory& mem, const TaSight& sight) {
  TaMemory& m = mem.ta;
  // back to its own deployment point with the field of Eq. (4)-(5), then rest, LEDs off
  const Command cmd =
      m.give_way > 0 ? give_way(p, mem) : drive_to(in, p, mem, mem.start, p.d_arrive, Led::kBlack);
  m.arrived = m.arrived || kCmPerM * dist(in.pose.p, mem.start) <= p.d_arrive;
  watch_for_pressing(in, p, mem);
  // refound_starved: JOIN a founder allocating from the resting robots (T11)
  const auto id = static_cast<std::uint8_t>(in.id);
  return say(cmd, sight.dm.send.type == MsgType::kJoin
                      ? sight.dm.send
                      : alloc_done_message(id, static_cast<std::uint8_t>(TaState::kRestingTask)));
}

}  // namespace swarmpath::sim
