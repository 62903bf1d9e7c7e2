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
  double track_gate = 20;           ///< vision-only tracking gate [cm]
  double w_seek = 1.0;              ///< weight of the pull toward a goal or RED light an explorer sees
  double t_trap = 100;              ///< ticks without progress toward a point before edge following [ticks]
  double trap_progress = 30;        ///< gain that counts as progress for T_trap [cm] [R]
  double dead_end_traps = 5;        ///< a following without progress for this many T_trap turns back [R]
  double t_follow = 2000;           ///< longest edge following [ticks]
  bool site_fidelity = true;        ///< start an exploration trip toward the last goal/subgoal sighting
  bool form_one_at_a_time = false;  ///< an explorer does not start forming while a WHITE robot is in view [R]
  double p_form = 0.1;              ///< per-tick probability that a waiting explorer starts forming
  bool guided_departure = true;     ///< TA: allocated robots follow the founder's CYAN light out [R]
  double guide_speed = 0.7;         ///< the founder's speed factor while leading
  double guide_gap = 40;            ///< distance a follower keeps to its guide [cm]
  double t_guide_lost = 30;         ///< ticks without a guide in view before a follower explores alone
  bool backoff_spot =
      false;  ///< forming: back off to the spot d_sub from the target toward the nest (else along the trail)
  bool share_goal = true;  ///< TA: the founder's ACK carries where it saw the goal (relative to the nest)
  bool seek_hidden_reference = true;  ///< aligning: a reference out of view at the start is looked for first
  bool nudge_parent = true;     ///< SUB_NEST: a parent still RED after T_nudge ticks cannot see this robot (a
                                ///< corner's view need not be mutual): close in on it until it turns [R]
  double t_nudge = 100;         ///< nudge_parent: ticks a sub-nest waits for its parent's OPT1 first [ticks]
  bool relink_recovery = true;  ///< SUB_NEST: a parent turned RECOVERY (row 13) is replaced by that robot's
                                ///< own parent, the light's tag, once in view; till then close in on it [R]
  double trail_slack = 45;      ///< forming, retracing its way home: how much farther from the nest than its
                                ///< target a robot may stop as a subgoal [cm] [R]
  bool backoff_far_spot = true;  ///< forming: back off to the spot when the goal was found from its far side
  /// forming, backing off to the spot: ticks without progress toward it, no wall in the way, before it
  /// retraces its trail (0: T_trap/4 always, before stop 32) [R]
  double spot_patience = 300;
  /// forming: the spot is the crumb of its own way out d_sub + 5 cm (within this tolerance) from the
  /// target, nearer the nest (0: the straight spot) [cm] [R]
  double spot_crumb_tol = 15;
  /// forming, retracing its trail from the spot's way: from the crumb nearest it among those nearer the
  /// nest than the target [R]
  bool trail_nestward = true;
  bool single_child = true;     ///< TA: allocated explorers attach only to an unclaimed goal or subgoal [R]
  bool ta_backoff_spot = true;  ///< TA: allocated robots back off to the spot toward the nest [R]
  double give_way = 20;         ///< TA: a resting robot pressed by another backs away this many ticks, then
                                ///< returns (0: never) [R]
  double depart_gap = 50;       ///< TA: ticks between departures, in ACK order (0: all at once) [R]
  bool seek_tip = true;   ///< TA: an allocated explorer that sees a robot forming a subgoal and no free one
                          ///< waits beside it for the free subgoal it becomes [R]
  double tip_hover = 50;  ///< TA, seek_tip: distance at which it waits by the forming robot [cm]
  bool chain_bypass = false;  ///< TA, single_child: a subgoal that sees its parent's parent within
                              ///< d_sub + 10 cm takes it as parent; the skipped robot leaves the chain [R]
  double nest_crowd = 200;    ///< TA: within this of the nest (the resting and waiting robots) an allocated
                              ///< robot does not edge-follow, it slides past robots instead [cm] [R]
  bool founder_seniority = true;  ///< TA T8: a founder that has ACKed robots outranks one that has not [R]
  double nest_wait = 0.5;         ///< TA: decision makers and robots waiting to leave stop this fraction of
                                  ///< R_nest_reach from the nest [R]
  bool return_finds = true;  ///< a robot going back to the nest (budget spent) that finds the goal within
                             ///< d_detect takes it as an explorer would (SPEC rule #1, TA T2) [R]
  bool return_lured = true;  ///< TA: a scout going home that sees the goal (within R_vis) goes to it, so that
                             ///< return_finds makes it the founder [R]
  bool skip_blocked_crumbs = true;  ///< a robot going home passes over a crumb it cannot reach in T_trap [R]
  double founder_wait = 0.9;  ///< TA: the founder runs the protocol this fraction of R_nest_reach from the
                              ///< nest, at the crowd's rim [R]
  bool rest_recruit = true;   ///< TA: a resting robot at its deployment point that sees a chain's end (a free
                              ///< RED subgoal) for T_recruit ticks joins it as the next link [R]
  bool recruit_call = true;   ///< TA, rest_recruit: a subgoal nobody has claimed for T_starve ticks calls
                              ///< resting robots over the medium (3 m) [R]
  double t_starve = 50;       ///< TA, recruit_call: ticks unclaimed before a subgoal calls [ticks]
  double t_founder_wait = 300;   ///< TA: the founder ends its allocation after this long without a JOIN [R]
  bool sighting_returns = true;  ///< TA, single_child: nothing free at the sighting -> home [R]
  bool refound_starved = true;   ///< TA, recruit_call: a chain's end unclaimed for T_refound goes home and
                                 ///< allocates the robots the rest of the path needs, as a founder [R]
  double t_refound = 1500;  ///< TA, refound_starved: ticks unclaimed before the chain's end goes home [ticks]
  double delta_refound = 0;  ///< TA, refound_starved: the delta of Eq. (3) for the rest of the path [robots]
  double t_recruit = 50;     ///< TA, rest_recruit: ticks the free subgoal stays in view first (plus up to as
                             ///< many again, drawn per robot, so that one robot goes) [ticks]
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
Params parse_params(std::string_view text, const std::string& name);

/// Writes every parameter as a params file that load_params reads back to the same values.
void write_params_toml(std::ostream& out, const Params& p, std::string_view header_comment = {});

/// Formats a value the way params files and exports print it.
std::string format_value(const Params& p, const ParamInfo& info);

}  // namespace swarmpath::sim
