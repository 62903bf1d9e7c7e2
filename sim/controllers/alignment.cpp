// SPDX-License-Identifier: MIT
#include "alignment.hpp"

#include <algorithm>
#include <cmath>

#include "path_formation.hpp"
#include "sim/controller.hpp"
#include "units.hpp"

namespace swarmpath::sim {

double error_angle(double theta1, double theta2) { return kPi - std::fabs(wrap_angle(theta1 - theta2)); }

Vec2 alignment_target(Vec2 a, Vec2 b, const Params& p) {
  const Vec2 ab = b - a;
  const double len2 = norm2(ab);
  if (len2 == 0.0) return a;
  const double len = std::sqrt(len2);
  // foot of the perpendicular from the origin (the robot)
  double t = std::clamp(dot(-a, ab) / len2, 0.0, 1.0);
  // keep both references in sight: |P - A| = t |AB| <= R_keep and |P - B| = (1 - t) |AB| <= R_keep
  const double t_hi = p.r_keep / len;
  const double t_lo = 1.0 - p.r_keep / len;
  t = t_lo > t_hi ? 0.5 : std::clamp(t, std::max(0.0, t_lo), std::min(1.0, t_hi));
  const Vec2 foot = a + t * ab;
  return (1.0 - p.lambda_mid) * foot + p.lambda_mid * (0.5 * (a + b));
}

bool aligned(double theta1, double theta2, Vec2 target, const Params& p) {
  return error_angle(theta1, theta2) <= deg2rad(p.e_tol) || norm(target) <= p.d_tol;
}

namespace {

// back where the alignment began: align() stops within d_tol of it (1 cm for the bodies' give)
bool back_at_safe_pos(const Pose& pose, const PfMemory& m, const Params& p) {
  return dist(pose.p, m.safe_pos) / kCm <= p.d_tol + 1.0;
}

bool view_limited(const PfMemory& m) { return m.align_leg != AlignLeg::kToFoot; }

// R (seek_hidden_reference): the one reference out of view (`debounced`: lost, else not seen this
// tick) while T_align_max is not spent, or nullptr (both in view, or both out of it)
const Tracked* hidden_reference(const PfMemory& m, const Params& p, bool debounced) {
  if (!p.seek_hidden_reference || !p.align_keep_view || static_cast<double>(m.t_state) >= p.t_align_max)
    return nullptr;
  const bool parent_out = debounced ? lost(m.parent, p) : !m.parent.visible;
  const bool child_out = debounced ? lost(m.child, p) : !m.child.visible;
  if (parent_out == child_out) return nullptr;
  return parent_out ? &m.parent : &m.child;
}

bool seeking_reference(const PfContext& c) {  // R: one reference out of view, looked for (align())
  const Tracked* hidden = hidden_reference(c.m, c.p, true);
  return hidden != nullptr && dist(c.in.pose.p, hidden->last_seen) / kCm > c.p.d_detect;  // not there yet
}

// align_keep_view: where a reference slips out of view (or time runs out), back to where the
// alignment began; seek_hidden_reference: still out of view from there, look for it where it was last
// seen; found (both in view), stay there
void next_align_leg(const Percept& in, const Params& p, PfMemory& m) {
  if (p.align_keep_view && m.align_leg == AlignLeg::kToFoot &&
      (!m.parent.visible || !m.child.visible || static_cast<double>(m.t_state) >= p.t_align_max)) {
    m.align_leg = AlignLeg::kBackToStart;
  }
  const Tracked* hidden = hidden_reference(m, p, false);
  if (hidden != nullptr && m.align_leg == AlignLeg::kBackToStart && back_at_safe_pos(in.pose, m, p))
    m.align_leg = AlignLeg::kSeekReference;
  if (m.align_leg == AlignLeg::kSeekReference && hidden == nullptr && m.parent.visible && m.child.visible) {
    m.align_leg = AlignLeg::kBackToStart;
    m.safe_pos = in.pose.p;  // found it: both in view here
  }
}

}  // namespace

bool alignment_done(const PfContext& c) {
  const bool both_seen = c.m.parent.visible && c.m.child.visible;
  // out of time: done, provided both references are in view (else first back to the start; SPEC: done)
  if (static_cast<double>(c.m.t_state) >= c.p.t_align_max && (both_seen || !c.p.align_keep_view)) return true;
  if (lost(c.m.parent, c.p) || lost(c.m.child, c.p)) return false;
  // as aligned as the view allows: a reference slipped out of sight; back at the start, both in view
  if (view_limited(c.m) && both_seen && back_at_safe_pos(c.in.pose, c.m, c.p)) return true;
  const Vec2 a = local_cm(c.in.pose, c.m.parent);
  const Vec2 b = local_cm(c.in.pose, c.m.child);
  return aligned(angle_of(a), angle_of(b), alignment_target(a, b, c.p), c.p);
}

bool parent_done_or_last_subgoal(const PfContext& c) {
  return c.m.parent.id == kGoalEmitter || (c.m.parent.visible && c.m.parent.color == Led::kBrown);
}

bool reference_lost(const PfContext& c) {
  // a reference that slipped behind an obstacle while the robot moved counts as lost only once
  // the robot is back where it last saw both and it is still out of sight, and (option) it has
  // looked for it where it was last seen
  if (seeking_reference(c)) return false;
  // (or, stall guard, cannot get back there in another T_align_max)
  const bool back = !view_limited(c.m) || back_at_safe_pos(c.in.pose, c.m, c.p) ||
                    static_cast<double>(c.m.t_state) >= 2.0 * c.p.t_align_max;
  return (lost(c.m.parent, c.p) || lost(c.m.child, c.p)) && back;
}

Command look_for(const Percept& in, const Params& p, RobotMemory& mem, Vec2 toward, PfState s) {
  const Avoidance avoid = diffusion(in.proximity, p);
  Vec2 v = (1.0 / std::max(norm(toward), 1e-9)) * toward;
  if (avoid.collision) v += avoid.direction;
  return pf_drive(p, mem, p.v_align * p.v_max * v, s);
}

// SPEC §2.4: drive to the alignment target P at v_align v_max with the diffusion vector D, and stop
// within d_tol of it.
Command align(const Percept& in, const Params& p, RobotMemory& mem, PfState s) {
  PfMemory& m = mem.pf;
  next_align_leg(in, p, m);
  if (m.align_leg == AlignLeg::kSeekReference) {
    // still out of view from the start (a subgoal's parent just behind an obstacle's corner): toward
    // where it was last seen until both are in view (R)
    const Tracked* hidden = hidden_reference(m, p, false);
    if (hidden != nullptr) return look_for(in, p, mem, local_cm(in.pose, *hidden), s);
  }
  const Vec2 a = local_cm(in.pose, m.parent);
  const Vec2 b = local_cm(in.pose, m.child);
  const Vec2 target =
      view_limited(m) ? (1.0 / kCm) * in.pose.to_local(m.safe_pos - in.pose.p) : alignment_target(a, b, p);
  const double len = norm(target);
  if (len <= p.d_tol) return pf_stop(s);
  const Avoidance avoid = diffusion(in.proximity, p);
  const Vec2 v = (1.0 / len) * target;
  // SPEC §2.4 as written: V = v_align v_max P/|P| + D, D the diffusion vector
  return pf_drive(p, mem, p.v_align * p.v_max * v + avoid.direction, s);
}

}  // namespace swarmpath::sim
