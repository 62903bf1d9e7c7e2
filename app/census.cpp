// SPDX-License-Identifier: MIT
#include "census.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "stalls.hpp"

namespace swarmpath::app {

namespace {

// "path_formation/exploring" and "exploring" (without task allocation) are both exploring
bool exploring(std::string_view state) {
  const std::size_t slash = state.rfind('/');
  return state.substr(slash == std::string_view::npos ? 0 : slash + 1) == "exploring";
}

std::string row_name(const std::vector<sim::RowName>& rows, int row) {
  const auto i = static_cast<std::size_t>(row - 1);
  return i < rows.size() ? rows[i].row : "row " + std::to_string(row);
}

// counts as a JSON object, the largest first (ties: by name)
nlohmann::ordered_json by_count(const std::map<std::string, std::int64_t>& counts) {
  std::vector<std::pair<std::string, std::int64_t>> v(counts.begin(), counts.end());
  std::stable_sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
  nlohmann::ordered_json o = nlohmann::ordered_json::object();
  for (const auto& [name, n] : v) o[name] = n;
  return o;
}

// the trips in one exploring state: how many, how long those that ended lasted, what they ended in
struct Trips {
  std::int64_t count = 0;
  std::vector<std::int64_t> ticks;
  std::map<std::string, std::int64_t> ended_in;
};

double median(std::vector<std::int64_t> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 == 1 ? static_cast<double>(v[m]) : 0.5 * static_cast<double>(v[m - 1] + v[m]);
}

}  // namespace

nlohmann::ordered_json census(const sim::Recording& r) {
  const auto n = static_cast<std::size_t>(r.robots);
  // each robot's state at tick 0: the first change's `from`, else the first frame's
  std::vector<int> state(n, 0);
  std::vector<bool> seen(n, false);
  for (std::size_t i = 0; i < n && r.frame_count() > 0; ++i) state[i] = r.state[i];
  for (const sim::StateChange& c : r.changes) {
    const auto i = static_cast<std::size_t>(c.robot);
    if (i >= n || seen[i]) continue;
    seen[i] = true;
    state[i] = c.from;
  }
  std::map<std::string, std::int64_t> ticks_in;
  std::map<std::string, std::int64_t> pf_rows;
  std::map<std::string, std::int64_t> ta_rows;
  std::map<std::string, Trips> trips;           // by the exploring state the trip stays in
  std::vector<std::int64_t> since(n, 0);        // the tick the current state began
  std::vector<std::int64_t> trip_start(n, -1);  // the tick the current trip began (-1: none)
  std::vector<std::string> trip_from(n);
  for (std::size_t i = 0; i < n; ++i) {
    if (!exploring(r.state_name(state[i]))) continue;
    trip_start[i] = 0;
    trip_from[i] = r.state_name(state[i]);
    ++trips[trip_from[i]].count;
  }
  for (const sim::StateChange& c : r.changes) {
    const auto i = static_cast<std::size_t>(c.robot);
    if (i >= n) continue;
    ticks_in[std::string(r.state_name(state[i]))] += c.tick - since[i];
    since[i] = c.tick;
    state[i] = c.to;
    if (c.pf_row > 0) ++pf_rows[row_name(r.pf_rows, c.pf_row)];
    if (c.ta_row > 0) ++ta_rows[row_name(r.ta_rows, c.ta_row)];
    const std::string_view to = r.state_name(c.to);
    if (trip_start[i] >= 0) {  // a stay in one exploring state ends with any change
      Trips& t = trips[trip_from[i]];
      t.ticks.push_back(c.tick - trip_start[i]);
      ++t.ended_in[std::string(to)];
      trip_start[i] = -1;
    }
    if (exploring(to)) {
      trip_start[i] = c.tick;
      trip_from[i] = to;
      ++trips[trip_from[i]].count;
    }
  }
  for (std::size_t i = 0; i < n; ++i) ticks_in[std::string(r.state_name(state[i]))] += r.ticks - since[i];

  nlohmann::ordered_json by_start = nlohmann::ordered_json::object();
  for (const auto& [from, t] : trips) {
    by_start[from] = {{"count", t.count},
                      {"ended", static_cast<std::int64_t>(t.ticks.size())},
                      {"median_ticks", median(t.ticks)},
                      {"ended_in", by_count(t.ended_in)}};
  }
  nlohmann::ordered_json rows = nlohmann::ordered_json::object();
  rows["path_formation"] = by_count(pf_rows);
  if (!ta_rows.empty()) rows["task_allocation"] = by_count(ta_rows);
  return {{"scenario", r.scenario_name},
          {"mode", std::string(sim::to_string(r.mode))},
          {"robots", r.robots},
          {"seed", r.seed},
          {"ticks", r.ticks},
          {"success", r.success},
          {"robot_ticks", by_count(ticks_in)},
          {"rows_fired", rows},
          {"trips", by_start},
          {"stalls", stalls_json(r)}};
}

}  // namespace swarmpath::app
