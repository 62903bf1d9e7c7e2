// SPDX-License-Identifier: MIT
#include "params.hpp"

#include <array>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>

#include "config_error.hpp"
#include "toml_reader.hpp"

namespace swarmpath::sim {

namespace {

using P = Params;
constexpr auto R = ParamType::kReal;
constexpr auto I = ParamType::kInteger;
constexpr auto B = ParamType::kBool;
constexpr auto C = ParamType::kChoice;

// clang-format off
// SPEC §7, in row order, then the options beyond it: row, name, type, field, default, lo, hi, step, fix?,
// unit, meaning, the SPEC rule an option changes.
const std::array kTable{
  ParamInfo{ 1, "d_detect",       R, &P::d_detect,       30,   15,   60,    1,    "P",   "cm",    "distance at which an explorer finds the goal or a RED subgoal", "", {}},
  ParamInfo{ 2, "d_sub",          R, &P::d_sub,          70,   40,   95,    1,    "P",   "cm",    "distance from the target at which a forming robot stops as a subgoal", "", {}},
  ParamInfo{ 3, "R_vis",          R, &P::r_vis,          100,  80,   150,   5,    "P/H", "cm",    "camera visible range (also v in n = l/v)", "", {}},
  ParamInfo{ 4, "r_rec",          R, &P::r_rec,          20,   10,   60,    1,    "P",   "cm",    "recovery repulsion range", "", {}},
  ParamInfo{ 5, "k_rec",          R, &P::k_rec,          1.0,  0,    3,     0.05, "",    "",      "recovery repulsion gain", "", {}},
  ParamInfo{ 6, "T_lost",         I, &P::t_lost,         3,    1,    20,    1,    "",    "ticks", "invisibility debounce before lost", "", {}},
  ParamInfo{ 7, "v_max",          R, &P::v_max,          20,   5,    30,    0.5,  "",    "cm/s",  "max wheel speed; also s in l = s*t", "", {}},
  ParamInfo{ 8, "v_align",        R, &P::v_align,        0.5,  0.1,  1.0,   0.05, "",    "",      "speed factor during OPT1/OPT2", "", {}},
  ParamInfo{ 9, "theta_hard",     R, &P::theta_hard,     90,   60,   150,   1,    "",    "deg",   "hard-turn threshold", "", {}},
  ParamInfo{10, "theta_soft",     R, &P::theta_soft,     70,   30,   90,    1,    "",    "deg",   "soft-turn threshold (<= theta_hard)", "", {}},
  ParamInfo{11, "theta_none",     R, &P::theta_none,     10,   2,    30,    1,    "",    "deg",   "no-turn threshold (<= theta_soft)", "", {}},
  ParamInfo{12, "diff_angle",     R, &P::diff_angle,     5,    1,    30,    1,    "",    "deg",   "half-width of the diffusion go-straight cone", "", {}},
  ParamInfo{13, "diff_delta",     R, &P::diff_delta,     0.1,  0.02, 0.5,   0.01, "",    "",      "proximity magnitude treated as clear", "", {}},
  ParamInfo{14, "T_explore0",     R, &P::t_explore0,     1000, 200,  5000,  50,   "",    "ticks", "initial exploration budget", "", {}},
  ParamInfo{15, "dT_explore",     R, &P::dt_explore,     500,  0,    3000,  50,   "",    "ticks", "additive budget growth per failed trip", "", {}},
  ParamInfo{16, "g_explore",      R, &P::g_explore,      1.0,  1.0,  2.0,   0.05, "",    "",      "multiplicative growth (applied after the additive one)", "", {}},
  ParamInfo{17, "T_explore_max",  R, &P::t_explore_max,  8000, 1000, 20000, 500,  "",    "ticks", "budget cap", "", {}},
  ParamInfo{18, "w_away",         R, &P::w_away,         0.5,  0,    2,     0.05, "",    "",      "weight of the away-from-nest field while exploring", "", {}},
  ParamInfo{19, "w_rw",           R, &P::w_rw,           0.5,  0,    2,     0.05, "",    "",      "weight of the random-walk heading", "", {}},
  ParamInfo{20, "p_turn",         R, &P::p_turn,         0.02, 0,    0.2,   0.005,"",    "",      "per-tick probability of a random heading change", "", {}},
  ParamInfo{21, "dphi_max",       R, &P::dphi_max,       45,   0,    180,   5,    "",    "deg",   "max random heading change", "", {}},
  ParamInfo{22, "T_rest",         R, &P::t_rest,         50,   0,    1000,  10,   "",    "ticks", "resting time at the nest (non-TA loop)", "", {}},
  ParamInfo{23, "T_nest_search",  R, &P::t_nest_search,  50,   0,    300,   10,   "",    "ticks", "time inside the nest before resting", "", {}},
  ParamInfo{24, "R_nest_reach",   R, &P::r_nest_reach,   100,  30,   150,   5,    "",    "cm",    "reached-the-nest radius", "", {}},
  ParamInfo{25, "T_form_timeout", R, &P::t_form_timeout, 600,  100,  3000,  50,   "",    "ticks", "stall guard for SUBGOAL_FORMING", "", {}},
  ParamInfo{26, "early_stop_in_rec", B, &P::early_stop_in_rec, 1, 0, 1,     1,    "",    "",      "rule #6 early stop near a recovery robot", "", {}},
  ParamInfo{27, "e_tol",          R, &P::e_tol,          5,    1,    20,    0.5,  "",    "deg",   "alignment error-angle tolerance", "", {}},
  ParamInfo{28, "d_tol",          R, &P::d_tol,          3,    1,    10,    0.5,  "",    "cm",    "alignment distance tolerance", "", {}},
  ParamInfo{29, "T_align_max",    R, &P::t_align_max,    300,  50,   2000,  25,   "",    "ticks", "alignment time-out", "", {}},
  ParamInfo{30, "lambda_mid",     R, &P::lambda_mid,     0.0,  0,    1,     0.05, "",    "",      "blend of the perpendicular foot toward the midpoint", "", {}},
  ParamInfo{31, "R_keep",         R, &P::r_keep,         90,   60,   150,   1,    "",    "cm",    "max distance kept to each reference while aligning (<= R_vis)", "", {}},
  ParamInfo{32, "revert_orphans", B, &P::revert_orphans, 0,    0,    1,     1,    "",    "",      "SUB_NEST/PATH_DONE revert to RED if the parent is lost", "", {}},
  ParamInfo{33, "delta_open",     R, &P::delta_open,      0,    0,    60,    1,    "",    "robots","delta for open environments", "", {}},
  ParamInfo{34, "delta_obstacle", R, &P::delta_obstacle,  0,   0,    60,    1,    "",    "robots","delta for obstacle environments", "", {}},
  ParamInfo{35, "delta_complex",  R, &P::delta_complex,   0,   0,    60,    1,    "",    "robots","delta for complex environments", "", {}},
  ParamInfo{36, "t_source",       C, &P::t_source,       0,    0,    1,     1,    "",    "",      "t in l = s*t: the budget or the elapsed trip time", "", {"budget", "elapsed"}},
  ParamInfo{37, "kappa",          R, &P::kappa,          1.2,  1,    3,     0.05, "",    "",      "allocated robots' budget = kappa * t_founder", "", {}},
  ParamInfo{38, "n_min",          R, &P::n_min,          2,    1,    10,    1,    "",    "robots","lower clamp on n", "", {}},
  ParamInfo{39, "founder_counts_self", B, &P::founder_counts_self, 1, 0, 1,   1,    "",    "",      "the founder is one of the n", "", {}},
  ParamInfo{40, "T_done",         R, &P::t_done,         50,   10,   200,   10,   "",    "ticks", "ticks DONE is broadcast", "", {}},
  ParamInfo{41, "T_dm_wait",      R, &P::t_dm_wait,      3000, 500,  10000, 100,  "",    "ticks", "decision-maker timeout at the nest without a REQUEST", "", {}},
  ParamInfo{42, "d_arrive",       R, &P::d_arrive,       5,    2,    20,    1,    "",    "cm",    "resting arrival tolerance at the deployment point", "", {}},
  ParamInfo{ 0, "neighbour_id", C, &P::neighbour_id, 0, 0, 1, 1, "", "",
            "chain tracking: camera blobs carry ids, or vision-only tracking",
            "§2.1 neighbour identity", {"vision_id", "vision_only"}},
  ParamInfo{ 0, "track_gate", R, &P::track_gate, 20, 5, 50, 1, "", "cm",
            "vision-only tracking gate",
            "§2.1 neighbour identity", {}},
  ParamInfo{ 0, "led_ring", B, &P::led_ring, 1, 0, 1, 1, "", "",
            "a robot is seen when the line to its centre or to either tangent point of its 9 cm LED ring is clear (ARGoS ray-casts every LED); off: the line to its centre only (SPEC's one blob per robot)",
            "§1.3 camera", {}},
  ParamInfo{ 0, "away_decay", R, &P::away_decay, 0.7, 0.3, 1, 0.05, "", "",
            "an explorer's away-from-nest weight (w_away, row 18) is multiplied by this each time a trip of its ends back home without a sighting of the goal or the chain (row #4), so that a robot that has searched in vain leans more on its random walk and less on the straight-line field, which presses every trip into the same far walls (an allocation starts it afresh at w_away; 1: w_away always, as SPEC)",
            "§2.1 fields, #4", {}},
  ParamInfo{ 0, "w_seek", R, &P::w_seek, 1, 0, 3, 0.05, "", "",
            "pull of an explorer toward the goal or RED light it sees within R_vis, until it is within d_detect (0: none; SPEC: it must pass within d_detect by chance)",
            "§2.1 exploring, #1", {}},
  ParamInfo{ 0, "T_trap", R, &P::t_trap, 100, 0, 2000, 10, "", "ticks",
            "a robot heading to or away from a point that has made no progress for this long while touching an obstacle follows its edge, and a robot going home switches to its trail (0: never, SPEC's pure potential fields)",
            "§2.1 fields", {}},
  ParamInfo{ 0, "trap_progress", R, &P::trap_progress, 30, 1, 200, 1, "", "cm",
            "what counts as progress for T_trap: a robot that has not got this much nearer its point (exploring: farther from the nest) for T_trap ticks is trapped",
            "§2.1 fields", {}},
  ParamInfo{ 0, "dead_end_traps", R, &P::dead_end_traps, 20, 1, 50, 1, "", "",
            "an edge following that has made no progress for this many T_trap ticks is taken for a dead end and turns back along the same edge (once)",
            "§2.1 fields", {}},
  ParamInfo{ 0, "T_follow", R, &P::t_follow, 2000, 50, 5000, 50, "", "ticks",
            "longest edge following",
            "§2.1 fields", {}},
  ParamInfo{ 0, "site_fidelity", B, &P::site_fidelity, 1, 0, 1, 1, "", "",
            "an exploration trip starts by travelling to where the goal or the chain's nest-most subgoal was last seen; travelling does not spend the budget (off: every trip explores from the nest)",
            "§2.3 #2", {}},
  ParamInfo{ 0, "travel_cap", R, &P::travel_cap, 3, 0, 20, 0.5, "", "",
            "site_fidelity, guided_departure: a trip whose travel has lasted this many exploration budgets ends (row #2; 0: travel never ends a trip)",
            "§2.3 #2", {}},
  ParamInfo{ 0, "return_finds", B, &P::return_finds, 1, 0, 1, 1, "", "",
            "a robot going back to the nest (its budget spent) that finds the goal within d_detect takes it as an explorer would (row #1h; in task allocation it becomes the founder, T2); subgoals it ignores (off: returning robots ignore the goal too, SPEC's reading)",
            "§2.3 #1, §2.6 T2", {}},
  ParamInfo{ 0, "return_lured", B, &P::return_lured, 1, 0, 1, 1, "", "",
            "task allocation, return_finds: a scout going back to the nest that sees the goal's light (within R_vis) turns to it and founds at d_detect (T2; off: it founds only when its way home passes within d_detect)",
            "§2.6 T2", {}},
  ParamInfo{ 0, "form_one_at_a_time", B, &P::form_one_at_a_time, 0, 0, 1, 1, "", "",
            "an explorer does not start forming a subgoal while a subgoal-forming (WHITE) robot is in view, so that the chain grows one link at a time",
            "§2.3 #1", {}},
  ParamInfo{ 0, "p_form", R, &P::p_form, 0.1, 0.01, 1, 0.01, "", "",
            "form_one_at_a_time: per-tick probability that an explorer at the chain's tip starts forming",
            "§2.3 #1", {}},
  ParamInfo{ 0, "trail_home", B, &P::trail_home, 1, 0, 1, 1, "", "",
            "a robot going home that the field has trapped for T_trap ticks retraces the breadcrumbs of its trip (dropped every 25 cm), from the crumb nearest it; one stuck on its way to that crumb falls back to a crumb it has been at (off: the field and edge following only)",
            "§2.1 fields, #3", {}},
  ParamInfo{ 0, "skip_blocked_crumbs", B, &P::skip_blocked_crumbs, 1, 0, 1, 1, "", "",
            "a robot going home along its breadcrumbs that makes no progress toward the next one for T_trap ticks (a robot stands on it) passes over it to the one after (off: it edge-follows and tries again)",
            "§2.1 fields", {}},
  ParamInfo{ 0, "backoff_trail", B, &P::backoff_trail, 1, 0, 1, 1, "", "",
            "a forming robot backs off toward the nest along its own way from the nest, a route it knows is passable (off: by the nest's field, SPEC's F_toward(nest))",
            "§2.3 #5", {}},
  ParamInfo{ 0, "retarget_nearer", B, &P::retarget_nearer, 1, 0, 1, 1, "", "",
            "a forming robot that sees a free RED subgoal nearer the nest than its target (by 20 cm) takes it as its target and first walks to it, so that the new link extends the chain's tip instead of branching (row #5r)",
            "§2.3 #5r", {}},
  ParamInfo{ 0, "subgoal_nestward", B, &P::subgoal_nestward, 1, 0, 1, 1, "", "",
            "rows #5 and #6b fire only nearer the nest than the target, the paper's \"in between the starting point and the detected subgoal\" (off: SPEC's rows, anywhere d_sub from the target)",
            "§2.3 #5, #6b", {}},
  ParamInfo{ 0, "trail_slack", R, &P::trail_slack, 45, 0, 3000, 5, "", "cm",
            "subgoal_nestward: a forming robot retracing its own way home (round an obstacle) may stop as a subgoal at most this much farther from the nest than its target (3000: anywhere on its way)",
            "§2.3 #5", {}},
  ParamInfo{ 0, "anywhere_after_edge", B, &P::anywhere_after_edge, 1, 0, 1, 1, "", "",
            "task allocation, subgoal_nestward: a forming robot (an allocated one, a scout, a late arrival) retracing its own way home that followed an obstacle's edge on this trip may stop as a subgoal anywhere on that way, however far from the nest (round a wall the way back may lead away from the nest first); a way that never followed an edge keeps trail_slack (off: trail_slack everywhere)",
            "§2.3 #5, #6b", {}},
  ParamInfo{ 0, "anywhere_after_edge_pf", B, &P::anywhere_after_edge_pf, 1, 0, 1, 1, "", "",
            "path formation without task allocation: anywhere_after_edge for its forming robots too (off: trail_slack everywhere)",
            "§2.3 #5, #6b", {}},
  ParamInfo{ 0, "backoff_spot", B, &P::backoff_spot, 0, 0, 1, 1, "", "",
            "a forming robot backs off to the spot d_sub + 5 cm from its target toward the nest (false: along its own way from the nest)",
            "§2.3 #5", {}},
  ParamInfo{ 0, "backoff_far_spot", B, &P::backoff_far_spot, 1, 0, 1, 1, "", "",
            "a forming robot that found the goal from its far side (farther from the nest than the goal) backs off to the spot, not along its own way",
            "§2.3 #5", {}},
  ParamInfo{ 0, "spot_crumb_tol", R, &P::spot_crumb_tol, 15, 0, 100, 5, "", "cm",
            "a forming robot's spot is the crumb of its own way from the nest whose distance from the target is nearest d_sub + 5 cm, within this tolerance, among the crumbs nearer the nest than the target (the way it knows is passable, round an obstacle); none: the point d_sub + 5 cm from the target toward the nest (0: always that point)",
            "§2.3 #5", {}},
  ParamInfo{ 0, "trail_nestward", B, &P::trail_nestward, 1, 0, 1, 1, "", "",
            "a forming robot that falls back from its spot to its own way from the nest starts that way at the crumb nearest it among those nearer the nest than its target (off: the crumb nearest it, which for a robot that reached the tip from the goal side leads back past the target)",
            "§2.3 #5", {}},
  ParamInfo{ 0, "spot_on_way", B, &P::spot_on_way, 1, 0, 1, 1, "", "",
            "task allocation: a forming robot (an allocated one, a scout, a late arrival) backing off to its spot (backoff_spot, ta_backoff_spot, backoff_far_spot) whose own way from the nest has no crumb d_sub + 5 cm (within spot_crumb_tol) from its target nearer the nest than it in a straight line takes as its spot the point where that way first came within d_sub + 5 cm of the target (the way it came, round an obstacle's end), however far from the nest in a straight line, and may stop as the subgoal within 25 cm of it (rows #5, #6b); a way that never came that near: the spot of spot_crumb_tol (off: that spot always)",
            "§2.3 #5, #6b", {}},
  ParamInfo{ 0, "spot_on_way_pf", B, &P::spot_on_way_pf, 0, 0, 1, 1, "", "",
            "path formation without task allocation: spot_on_way for its forming robots (off: the spot of spot_crumb_tol always)",
            "§2.3 #5, #6b", {}},
  ParamInfo{ 0, "way_after_edge", B, &P::way_after_edge, 1, 0, 1, 1, "", "",
            "spot_on_way, spot_on_way_pf: the spot on the way is taken only by a robot that followed an obstacle's edge on this trip (its way went round something; in an open room the way is the robot's own wandering, and the spot of spot_crumb_tol stands)",
            "§2.3 #5, #6b", {}},
  ParamInfo{ 0, "tip_by_links", B, &P::tip_by_links, 0, 0, 1, 1, "", "",
            "retarget_nearer: a forming robot that sees a free RED subgoal whose light names its target as parent (the target's child) takes it as its target and walks to it, down the chain to its tip by the chain's own links (off: the free RED nearest the nest, by 20 cm)",
            "§2.3 #5r", {}},
  ParamInfo{ 0, "retarget_tip", B, &P::retarget_tip, 1, 0, 1, 1, "", "",
            "retarget_nearer with vision + ID: a forming robot re-targets only to a free RED subgoal that no RED light in view names as its parent (a tip of the chain as far as it sees), so that where the chain bends away from the nest it is not drawn back from the tip to a link inside the chain nearer the nest in a straight line (off: any free RED nearer the nest)",
            "§2.3 #5r", {}},
  ParamInfo{ 0, "link_outward", B, &P::link_outward, 0, 0, 1, 1, "", "",
            "subgoal_nestward: a forming robot of a task-allocation run (an allocated robot, a scout, a late arrival) retracing its own way from the nest may stop as a subgoal wherever its target is the nearest chain light in view (the new link extends the chain instead of folding back beside it), however far from the nest (off: at most trail_slack farther from the nest than its target)",
            "§2.3 #5, #6b", {}},
  ParamInfo{ 0, "link_outward_pf", B, &P::link_outward_pf, 0, 0, 1, 1, "", "",
            "path formation without task allocation: link_outward for its forming robots (off: at most trail_slack farther from the nest than the target)",
            "§2.3 #5, #6b", {}},
  ParamInfo{ 0, "form_retries", R, &P::form_retries, 3, 0, 20, 1, "", "",
            "a forming robot that loses its target (row #7: out of view a visible range away; row #8b: timed out with it out of view) goes home along its own way from the nest (RETURN_TO_NEST), rests and explores again, its next trip starting at its sighting of the chain (site_fidelity), instead of turning RECOVERY, which is final: at most this many times in a run, then RECOVERY (row #7h; 0: RECOVERY at once, as SPEC)",
            "§2.3 #7, #8b", {}},
  ParamInfo{ 0, "T_leaf", R, &P::t_leaf, 1500, 0, 20000, 100, "", "ticks",
            "path formation without task allocation: a RED subgoal that no robot in view names as its parent or target (no child, nobody forming from it) for this many ticks in a row, a leaf of the chain that no explorer extends (a side branch of the fan at the goal), leaves the chain and goes home along its own way out (RETURN_TO_NEST); its next trip starts at its sighting of the chain, the RED nearest the nest it saw on its way home, so it comes back to the chain's tip from the nest's side (row #21; 0: never, as SPEC)",
            "§2.3 #21", {}},
  ParamInfo{ 0, "leaf_in_fan", B, &P::leaf_in_fan, 0, 0, 1, 1, "", "",
            "with T_leaf: a leaf counts its unnamed ticks only while it sees a chain light other than its parent's and its parent's parent's (another branch of a fan), so that the lone tip of a single chain, which sees only its own links, stays (off: every unnamed tick counts)",
            "§2.3 #21", {}},
  ParamInfo{ 0, "T_leaf_allocated", R, &P::t_leaf_allocated, 0, 0, 3000, 100, "", "ticks",
            "task allocation: an allocated RED subgoal that sees a chain light other than its parent's and its parent's parent's (another branch of a fan, leaf_in_fan's test) and that no robot in view names as its parent or target for this many ticks of that sight leaves the chain and goes home as row #21's leaf does, so that the fans where robots led round a wall's end meet the chain give back their robots; the lone tip of a single chain, waiting for robots, never counts (0: allocated subgoals stay, as T_leaf leaves them)",
            "§2.3 #21", {}},
  ParamInfo{ 0, "share_sighting", R, &P::share_sighting, 300, 0, 1000, 50, "", "cm",
            "path formation without task allocation: a robot within this distance of the nest that knows where it last saw the goal or the chain (site_fidelity's sighting) tells it on the range-and-bearing medium (3 m), and a resting robot with no sighting of its own takes the nearest teller's, so that its next trip starts toward it, as task allocation's ACK tells the allocated robots where the goal is (share_goal); a trip that sees nothing there forgets it on the way home (0: off, each robot knows only what it saw)",
            "§2.3 #2, #4", {}},
  ParamInfo{ 0, "share_after", R, &P::share_after, 12500, 0, 36000, 500, "", "ticks",
            "share_sighting: robots tell their sightings only once the run has lasted this many ticks, so that sharing helps the searches that have not found their way by then (a detour) and leaves the quick ones as they are (0: from the start)",
            "§2.3 #2, #4", {}},
  ParamInfo{ 0, "share_after_trips", I, &P::share_after_trips, 0, 0, 20, 1, "", "",
            "share_sighting: a robot tells its sighting, and listens for one, only once it has come home this many times from a trip without a sighting of the goal or the chain (a search it senses has stalled), instead of from tick share_after of the run, which it then replaces (0: share_after decides)",
            "§2.3 #2, #4", {}},
  ParamInfo{ 0, "walk_way", B, &P::walk_way, 0, 0, 1, 1, "", "",
            "task allocation, site_fidelity: a scout or allocated robot whose trip saw the goal or the chain keeps that trip's way out (its breadcrumbs, from where the trip began to its crumb nearest the sighting) and its next trip to that sighting walks it from the start, crumb by crumb, a crumb it cannot reach passed over after T_trap ticks (off: the field toward the sighting, and route_to_sighting's way only once trapped; path formation without task allocation: share_way)",
            "§2.3 #2", {}},
  ParamInfo{ 0, "share_way", B, &P::share_way, 0, 0, 1, 1, "", "",
            "share_sighting: a robot tells its sighting only with the way there, which it knows from its own trip that saw it (kept when it turned home, as walk_way keeps it) or heard whole: on every other tick one corner of it (its breadcrumbs from where that trip began to the crumb nearest the sighting, straight stretches dropped, at most 16 corners); a robot that took its sighting listens on, resting or leaving the nest, and its trips to the sighting, once it has the whole way, walk it from the start, corner by corner, instead of heading straight at the sighting into whatever wall lies between; so does a robot's trip along its own way (off: the sighting alone is told, and travelled to by the field)",
            "§2.3 #2, #4", {}},
  ParamInfo{ 0, "resume_search", B, &P::resume_search, 1, 0, 1, 1, "", "",
            "an exploration trip that ends back home without a sighting of the goal or the chain keeps its way out (its breadcrumbs), and the robot's next trip, when it has no sighting to travel to (site_fidelity), first travels along that way to where the trip ended, without spending its budget (travel_cap bounds it), and explores from there, so that a robot's successive trips reach farther instead of each starting over at the nest (off: every such trip explores from the nest, as SPEC)",
            "§2.1 exploring, #4", {}},
  ParamInfo{ 0, "lead_way", B, &P::lead_way, 1, 0, 1, 1, "", "",
            "share_goal, site_fidelity: task allocation: the goal's founder keeps the way of the trip that found the goal (its breadcrumbs from where that trip began to the crumb nearest the goal, straight stretches dropped, at most 16 corners) and tells it on the medium on every other tick, one corner after another, while it runs the protocol at the nest and while it leads; a decision maker or allocated robot that hears it whole walks it from the start, corner by corner, once it has lost its guide, and the founder leads along it, instead of heading straight at the goal into whatever wall lies between; a chain's end that goes home to fetch more robots (refound_starved) tells its way out to that end the same (off: the founder and the robots that lose it head for the goal by the field)",
            "§2.6 T5, T9", {}},
  ParamInfo{ 0, "way_home_leg", B, &P::way_home_leg, 0, 0, 1, 1, "", "",
            "lead_way, route_to_sighting: the way a robot keeps of its trip (a goal founder's, to tell and to lead along; a chain's end's that goes home to fetch more robots) goes on past the crumb where the trip turned home, along the leg it has walked home by the field before taking its trail (a crumb every 25 cm, loops erased), so that a founder that found the goal on its way home (return_finds) keeps and tells a way that reaches it (off: the way ends where the trip turned home; a goal found after that lies off it, no way is told, and the founder and the robots it allocates head for the goal by the field)",
            "§2.6 T5, T9", {}},
  ParamInfo{ 0, "route_to_sighting", B, &P::route_to_sighting, 0, 0, 1, 1, "", "",
            "site_fidelity: a robot travelling back to its last sighting of the goal or the chain (a founder leading the allocated robots there too) that the field traps against an obstacle (T_trap: edge following would begin) retraces its own way there instead: the breadcrumbs of the trip that saw it (kept when it turned home, or when a founder set out for the nest), from the crumb nearest it that it can have reached (no farther along that way than it stands from the nest) to the crumb nearest the sighting, then straight to it; a sighting that no crumb of that way lies within R_vis of, or one told by another robot: the field and edge following (off: the field and edge following always)",
            "§2.3 #2", {}},
  ParamInfo{ 0, "align_keep_view", B, &P::align_keep_view, 1, 0, 1, 1, "", "",
            "an aligning robot that loses sight of a reference goes back to where its alignment began and stops there (aligned as far as its view allows); row #13 fires only if a reference is still missing there, and a timed-out alignment counts as done only with both references in view (off: SPEC's rows #10 and #13)",
            "§2.4, §2.3 #10, #13", {}},
  ParamInfo{ 0, "seek_hidden_reference", B, &P::seek_hidden_reference, 1, 0, 1, 1, "", "",
            "align_keep_view: an aligning robot back where its alignment began with one reference still out of view drives toward where it last saw it before row #13; a SUB_NEST robot whose parent is out of view goes round the corner toward where it last saw it (row #11)",
            "§2.3 #11, #13", {}},
  ParamInfo{ 0, "relink_recovery", B, &P::relink_recovery, 1, 0, 1, 1, "", "",
            "a SUB_NEST robot whose parent turned RECOVERY during an alignment (row #13) drives toward it (v_align v_max, round corners along their edge, to r_rec from it) until it sees that robot's own parent (the tag its light carries), and takes it as its parent (row #17). Off: it waits for ever, and the chain with it",
            "§2.3 #17", {}},
  ParamInfo{ 0, "chain_repair", B, &P::chain_repair, 1, 0, 1, 1, "", "",
            "a chain robot (RED, BLUE or BROWN) that has not seen a neighbour's link light for T_repair ticks (it failed and went dark, or shows another colour) mends the chain: its parent gone, it takes the robot the parent's light named as its parent (the goal or the next link goalward) when that one is in view (row #18), else it leaves the chain for the nest, as its own children then do in turn (row #19); its child gone, it turns RED again, the chain's tip, from which the chain re-forms toward the nest (row #20). Off: a chain with a gap waits for ever (docs/faults.md)",
            "§2.3 #18-#20", {}},
  ParamInfo{ 0, "T_repair", R, &P::t_repair, 50, 5, 5000, 5, "", "ticks",
            "chain_repair: how long a neighbour's link light must be gone before the chain is mended",
            "§2.3 #18-#20", {}},
  ParamInfo{ 0, "late_founder_rests", B, &P::late_founder_rests, 1, 0, 1, 1, "", "",
            "task allocation: a founder that hears ALLOC_DONE before it has begun allocating rests (T7f; off: it runs a second allocation at the nest)",
            "§2.6 T7f", {}},
  ParamInfo{ 0, "resend_lost_ack", B, &P::resend_lost_ack, 1, 0, 1, 1, "", "",
            "task allocation: a JOIN from a robot already ACKed (its ACK was lost, or its JOIN crossed the ACK) is answered with a fresh ACK, also after the count has reached zero, without counting it again (off: it is ignored)",
            "§2.6 protocol", {}},
  ParamInfo{ 0, "founder_seniority", B, &P::founder_seniority, 1, 0, 1, 1, "", "",
            "task allocation: of two founders at the nest, one that has ACKed robots outranks one that has not (then the smaller id), so that a late founder does not run a second allocation",
            "§2.6 T8", {}},
  ParamInfo{ 0, "founder_wait", R, &P::founder_wait, 0.9, 0.1, 1, 0.05, "", "",
            "task allocation: the founder stops this fraction of R_nest_reach from the nest to run the protocol, at the rim of the decision makers' crowd, so that it can lead the allocated robots out (nest_wait's 0.5: among them)",
            "§2.6 T4", {}},
  ParamInfo{ 0, "nest_wait", R, &P::nest_wait, 0.5, 0.1, 1, 0.05, "", "",
            "task allocation: decision makers and allocated robots waiting their turn drive to within this fraction of R_nest_reach of the nest, then stop",
            "§2.6 T3", {}},
  ParamInfo{ 0, "T_founder_wait", R, &P::t_founder_wait, 300, 0, 10000, 10, "", "ticks",
            "task allocation: a founder that has heard no JOIN for this long while it still needs robots stops allocating and leads out those it has (0: it waits for ever, as SPEC)",
            "§2.6 T9", {}},
  ParamInfo{ 0, "guided_departure", B, &P::guided_departure, 1, 0, 1, 1, "", "",
            "task allocation: the allocated robots follow the founder's CYAN light on their first trip, the founder leading them back to the goal",
            "§2.6 T5, T9", {}},
  ParamInfo{ 0, "guide_speed", R, &P::guide_speed, 0.7, 0.2, 1, 0.05, "", "",
            "guided_departure: speed factor of the founder while it leads",
            "§2.6 T9", {}},
  ParamInfo{ 0, "guide_gap", R, &P::guide_gap, 40, 20, 90, 5, "", "cm",
            "guided_departure: distance a follower keeps to its guide",
            "§2.6 T5", {}},
  ParamInfo{ 0, "T_guide_lost", R, &P::t_guide_lost, 30, 10, 1000, 10, "", "ticks",
            "guided_departure: ticks without a guide in view before a follower explores on its own",
            "§2.6 T5", {}},
  ParamInfo{ 0, "share_goal", B, &P::share_goal, 1, 0, 1, 1, "", "",
            "task allocation: the founder's ACK carries where it saw the goal (relative to the nest); an allocated robot that loses its guide travels there",
            "§2.6 protocol, T5", {}},
  ParamInfo{ 0, "depart_gap", R, &P::depart_gap, 50, 0, 1000, 10, "", "ticks",
            "task allocation: an allocated robot waits at the nest this many ticks per robot ACKed after it (the ACK's remaining count), so that the robots leave one after another (0: all at once)",
            "§2.6 T5", {}},
  ParamInfo{ 0, "nest_crowd", R, &P::nest_crowd, 200, 0, 500, 10, "", "cm",
            "within this distance of the nest, crowded in task allocation with resting and waiting robots, an allocated robot does not follow obstacle edges (robots are not walls) and steers by avoidance and its field alone, and no robot going home along its trail falls back to an earlier crumb (0: everywhere)",
            "§2.1 fields", {}},
  ParamInfo{ 0, "founder_retrace", B, &P::founder_retrace, 0, 0, 1, 1, "", "",
            "task allocation (T4): a goal founder on its way to the nest that the field traps, and whose trail home would begin at the trail's first crumb (the nest itself, nearest in a straight line though behind a wall, what the field already steers at), goes back instead to the crumb nearest home it has been at on this way (where it left its way out; the crumb where it turned home when it touched none) and home along its trail from there, also within nest_crowd, so that a founder beside a nest it cannot reach straight finds the way in (off: the crumb behind the wall is passed over and the founder follows edges)",
            "§2.6 T4", {}},
  ParamInfo{ 0, "dm_rescout", B, &P::dm_rescout, 1, 0, 1, 1, "", "",
            "task allocation (T6): a decision maker that has waited T_dm_wait at the nest without ever hearing a REQUEST (no founder came: the founder may have failed on its way, fail_fraction) scouts again instead of resting, from the nest, as at the start of the run, and from then on only a founder's CYAN light or a REQUEST makes it a decision maker again (the GRAY80 lights of those still waiting led to no founder), so that the goal is found anew and a new founder allocates (off: it rests, SPEC T6, and a swarm whose only founder failed rests for the rest of the run)",
            "§2.6 T6", {}},
  ParamInfo{ 0, "founder_in_crowd", B, &P::founder_in_crowd, 0, 0, 1, 1, "", "",
            "task allocation (T4): a goal founder on its way to the nest that is within nest_crowd of it, sees a CYAN or GRAY80 light (decision makers or founders waiting there) and has come no nearer the nest by trap_progress for T_trap ticks starts its protocol where it stands instead of within R_nest_reach, since the crowd it cannot pass is the robots it asks, within the medium's range (off: it asks only within R_nest_reach)",
            "§2.6 T4", {}},
  ParamInfo{ 0, "give_way", R, &P::give_way, 20, 0, 200, 5, "", "ticks",
            "task allocation: a resting robot whose proximity reading grows past what its static neighbours gave when it settled (a robot pressing through the crowd at the nest) backs away from it at half speed for this many ticks, then returns to its deployment point (0: resting robots never move)",
            "§2.6 T6", {}},
  ParamInfo{ 0, "single_child", B, &P::single_child, 1, 0, 1, 1, "", "",
            "task allocation: an allocated explorer attaches only to a goal or RED subgoal that no robot in view claims (a WHITE robot forming from it, or a path robot advertising it as its parent); claimed ones do not lure it",
            "§2.3 #1", {}},
  ParamInfo{ 0, "ta_backoff_spot", B, &P::ta_backoff_spot, 1, 0, 1, 1, "", "",
            "task allocation: an allocated robot forming a subgoal backs off to the spot d_sub from its target toward the nest, as backoff_spot does for every robot",
            "§2.3 #5", {}},
  ParamInfo{ 0, "seek_tip", B, &P::seek_tip, 1, 0, 1, 1, "", "",
            "task allocation, single_child: an allocated explorer that sees a robot forming a subgoal (WHITE) and no free subgoal walks to the forming robot (the one nearest the nest) and waits tip_hover from it for the free subgoal it becomes; waiting spends the budget",
            "§2.3 #1", {}},
  ParamInfo{ 0, "tip_hover", R, &P::tip_hover, 50, 20, 150, 5, "", "cm",
            "seek_tip: distance at which an allocated explorer waits by a forming robot",
            "§2.3 #1", {}},
  ParamInfo{ 0, "sighting_returns", B, &P::sighting_returns, 1, 0, 1, 1, "", "",
            "task allocation, single_child: an allocated robot that reaches the place where it last saw the chain's tip (or the goal) and sees nothing free there ends its trip and goes home (row #2): the tip has moved nestward, past it (off: it explores on from there, away from the nest)",
            "§2.3 #2", {}},
  ParamInfo{ 0, "chain_bypass", B, &P::chain_bypass, 1, 0, 1, 1, "", "",
            "task allocation: a RED subgoal (an allocated robot's, a scout's, a late arrival's) that sees its parent's parent (RED, or the goal) within bypass_reach takes it as its parent (row #15); the skipped robot, once every robot that named it as parent (by its light's tag, or a claim on the medium) names another, goes back to the nest and out again to the chain's tip (row #16): a winding chain gives back the links it does not need (off: every link stays, as SPEC)",
            "§2.3 #15, #16", {}},
  ParamInfo{ 0, "chain_bypass_pf", B, &P::chain_bypass_pf, 1, 0, 1, 1, "", "",
            "path formation without task allocation: chain_bypass's rows #15-#16 for its subgoals too (off: they keep every link)",
            "§2.3 #15, #16", {}},
  ParamInfo{ 0, "bypass_reach", R, &P::bypass_reach, 95, 40, 150, 5, "", "cm",
            "chain_bypass, chain_bypass_pf: how near (camera distance) the parent's parent must be for a subgoal to skip its parent (d_sub + 10 cm: only where the chain folds back; near R_vis: wherever it is in view)",
            "§2.3 #15", {}},
  ParamInfo{ 0, "rest_recruit", B, &P::rest_recruit, 1, 0, 1, 1, "", "",
            "task allocation: a resting robot at its deployment point that sees the end of a chain (a RED subgoal nobody claims) for T_recruit ticks joins the path formation there and forms the next link (T10; it counts as allocated). Off: resting robots rest for good, the paper's reading",
            "§2.6 T10", {}},
  ParamInfo{ 0, "T_recruit", R, &P::t_recruit, 50, 0, 5000, 50, "", "ticks",
            "rest_recruit: how long a free RED subgoal stays in a resting robot's view before it joins; each robot waits up to as long again, drawn at random, so that one of several goes",
            "§2.6 T10", {}},
  ParamInfo{ 0, "recruit_call", B, &P::recruit_call, 1, 0, 1, 1, "", "",
            "task allocation, rest_recruit: a RED subgoal that no robot has claimed (formed from, or named as parent) for T_starve ticks calls for a link on the range-and-bearing medium (3 m, past the camera's 1 m); a resting robot at its deployment point that hears the call for T_recruit ticks (plus its draw) and no robot answering it goes there, claiming the subgoal on the medium on its way, and forms the next link (T10)",
            "§2.6 T10", {}},
  ParamInfo{ 0, "T_starve", R, &P::t_starve, 50, 0, 10000, 50, "", "ticks",
            "recruit_call: how long a RED subgoal goes unclaimed before it calls resting robots",
            "§2.6 T10", {}},
  ParamInfo{ 0, "refound_starved", B, &P::refound_starved, 1, 0, 1, 1, "", "",
            "task allocation, recruit_call: a chain's end (a RED subgoal nobody claims) still unclaimed after T_refound ticks, its call unanswered, leaves the chain and becomes a founder for the rest of the path (T12): it tells its parent (which then waits 3 T_refound before it may do the same), drives home along its trail, computes n = l/v + delta_refound from that trip's time (Eq. 1-3), allocates n robots from the resting ones with the protocol (REQUEST with flags bit 4; resting robots at their deployment points answer JOIN, the ACKed ones start path formation, T11) and leads them back to where it left its parent. Off: the chain waits for explorers and calls (the paper has no second allocation)",
            "§2.6 T11, T12", {}},
  ParamInfo{ 0, "T_refound", R, &P::t_refound, 1500, 100, 20000, 100, "", "ticks",
            "refound_starved: how long a chain's end goes unclaimed before it goes home to allocate more robots",
            "§2.6 T12", {}},
  ParamInfo{ 0, "delta_refound", R, &P::delta_refound, 0, 0, 60, 1, "", "robots",
            "refound_starved: the delta a chain's end adds to l/v when it allocates the rest of the path (the environment class's delta is the whole path's slack)",
            "§2.7 Eq. 3", {}},
};

// clang-format on

std::string fmt(double v) {
  std::ostringstream o;
  o << std::setprecision(12) << v;
  return o.str();
}

}  // namespace

std::span<const ParamInfo> param_table() { return kTable; }

const ParamInfo* find_param(std::string_view name) {
  for (const ParamInfo& info : kTable) {
    if (info.name == name) return &info;
  }
  return nullptr;
}

double get_value(const Params& p, const ParamInfo& info) {
  return std::visit(
      [&](auto member) -> double {
        using T = std::decay_t<decltype(p.*member)>;
        if constexpr (std::is_same_v<T, double>) {
          return p.*member;
        } else if constexpr (std::is_same_v<T, bool>) {
          return (p.*member) ? 1.0 : 0.0;
        } else {
          return static_cast<double>(static_cast<int>(p.*member));
        }
      },
      info.field);
}

void set_value(Params& p, const ParamInfo& info, double v) {
  std::visit(
      [&](auto member) {
        using T = std::decay_t<decltype(p.*member)>;
        if constexpr (std::is_same_v<T, double>) {
          p.*member = v;
        } else if constexpr (std::is_same_v<T, bool>) {
          p.*member = v != 0.0;
        } else {
          p.*member = static_cast<T>(static_cast<int>(std::lround(v)));
        }
      },
      info.field);
}

std::string format_value(const Params& p, const ParamInfo& info) {
  const double v = get_value(p, info);
  switch (info.type) {
    case ParamType::kBool:
      return v != 0.0 ? "true" : "false";
    case ParamType::kChoice:
      return "\"" + std::string(info.choices[v != 0.0 ? 1 : 0]) + "\"";
    case ParamType::kInteger:
    case ParamType::kReal:
      break;
  }
  return fmt(v);
}

std::string check_params(const Params& p) {
  for (const ParamInfo& info : kTable) {
    const double v = get_value(p, info);
    if (!std::isfinite(v) || v < info.lo || v > info.hi) {
      return std::string(info.name) + " = " + fmt(v) + " lies outside its range [" + fmt(info.lo) + ", " +
             fmt(info.hi) + "] (SPEC §7 row " + std::to_string(info.row) + ")";
    }
    if (info.type == ParamType::kInteger && v != std::floor(v)) {
      return std::string(info.name) + " = " + fmt(v) + " must be an integer";
    }
  }
  if (p.theta_soft > p.theta_hard)
    return "theta_soft (" + fmt(p.theta_soft) + ") must be <= theta_hard (" + fmt(p.theta_hard) + ")";
  if (p.theta_none > p.theta_soft)
    return "theta_none (" + fmt(p.theta_none) + ") must be <= theta_soft (" + fmt(p.theta_soft) + ")";
  if (p.d_sub >= p.r_vis) return "d_sub (" + fmt(p.d_sub) + ") must be < R_vis (" + fmt(p.r_vis) + ")";
  if (p.r_keep > p.r_vis) return "R_keep (" + fmt(p.r_keep) + ") must be <= R_vis (" + fmt(p.r_vis) + ")";
  if (p.t_explore0 > p.t_explore_max) {
    return "T_explore0 (" + fmt(p.t_explore0) + ") must be <= T_explore_max (" + fmt(p.t_explore_max) + ")";
  }
  return {};
}

namespace {

// the name of the parameter that check_params() complains about, for the error's line
std::string_view culprit(const std::string& message) {
  const auto end = message.find_first_of(" (");
  return std::string_view(message).substr(0, end);
}

// Switches that were measured and removed from the controller (docs/ablation.md): a params file that
// still names one is told so, instead of "unknown key".
struct RemovedParam {
  std::string_view name;
  std::string_view why;
};

constexpr std::string_view kNothingOnTraining =
    "it showed nothing on the training arenas' ablation (docs/ablation.md); the controller behaves as its "
    "off setting did";

constexpr std::array kRemoved{
    RemovedParam{"nudge_parent", "it changed no run of the ablation (docs/ablation.md)"},
    RemovedParam{
        "T_nudge",
        "it was nudge_parent's wait, and nudge_parent changed no run of the ablation (docs/ablation.md)"},
    RemovedParam{"align_taper",
                 "it cost about 400 ticks on the training arenas (docs/ablation.md); the alignment is SPEC "
                 "§2.4's V = v_align v_max P/|P| + D"},
    RemovedParam{"r_keep_pull",
                 "it showed no effect on the paper or the training arenas (docs/ablation.md); R_keep bounds "
                 "the target point P, as SPEC §2.4"},
    RemovedParam{"blocked_trip_ends", kNothingOnTraining},
    RemovedParam{"stop_at_view_edge", kNothingOnTraining},
    RemovedParam{"spot_patience", kNothingOnTraining},
};

Params parse(const TomlDoc& doc, const Params& base) {
  Params p = base;
  const TableReader root(doc, doc.root(), "");
  for (const std::string& key : root.keys()) {
    if (key == "meta") {
      (void)root.table("meta");  // free-form provenance: not checked
      continue;
    }
    for (const RemovedParam& gone : kRemoved) {
      if (key == gone.name)
        root.fail(key, "was removed from the controller: " + std::string(gone.why) + "; delete this line");
    }
    const ParamInfo* info = find_param(key);
    if (info == nullptr) continue;  // finish() reports it with a suggestion
    switch (info->type) {
      case ParamType::kBool:
        set_value(p, *info, root.boolean(key) ? 1.0 : 0.0);
        break;
      case ParamType::kChoice: {
        const std::string v = root.string(key);
        if (v == info->choices[0]) {
          set_value(p, *info, 0.0);
        } else if (v == info->choices[1]) {
          set_value(p, *info, 1.0);
        } else {
          root.fail(key, "must be \"" + std::string(info->choices[0]) + "\" or \"" +
                             std::string(info->choices[1]) + "\", got \"" + v + "\"");
        }
        break;
      }
      case ParamType::kInteger:
        set_value(p, *info, static_cast<double>(root.integer(key)));
        break;
      case ParamType::kReal:
        set_value(p, *info, root.number(key));
        break;
    }
    const double v = get_value(p, *info);
    if (v < info->lo || v > info->hi) {
      root.fail(key, "value " + fmt(v) + " lies outside its range [" + fmt(info->lo) + ", " + fmt(info->hi) +
                         "] (SPEC §7 row " + std::to_string(info->row) + ")");
    }
  }
  // unknown names, with a "did you mean": mark every known name as a valid key first
  for (const ParamInfo& info : kTable) root.allow(info.name);
  root.finish();
  if (const std::string err = check_params(p); !err.empty()) root.fail(culprit(err), err);
  return p;
}

}  // namespace

Params parse_params(std::string_view text, const std::string& name, const Params& base) {
  const TomlDoc doc = TomlDoc::parse_string(text, name);
  return parse(doc, base);
}

Params load_params(const std::string& path) {
  const TomlDoc doc = TomlDoc::parse_file(path);
  return parse(doc, Params{});
}

void write_params_toml(std::ostream& out, const Params& p, std::string_view header_comment) {
  if (!header_comment.empty()) out << header_comment;
  for (const ParamInfo& info : kTable) {
    std::string line = std::string(info.name) + " = " + format_value(p, info);
    if (line.size() < 32) line.resize(32, ' ');
    out << line << "# ";
    if (info.row > 0) out << "row " << info.row << ": ";
    if (!info.rule.empty()) out << "beyond " << info.rule << ": ";
    out << info.meaning;
    if (!info.unit.empty()) out << " [" << info.unit << "]";
    if (info.type == ParamType::kReal || info.type == ParamType::kInteger) {
      out << ", range " << fmt(info.lo) << "-" << fmt(info.hi);
    }
    if (!info.fixed.empty()) out << " (fixed: " << info.fixed << ")";
    out << "\n";
  }
}

}  // namespace swarmpath::sim
