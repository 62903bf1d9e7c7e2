// SPDX-License-Identifier: MIT
// The chain's links (SPEC §2.3 rows #9, #14-#17, §2.1 neighbour identity): who claims which subgoal
// (single_child), which sub-nest is a subgoal's own child, and how a link is mended when a parent
// is skipped, never turns, or breaks off; what a chain robot advertises on its light and the medium.
#pragma once

#include "colours.hpp"
#include "pf_perception.hpp"
#include "sim/percept.hpp"
#include "ta_protocol.hpp"

namespace swarmpath::sim {

struct RobotMemory;

/// single_child [R]: what robots claim, the goal or a subgoal: a WHITE robot forming from it, or a
/// chain robot advertising it as its parent, seen (vision + ID tags) or heard on the range-and-bearing
/// medium (3 m, past the camera's R_vis). Gathered once per tick.
struct Claims {
  IdSet robots;
  bool goal = false;

  void add(int emitter) {
    if (emitter == kGoalEmitter) goal = true;
    if (emitter >= 0 && emitter <= 255) robots.insert(static_cast<std::uint8_t>(emitter));
  }

  bool has(int emitter) const {
    if (emitter == kGoalEmitter) return goal;
    return emitter >= 0 && emitter <= 255 && robots.contains(static_cast<std::uint8_t>(emitter));
  }
};

/// Calls f(robot, named) for every robot this tick that names a target or parent: a chain robot's or
/// forming robot's light tag (not a recovery robot's), and claims on the medium.
template <typename F>
void for_each_naming(const Percept& in, F&& f) {
  for (const Blob& b : in.blobs) {
    if (b.emitter < 0 || b.tag == kNobody) continue;
    if (is_path_colour(b.color) && b.color != Led::kOrange) f(b.emitter, b.tag);
  }
  for_each_claim_heard(in.rab, f);
}

Claims gather_claims(const Percept& in);

/// single_child [R]: the RED subgoal in view, nearest first, that no robot in view or on the
/// medium names as its target or parent: the end of a chain, where the next link goes.
const Blob* free_subgoal_in_view(const Percept& in);

/// chain_bypass [R]: the parent's parent in view (row #15) and whether this subgoal was skipped (#16).
void perceive_bypass(const Percept& in, const Params& p, PfMemory& m, const Claims& claims, PfSight& sight);

/// leaf_in_fan [R] (row #21): a chain light in view that is neither the parent nor the parent's parent
/// (the tag the parent's light carries): another branch, so this subgoal stands in a fan.
bool sees_another_branch(const Percept& in, const PfMemory& m);

/// relink_recovery [R]: the parent turned RECOVERY; its own parent, the tag its light carries, in view.
void perceive_heir(const Percept& in, const PfMemory& m, PfSight& sight);

// guards (rows #9, #14-#17)
bool sees_nest(const PfContext& c);          ///< #9a, label g: the nest beacon in view
bool sees_own_sub_nest(const PfContext& c);  ///< #9b, label g: a SUB_NEST that names me its parent
bool orphaned(const PfContext& c);           ///< #14, revert_orphans: the parent lost
bool sees_grandparent(const PfContext& c);   ///< #15, chain_bypass
bool bypassed(const PfContext& c);           ///< #16, chain_bypass
bool heir_in_view(const PfContext& c);       ///< #17, relink_recovery
bool leaf_unextended(const PfContext& c);    ///< #21, T_leaf

// actions
void child_is_nest(const PfContext& c, PfMemory& m);
void child_is_sub_nest(const PfContext& c, PfMemory& m);
void grandparent_becomes_parent(const PfContext& c, PfMemory& m);
void heir_becomes_parent(const PfContext& c, PfMemory& m);
void leave_chain(const PfContext& c, PfMemory& m);

/// SUB_NEST (LED blue): waits for its parent to be done (row #11), closing in on one out of view
/// (seek_hidden_reference) or one broken off (relink_recovery).
Command wait_for_parent(const Percept& in, const Params& p, RobotMemory& mem);

/// What the robot advertises: its light's tag (its parent, its target while forming, a guide's hop
/// count) and, single_child, its claim on the medium (with recruit_call's flag when it calls).
void advertise_links(const Percept& in, const Params& p, const PfMemory& m, Command& cmd);

}  // namespace swarmpath::sim
