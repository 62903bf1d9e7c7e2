// SPDX-License-Identifier: MIT
// chain_repair [R]: a broken chain mends itself. A chain robot notices that a neighbour's light has
// gone (dark: it failed; or no longer a chain link's colour) for T_repair ticks. Its parent gone, it
// re-links to the robot the parent's light named as its own parent (the goal, or the next link
// goalward) when that one is in view, else it leaves the chain (home, and out again to the tip), and
// its own children notice the same in turn; its child gone, it turns RED again: the chain's tip,
// from which the chain re-forms toward the nest (rows #18-#20).
#pragma once

#include "pf_perception.hpp"
#include "sim/percept.hpp"

namespace swarmpath::sim {

/// Counts how long the parent and the child have been gone, remembers whom the parent's light names
/// (its own parent, the heir of a gone parent), and finds that heir in view.
void perceive_gaps(const Percept& in, const Params& p, PfMemory& m, PfSight& sight);

// guards (rows #18-#20)
bool parent_gone_heir_in_view(const PfContext& c);  ///< #18: re-link over the gap
bool parent_gone(const PfContext& c);               ///< #19: leave the chain
bool child_gone(const PfContext& c);                ///< #20: the chain's tip again

// actions
void relink_over_gap(const PfContext& c, PfMemory& m);
void leave_broken_chain(const PfContext& c, PfMemory& m);
void become_tip(const PfContext& c, PfMemory& m);

}  // namespace swarmpath::sim
