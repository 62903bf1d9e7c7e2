// SPDX-License-Identifier: MIT
// Faults and sensor noise [R] (the paper claims fault tolerance but models none): robots that
// fail-stop during the run, camera misses and false blobs, range-and-bearing packet loss,
// wheel-speed noise and positioning noise. Off by default. Every draw comes from streams derived
// from the run's seed apart from the robots' own streams, one per source and robot, and a rate of
// zero draws nothing: a run without faults is bit-identical to one before the model existed, and
// turning one source on leaves the draws of the others as they were.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "percept.hpp"
#include "rng.hpp"

namespace swarmpath::sim {

class TableReader;

/// Which robots fail.
enum class FailTarget : std::uint8_t {
  kAny,    ///< robots drawn from the whole swarm at deployment
  kChain,  ///< at each failure time, a robot then showing a chain link's light (RED ... BROWN)
};

std::string_view to_string(FailTarget t);

/// "any" or "chain" (the `fail_target` key, --fail-target); nullopt for anything else.
std::optional<FailTarget> fail_target_from(std::string_view text);

/// The fault and noise model of a scenario (`[faults]` in its file, or command-line overrides).
struct FaultModel {
  double fail_fraction = 0;        ///< share of the swarm that fail-stops, round(f N) robots [0, 1]
  std::int64_t fail_from = 0;      ///< failure times are uniform over [fail_from, fail_until] [ticks]
  std::int64_t fail_until = 5000;  ///< (paper arenas: the goal is found by ~1000, paths form after 3250)
  FailTarget fail_target = FailTarget::kAny;
  double camera_miss = 0;     ///< probability that the camera misses a blob it would see, per blob and tick
  double camera_false = 0;    ///< probability of one false blob, per robot and tick
  double packet_loss = 0;     ///< probability that a range-and-bearing message is lost, per receiver
  double wheel_noise = 0;     ///< standard deviation of each wheel's speed, relative to it, per tick
  double position_noise = 0;  ///< standard deviation of the positioning sensor's x and y [cm]
  double heading_noise = 0;   ///< standard deviation of the positioning sensor's heading [deg]

  bool any() const {
    return fail_fraction > 0 || camera_miss > 0 || camera_false > 0 || packet_loss > 0 || wheel_noise > 0 ||
           position_noise > 0 || heading_noise > 0;
  }
};

/// Emitter id of a false camera blob: matches no robot and no beacon.
inline constexpr int kPhantomEmitter = -3;

/// Upper bounds that catch absurd noise levels.
inline constexpr double kMaxWheelNoise = 2.0;       ///< relative
inline constexpr double kMaxPositionNoiseCm = 500;  ///< [cm]
inline constexpr double kMaxHeadingNoiseDeg = 180;  ///< [deg]

/// An empty string when `f` is valid, else what is wrong, starting with the key's name
/// (fail_fraction, fail_window, ...).
std::string check_faults(const FaultModel& f);

/// Reads a `[faults]` table (every key optional); throws ConfigError at the offending key.
FaultModel parse_faults(const TableReader& t);

/// One robot's noise streams, one per source, so that one source's draws never shift another's.
struct RobotNoise {
  Rng camera;
  Rng rab;
  Rng wheels;
  Rng pose;
};

/// A robot that fails at `tick` (`robot` < 0: the victim is drawn then, FailTarget::kChain).
struct FailureEvent {
  std::int64_t tick = 0;
  int robot = -1;
};

/// The faults of one run (part of the World).
struct FaultState {
  FaultModel model;                    ///< the scenario's
  bool noisy = false;                  ///< some noise source is on (streams allocated)
  std::vector<RobotNoise> noise;       ///< per robot, when noisy
  std::vector<std::uint8_t> failed;    ///< per robot: has failed (always sized, zeros without faults)
  std::vector<FailureEvent> schedule;  ///< by tick
  std::size_t next = 0;                ///< the first event not yet due
  Rng victims;                         ///< FailTarget::kChain: draws each victim at its time
  int failures = 0;                    ///< robots failed so far
  int chain_failures = 0;              ///< of them, robots showing a chain link's light when they failed
};

/// The faults of a run of `robots` robots with `seed`: the failure schedule is drawn here.
FaultState make_fault_state(const FaultModel& f, int robots, std::uint64_t seed);

/// The lights of a chain link: SUBGOAL (RED) through PATH_DONE (BROWN) (SPEC §2.2).
bool is_chain_light(Led c);

/// Camera: drops blobs[from..] each with probability camera_miss, then adds a false blob with
/// probability camera_false: a robot's light of a random colour at a random point within `range_m`.
void camera_noise(const FaultModel& f, Rng& rng, double range_m, std::vector<Blob>& blobs, std::size_t from);

/// Range and bearing: drops inbox[from..] each with probability packet_loss.
void rab_noise(const FaultModel& f, Rng& rng, std::vector<RabMessage>& inbox, std::size_t from);

/// Positioning sensor: the pose read, with Gaussian noise on x, y and the heading.
Pose pose_noise(const FaultModel& f, Rng& rng, const Pose& truth);

/// Wheels: each speed times (1 + wheel_noise n), n standard normal (a stopped wheel stays stopped).
void wheel_noise(const FaultModel& f, Rng& rng, double& left, double& right);

}  // namespace swarmpath::sim
