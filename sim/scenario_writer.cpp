// SPDX-License-Identifier: MIT
#include "scenario_writer.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

namespace swarmpath::sim {

std::string toml_number(double v) {
  if (v == 0.0 && std::signbit(v)) return "-0.0";  // "-0" would read back as the integer 0
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

double yaw_degrees_exact(double yaw_rad) {
  const double d0 = rad2deg(yaw_rad);
  if (deg2rad(d0) == yaw_rad) return d0;
  double up = d0, down = d0;
  for (int k = 0; k < 16; ++k) {
    up = std::nextafter(up, HUGE_VAL);
    if (deg2rad(up) == yaw_rad) return up;
    down = std::nextafter(down, -HUGE_VAL);
    if (deg2rad(down) == yaw_rad) return down;
  }
  return d0;
}

namespace {

std::string pair(Vec2 v) { return "[" + toml_number(v.x) + ", " + toml_number(v.y) + "]"; }

std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string_view boolean(bool b) { return b ? "true" : "false"; }

}  // namespace

std::string write_scenario_toml(const Scenario& s, std::string_view header) {
  std::ostringstream o;
  if (!header.empty()) {
    o << header;
    if (header.back() != '\n') o << '\n';
  }
  o << "name = " << quoted(s.name) << "\n";
  o << "class = \"" << to_string(s.env_class)
    << "\"      # open | obstacle | complex (selects delta in Eq. 3)\n";
  o << "nest = " << pair(s.nest) << "   # BLUE beacon\n";
  o << "goal = " << pair(s.goal) << "   # YELLOW beacon\n";
  o << "\n[arena]\nsize = " << pair(s.arena_size) << "\nwall_thickness = " << toml_number(s.wall_thickness)
    << "\n";
  o << "\n[deployment]\ncenter = " << pair(s.deployment.center) << "\nsize = " << pair(s.deployment.size)
    << "\nmin_spacing = " << toml_number(s.min_spacing) << "\nrobots = " << s.robots << "\n";
  const SimSettings& m = s.sim;
  o << "\n[simulation]\nticks_per_second = " << m.ticks_per_second << "\nmax_ticks = " << m.max_ticks
    << "\nvelocity_iterations = " << m.velocity_iterations
    << "\nposition_iterations = " << m.position_iterations
    << "\nocclude_by_robots = " << boolean(m.occlude_by_robots)
    << "\nstop_when_complete = " << boolean(m.stop_when_complete)
    << "\ngrid_cell = " << toml_number(m.grid_cell) << "\nphysics_regions = [" << m.physics_regions_x << ", "
    << m.physics_regions_y << "]\n";
  if (s.faults.any()) {
    const FaultModel& f = s.faults;
    o << "\n[faults]\nfail_fraction = " << toml_number(f.fail_fraction) << "\nfail_window = [" << f.fail_from
      << ", " << f.fail_until << "]\nfail_target = " << quoted(std::string(to_string(f.fail_target)))
      << "\ncamera_miss = " << toml_number(f.camera_miss)
      << "\ncamera_false = " << toml_number(f.camera_false)
      << "\npacket_loss = " << toml_number(f.packet_loss) << "\nwheel_noise = " << toml_number(f.wheel_noise)
      << "\nposition_noise = " << toml_number(f.position_noise)
      << "\nheading_noise = " << toml_number(f.heading_noise) << "\n";
  }
  if (s.origin) {
    o << "\n[generator]             # swarmpath arena generate draws this arena again from these\n";
    o << "family = " << quoted(s.origin->family) << "\nseed = " << s.origin->seed
      << "\nversion = " << s.origin->version << "\nparams = {";
    for (std::size_t i = 0; i < s.origin->params.size(); ++i) {
      o << (i ? ", " : " ") << s.origin->params[i].first << " = " << toml_number(s.origin->params[i].second);
    }
    o << (s.origin->params.empty() ? "}" : " }") << "\n";
  }
  for (const BoxObstacle& b : s.boxes) {
    o << "\n[[box]]\ncenter = " << pair(b.center) << "\nsize = " << pair(b.size) << "\n";
    if (b.yaw != 0.0) o << "yaw_deg = " << toml_number(yaw_degrees_exact(b.yaw)) << "\n";
  }
  for (const CylinderObstacle& c : s.cylinders) {
    o << "\n[[cylinder]]\ncenter = " << pair(c.center) << "\nradius = " << toml_number(c.radius) << "\n";
  }
  return o.str();
}

}  // namespace swarmpath::sim
