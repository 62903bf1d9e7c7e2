// SPDX-License-Identifier: MIT
// Every tunable controller parameter of SPEC §7 (rows 1-42) in one struct, with a descriptor
// table (name, default, range, step, fixed tag) that the params files, the genome and the
// exporters all read. Units as in SPEC §7: cm, ticks (0.1 s), degrees.
#pragma once

#include <cstdint>
#include <iosfwd>
#include <span>
#include <string>
#include <string_view>
#include <variant>

namespace swarmpath::sim {

/// Row 36: where t in l = s*t (Eq. 1) comes from.
enum class TSource : std::uint8_t { kBudget, kElapsed };

/// Neighbour identity for chain tracking (SPEC §2.1): camera blobs carry the emitter's id, or
/// the robot tracks its reference's last global position (20 cm gate).
enum class NeighbourId : std::uint8_t { kVisionId, kVisionOnly };

struct Params {
  // paper thresholds (SPEC §2.3)
  double d_detect = 30;  ///< 1: goal/subgoal detection distance [cm]
  double d_sub = 70;     ///< 2: subgoal placement distance [cm]
  double r_vis = 100;    ///< 3: R_vis, camera range, also v in Eq. 2 [cm]
  double r_rec = 20;     ///< 4: recovery repulsion range [cm]
  double k_rec = 1.0;    ///< 5: recovery repulsion gain
  double t_lost = 3;     ///< 6: T_lost, invisibility debounce [ticks]
  // motion (SPEC §1.2, §2.1)
  double v_max = 20;        ///< 7: max wheel speed, also s in Eq. 1 [cm/s] (SPEC: 10 [A]; docs/CHOICES.md)
  double v_align = 0.5;     ///< 8: speed factor while aligning
  double theta_hard = 90;   ///< 9: hard-turn threshold [deg]
  double theta_soft = 70;   ///< 10: soft-turn threshold [deg]
  double theta_none = 10;   ///< 11: no-turn threshold [deg]
  double diff_angle = 5;    ///< 12: half-width of the diffusion go-straight cone [deg]
  double diff_delta = 0.1;  ///< 13: proximity magnitude treated as clear
  // exploration budget (SPEC §6.25)
  double t_explore0 = 1000;       ///< 14: T_explore0 [ticks]
  double dt_explore = 500;        ///< 15: dT_explore, additive growth per failed trip [ticks]
  double g_explore = 1.0;         ///< 16: multiplicative growth
  double t_explore_max = 8000;    ///< 17: T_explore_max [ticks]
  double w_away = 0.5;            ///< 18: weight of the away-from-nest field
  double w_rw = 0.5;              ///< 19: weight of the random-walk heading
  double p_turn = 0.02;           ///< 20: per-tick probability of a heading change
  double dphi_max = 45;           ///< 21: max heading change [deg]
  double t_rest = 50;             ///< 22: T_rest [ticks]
  double t_nest_search = 50;      ///< 23: T_nest_search [ticks]
  double r_nest_reach = 100;      ///< 24: R_nest_reach [cm]
  double t_form_timeout = 600;    ///< 25: SUBGOAL_FORMING stall guard [ticks]
  bool early_stop_in_rec = true;  ///< 26: rule #6 early stop near a recovery robot
  // alignment (SPEC §2.4)
  double e_tol = 5;             ///< 27: error-angle tolerance [deg]
  double d_tol = 3;             ///< 28: distance tolerance [cm]
  double t_align_max = 300;     ///< 29: alignment time-out [ticks]
  double lambda_mid = 0.0;      ///< 30: blend of the foot toward the midpoint
  double r_keep = 90;           ///< 31: max distance kept to each reference [cm]
  bool revert_orphans = false;  ///< 32: SUB_NEST/PATH_DONE revert to RED when the parent is lost
  // task allocation (SPEC §2.6, §2.7)
  double delta_open = 0;                ///< 33: delta for open environments [robots]
  double delta_obstacle = 0;            ///< 34: delta for obstacle environments [robots]
  double delta_complex = 0;             ///< 35: delta for complex environments [robots]
  TSource t_source = TSource::kBudget;  ///< 36: t in l = s*t
  double kappa = 1.2;                   ///< 37: allocated robots' budget = kappa * t_founder
  double n_min = 2;                     ///< 38: lower clamp on n [robots]
  bool founder_counts_self = true;      ///< 39: the founder is one of the n
  double t_done = 50;                   ///< 40: ticks DONE is broadcast
  double t_dm_wait = 3000;              ///< 41: decision-maker timeout [ticks]
  double d_arrive = 5;                  ///< 42: resting arrival tolerance [cm]
  // options outside the genome (SPEC §2.1, §7 "fixed experiment settings")
  NeighbourId neighbour_id = NeighbourId::kVisionId;
  double track_gate = 20;  ///< vision-only tracking gate [cm]

