// SPDX-License-Identifier: MIT
#include "founder_way.hpp"

#include <cstddef>

#include "exploring.hpp"
#include "sighting_share.hpp"
#include "sim/controller.hpp"
#include "units.hpp"

namespace swarmpath::sim {

void keep_founder_way(const Params& p, RobotMemory& mem) {
  if (!p.lead_way) return;
  mem.route.keep(mem.trail, p.way_home_leg);
  mem.pf.knows_way = true;
  mem.pf.tell_count = -1;
}

bool tell_founder_way(std::int64_t tick, int id, const Params& p, RobotMemory& mem, Command& cmd) {
  int k = 0;
  Vec2 rel;
  if (!p.lead_way || !corner_to_tell(p, mem.route, mem.pf, tick, mem.nest, k, rel)) return false;
  cmd.rab_send = true;
  cmd.rab = way_message(static_cast<std::uint8_t>(id & 0xff), {k, mem.pf.tell_count, rel.x, rel.y});
  return true;
}

bool listens_for_founder_way(const Params& p, const RobotMemory& mem, std::int64_t tick) {
  if (!p.lead_way) return false;
  // a resting robot that a chain's end may fetch (refound_starved, T11), at its deployment point
  if (mem.ta.state == TaState::kRestingTask) return p.refound_starved && mem.ta.arrived;
  if (mem.pf.told.complete()) return false;
  if (mem.ta.state == TaState::kDecisionMaker) return true;
  if (mem.ta.state != TaState::kPathFormation || mem.pf.state != PfState::kExploring || mem.pf.knows_way)
    return false;
  const ExploreLeg leg = mem.pf.explore_leg;
  return tick < mem.ta.depart_tick || leg == ExploreLeg::kFollowThenWalk ||
         leg == ExploreLeg::kFollowThenSighting;
}

void hear_founder_way(std::span<const RabMessage> inbox, RobotMemory& mem) {
  ToldWay& told = mem.pf.told;
  // the teller listened to while it tells; when it is silent, the nearest that tells (ties: the
  // smaller id), whose way replaces the one heard
  const RabMessage* nearest = nullptr;
  for (const RabMessage& r : inbox) {
    if (decode(r.data).type != MsgType::kWay) continue;
    if (r.sender == told.teller) {
      nearest = nullptr;
      break;
    }
    if (nearest == nullptr || r.range_cm < nearest->range_cm ||
        (r.range_cm == nearest->range_cm && r.sender < nearest->sender))
      nearest = &r;
  }
  if (nearest != nullptr) {
    told = ToldWay{};
    told.teller = nearest->sender;
  }
  for (const RabMessage& r : inbox) {
    if (r.sender != told.teller || decode(r.data).type != MsgType::kWay) continue;
    const WayCorner c = way_corner(r.data);
    if (c.count < 1 || c.count > ToldWay::kMax || c.index >= c.count) continue;
    if (c.count != told.count) {  // another way than the one begun
      told.count = c.count;
      told.heard = 0;
    }
    told.corners[static_cast<std::size_t>(c.index)] = mem.nest + kCm * Vec2{c.x_cm, c.y_cm};
    told.heard |= std::uint32_t{1} << c.index;
  }
  if (told.complete() && mem.ta.state == TaState::kPathFormation) take_founder_way(mem);
}

void take_founder_way(RobotMemory& mem) {
  PfMemory& m = mem.pf;
  if (!m.told.complete()) return;
  mem.route.assign(std::span<const Vec2>(m.told.corners.data(), static_cast<std::size_t>(m.told.count)));
  m.knows_way = true;
  m.tell_count = -1;
}

}  // namespace swarmpath::sim
