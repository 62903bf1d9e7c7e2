// SPDX-License-Identifier: MIT
#include "fault_options.hpp"

#include <algorithm>
#include <sstream>

#include <CLI/CLI.hpp>

#include "common.hpp"
#include "sim/config_error.hpp"

namespace swarmpath::app {

void add_fault_options(CLI::App& app, FaultOptions& o, bool sweep) {
  const std::string g = "Faults and noise (override the scenarios' [faults]; docs/faults.md)";
  if (!sweep) {
    app.add_option("--fail-fraction", o.fail_fraction,
                   "Share of the robots that fail-stop during the run (0-1): they stop, their LEDs go dark, "
                   "they sense and send nothing, and stay where they are as obstacles")
        ->group(g);
  }
  app.add_option("--fail-window", o.fail_window,
                 "Failure times are uniform over these ticks, FROM,UNTIL (default 0,5000)")
      ->delimiter(',')
      ->expected(2)
      ->group(g);
  app.add_option("--fail-target", o.fail_target,
                 "any (robots drawn from the whole swarm) or chain (at each failure time, a robot showing a "
                 "chain link's light, RED to BROWN)")
      ->group(g);
  app.add_option("--camera-miss", o.camera_miss,
                 "Probability that the camera misses a blob it would see, per blob and tick (0-1)")
      ->group(g);
  app.add_option("--camera-false", o.camera_false,
                 "Probability of a false blob (a robot's light of a random colour within R_vis, no id), per "
                 "robot and tick (0-1)")
      ->group(g);
  if (!sweep) {
    app.add_option("--packet-loss", o.packet_loss,
                   "Probability that a range-and-bearing message is lost, per receiver (0-1)")
        ->group(g);
  }
  app.add_option("--wheel-noise", o.wheel_noise,
                 "Standard deviation of each wheel's speed relative to the command, per tick (0-2)")
      ->group(g);
  app.add_option("--position-noise", o.position_noise,
                 "Standard deviation of the positioning sensor's x and y, in cm (0-500)")
      ->group(g);
  app.add_option("--heading-noise", o.heading_noise,
                 "Standard deviation of the positioning sensor's heading, in degrees (0-180)")
      ->group(g);
}

namespace {

std::string fmt(double v) {
  std::ostringstream o;
  o << v;
  return o.str();
}

// fail_window -> --fail-window
std::string option_of(std::string_view key) {
  std::string option = "--" + std::string(key);
  std::replace(option.begin(), option.end(), '_', '-');
  return option;
}

}  // namespace

sim::FaultModel apply_fault_options(const sim::FaultModel& base, const FaultOptions& o) {
  sim::FaultModel f = base;
  if (o.fail_fraction) f.fail_fraction = *o.fail_fraction;
  if (!o.fail_window.empty()) {
    if (o.fail_window.size() != 2)
      throw sim::ConfigError("--fail-window", 0, "", "must be FROM,UNTIL ticks with 0 <= FROM <= UNTIL");
    f.fail_from = o.fail_window[0];
    f.fail_until = o.fail_window[1];
  }
  if (o.fail_target) {
    const std::optional<sim::FailTarget> t = sim::fail_target_from(*o.fail_target);
    if (!t)
      throw sim::ConfigError("--fail-target", 0, "", "must be any or chain, got \"" + *o.fail_target + "\"");
    f.fail_target = *t;
  }
  if (o.camera_miss) f.camera_miss = *o.camera_miss;
  if (o.camera_false) f.camera_false = *o.camera_false;
  if (o.packet_loss) f.packet_loss = *o.packet_loss;
  if (o.wheel_noise) f.wheel_noise = *o.wheel_noise;
  if (o.position_noise) f.position_noise = *o.position_noise;
  if (o.heading_noise) f.heading_noise = *o.heading_noise;
  // the ranges of a [faults] table (the scenario's own values were checked at load), blamed on the
  // option that set the value
  if (const std::string e = sim::check_faults(f); !e.empty())
    throw sim::ConfigError(option_of(std::string_view(e).substr(0, e.find(' '))), 0, "", e);
  return f;
}

nlohmann::ordered_json faults_json(const sim::FaultModel& f) {
  return {{"fail_fraction", f.fail_fraction},
          {"fail_window", {f.fail_from, f.fail_until}},
          {"fail_target", std::string(sim::to_string(f.fail_target))},
          {"camera_miss", f.camera_miss},
          {"camera_false", f.camera_false},
          {"packet_loss", f.packet_loss},
          {"wheel_noise", f.wheel_noise},
          {"position_noise", f.position_noise},
          {"heading_noise", f.heading_noise}};
}

std::string faults_text(const sim::FaultModel& f) {
  std::string t;
  const auto add = [&](bool on, const std::string& what) {
    if (on) t += (t.empty() ? "" : ", ") + what;
  };
  add(f.fail_fraction > 0, "fail " + fmt(100 * f.fail_fraction) + " % (" +
                               std::string(sim::to_string(f.fail_target)) + ", ticks " +
                               std::to_string(f.fail_from) + "-" + std::to_string(f.fail_until) + ")");
  add(f.camera_miss > 0, "camera misses " + fmt(100 * f.camera_miss) + " %");
  add(f.camera_false > 0, "false blobs " + fmt(100 * f.camera_false) + " %");
  add(f.packet_loss > 0, "packet loss " + fmt(100 * f.packet_loss) + " %");
  add(f.wheel_noise > 0, "wheel noise " + fmt(100 * f.wheel_noise) + " %");
  add(f.position_noise > 0, "position noise " + fmt(f.position_noise) + " cm");
  add(f.heading_noise > 0, "heading noise " + fmt(f.heading_noise) + " deg");
  return t.empty() ? "none" : t;
}

sim::Scenario with_fault_options(const sim::Scenario& s, const FaultOptions& o) {
  return sim::with_faults(s, apply_fault_options(s.faults, o));
}

}  // namespace swarmpath::app