  // Behaviours beyond SPEC (additions): each is switched off by the value its help line names, and
  // genomes/paper-literal.toml switches every one off (sim/additions.hpp lists them with their SPEC rule).
  // sensing (SPEC §1.3)
  bool led_ring = true;  ///< a robot is seen when the line to its centre or to its LED ring's edge is clear
  // exploring (SPEC §2.1, §2.3 rows #1, #2)
  double away_decay = 0.7;          ///< row 18: w_away's factor per trip home without a sighting (1: none)
  double w_seek = 1.0;              ///< pull of an explorer toward the goal or RED light it sees (0: none)
  double t_trap = 100;              ///< ticks without progress before edge following and the trail (0: never)
  double trap_progress = 30;        ///< gain that counts as progress for T_trap [cm]
  double dead_end_traps = 20;       ///< a following without progress for this many T_trap turns back
  double t_follow = 2000;           ///< longest edge following [ticks]
  bool site_fidelity = true;        ///< start an exploration trip toward the last goal/subgoal sighting
  double travel_cap = 3;            ///< row #2: travel ends the trip after this many budgets (0: never)
  bool return_finds = true;         ///< row #1h: a robot going home takes the goal it finds within d_detect
  bool return_lured = true;         ///< TA, return_finds: a scout going home turns to the goal it sees
  bool form_one_at_a_time = false;  ///< row #1: no forming while a WHITE robot is in view (p_form per tick)
  double p_form = 0.1;              ///< form_one_at_a_time: per-tick probability of starting to form
  // going home along the breadcrumbs (path integration)
  bool trail_home = true;           ///< a robot going home that the field traps retraces its own trail
  bool skip_blocked_crumbs = true;  ///< a robot going home passes over a crumb it cannot reach in T_trap
  // forming a subgoal (SPEC §2.3 rows #5-#8)
  bool backoff_trail = true;  ///< a forming robot backs off along its own way from the nest (else the field)
  bool retarget_nearer = true;         ///< row #5r: a forming robot re-targets to a RED robot nearer the nest
  bool subgoal_nestward = true;        ///< rows #5, #6b: a subgoal forms only nearer the nest than its target
  double trail_slack = 45;             ///< subgoal_nestward, on its trail: how much farther it may stop [cm]
  bool anywhere_after_edge = true;     ///< TA: subgoal_nestward, on a trail that followed an edge: no bound
  bool anywhere_after_edge_pf = true;  ///< the same in path formation without task allocation
  bool backoff_spot = false;     ///< forming: back off to the spot d_sub from the target toward the nest
  bool backoff_far_spot = true;  ///< forming: back off to the spot when the goal was found from its far side
  double spot_crumb_tol = 15;    ///< the spot: a crumb of its way out this near d_sub + 5 cm [cm] (0: none)
  bool trail_nestward = true;    ///< from the spot back to its trail: nearer the nest than the target
  bool spot_on_way = true;       ///< TA: the spot: where its way out first came that near the target
  bool spot_on_way_pf = false;   ///< the same in path formation without task allocation
  bool way_after_edge = true;    ///< spot_on_way: only a way that followed an obstacle's edge
  bool tip_by_links = false;     ///< row #5r: re-target to the target's child (by links), not by distance
  bool retarget_tip = true;      ///< row #5r: re-target only to a RED no RED in view names as its parent
  bool link_outward = false;     ///< rows #5, #6b (task allocation): stop on its trail by the nearest light
  bool link_outward_pf = false;  ///< the same in path formation without task allocation
  double form_retries = 3;       ///< rows #7, #8b: a robot losing its target goes home, this often
  double t_leaf = 1500;          ///< row #21: a RED leaf nobody names this long goes home [ticks]
  bool leaf_in_fan = false;      ///< row #21: T_leaf counts only while another branch is in view
  double t_leaf_allocated = 0;   ///< row #21 (TA): an allocated leaf in a fan this long goes home [ticks]
  bool walk_way =
      false;  ///< site_fidelity: a trip to the sighting walks the way it was seen from, from the start
  bool share_way = false;          ///< share_sighting: the teller tells its own way there, corner by corner
  bool route_to_sighting = false;  ///< site_fidelity: travel to the sighting along the way it was seen from
  bool resume_search = true;       ///< #4: a trip after a fruitless one starts where that one ended
  bool lead_way = true;         ///< share_goal: the founder tells and leads along the way it found the goal
  bool way_home_leg = false;    ///< lead_way: a kept way goes on along the leg walked home by the field
  double share_sighting = 300;  ///< pf: robots this near the nest tell where they saw the chain [cm] (0: off)
  double share_after = 12500;   ///< share_sighting: telling begins at this tick of the run [ticks]
  double share_after_trips =
      0;  ///< share_sighting: a robot tells / listens after this many fruitless trips (0: share_after)
  // aligning (SPEC §2.4, rows #10-#13) and the chain's links
  bool align_keep_view = true;        ///< rows #10, #13: an aligning robot keeps both references in view
  bool seek_hidden_reference = true;  ///< rows #11, #13: a reference out of view is looked for where it was
  bool relink_recovery = true;  ///< row #17: a SUB_NEST replaces a RECOVERY parent by that robot's parent
  bool chain_repair = true;  ///< rows #18-#20: a chain robot whose neighbour's light is gone mends the chain
  double t_repair = 50;      ///< chain_repair: ticks a neighbour's light is gone before it counts as gone
  // task allocation (SPEC §2.6, §2.7)
  bool late_founder_rests = true;  ///< T7f: a founder that hears ALLOC_DONE before it allocates rests
  bool resend_lost_ack = true;    ///< protocol: a JOIN from a robot already ACKed is ACKed again, not counted
  bool founder_seniority = true;  ///< T8: a founder that has ACKed robots outranks one that has not
  double founder_wait = 0.9;      ///< T4: the founder runs the protocol this fraction of R_nest_reach out
  double nest_wait = 0.5;         ///< T3, T5: decision makers wait this fraction of R_nest_reach out
  double t_founder_wait = 300;  ///< the founder ends its allocation after this long without a JOIN (0: never)
  bool guided_departure = true;  ///< T5, T9: the allocated robots follow the founder's CYAN light out
  double guide_speed = 0.7;      ///< guided_departure: the founder's speed factor while leading
  double guide_gap = 40;         ///< guided_departure: distance a follower keeps to its guide [cm]
  double t_guide_lost = 30;      ///< guided_departure: ticks without a guide before exploring alone
  bool share_goal = true;        ///< T5: the founder's ACK carries where it saw the goal
  double depart_gap = 50;        ///< T5: ticks between departures, in ACK order (0: all at once)
  double nest_crowd = 200;  ///< no edge following (allocated) nor trail fall-back this near the nest [cm]
  bool founder_retrace = false;  ///< T4: a founder whose trail home is the nest alone goes back along its way
  bool dm_rescout = true;        ///< T6s: a decision maker whose wait heard no REQUEST scouts again
  bool founder_in_crowd = false;  ///< T4: a founder held off the nest by its crowd asks from where it stands
  double give_way = 20;  ///< T6: a resting robot pressed by another backs away this long [ticks] (0: never)
  bool single_child = true;      ///< row #1 (TA): allocated explorers attach only to an unclaimed subgoal
  bool ta_backoff_spot = true;   ///< TA: allocated robots back off to the spot toward the nest
  bool seek_tip = true;          ///< TA, single_child: an allocated explorer waits by a forming robot
  double tip_hover = 50;         ///< seek_tip: distance at which it waits [cm]
  bool sighting_returns = true;  ///< TA, single_child: nothing free at the sighting -> home (row #2)
  bool chain_bypass = true;      ///< TA: rows #15-#16, a subgoal skips a parent whose parent it sees
  bool chain_bypass_pf = true;   ///< rows #15-#16 in path formation without task allocation too
  double bypass_reach = 95;      ///< chain_bypass: the parent's parent in view this near [cm]
  bool rest_recruit = true;      ///< T10: a resting robot that sees a chain's free end joins it
  double t_recruit = 50;     ///< rest_recruit: ticks the free end stays in view first (plus a draw) [ticks]
  bool recruit_call = true;  ///< T10: a subgoal unclaimed for T_starve calls resting robots (3 m)
  double t_starve = 50;      ///< recruit_call: ticks unclaimed before it calls [ticks]
  bool refound_starved = true;  ///< T11, T12: a chain's end unclaimed for T_refound fetches more robots
  double t_refound = 1500;      ///< refound_starved: ticks unclaimed before it goes home [ticks]
  double delta_refound = 0;     ///< refound_starved: the delta of Eq. (3) for the rest of the path [robots]
};

enum class ParamType : std::uint8_t { kReal, kInteger, kBool, kChoice };

/// One row of SPEC §7.
struct ParamInfo {
  int row;                ///< SPEC §7 row number (0 for options outside the table)
  std::string_view name;  ///< the SPEC's name, as written in params files
  ParamType type;
  std::variant<double Params::*, bool Params::*, TSource Params::*, NeighbourId Params::*> field;
  double def;  ///< default (bools and choices as 0/1)
  double lo;
  double hi;
  double step;
  std::string_view fixed;  ///< "P" (paper value), "H" (hardware), "P/H" or ""
  std::string_view unit;
  std::string_view meaning;
  std::string_view rule;  ///< options beyond SPEC: the SPEC section or rule they change (e.g. "§2.3 #5")
  std::string_view choices[2];  ///< names of choice values 0 and 1
};

/// The descriptor table, in SPEC §7 row order, followed by the non-genome options.
std::span<const ParamInfo> param_table();

/// The descriptor of `name`, or nullptr.
const ParamInfo* find_param(std::string_view name);

/// A parameter's value as a double (bools and choices as 0/1).
double get_value(const Params& p, const ParamInfo& info);

/// Sets a parameter from a double (bools: != 0; choices: index); no range check.
void set_value(Params& p, const ParamInfo& info, double v);

/// Checks ranges and the cross constraints (theta_none <= theta_soft <= theta_hard,
/// d_sub < R_vis, R_keep <= R_vis, T_explore0 <= T_explore_max); empty when valid.
std::string check_params(const Params& p);

/// Loads a params file: top-level keys named as in SPEC §7 (unset keys keep the paper's
/// defaults) and an optional free-form [meta] table. Throws ConfigError.
Params load_params(const std::string& path);
/// The same from TOML text (`name` stands for the file in messages), starting from `base`: keys
/// not in the text keep base's values, and the cross constraints are checked on the result.
Params parse_params(std::string_view text, const std::string& name, const Params& base = Params{});

/// Writes every parameter as a params file that load_params reads back to the same values.
void write_params_toml(std::ostream& out, const Params& p, std::string_view header_comment = {});

/// Formats a value the way params files and exports print it.
std::string format_value(const Params& p, const ParamInfo& info);

}  // namespace swarmpath::sim
