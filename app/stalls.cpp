// SPDX-License-Identifier: MIT
#include "stalls.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <map>
#include <string>
#include <string_view>

namespace swarmpath::app {

namespace {

// the states in which a robot is meant to move: path formation's exploring, going home and forming
// a subgoal, and a goal founder's (home, then its protocol); not a robot that task allocation told
// to rest or to wait at the nest, whatever its path-formation state
bool travelling(std::string_view state) {
  if (state.starts_with("resting_task/") || state.starts_with("decision_maker/")) return false;
  if (state.starts_with("goal_founder/")) return true;
  const std::size_t slash = state.rfind('/');
  const std::string_view pf = state.substr(slash == std::string_view::npos ? 0 : slash + 1);
  return pf == "exploring" || pf == "return_to_nest" || pf == "subgoal_forming";
}

}  // namespace

std::vector<Stall> find_stalls(const sim::Recording& r) {
  std::vector<Stall> out;
  const std::size_t frames = r.frame_count();
  const auto n = static_cast<std::size_t>(r.robots);
  const auto code = [&](std::size_t f, int i) { return r.state[f * n + static_cast<std::size_t>(i)]; };
  for (int i = 0; i < r.robots; ++i) {
    std::size_t begin = 0;  // the frame the current stay began at
    for (std::size_t f = 1; f <= frames; ++f) {
      const bool stays = f < frames && code(f, i) == code(begin, i) &&
                         100.0 * dist(r.position(f, i), r.position(begin, i)) <= kStallCm;
      if (stays) continue;
      const std::int64_t ticks = r.frame_ticks[f - 1] - r.frame_ticks[begin];
      if (ticks >= kStallTicks && travelling(r.state_name(code(begin, i))))
        out.push_back({i, code(begin, i), r.frame_ticks[begin], ticks, r.position(begin, i)});
      begin = f;
    }
  }
  return out;
}

nlohmann::ordered_json stalls_json(const sim::Recording& r) {
  std::vector<Stall> all = find_stalls(r);
  std::map<std::string, std::pair<std::int64_t, std::int64_t>> by_state;  // count, robot-ticks
  std::int64_t robot_ticks = 0;
  for (const Stall& s : all) {
    auto& [count, ticks] = by_state[std::string(r.state_name(s.state))];
    ++count;
    ticks += s.ticks;
    robot_ticks += s.ticks;
  }
  nlohmann::ordered_json states = nlohmann::ordered_json::object();
  for (const auto& [name, v] : by_state) states[name] = {{"count", v.first}, {"robot_ticks", v.second}};
  std::stable_sort(all.begin(), all.end(), [](const Stall& a, const Stall& b) { return a.ticks > b.ticks; });
  nlohmann::ordered_json longest = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < std::min<std::size_t>(10, all.size()); ++k) {
    const Stall& s = all[k];
    const auto round_cm = [](double m) { return std::round(100.0 * m) / 100.0; };
    longest.push_back({{"robot", s.robot},
                       {"state", std::string(r.state_name(s.state))},
                       {"from_tick", s.from},
                       {"ticks", s.ticks},
                       {"x", round_cm(s.at.x)},
                       {"y", round_cm(s.at.y)},
                       {"from_nest_m", round_cm(dist(s.at, r.nest))}});
  }
  return {
      {"min_ticks", kStallTicks},   {"within_cm", kStallCm}, {"count", static_cast<std::int64_t>(all.size())},
      {"robot_ticks", robot_ticks}, {"by_state", states},    {"longest", longest}};
}

}  // namespace swarmpath::app
