// SPDX-License-Identifier: MIT
#include "pf_perception.hpp"

#include "chain_links.hpp"
#include "chain_repair.hpp"
#include "colours.hpp"
#include "ta_protocol.hpp"
#include "units.hpp"

namespace swarmpath::sim {

Vec2 blob_position(const Pose& pose, const Blob& b) {
  return pose.p + (b.distance_cm * kCm) * pose.to_world(b.dir);
}

const Blob* blob_of(const Percept& in, int emitter) {
  for (const Blob& b : in.blobs) {
    if (b.emitter == emitter) return &b;
  }
  return nullptr;
}

Tracked follow(const Blob& b, const Pose& pose) {
  Tracked t;
  t.id = b.emitter;
  t.last_seen = blob_position(pose, b);
  t.visible = true;
  t.color = b.color;
  return t;
}

bool lost(const Tracked& t, const Params& p) { return !t.valid() || t.unseen >= static_cast<int>(p.t_lost); }

Vec2 local_cm(const Pose& pose, const Tracked& t) {
  return (1.0 / kCm) * pose.to_local(t.last_seen - pose.p);
}

namespace {

// colours a reference may show, for vision-only tracking
bool allowed_for(const Tracked& t, Led c, bool nest_side) {
  if (t.id == kGoalEmitter) return c == Led::kYellow;
  if (t.id == kNestEmitter) return false;  // beacons are matched by emitter below
  if (nest_side) return c == Led::kBlue || c == Led::kMagenta || c == Led::kPurple || c == Led::kBrown;
  return c == Led::kRed || c == Led::kMagenta || c == Led::kBlue || c == Led::kPurple || c == Led::kBrown ||
         c == Led::kWhite;
}

// Updates one tracked reference from the blobs: by emitter id (vision + ID), or by the nearest
// blob of an allowed colour within the gate around its last position (vision only).
void track(Tracked& t, const Percept& in, const Params& p, bool nest_side) {
  if (!t.valid()) return;
  const Blob* seen = nullptr;
  const bool beacon = t.id == kNestEmitter || t.id == kGoalEmitter;
  if (beacon || p.neighbour_id == NeighbourId::kVisionId) {
    seen = blob_of(in, t.id);
  } else {
    double best = p.track_gate * kCm;
    for (const Blob& b : in.blobs) {
      if (!allowed_for(t, b.color, nest_side)) continue;
      const double d = dist(blob_position(in.pose, b), t.last_seen);
      if (d <= best) {
        best = d;
        seen = &b;
      }
    }
  }
  t.visible = seen != nullptr;
  if (seen == nullptr) {
    ++t.unseen;
    return;
  }
  t.unseen = 0;
  t.id = seen->emitter;
  t.color = seen->color;
  t.last_seen = blob_position(in.pose, *seen);
}

// the lights of this tick: beacons, guides, lures, sub-nests, forming robots, repulsion
void read_lights(const Percept& in, const Params& p, Vec2 nest, const PfMemory& m, const Claims& claims,
                 PfSight& sight) {
  double red_best = p.d_detect;
  double lure_best = p.r_vis + 1.0;
  double sub_best = p.r_vis + 1.0;
  // R: a follower takes only a guide fewer hops from the founder than itself (a fresh one counts
  // kMaxGuideHops), so that hop counts only go down and no followers follow each other in a loop
  int guide_hops = m.guide_hops - 1;
  double guide_far = -1.0;
  double forming_to_nest = 1e18;
  const bool following =
      m.explore_leg == ExploreLeg::kFollowThenWalk || m.explore_leg == ExploreLeg::kFollowThenSighting;
  const bool seeks_tip = claims_links(p, m) && p.seek_tip;
  for (const Blob& b : in.blobs) {
    if (following && b.color == Led::kCyan && b.emitter >= 0) {
      // the light's tag is its hop count to the founder (the founder at the nest advertises none)
      const int hops = b.tag == kNobody ? 0 : b.tag;
      const double to_nest = dist(blob_position(in.pose, b), nest);
      if (hops >= 0 && (hops < guide_hops || (hops == guide_hops && to_nest > guide_far))) {
        guide_hops = hops;
        guide_far = to_nest;
        sight.guide = &b;
      }
      continue;
    }
    if (b.emitter == kGoalEmitter) {
      sight.goal = &b;
      sight.goal_claimed = claims.has(kGoalEmitter);
      if (!sight.goal_claimed) {
        sight.lure = &b;
        lure_best = -1.0;  // the goal beats any subgoal
      }
      continue;
    }
    if (b.emitter == kNestEmitter) {
      sight.nest = &b;
      continue;
    }
    const bool free_red = b.color == Led::kRed && !claims.has(b.emitter);
    if (free_red && b.distance_cm <= red_best) {
      red_best = b.distance_cm;
      sight.red_near = &b;
    }
    if (free_red && b.distance_cm < lure_best) {
      lure_best = b.distance_cm;
      sight.lure = &b;
    }
    const bool mine = p.neighbour_id == NeighbourId::kVisionId ? b.tag == in.id : b.emitter != m.parent.id;
    if (b.color == Led::kBlue && mine && b.distance_cm < sub_best) {
      sub_best = b.distance_cm;
      sight.my_subnest = &b;
    }
    if (b.color == Led::kWhite && b.emitter >= 0) sight.forming_in_view = true;
    // R (seek_tip): the forming (WHITE) robot nearest the nest, where the next free subgoal will stand
    if (seeks_tip && b.color == Led::kWhite && b.emitter >= 0) {
      const double to_nest = dist(blob_position(in.pose, b), nest);
      if (to_nest < forming_to_nest) {
        forming_to_nest = to_nest;
        sight.forming_link = &b;
      }
    }
    // R: recovery robots repel everyone; explorers keep clear of path robots too (label e)
    const bool repels =
        b.color == Led::kOrange || (m.state == PfState::kExploring && repels_explorers(b.color));
    if (repels && b.distance_cm <= p.r_rec) {
      sight.repulsion -= p.k_rec * (1.0 - b.distance_cm / p.r_rec) * b.dir;
      if (b.color == Led::kOrange) sight.recovery_near = true;
    }
  }
}

// site fidelity: where the chain needs robots: the RED subgoal in view nearest the nest (its tip),
// or else the goal
void remember_sighting(const Percept& in, Vec2 nest, const PfSight& sight, PfMemory& m) {
  bool seen = false;
  double tip_to_nest = 1e18;
  for (const Blob& b : in.blobs) {
    if (b.color != Led::kRed) continue;
    const Vec2 at = blob_position(in.pose, b);
    if (dist(at, nest) < tip_to_nest) {
      tip_to_nest = dist(at, nest);
      m.sighting = at;
      seen = true;
    }
  }
  if (!seen && sight.goal != nullptr) {
    m.sighting = blob_position(in.pose, *sight.goal);
    seen = true;
  }
  if (seen) {
    m.has_sighting = true;
    m.sighted_this_trip = true;
  }
}

// R (retarget_tip): another RED light in view names this one as its parent: a link inside the chain
bool named_as_parent(const Percept& in, int emitter) {
  for (const Blob& o : in.blobs) {
    if (o.color == Led::kRed && o.emitter >= 0 && o.emitter != emitter && o.tag == emitter) return true;
  }
  return false;
}

// while forming: the free RED subgoal in view that lies nearest the nest, if it is nearer than the
// target (the chain's tip, so that the new subgoal extends it)
const Blob* red_nearer_nest(const Percept& in, const Params& p, Vec2 nest, const PfMemory& m,
                            const Claims& claims) {
  if (p.tip_by_links && p.neighbour_id == NeighbourId::kVisionId) {
    // R (tip_by_links): the target's child, by the parent its light names; down the chain to its tip
    const Blob* child = nullptr;
    for (const Blob& b : in.blobs) {
      if (b.color != Led::kRed || b.emitter < 0 || b.emitter == m.target.id || b.tag != m.target.id) continue;
      if (claims.has(b.emitter)) continue;
      if (child == nullptr || b.distance_cm < child->distance_cm) child = &b;
    }
    return child;
  }
  constexpr double kMargin = 0.2;  // [m]
  double best = dist(m.target.last_seen, nest) - kMargin;
  const Blob* found = nullptr;
  // R (retarget_tip): where the chain bends away from the nest, a link inside it lies nearer the nest
  // than its tip; only the tips (no RED light in view names them as parent) extend the chain
  const bool tips_only = p.retarget_tip && p.neighbour_id == NeighbourId::kVisionId;
  for (const Blob& b : in.blobs) {
    if (b.color != Led::kRed || b.emitter == m.target.id) continue;
    if (claims.has(b.emitter)) continue;
    const double to_nest = dist(blob_position(in.pose, b), nest);
    if (to_nest >= best) continue;
    // R (retarget_tip): asked only of a RED that would win
    if (tips_only && b.emitter >= 0 && named_as_parent(in, b.emitter)) continue;
    best = to_nest;
    found = &b;
  }
  return found;
}

}  // namespace

void pf_perceive(const Percept& in, const Params& p, Vec2 nest, PfMemory& m, PfSight& sight) {
  sight = PfSight{};
  Claims claims;
  if (claims_links(p, m)) claims = gather_claims(in);
  sight.nest_distance_cm = dist(in.pose.p, nest) / kCm;
  read_lights(in, p, nest, m, claims, sight);
  track(m.target, in, p, false);
  track(m.parent, in, p, false);
  track(m.child, in, p, true);
  // chain_bypass [R]: every RED subgoal of its mode; the robots naming it are those the lights and the
  // medium tell (an allocated one's claims, gathered above, are the same)
  const bool bypass = by_mode(m.role, p.chain_bypass_pf, p.chain_bypass);
  if (bypass && m.state == PfState::kSubgoal)
    perceive_bypass(in, p, m, claims_links(p, m) ? claims : gather_claims(in), sight);
  if (p.relink_recovery && m.state == PfState::kSubNest) perceive_heir(in, m, sight);
  if (p.chain_repair) perceive_gaps(in, p, m, sight);
  // recruit_call [R]: how long this subgoal has gone without a robot forming from it or naming it
  m.unclaimed = calls_links(p, m) && m.state == PfState::kSubgoal && !claims.has(in.id) ? m.unclaimed + 1 : 0;
  // refound_starved [R]: its child left to fetch robots; it does not leave itself meanwhile
  if (p.refound_starved && m.state == PfState::kSubgoal) {
    for (const RabMessage& r : in.rab) {
      if (fetch_for(decode(r.data)) == in.id)
        m.help_until = in.tick + static_cast<std::int64_t>(3.0 * p.t_refound);
    }
  }
  // T_leaf [R]: how long this subgoal has stood without a robot in view naming it (a leaf nobody extends)
  // T_leaf_allocated [R]: the same count for an allocated subgoal, only while it stands in a fan
  const bool allocated = p.t_leaf_allocated > 0.0 && m.role == PfRole::kAllocated;
  if (m.state == PfState::kSubgoal && (allocated || (p.t_leaf > 0.0 && m.role == PfRole::kSwarm))) {
    bool named = false;
    for_each_naming(in, [&](int, int n) { named = named || n == in.id; });
    if (named) {
      m.childless = 0;
    } else if ((!allocated && !p.leaf_in_fan) || sees_another_branch(in, m)) {
      ++m.childless;
    }
  } else {
    m.childless = 0;
  }
  remember_sighting(in, nest, sight, m);
  if (m.state == PfState::kSubgoalForming && m.target.valid())
    sight.red_nearer_nest = red_nearer_nest(in, p, nest, m, claims);
  if (m.state == PfState::kSubgoalForming && m.target.valid()) {
    for (const Blob& b : in.blobs) {
      if (b.emitter == m.target.id) continue;
      const bool chain = b.emitter == kGoalEmitter || (b.emitter >= 0 && is_path_colour(b.color) &&
                                                       b.color != Led::kWhite && b.color != Led::kOrange);
      if (chain && b.distance_cm < sight.other_chain_cm) sight.other_chain_cm = b.distance_cm;
    }
  }
  m.nest_ticks =
      (m.state == PfState::kReturnToNest && sight.nest_distance_cm <= p.r_nest_reach) ? m.nest_ticks + 1 : 0;
}

}  // namespace swarmpath::sim
