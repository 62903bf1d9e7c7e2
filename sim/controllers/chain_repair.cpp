// SPDX-License-Identifier: MIT
#include "chain_repair.hpp"

namespace swarmpath::sim {

namespace {

// a chain link's light (SPEC §2.2): RED through BROWN; WHITE, ORANGE, dark and the others are no link
bool link_light(Led c) {
  return c == Led::kRed || c == Led::kMagenta || c == Led::kBlue || c == Led::kPurple || c == Led::kBrown;
}

// a neighbour robot is gone this tick: out of view, or in view with a light that is no link
bool gone_now(const Tracked& t) { return t.id >= 0 && (!t.visible || !link_light(t.color)); }

// the states whose robots stand still in the chain and watch its links (the aligning ones have
// row #13 for a reference lost)
bool watches_links(PfState s) {
  return s == PfState::kSubgoal || s == PfState::kSubNest || s == PfState::kPathDone;
}

}  // namespace

void perceive_gaps(const Percept& in, const Params& p, PfMemory& m, PfSight& sight) {
  if (!watches_links(m.state)) {
    m.parent_gone = 0;
    m.child_gone = 0;
    return;
  }
  // whom the parent's light names: its own parent (the tag of a chain robot's light, SPEC §2.1)
  if (m.parent.id >= 0 && m.parent.visible && link_light(m.parent.color)) {
    if (const Blob* b = blob_of(in, m.parent.id)) m.grandparent = b->tag;
  }
  m.parent_gone = gone_now(m.parent) ? m.parent_gone + 1 : 0;
  m.child_gone = m.state != PfState::kSubgoal && gone_now(m.child) ? m.child_gone + 1 : 0;
  if (static_cast<double>(m.parent_gone) < p.t_repair || m.grandparent == kNobody || m.grandparent == in.id)
    return;
  for (const Blob& b : in.blobs) {
    if (b.emitter == m.grandparent && (b.emitter == kGoalEmitter || link_light(b.color)) && b.tag != in.id)
      sight.gap_heir = &b;
  }
}

bool parent_gone_heir_in_view(const PfContext& c) { return c.p.chain_repair && c.sight.gap_heir != nullptr; }

bool parent_gone(const PfContext& c) {
  return c.p.chain_repair && static_cast<double>(c.m.parent_gone) >= c.p.t_repair;
}

bool child_gone(const PfContext& c) {
  return c.p.chain_repair && static_cast<double>(c.m.child_gone) >= c.p.t_repair;
}

void relink_over_gap(const PfContext& c, PfMemory& m) {
  m.parent = follow(*c.sight.gap_heir, c.in.pose);
  m.grandparent = kNobody;
  m.parent_gone = 0;
}

// row #19: like row #16, home and out again to the tip; the child, the neighbour nestward, sees
// this robot's light turn and does the same in turn
void leave_broken_chain(const PfContext&, PfMemory& m) {
  m.parent = Tracked{};
  m.child = Tracked{};
  m.target = Tracked{};
  m.grandparent = kNobody;
  m.parent_gone = 0;
  m.child_gone = 0;
}

void become_tip(const PfContext&, PfMemory& m) {
  m.child = Tracked{};
  m.child_gone = 0;
}

}  // namespace swarmpath::sim
