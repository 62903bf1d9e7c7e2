// SPDX-License-Identifier: MIT
// Recordings (.swrec): a recorded run is the same run; frames hold what the world held; the state
// changes replay to the frames' states; the bytes read back to the same recording; bad bytes are
// rejected with a message; a 100-robot, 36 000-tick run fits in 10 MB.
#include "sim/recording.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include <gtest/gtest.h>

#include "sim/config_error.hpp"
#include "sim/recorder.hpp"
#include "sim/step.hpp"
#include "test_support.hpp"

namespace swarmpath::sim {
namespace {

Scenario short_chain() { return load_scenario(test::source_path("tests/data/short_chain.toml")); }

Scenario env4(int robots, std::int64_t ticks) {
  return with_max_ticks(with_robots(load_scenario(test::paper_env(4)), robots), ticks);
}

TEST(Recording, ARecordedRunIsTheSameRun) {
  for (const Mode mode : {Mode::kPathFormation, Mode::kTaskAllocation}) {
    const Scenario s = short_chain();
    const Metrics plain = evaluate(Params{}, s, mode, 5);
    Metrics recorded;
    const Recording r = record_run(Params{}, s, mode, 5, 10, &recorded);
    EXPECT_EQ(recorded.state_hash, plain.state_hash) << to_string(mode);
    EXPECT_EQ(recorded.ticks, plain.ticks);
    EXPECT_EQ(r.state_hash, plain.state_hash);
    EXPECT_EQ(r.ticks, plain.ticks);
    EXPECT_EQ(r.success, plain.success);
    EXPECT_TRUE(plain.success) << "the short chain forms (else the milestones below are not exercised)";
  }
}

TEST(Recording, FramesHoldTheWorldEveryKthTick) {
  const Scenario s = short_chain();
  constexpr std::int64_t kEvery = 7;

  // the world as the run had it at a few frame ticks
  struct Seen {
    std::int64_t tick;
    std::vector<Pose> poses;
    std::vector<Led> leds;
    std::vector<std::uint8_t> states;
    std::vector<int> parents, children;
  };

  std::vector<Seen> seen;
  const Recording r = record_run(Params{}, s, Mode::kPathFormation, 2, kEvery, nullptr, [&](const World& w) {
    if (w.tick % (kEvery * 10) == 0) {
      Seen x{w.tick, w.poses, w.leds, {}, {}, {}};
      for (const RobotMemory& m : w.memory) {
        x.states.push_back(m.state);
        x.parents.push_back(m.pf.parent.id);
        x.children.push_back(m.pf.child.id);
      }
      seen.push_back(std::move(x));
    }
    return false;
  });
  ASSERT_GE(seen.size(), 3U);
  // frames at 0, k, 2k, ... and the last tick
  ASSERT_GE(r.frame_count(), 2U);
  for (std::size_t f = 0; f + 1 < r.frame_count(); ++f)
    EXPECT_EQ(r.frame_ticks[f], static_cast<std::int64_t>(f) * kEvery);
  EXPECT_EQ(r.frame_ticks.back(), r.ticks);
  std::set<std::string> seen_parents;
  for (const Seen& x : seen) {
    const auto f = static_cast<std::size_t>(x.tick / kEvery);
    ASSERT_EQ(r.frame_ticks[f], x.tick);
    for (int i = 0; i < r.robots; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const Vec2 p = r.position(f, i);
      EXPECT_LE(std::abs(p.x - x.poses[k].p.x), r.quantum / 2 + 1e-12) << "tick " << x.tick << " robot " << i;
      EXPECT_LE(std::abs(p.y - x.poses[k].p.y), r.quantum / 2 + 1e-12);
      const double dyaw = std::remainder(r.yaw(f, i) - x.poses[k].yaw(), 2 * std::numbers::pi);
      EXPECT_LE(std::abs(dyaw), std::numbers::pi / 256 + 1e-9);
      EXPECT_EQ(r.led[f * r.robots + k], static_cast<std::uint8_t>(x.leds[k]));
      EXPECT_EQ(r.state[f * r.robots + k], x.states[k]);
      EXPECT_EQ(r.parent[f * r.robots + k], x.parents[k]);
      EXPECT_EQ(r.child[f * r.robots + k], x.children[k]);
      if (x.parents[k] >= 0) seen_parents.insert("robot");
    }
  }
  EXPECT_FALSE(seen_parents.empty()) << "some frame holds a chain link between robots";
}

TEST(Recording, StateChangesReplayToTheFramesStates) {
  const Recording r = record_run(Params{}, short_chain(), Mode::kTaskAllocation, 4, 10);
  ASSERT_FALSE(r.changes.empty());
  const auto n = static_cast<std::size_t>(r.robots);
  std::vector<std::uint8_t> state(r.state.begin(), r.state.begin() + static_cast<std::ptrdiff_t>(n));
  std::size_t e = 0;
  int rows = 0;
  for (std::size_t f = 1; f < r.frame_count(); ++f) {
    for (; e < r.changes.size() && r.changes[e].tick <= r.frame_ticks[f]; ++e) {
      const StateChange& c = r.changes[e];
      EXPECT_EQ(state[static_cast<std::size_t>(c.robot)], c.from) << "change " << e;
      state[static_cast<std::size_t>(c.robot)] = c.to;
      EXPECT_NE(c.from, c.to);
      rows += c.pf_row > 0 || c.ta_row > 0 ? 1 : 0;
      EXPECT_LE(c.pf_row, r.pf_rows.size());
      EXPECT_LE(c.ta_row, r.ta_rows.size());
    }
    for (std::size_t i = 0; i < n; ++i)
      ASSERT_EQ(state[i], r.state[f * n + i]) << "frame " << f << " robot " << i;
  }
  EXPECT_EQ(e, r.changes.size());
  EXPECT_GT(rows, static_cast<int>(r.changes.size()) / 2) << "most changes name the row that fired";
}

TEST(Recording, MilestonesPathsNotesAndNamesFollowTheRun) {
  World last;
  const Scenario s = short_chain();
  Recorder rec(Params{}, s, Mode::kTaskAllocation, 4, 10);
  const Metrics run_m = run(
      Params{}, s, Mode::kTaskAllocation, 4,
      [&](const World& w) {
        rec.observe(w);
        return false;
      },
      &last);
  const Recording r = rec.finish(last, run_m);
  ASSERT_TRUE(run_m.success);
  const auto tick_of = [&](const std::string& name) {
    for (const Milestone& x : r.milestones) {
      if (x.name == name) return x.tick;
    }
    return std::int64_t{-2};
  };
  EXPECT_EQ(tick_of("chain"), run_m.ticks_to_chain);
  EXPECT_EQ(tick_of("opt1"), run_m.ticks_to_opt1);
  EXPECT_EQ(tick_of("form"), run_m.ticks_to_form);
  EXPECT_EQ(tick_of("alloc"), run_m.ticks_to_allocate);
  EXPECT_TRUE(std::is_sorted(r.milestones.begin(), r.milestones.end(),
                             [](const Milestone& a, const Milestone& b) { return a.tick < b.tick; }));
  std::vector<std::string> paths;
  for (const RecordedPath& p : r.paths) paths.push_back(p.name);
  EXPECT_EQ(paths, (std::vector<std::string>{"astar", "subgoal", "opt1", "final"}));
  EXPECT_EQ(r.paths.back().robots, run_m.final_path.robots);
  // the allocation's notes: a founder, allocated robots, DONE
  const auto noted = [&](const std::string& what) {
    return std::count_if(r.notes.begin(), r.notes.end(),
                         [&](const RecordedNote& x) { return x.text.starts_with(what); });
  };
  EXPECT_GE(noted("goal founder"), 1);
  EXPECT_GE(noted("allocated"), 1);
  EXPECT_GE(noted("DONE"), 1);
  // every code in the frames is named by the controllers' own names
  const std::size_t f = r.frame_count() - 1;
  for (int i = 0; i < r.robots; ++i) {
    const RobotMemory& mem = last.memory[static_cast<std::size_t>(i)];
    const std::string want =
        std::string(to_string(mem.ta.state)) + "/" + std::string(to_string(mem.pf.state));
    EXPECT_EQ(r.state_name(r.state[f * static_cast<std::size_t>(r.robots) + static_cast<std::size_t>(i)]),
              want);
  }
  for (int c = 0; c < kLedCount; ++c)
    EXPECT_EQ(r.leds[static_cast<std::size_t>(c)].name, name(static_cast<Led>(c)));
}

TEST(Recording, BytesReadBackToTheSameRecording) {
  const Recording a = record_run(Params{}, short_chain(), Mode::kTaskAllocation, 6, 10);
  const std::string bytes = encode_recording(a);
  const Recording b = decode_recording(bytes, "run.swrec");
  EXPECT_EQ(b.frame_ticks, a.frame_ticks);
  EXPECT_EQ(b.qx, a.qx);
  EXPECT_EQ(b.qy, a.qy);
  EXPECT_EQ(b.heading, a.heading);
  EXPECT_EQ(b.led, a.led);
  EXPECT_EQ(b.state, a.state);
  EXPECT_EQ(b.parent, a.parent);
  EXPECT_EQ(b.child, a.child);
  ASSERT_EQ(b.changes.size(), a.changes.size());
  for (std::size_t i = 0; i < a.changes.size(); ++i) {
    EXPECT_EQ(b.changes[i].tick, a.changes[i].tick);
    EXPECT_EQ(b.changes[i].robot, a.changes[i].robot);
    EXPECT_EQ(b.changes[i].to, a.changes[i].to);
    EXPECT_EQ(b.changes[i].pf_row, a.changes[i].pf_row);
  }
  EXPECT_EQ(b.state_names, a.state_names);
  EXPECT_EQ(b.state_hash, a.state_hash);
  EXPECT_EQ(b.mode, a.mode);
  EXPECT_EQ(b.seed, a.seed);
  EXPECT_EQ(b.params_toml, a.params_toml);
  EXPECT_EQ(b.obstacles.size(), a.obstacles.size());
  EXPECT_EQ(b.milestones.size(), a.milestones.size());
  EXPECT_EQ(b.notes.size(), a.notes.size());
  ASSERT_EQ(b.paths.size(), a.paths.size());
  EXPECT_EQ(b.paths[1].points, a.paths[1].points);
  EXPECT_EQ(encode_recording(b), bytes) << "decoding and encoding again gives the same bytes";
}

TEST(Recording, BadBytesAreRejectedWithAMessage) {
  const std::string good = encode_recording(record_run(Params{}, short_chain(), Mode::kPathFormation, 1, 50));
  const auto message = [](const std::string& bytes) {
    try {
      decode_recording(bytes, "bad.swrec");
    } catch (const ConfigError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("hello world, not a recording").find("not a swarmpath recording"), std::string::npos);
  std::string version = good;
  version[8] = 9;
  EXPECT_NE(message(version).find("format version 9"), std::string::npos);
  EXPECT_NE(message(good.substr(0, good.size() - 10)).find("truncated"), std::string::npos);
  std::string corrupt = good;
  corrupt[corrupt.size() - 20] = static_cast<char>(corrupt[corrupt.size() - 20] ^ 0x5a);
  EXPECT_NE(message(corrupt).find("corrupt"), std::string::npos) << message(corrupt);
  std::string header = good;
  header[20] = '!';  // inside the JSON
  EXPECT_NE(message(header).find("malformed header"), std::string::npos);
  EXPECT_EQ(message(good), "accepted");
  EXPECT_EQ(message(good).find("bad.swrec"), std::string::npos);
  EXPECT_EQ(message(good.substr(0, 12)).rfind("bad.swrec: ", 0), 0U) << "messages name the file";
}

TEST(Recording, AHundredRobotsFor36000TicksFitIn10Megabytes) {
  // 3 600 of the 36 000 ticks, the path kept moving (explorers are the frames that do not compress):
  // the bytes per frame times the 3 601 frames of a whole run at one frame a second
  Scenario s = env4(100, 3600);
  s.sim.stop_when_complete = false;
  const Recording r = record_run(Params{}, s, Mode::kPathFormation, 1, 10);
  ASSERT_EQ(r.frame_count(), 361U);
  const double per_frame =
      static_cast<double>(encode_recording(r).size()) / static_cast<double>(r.frame_count());
  EXPECT_LE(per_frame * 3601.0, 10e6) << per_frame << " bytes a frame";
  RecordProperty("bytes_per_frame", std::to_string(per_frame));
}

TEST(Recording, EveryMustBePositive) {
  EXPECT_THROW(Recorder(Params{}, short_chain(), Mode::kPathFormation, 1, 0), ConfigError);
}

}  // namespace
}  // namespace swarmpath::sim
