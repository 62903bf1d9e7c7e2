// SPDX-License-Identifier: MIT
#include "chain_links.hpp"

#include <array>

#include "alignment.hpp"
#include "navigation.hpp"
#include "path_formation.hpp"
#include "sim/controller.hpp"

namespace swarmpath::sim {

Claims gather_claims(const Percept& in) {
  Claims c;
  for_each_naming(in, [&](int, int named) { c.add(named); });
  return c;
}

const Blob* free_subgoal_in_view(const Percept& in) {
  const Claims claims = gather_claims(in);
  const Blob* best = nullptr;
  for (const Blob& b : in.blobs) {
    if (b.emitter < 0 || b.color != Led::kRed || claims.has(b.emitter)) continue;
    if (best == nullptr || b.distance_cm < best->distance_cm) best = &b;
  }
  return best;
}

// chain_bypass [R]: a RED subgoal whose parent's parent (the RED robot the parent's light names, or
// the goal) is in view within bypass_reach skips the parent. A RED subgoal leaves the chain once
// every robot that has named it as parent (its children, by their lights' tags or claims on the
// medium) is seen or heard naming another, one of them its own parent: it was skipped
void perceive_bypass(const Percept& in, const Params& p, PfMemory& m, const Claims& claims, PfSight& sight) {
  // what each robot that ever named me names this tick
  std::array<int, Claimants::kMax> names;
  names.fill(kNobody);
  for_each_naming(in, [&](int robot, int named) {
    if (named == in.id) m.claimants.add(robot);
    for (std::size_t i = 0; i < m.claimants.ids.size(); ++i) {
      if (m.claimants.ids[i] == robot) names[i] = named;
    }
  });
  const Claimants& who = m.claimants;
  bool all_renamed = who.count > 0 && who.count <= Claimants::kMax && !claims.has(in.id);
  bool to_parent = false;
  for (int i = 0; i < std::min(who.count, Claimants::kMax); ++i) {
    all_renamed = all_renamed && names[i] != kNobody && names[i] != in.id;
    to_parent = to_parent || (m.parent.valid() && names[i] == m.parent.id);
  }
  sight.bypassed = all_renamed && to_parent;

  if (!m.parent.valid() || !m.parent.visible) return;
  const Blob* parent = blob_of(in, m.parent.id);
  const int grandparent = parent != nullptr && parent->color == Led::kRed ? parent->tag : kNobody;
  for (const Blob& b : in.blobs) {
    // (not where the grandparent names my parent or me as its own: a loop, not a chain)
    if (grandparent != kNobody && b.emitter == grandparent && b.distance_cm <= p.bypass_reach &&
        (b.color == Led::kRed || b.emitter == kGoalEmitter) && b.tag != m.parent.id && b.tag != in.id) {
      sight.grandparent = &b;
    }
  }
}

// relink_recovery [R]: a parent that turned RECOVERY (row 13) still names its own parent with its
// light's tag; that robot, in view, is the heir
void perceive_heir(const Percept& in, const PfMemory& m, PfSight& sight) {
  if (!m.parent.valid() || !m.parent.visible || m.parent.color != Led::kOrange) return;
  const Blob* parent = blob_of(in, m.parent.id);
  const int heir = parent != nullptr ? parent->tag : kNobody;
  if (heir == kNobody || heir == in.id) return;
  for (const Blob& b : in.blobs) {
    if (b.emitter == heir && b.color != Led::kOrange) sight.heir = &b;
  }
}

// ---- guards ----

bool sees_nest(const PfContext& c) { return c.sight.nest != nullptr; }

bool sees_own_sub_nest(const PfContext& c) { return c.sight.my_subnest != nullptr; }

bool orphaned(const PfContext& c) { return c.p.revert_orphans && lost(c.m.parent, c.p); }

bool sees_grandparent(const PfContext& c) { return c.sight.grandparent != nullptr; }

bool bypassed(const PfContext& c) { return c.sight.bypassed; }

bool heir_in_view(const PfContext& c) { return c.sight.heir != nullptr; }

// ---- actions ----

void child_is_nest(const PfContext& c, PfMemory& m) { m.child = follow(*c.sight.nest, c.in.pose); }

void child_is_sub_nest(const PfContext& c, PfMemory& m) { m.child = follow(*c.sight.my_subnest, c.in.pose); }

void grandparent_becomes_parent(const PfContext& c, PfMemory& m) {
  m.parent = follow(*c.sight.grandparent, c.in.pose);
}

void heir_becomes_parent(const PfContext& c, PfMemory& m) { m.parent = follow(*c.sight.heir, c.in.pose); }

// row 21 [R] (T_leaf): a subgoal that nobody has named as parent or target for T_leaf ticks is a leaf
// that no explorer extends (a side branch of the fan at the goal); it leaves as row 16's does
bool leaf_unextended(const PfContext& c) {
  const double limit = c.m.role == PfRole::kAllocated ? c.p.t_leaf_allocated : c.p.t_leaf;
  return limit > 0.0 && static_cast<double>(c.m.childless) >= limit;
}

bool sees_another_branch(const Percept& in, const PfMemory& m) {
  int grandparent = kNobody;
  for (const Blob& b : in.blobs)
    if (b.emitter == m.parent.id) grandparent = b.tag;
  for (const Blob& b : in.blobs) {
    if (b.emitter < 0 || !is_path_colour(b.color) || b.color == Led::kOrange) continue;
    if (b.emitter != m.parent.id && b.emitter != grandparent) return true;
  }
  return false;
}

// row 16 [R]: back to the nest along its way out, then out again to the sighting, the RED robot
// nearest the nest that it saw (pf_perceive): its next approach to the tip is from the nest side
void leave_chain(const PfContext&, PfMemory& m) {
  m.parent = Tracked{};
  m.target = Tracked{};
}

// ---- SUB_NEST ----

// The camera's view of a corner need not be mutual, so a parent can be waited for for ever: one out of
// view, behind a corner (R, seek_hidden_reference), or one that turned RECOVERY in its alignment (row
// 13), whose own parent this robot looks for (R, relink_recovery; row 17 takes it). Go round the
// corner toward where the parent was last seen, the child in view or not: under a wall's tip a robot
// may see neither
Command wait_for_parent(const Percept& in, const Params& p, RobotMemory& mem) {
  const PfMemory& m = mem.pf;
  const PfState s = PfState::kSubNest;
  // (the two exclude each other: the parent out of view, in view and ORANGE)
  const bool hidden = p.seek_hidden_reference && lost(m.parent, p);
  const bool broken = p.relink_recovery && m.parent.visible && m.parent.color == Led::kOrange;
  if (!(hidden || broken)) return pf_stop(s);
  const Vec2 toward = local_cm(in.pose, m.parent);
  // (a broken link: to the edge of its repulsion, since its parent stands up to d_sub beyond it)
  if (norm(toward) <= (broken ? p.r_rec : p.d_detect)) return pf_stop(s);
  const Vec2 f = nav_toward(in, p, mem.nav, mem.rng, m.parent.last_seen);
  const Vec2 v = with_avoidance(in, p, mem.nav, f);
  return pf_drive(p, mem, p.v_align * p.v_max * v, s);
}

void advertise_links(const Percept& in, const Params& p, const PfMemory& m, Command& cmd) {
  // vision + ID: the light also carries the robot's parent (SPEC §2.1), so that a subgoal can tell
  // which sub-nest is its own (row 9b)
  cmd.tag = m.parent.valid() ? m.parent.id : kNobody;
  // ... and a forming robot's light, its target: the target is claimed (single_child)
  if (m.state == PfState::kSubgoalForming && m.target.valid()) cmd.tag = m.target.id;
  // single_child: the claim also goes on the medium, which reaches past the camera's range
  const bool chained = m.state != PfState::kExploring && m.state != PfState::kReturnToNest &&
                       m.state != PfState::kResting && m.state != PfState::kRecovery;
  if (claims_links(p, m) && chained && cmd.tag != kNobody) {
    TaMessage claim = claim_message(static_cast<std::uint8_t>(in.id), cmd.tag);
    // recruit_call: a subgoal nobody has claimed for T_starve calls resting robots
    if (m.state == PfState::kSubgoal && static_cast<double>(m.unclaimed) >= p.t_starve && calls_links(p, m))
      claim.flags = static_cast<std::uint8_t>(claim.flags | kFlagNeed);
    cmd.rab_send = true;
    cmd.rab = encode(claim);
  } else if (m.state == PfState::kExploring && m.answering >= 0) {
    // ... and a robot answering the call claims it on its way, so that no other robot answers
    cmd.rab_send = true;
    cmd.rab = encode(claim_message(static_cast<std::uint8_t>(in.id), m.answering));
  }
  // guided departure: a guide's light carries its hop count to the founder instead
  if (cmd.led == Led::kCyan) cmd.tag = m.explore_leg == ExploreLeg::kLead ? 0 : m.guide_hops;
}

}  // namespace swarmpath::sim
