// SPDX-License-Identifier: MIT
// What a path-formation robot makes of its camera, its medium and its position each tick (SPEC
// §2.1, §2.3): the lights that matter to its rows, and its beliefs about the references it tracks
// (T_lost debounce, last positions), where it last saw the chain, how long it has waited. It
// perceives only: it changes no state and no leg.
#pragma once

#include "pf_memory.hpp"
#include "sim/params.hpp"
#include "sim/percept.hpp"

namespace swarmpath::sim {

/// What the robot makes of this tick's camera blobs (computed once, before the guards).
struct PfSight {
  const Blob* goal = nullptr;      ///< the goal beacon, when visible
  const Blob* nest = nullptr;      ///< the nest beacon, when visible
  const Blob* red_near = nullptr;  ///< the nearest RED robot within d_detect
  const Blob* lure = nullptr;      ///< the goal, or else the nearest RED robot, within R_vis
  const Blob* red_nearer_nest =
      nullptr;  ///< forming: the RED robot in view nearest the nest, if nearer than the target
  const Blob* my_subnest = nullptr;    ///< the nearest BLUE robot advertising me as its parent
  const Blob* guide = nullptr;         ///< follower: the CYAN robot in view fewest hops from the founder
  const Blob* forming_link = nullptr;  ///< seek_tip: the WHITE (forming) robot in view nearest the nest
  const Blob* grandparent = nullptr;   ///< bypass: the parent's parent (RED or the goal) within d_sub + 10 cm
  const Blob* heir = nullptr;          ///< relink_recovery: the parent is ORANGE; its own parent, in view
  const Blob* gap_heir = nullptr;      ///< chain_repair: the parent gone, the robot its light named, in view
  bool bypassed = false;               ///< bypass: every robot that named me now names another, one my parent
  double other_chain_cm = 1e9;   ///< forming: the nearest chain light (goal, RED..BROWN) but the target [cm]
  bool recovery_near = false;    ///< an ORANGE robot within r_rec
  bool forming_in_view = false;  ///< a WHITE (subgoal-forming) robot within R_vis
  bool goal_claimed = false;     ///< single_child: a robot in view forms from the goal or has it as parent
  bool may_form = true;          ///< this tick's draw of p_form (one at a time)
  Vec2 repulsion;                ///< R (SPEC §2.1), robot frame
  double nest_distance_cm = 0;   ///< from the positioning sensor
};

/// Everything a guard or an action may read.
struct PfContext {
  const Percept& in;
  const Params& p;
  const PfMemory& m;
  const PfSight& sight;
  Vec2 nest;                ///< the nest's global position [m]
  bool on_trail = false;    ///< heading home along its own breadcrumbs
  bool went_round = false;  ///< its way on this trip followed an obstacle's edge
};

/// Reads the camera and the medium into `sight` and updates the robot's beliefs in `m`: the tracked
/// references, the sighting, the counters of rows #3 and T10-T12.
void pf_perceive(const Percept& in, const Params& p, Vec2 nest, PfMemory& m, PfSight& sight);

/// Global position of a blob [m].
Vec2 blob_position(const Pose& pose, const Blob& b);

/// The blob of one emitter this tick, if in view.
const Blob* blob_of(const Percept& in, int emitter);

/// A reference to follow from now on: the robot or beacon `b`, seen now.
Tracked follow(const Blob& b, const Pose& pose);

/// T_lost: a reference out of view for T_lost ticks (or none) is lost.
bool lost(const Tracked& t, const Params& p);

/// Robot-frame position of a reference [cm].
Vec2 local_cm(const Pose& pose, const Tracked& t);

}  // namespace swarmpath::sim
