// SPDX-License-Identifier: MIT
#include "faults.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "robot_model.hpp"
#include "toml_reader.hpp"

namespace swarmpath::sim {

std::string_view to_string(FailTarget t) {
  switch (t) {
    case FailTarget::kAny:
      return "any";
    case FailTarget::kChain:
      return "chain";
  }
  return "?";
}

std::optional<FailTarget> fail_target_from(std::string_view text) {
  for (const FailTarget t : {FailTarget::kAny, FailTarget::kChain}) {
    if (text == to_string(t)) return t;
  }
  return std::nullopt;
}

namespace {

std::string fmt(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

// "key must lie in [lo, hi] (got v)", or empty
std::string outside(std::string_view key, double v, double lo, double hi) {
  if (std::isfinite(v) && v >= lo && v <= hi) return {};
  return std::string(key) + " must lie in [" + fmt(lo) + ", " + fmt(hi) + "] (got " + fmt(v) + ")";
}

// the key an error message of check_faults() starts with
std::string_view culprit(const std::string& message) {
  return std::string_view(message).substr(0, message.find(' '));
}

// stream purposes, mixed with the run's seed (never the robots' own "robot" streams)
constexpr std::uint64_t kFailureStream = 0x6661696c757265ULL;  // "failure"
constexpr std::uint64_t kVictimStream = 0x76696374696dULL;     // "victim"
constexpr std::uint64_t kCameraStream = 0x63616d657261ULL;     // "camera"
constexpr std::uint64_t kRabStream = 0x726162ULL;              // "rab"
constexpr std::uint64_t kWheelStream = 0x776865656cULL;        // "wheel"
constexpr std::uint64_t kPoseStream = 0x706f7365ULL;           // "pose"

}  // namespace

std::string check_faults(const FaultModel& f) {
  for (const std::string& e :
       {outside("fail_fraction", f.fail_fraction, 0, 1), outside("camera_miss", f.camera_miss, 0, 1),
        outside("camera_false", f.camera_false, 0, 1), outside("packet_loss", f.packet_loss, 0, 1),
        outside("wheel_noise", f.wheel_noise, 0, kMaxWheelNoise),
        outside("position_noise", f.position_noise, 0, kMaxPositionNoiseCm),
        outside("heading_noise", f.heading_noise, 0, kMaxHeadingNoiseDeg)}) {
    if (!e.empty()) return e;
  }
  if (f.fail_from < 0 || f.fail_until < f.fail_from) {
    return "fail_window must be two tick counts [from, until] with 0 <= from <= until (got [" +
           std::to_string(f.fail_from) + ", " + std::to_string(f.fail_until) + "])";
  }
  return {};
}

FaultModel parse_faults(const TableReader& t) {
  FaultModel f;
  f.fail_fraction = t.number_or("fail_fraction", f.fail_fraction);
  if (t.has("fail_window")) {
    const Vec2 w = t.vec2("fail_window");
    if (w.x != std::floor(w.x) || w.y != std::floor(w.y) || std::fabs(w.x) > 1e12 || std::fabs(w.y) > 1e12)
      t.fail("fail_window",
             "must be two whole tick counts [from, until] (got [" + fmt(w.x) + ", " + fmt(w.y) + "])");
    f.fail_from = static_cast<std::int64_t>(w.x);
    f.fail_until = static_cast<std::int64_t>(w.y);
  }
  const std::string target = t.string_or("fail_target", "any");
  const std::optional<FailTarget> ft = fail_target_from(target);
  if (!ft) t.fail("fail_target", "must be \"any\" or \"chain\", got \"" + target + "\"");
  f.fail_target = *ft;
  f.camera_miss = t.number_or("camera_miss", f.camera_miss);
  f.camera_false = t.number_or("camera_false", f.camera_false);
  f.packet_loss = t.number_or("packet_loss", f.packet_loss);
  f.wheel_noise = t.number_or("wheel_noise", f.wheel_noise);
  f.position_noise = t.number_or("position_noise", f.position_noise);
  f.heading_noise = t.number_or("heading_noise", f.heading_noise);
  t.finish();
  if (const std::string err = check_faults(f); !err.empty()) t.fail(culprit(err), err);
  return f;
}

FaultState make_fault_state(const FaultModel& f, int robots, std::uint64_t seed) {
  FaultState st;
  st.model = f;
  const auto n = static_cast<std::size_t>(std::max(robots, 0));
  st.failed.assign(n, 0);
  st.noisy = f.camera_miss > 0 || f.camera_false > 0 || f.packet_loss > 0 || f.wheel_noise > 0 ||
             f.position_noise > 0 || f.heading_noise > 0;
  if (st.noisy) {
    st.noise.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      st.noise.push_back({Rng(mix_seed(seed, kCameraStream, i)), Rng(mix_seed(seed, kRabStream, i)),
                          Rng(mix_seed(seed, kWheelStream, i)), Rng(mix_seed(seed, kPoseStream, i))});
    }
  }
  if (f.fail_fraction <= 0 || n == 0) return st;
  // round(f N) failures at times uniform over the window; FailTarget::kAny draws the robots now
  // (a partial Fisher-Yates shuffle), kChain at each failure's time from its own stream
  const auto count = static_cast<std::size_t>(std::llround(f.fail_fraction * static_cast<double>(n)));
  Rng rng(mix_seed(seed, kFailureStream));
  std::vector<int> ids(n);
  for (std::size_t i = 0; i < n; ++i) ids[i] = static_cast<int>(i);
  const auto span = static_cast<std::uint64_t>(f.fail_until - f.fail_from) + 1;
  for (std::size_t k = 0; k < count; ++k) {
    FailureEvent e;
    e.tick = f.fail_from + static_cast<std::int64_t>(rng.below(span));
    if (f.fail_target == FailTarget::kAny) {
      const std::size_t j = k + static_cast<std::size_t>(rng.below(n - k));
      std::swap(ids[k], ids[j]);
      e.robot = ids[k];
    }
    st.schedule.push_back(e);
  }
  std::stable_sort(st.schedule.begin(), st.schedule.end(),
                   [](const FailureEvent& a, const FailureEvent& b) { return a.tick < b.tick; });
  st.victims = Rng(mix_seed(seed, kVictimStream));
  return st;
}

bool is_chain_light(Led c) {
  return c == Led::kRed || c == Led::kMagenta || c == Led::kBlue || c == Led::kPurple || c == Led::kBrown;
}

void camera_noise(const FaultModel& f, Rng& rng, double range_m, std::vector<Blob>& blobs, std::size_t from) {
  if (f.camera_miss > 0) {
    std::size_t kept = from;
    for (std::size_t k = from; k < blobs.size(); ++k) {
      if (!rng.bernoulli(f.camera_miss)) blobs[kept++] = blobs[k];
    }
    blobs.resize(kept);
  }
  if (f.camera_false > 0 && rng.bernoulli(f.camera_false)) {
    // the colours a robot's LEDs show (SPEC §2.2), not black (off) and not the beacons' yellow
    static constexpr Led kColours[] = {Led::kGreen,   Led::kGray50, Led::kWhite,  Led::kRed,
                                       Led::kMagenta, Led::kBlue,   Led::kPurple, Led::kBrown,
                                       Led::kOrange,  Led::kCyan,   Led::kGray80};
    constexpr auto kCount = sizeof kColours / sizeof kColours[0];
    Blob b;
    b.color = kColours[rng.below(kCount)];
    b.emitter = kPhantomEmitter;
    // uniform over the ring from touching bodies (2 radii) to the camera's range
    const double r0 = 2.0 * kRobotRadius;
    const double r = std::sqrt(r0 * r0 + (range_m * range_m - r0 * r0) * rng.uniform());
    const double a = rng.uniform(-kPi, kPi);
    b.dir = {std::cos(a), std::sin(a)};
    b.distance_cm = 100.0 * r;
    blobs.push_back(b);
  }
}

void rab_noise(const FaultModel& f, Rng& rng, std::vector<RabMessage>& inbox, std::size_t from) {
  if (f.packet_loss <= 0) return;
  std::size_t kept = from;
  for (std::size_t k = from; k < inbox.size(); ++k) {
    if (!rng.bernoulli(f.packet_loss)) inbox[kept++] = inbox[k];
  }
  inbox.resize(kept);
}

Pose pose_noise(const FaultModel& f, Rng& rng, const Pose& truth) {
  Pose out = truth;
  if (f.position_noise > 0) {
    const double sigma = f.position_noise / 100.0;
    out.p.x += sigma * rng.normal();
    out.p.y += sigma * rng.normal();
  }
  if (f.heading_noise > 0) {
    const double da = deg2rad(f.heading_noise) * rng.normal();
    out.c = truth.c * std::cos(da) - truth.s * std::sin(da);
    out.s = truth.s * std::cos(da) + truth.c * std::sin(da);
  }
  return out;
}

void wheel_noise(const FaultModel& f, Rng& rng, double& left, double& right) {
  if (f.wheel_noise <= 0) return;
  const double nl = rng.normal();
  const double nr = rng.normal();
  left *= 1.0 + f.wheel_noise * nl;
  right *= 1.0 + f.wheel_noise * nr;
}

}  // namespace swarmpath::sim
