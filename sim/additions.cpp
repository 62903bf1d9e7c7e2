// SPDX-License-Identifier: MIT
#include "additions.hpp"

#include <algorithm>
#include <array>

namespace swarmpath::sim {

namespace {

constexpr auto kBoth = AdditionScope::kBoth;
constexpr auto kTa = AdditionScope::kTaskAllocation;

// clang-format off
// name, title, SPEC rule, scope, off settings, the additions it acts only beside
const std::array kAdditions{
  // sensing
  Addition{"led_ring", "a robot is seen by its LED ring, not only its centre", "§1.3 camera", kBoth, {{{"led_ring", 0}}}, {}},
  // exploring
  Addition{"away_decay", "explorers back from fruitless trips lean less on the away field", "§2.1 fields, #4", kBoth, {{{"away_decay", 1}}}, {}},
  Addition{"w_seek", "explorers steer to the goal or a RED light in view", "§2.1, #1", kBoth, {{{"w_seek", 0}}}, {}},
  Addition{"T_trap", "edge following out of a field's minima", "§2.1 fields", kBoth, {{{"T_trap", 0}}}, {}},
  Addition{"site_fidelity", "a trip starts at the last sighting of the chain", "§2.3 #2", kBoth, {{{"site_fidelity", 0}}}, {}},
  Addition{"travel_cap", "travel to a sighting ends the trip after 3 budgets", "§2.3 #2", kBoth, {{{"travel_cap", 0}}}, {"site_fidelity"}},
  Addition{"return_finds", "a robot going home takes the goal it finds", "§2.3 #1h, §2.6 T2", kBoth, {{{"return_finds", 0}}}, {}},
  Addition{"leaf_in_fan", "T_leaf counts only while another branch is in view", "§2.3 #21", kBoth, {{{"leaf_in_fan", 0}}}, {"T_leaf"}},
  Addition{"share_sighting", "robots at the nest tell each other where they saw the chain", "§2.3 #2, #4", kBoth, {{{"share_sighting", 0}}}, {"site_fidelity"}},
  Addition{"resume_search", "a trip after a fruitless one explores on from where that one ended", "§2.1 exploring, #4", kBoth, {{{"resume_search", 0}}}, {}},
  Addition{"walk_way", "a trip to the sighting walks the way it was seen from", "§2.3 #2", kBoth, {{{"walk_way", 0}}}, {"site_fidelity"}},
  Addition{"share_way", "robots at the nest tell the way to where they saw the chain", "§2.3 #2, #4", kBoth, {{{"share_way", 0}}}, {"share_sighting", "site_fidelity"}},
  Addition{"lead_way", "the founder tells and leads along the way it found the goal", "§2.6 T5, T9", kTa, {{{"lead_way", 0}}}, {"share_goal", "site_fidelity"}},
  Addition{"route_to_sighting", "a trip to the sighting retraces the way it was seen from", "§2.3 #2", kBoth, {{{"route_to_sighting", 0}}}, {"site_fidelity", "T_trap"}},
  Addition{"return_lured", "a scout going home turns to the goal it sees", "§2.6 T2", kTa, {{{"return_lured", 0}}}, {"return_finds"}},
  // going home along the breadcrumbs
  Addition{"trail_home", "a robot going home that the field traps retraces its trail", "§2.1 fields, #3", kBoth, {{{"trail_home", 0}}}, {"T_trap"}},
  Addition{"skip_blocked_crumbs", "a crumb a robot cannot reach is passed over", "§2.1 fields", kBoth, {{{"skip_blocked_crumbs", 0}}}, {"T_trap", "trail_home"}},
  // forming a subgoal
  Addition{"backoff_trail", "forming robots back off along their own way out", "§2.3 #5", kBoth, {{{"backoff_trail", 0}}}, {}},
  Addition{"retarget_nearer", "a forming robot re-targets to a RED nearer the nest", "§2.3 #5r", kBoth, {{{"retarget_nearer", 0}}}, {}},
  Addition{"retarget_tip", "a forming robot re-targets only to a tip of the chain", "§2.3 #5r", kBoth, {{{"retarget_tip", 0}}}, {"retarget_nearer"}},
  Addition{"subgoal_nestward", "subgoals form only nearer the nest than their target", "§2.3 #5, #6b", kBoth, {{{"subgoal_nestward", 0}}}, {}},
  Addition{"form_retries", "a robot that lost its target goes home and tries again", "§2.3 #7, #8b", kBoth, {{{"form_retries", 0}}}, {}},
  Addition{"T_leaf", "a RED leaf nobody extends leaves the chain and goes home", "§2.3 #21", kBoth, {{{"T_leaf", 0}}}, {}},
  Addition{"backoff_far_spot", "the goal found from its far side: back off to the spot", "§2.3 #5", kBoth, {{{"backoff_far_spot", 0}}}, {}},
  Addition{"spot_crumb_tol", "the spot is a crumb of the robot's own way out", "§2.3 #5", kBoth, {{{"spot_crumb_tol", 0}}}, {"backoff_far_spot"}},
  Addition{"trail_nestward", "falling back from the spot, the trail starts nestward", "§2.3 #5", kBoth, {{{"trail_nestward", 0}}}, {"backoff_far_spot", "T_trap"}},
  Addition{"spot_on_way", "the spot is where the robot's own way out first came that near", "§2.3 #5, #6b", kTa, {{{"spot_on_way", 0}}}, {"ta_backoff_spot"}},
  Addition{"spot_on_way_pf", "the same in path formation without task allocation", "§2.3 #5, #6b", kBoth, {{{"spot_on_way_pf", 0}}}, {"backoff_far_spot"}},
  Addition{"link_outward_pf", "path formation: on its way out, a subgoal where the target is the nearest chain light", "§2.3 #5, #6b", kBoth, {{{"link_outward_pf", 0}}}, {"subgoal_nestward"}},
  Addition{"anywhere_after_edge", "a way that went round an obstacle: a subgoal anywhere on it", "§2.3 #5, #6b", kTa, {{{"anywhere_after_edge", 0}}}, {"subgoal_nestward", "T_trap"}},
  Addition{"anywhere_after_edge_pf", "the same in path formation without task allocation", "§2.3 #5, #6b", kBoth, {{{"anywhere_after_edge_pf", 0}}}, {"subgoal_nestward", "T_trap"}},
  Addition{"way_after_edge", "the spot on the way only after an obstacle's edge on this trip", "§2.3 #5, #6b", kBoth, {{{"way_after_edge", 0}}}, {"spot_on_way", "T_trap"}},
  // aligning and the chain's links
  Addition{"align_keep_view", "an aligning robot keeps both references in view", "§2.4, #10, #13", kBoth, {{{"align_keep_view", 0}}}, {}},
  Addition{"seek_hidden_reference", "a reference out of view is looked for where it was", "§2.3 #11, #13", kBoth, {{{"seek_hidden_reference", 0}}}, {"align_keep_view"}},
  Addition{"relink_recovery", "a SUB_NEST takes a RECOVERY parent's parent", "§2.3 #17", kBoth, {{{"relink_recovery", 0}}}, {}},
  Addition{"chain_bypass", "a subgoal that sees its parent's parent skips its parent", "§2.3 #15, #16", kTa, {{{"chain_bypass", 0}}}, {}},
  Addition{"chain_bypass_pf", "the same in path formation without task allocation", "§2.3 #15, #16", kBoth, {{{"chain_bypass_pf", 0}}}, {}},
  Addition{"chain_repair", "a chain robot whose neighbour's light is gone mends the chain", "§2.3 #18-#20", kBoth, {{{"chain_repair", 0}}}, {}},
  // task allocation
  Addition{"late_founder_rests", "a founder that hears ALLOC_DONE first rests", "§2.6 T7f", kTa, {{{"late_founder_rests", 0}}}, {}},
  Addition{"resend_lost_ack", "a repeated JOIN is ACKed again, not counted", "§2.6 protocol", kTa, {{{"resend_lost_ack", 0}}}, {}},
  Addition{"founder_seniority", "a founder that has ACKed outranks a smaller id", "§2.6 T8", kTa, {{{"founder_seniority", 0}}}, {}},
  Addition{"founder_wait", "the founder runs the protocol at the crowd's rim", "§2.6 T4", kTa, {{{"founder_wait", 0.5}}}, {}},
  Addition{"T_founder_wait", "the founder stops allocating after 300 ticks without a JOIN", "§2.6 T9", kTa, {{{"T_founder_wait", 0}}}, {}},
  Addition{"guided_departure", "the allocated robots follow the founder out", "§2.6 T5, T9", kTa, {{{"guided_departure", 0}}}, {"site_fidelity"}},
  Addition{"share_goal", "the ACK carries where the goal was seen", "§2.6 protocol, T5", kTa, {{{"share_goal", 0}}}, {"site_fidelity"}},
  Addition{"depart_gap", "allocated robots leave one after another", "§2.6 T5", kTa, {{{"depart_gap", 0}}}, {}},
  Addition{"nest_crowd", "no edge following or falling back among the robots at the nest", "§2.1 fields", kBoth, {{{"nest_crowd", 0}}}, {"T_trap"}},
  Addition{"way_home_leg", "a kept way goes on along the leg walked home by the field", "§2.6 T5, T9", kTa, {{{"way_home_leg", 0}}}, {"lead_way"}},
  Addition{"founder_retrace", "a founder that cannot reach the nest straight goes back along its way", "§2.6 T4", kTa, {{{"founder_retrace", 0}}}, {}},
  Addition{"dm_rescout", "a decision maker that no founder came to scouts again", "§2.6 T6", kTa, {{{"dm_rescout", 0}}}, {}},
  Addition{"founder_in_crowd", "a founder held off the nest by its crowd asks from where it stands", "§2.6 T4", kTa, {{{"founder_in_crowd", 0}}}, {"nest_crowd"}},
  Addition{"give_way", "resting robots give way to a robot pressing on them", "§2.6 T6", kTa, {{{"give_way", 0}}}, {}},
  Addition{"single_child", "allocated explorers attach only to an unclaimed subgoal", "§2.3 #1", kTa, {{{"single_child", 0}}}, {}},
  Addition{"ta_backoff_spot", "allocated robots back off to the spot toward the nest", "§2.3 #5", kTa, {{{"ta_backoff_spot", 0}}}, {}},
  Addition{"seek_tip", "an allocated explorer waits by a forming robot", "§2.3 #1", kTa, {{{"seek_tip", 0}}}, {"single_child"}},
  Addition{"sighting_returns", "nothing free at the sighting: home", "§2.3 #2", kTa, {{{"sighting_returns", 0}}}, {"single_child", "site_fidelity"}},
  Addition{"rest_recruit", "a resting robot joins a chain's free end in view", "§2.6 T10", kTa, {{{"rest_recruit", 0}}}, {}},
  Addition{"recruit_call", "a chain's end calls resting robots on the medium", "§2.6 T10", kTa, {{{"recruit_call", 0}}}, {"rest_recruit", "single_child"}},
  Addition{"refound_starved", "a chain's end fetches more robots (a second allocation)", "§2.6 T11, T12", kTa, {{{"refound_starved", 0}}}, {"recruit_call"}},
  Addition{"T_leaf_allocated", "an allocated leaf in a fan leaves the chain and goes home", "§2.3 #21", kTa, {{{"T_leaf_allocated", 0}}}, {}},
};

// additions under trial: registered so that the ablation can measure them, off in the default
// (docs/detours.md)
constexpr std::array<std::string_view, 10> kOffInDefault{
    "spot_on_way_pf", "leaf_in_fan",      "route_to_sighting", "walk_way",         "share_way",
    "founder_retrace", "founder_in_crowd", "way_home_leg",      "T_leaf_allocated", "link_outward_pf"};

// SPEC §7's defaults where the code's differ (docs/CHOICES.md: the speed and the allocation)
constexpr std::array kSpecDefaults{
  Setting{"v_max", 10},            // row 7 [A]
  Setting{"delta_open", 5},        // row 33
  Setting{"delta_obstacle", 15},   // row 34
  Setting{"delta_complex", 20},    // row 35
};

// clang-format on

void set(Params& p, const Setting& s) {
  const ParamInfo* info = find_param(s.key);
  if (info != nullptr) set_value(p, *info, s.value);
}

}  // namespace

std::span<const Addition> additions() { return kAdditions; }

bool in_default(const Addition& a) {
  return std::find(kOffInDefault.begin(), kOffInDefault.end(), a.name) == kOffInDefault.end();
}

const Addition* find_addition(std::string_view name) {
  for (const Addition& a : kAdditions) {
    if (a.name == name) return &a;
  }
  return nullptr;
}

void switch_off(Params& p, const Addition& a) {
  for (const Setting& s : a.off) {
    if (!s.key.empty()) set(p, s);
  }
}

void switch_on(Params& p, const Addition& a) {
  const Params defaults;
  for (const Setting& s : a.off) {
    const ParamInfo* info = s.key.empty() ? nullptr : find_param(s.key);
    // under trial (off in the default): the key's upper bound, true for a switch
    if (info != nullptr) set_value(p, *info, in_default(a) ? get_value(defaults, *info) : info->hi);
  }
  for (const std::string_view need : a.needs) {
    const Addition* other = need.empty() ? nullptr : find_addition(need);
    if (other != nullptr) switch_on(p, *other);
  }
}

bool is_on(const Params& p, const Addition& a) {
  for (const Setting& s : a.off) {
    const ParamInfo* info = s.key.empty() ? nullptr : find_param(s.key);
    if (info != nullptr && get_value(p, *info) != s.value) return true;
  }
  return false;
}

const Setting* spec_default(std::string_view key) {
  for (const Setting& s : kSpecDefaults) {
    if (s.key == key) return &s;
  }
  return nullptr;
}

Params paper_literal() {
  Params p;
  for (const Setting& s : kSpecDefaults) set(p, s);
  for (const Addition& a : kAdditions) switch_off(p, a);
  return p;
}

namespace {

bool same(const Params& a, const Params& b) {
  for (const ParamInfo& info : param_table()) {
    if (get_value(a, info) != get_value(b, info)) return false;
  }
  return true;
}

}  // namespace

std::string_view controller_name(const Params& p) {
  if (same(p, Params{})) return "default";
  if (same(p, paper_literal())) return "paper-literal";
  return "custom";
}

int additions_on(const Params& p) {
  int n = 0;
  for (const Addition& a : kAdditions) n += is_on(p, a) ? 1 : 0;
  return n;
}

}  // namespace swarmpath::sim
