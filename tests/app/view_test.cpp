// SPDX-License-Identifier: MIT
// simulate --record, view --out / --frame-json / --mp4 / --gif: the files, their content and the
// errors. The page itself is tested in a browser by tests/web/viewer_test.mjs.
#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/recording_file.hpp"
#include "app/video.hpp"
#include "app/web_page.hpp"
#include "cli_support.hpp"
#include "sim/hash.hpp"

namespace swarmpath::app {
namespace {

using cli_support::cli;

std::string source(const std::string& rel) { return std::string(SWARMPATH_SOURCE_DIR) + "/" + rel; }

std::string temp_dir(const std::string& name) {
  const auto d =
      std::filesystem::temp_directory_path() / ("swarmpath_view_" + std::to_string(::getpid()) + "_" + name);
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d.string();
}

std::string slurp(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  std::ostringstream s;
  s << f.rdbuf();
  return s.str();
}

// a short path-formation run, recorded
std::string recorded(const std::string& dir, const std::string& mode = "pf") {
  const std::string file = dir + "/run.swrec";
  const auto r = cli({"simulate", "--scenario", source("tests/data/short_chain.toml"), "--mode", mode,
                      "--seed", "2", "--record", file, "--json"});
  EXPECT_EQ(r.code, 0) << r.err;
  return file;
}

TEST(View, SimulateRecordsTheSameRunItReports) {
  const std::string dir = temp_dir("same");
  const auto plain =
      cli({"simulate", "--scenario", source("tests/data/short_chain.toml"), "--mode", "ta", "--json"});
  const auto rec = cli({"simulate", "--scenario", source("tests/data/short_chain.toml"), "--mode", "ta",
                        "--json", "--record", dir + "/a.swrec", "--record-every", "3"});
  ASSERT_EQ(rec.code, 0) << rec.err;
  const auto a = nlohmann::json::parse(plain.out), b = nlohmann::json::parse(rec.out);
  EXPECT_EQ(a["state_hash"], b["state_hash"]);
  EXPECT_EQ(a["ticks_to_form"], b["ticks_to_form"]);
  const sim::Recording r = read_recording_file(dir + "/a.swrec");
  EXPECT_EQ(r.every, 3);
  EXPECT_EQ(b["recording"]["frames"].get<std::size_t>(), r.frame_count());
  EXPECT_EQ(r.scenario_name, "short_chain");
  EXPECT_NE(r.scenario_toml.find("short_chain"), std::string::npos) << "the scenario file's text goes in";
  EXPECT_NE(r.generator.find("swarmpath"), std::string::npos);
  EXPECT_EQ(cli({"simulate", "--scenario", source("tests/data/short_chain.toml"), "--record",
                 dir + "/b.swrec", "--record-every", "0"})
                .code,
            0)
      << "0 means the default, one second";
  EXPECT_EQ(read_recording_file(dir + "/b.swrec").every, 10);
  EXPECT_EQ(cli({"simulate", "--scenario", source("tests/data/short_chain.toml"), "--record",
                 dir + "/c.swrec", "--record-every", "-4"})
                .code,
            2);
}

TEST(View, ThePageIsOneSelfContainedFile) {
  const std::string dir = temp_dir("page");
  const std::string file = recorded(dir);
  const auto r = cli({"view", file, "--out", dir + "/run.html"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string page = slurp(dir + "/run.html");
  // the recording's bytes, the script and the style are all inside; nothing is fetched
  EXPECT_NE(page.find(base64(slurp(file)).substr(0, 120)), std::string::npos);
  EXPECT_NE(page.find("class=\"swp-viewer\""), std::string::npos);
  EXPECT_NE(page.find("DecompressionStream"), std::string::npos);
  EXPECT_NE(page.find(".swp-stage"), std::string::npos);
  EXPECT_EQ(page.find("{{"), std::string::npos) << "every placeholder filled";
  for (const char* remote : {"http://", "https://", "<script src", "<link ", "@import", "fetch("})
    EXPECT_EQ(page.find(remote), std::string::npos) << remote;
  EXPECT_NE(page.find("<title>short_chain, 20 robots, pf, seed 2</title>"), std::string::npos);
  // two scripts (the recording's and the player's) and no other end tag, which would end one early
  std::size_t ends = 0;
  for (std::size_t at = page.find("</script"); at != std::string::npos; at = page.find("</script", at + 1))
    ++ends;
  EXPECT_EQ(ends, 2U);
}

TEST(View, SeveralRecordingsMakeOnePageWithAPicker) {
  const std::string dir = temp_dir("several");
  const std::string a = recorded(dir);
  ASSERT_EQ(cli({"simulate", "--scenario", source("tests/data/short_chain.toml"), "--mode", "ta", "--record",
                 dir + "/ta.swrec"})
                .code,
            0);
  ASSERT_EQ(cli({"view", a, dir + "/ta.swrec", "--out", dir + "/both.html", "--title", "A & B"}).code, 0);
  const std::string page = slurp(dir + "/both.html");
  std::size_t count = 0;
  for (std::size_t at = page.find("application/x-swrec\" data-title="); at != std::string::npos;
       at = page.find("application/x-swrec\" data-title=", at + 1))
    ++count;
  EXPECT_EQ(count, 2U);
  EXPECT_NE(page.find("<title>A &amp; B</title>"), std::string::npos);
}

TEST(View, FrameJsonGivesTheRecordedFrame) {
  const std::string dir = temp_dir("frame");
  const std::string file = recorded(dir);
  const sim::Recording rec = read_recording_file(file);
  const auto r = cli({"view", file, "--frame-json", "105"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["tick"], 100) << "the last frame at or before the tick";
  ASSERT_EQ(j["robots"].size(), 20U);
  const auto& r7 = j["robots"][7];
  EXPECT_EQ(r7["x"].get<double>(), rec.position(10, 7).x);
  EXPECT_EQ(r7["led"], rec.leds[rec.led[10 * 20 + 7]].name);
  EXPECT_EQ(r7["state"], std::string(rec.state_name(rec.state[10 * 20 + 7])));
}

// view --census counts the run from its state changes: every robot's every tick in one state, each
// change's row once, and each trip (a stay in an exploring state) ended once or still under way
TEST(View, CensusCountsEveryTickEveryRowAndEveryTrip) {
  const std::string dir = temp_dir("census");
  for (const std::string mode : {"pf", "ta"}) {
    const std::string file = recorded(dir, mode);
    const sim::Recording rec = read_recording_file(file);
    const auto r = cli({"view", file, "--census"});
    ASSERT_EQ(r.code, 0) << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["mode"], mode);
    std::int64_t ticks = 0;
    for (const auto& [state, n] : j["robot_ticks"].items()) ticks += n.get<std::int64_t>();
    EXPECT_EQ(ticks, rec.robots * rec.ticks) << mode;
    std::int64_t pf_rows = 0;
    std::int64_t ta_rows = 0;
    for (const sim::StateChange& c : rec.changes) {
      pf_rows += c.pf_row > 0 ? 1 : 0;
      ta_rows += c.ta_row > 0 ? 1 : 0;
    }
    std::int64_t counted = 0;
    for (const auto& [row, n] : j["rows_fired"]["path_formation"].items()) counted += n.get<std::int64_t>();
    EXPECT_EQ(counted, pf_rows) << mode;
    EXPECT_EQ(j["rows_fired"].contains("task_allocation"), ta_rows > 0) << mode;
    if (ta_rows > 0) {
      counted = 0;
      for (const auto& [row, n] : j["rows_fired"]["task_allocation"].items())
        counted += n.get<std::int64_t>();
      EXPECT_EQ(counted, ta_rows);
    }
    // trips by their exploring state; every robot sets out exploring at tick 0, and the path
    // formed, so some trip ended forming a link
    std::int64_t count = 0;
    std::int64_t forming = 0;
    for (const auto& [from, t] : j["trips"].items()) {
      std::int64_t ended = 0;
      for (const auto& [to, n] : t["ended_in"].items()) {
        ended += n.get<std::int64_t>();
        if (to.ends_with("subgoal_forming")) forming += n.get<std::int64_t>();
      }
      EXPECT_EQ(ended, t["ended"].get<std::int64_t>()) << from;
      EXPECT_LE(ended, t["count"].get<std::int64_t>()) << from;
      if (ended > 0) {
        EXPECT_GT(t["median_ticks"].get<double>(), 0.0) << from;
      }
      count += t["count"].get<std::int64_t>();
    }
    EXPECT_GE(count, rec.robots) << mode;
    EXPECT_TRUE(rec.success) << mode;
    EXPECT_GT(forming, 0) << mode;
  }
}

TEST(View, BadInputIsRejected) {
  const std::string dir = temp_dir("bad");
  { std::ofstream(dir + "/junk.swrec") << "not a recording at all"; }
  const auto junk = cli({"view", dir + "/junk.swrec", "--out", dir + "/x.html"});
  EXPECT_EQ(junk.code, 2);
  EXPECT_NE(junk.err.find("junk.swrec: not a swarmpath recording"), std::string::npos) << junk.err;
  EXPECT_FALSE(std::filesystem::exists(dir + "/x.html"));
  EXPECT_EQ(cli({"view", dir + "/missing.swrec", "--out", dir + "/x.html"}).code, 2);
  const std::string file = recorded(dir);
  const auto nothing = cli({"view", file});
  EXPECT_EQ(nothing.code, 2);
  EXPECT_NE(nothing.err.find("--out"), std::string::npos);
  EXPECT_EQ(cli({"view", file, file, "--mp4", dir + "/x.mp4"}).code, 2);
  EXPECT_EQ(cli({"view", file, file, "--census"}).code, 2);
  EXPECT_EQ(cli({"view", file, "--frame-json", "5", "--census"}).code, 2);
  const auto unwritable = cli({"view", file, "--out", dir + "/no/such/dir/x.html"});
  EXPECT_EQ(unwritable.code, 2) << "the output's folder must exist";
  EXPECT_NE(unwritable.err.find("--out"), std::string::npos) << unwritable.err;
  const auto over_input = cli({"view", file, "--out", file});
  EXPECT_EQ(over_input.code, 2) << "an input is never overwritten";
  EXPECT_EQ(read_recording_file(file).robots, 20);
}

TEST(Video, FramesDrawTheRobotsInTheirLedColours) {
  const std::string dir = temp_dir("raster");
  const sim::Recording r = read_recording_file(recorded(dir));
  const std::size_t f = r.frame_count() - 1;
  constexpr int kWidth = 600;
  const Raster img = render_frame(r, static_cast<double>(r.frame_ticks[f]), kWidth);
  EXPECT_EQ(img.width(), kWidth);
  EXPECT_EQ(img.height() % 2, 0);
  int checked = 0;
  for (int i = 0; i < r.robots; ++i) {
    const sim::Vec2 p = r.position(f, i);
    bool alone = true;
    for (int k = 0; k < r.robots; ++k)
      alone = alone && (k == i || sim::dist(p, r.position(f, k)) > 4 * r.robot_radius);
    if (!alone) continue;
    // half way to the rim, behind the heading mark
    const double yaw = r.yaw(f, i);
    const sim::Vec2 q =
        frame_pixel(r, kWidth, p - 0.45 * r.robot_radius * sim::Vec2{std::cos(yaw), std::sin(yaw)});
    const sim::Rgb want =
        r.leds[r.led[f * static_cast<std::size_t>(r.robots) + static_cast<std::size_t>(i)]].rgb;
    const sim::Rgb got = img.at(static_cast<int>(q.x), static_cast<int>(q.y));
    EXPECT_NEAR(got.r, want.r, 12) << "robot " << i;
    EXPECT_NEAR(got.g, want.g, 12) << "robot " << i;
    EXPECT_NEAR(got.b, want.b, 12) << "robot " << i;
    ++checked;
  }
  EXPECT_GE(checked, 5);
}

TEST(Video, Mp4AndGifThroughFfmpegOrAClearMessage) {
  const std::string dir = temp_dir("video");
  const std::string file = recorded(dir);
  if (!find_program("ffmpeg")) {
    const auto r = cli({"view", file, "--mp4", dir + "/run.mp4"});
    EXPECT_EQ(r.code, 1);
    EXPECT_NE(r.err.find("apt-get install ffmpeg"), std::string::npos) << r.err;
    GTEST_SKIP() << "ffmpeg is not installed: only its absence was checked";
  }
  const auto mp4 = cli({"view", file, "--mp4", dir + "/run.mp4", "--width", "320", "--video-speed", "40"});
  ASSERT_EQ(mp4.code, 0) << mp4.err;
  EXPECT_EQ(slurp(dir + "/run.mp4").substr(4, 4), "ftyp");
  const auto gif =
      cli({"view", file, "--gif", dir + "/run.gif", "--width", "200", "--video-speed", "80", "--fps", "5"});
  ASSERT_EQ(gif.code, 0) << gif.err;
  EXPECT_EQ(slurp(dir + "/run.gif").substr(0, 6), "GIF89a");
  // without ffmpeg on PATH: a clear message, exit 1
  const std::string path = std::getenv("PATH");
  setenv("PATH", "/nonexistent", 1);
  const auto missing = cli({"view", file, "--mp4", dir + "/x.mp4"});
  setenv("PATH", path.c_str(), 1);
  EXPECT_EQ(missing.code, 1);
  EXPECT_NE(missing.err.find("needs ffmpeg, which is not installed: apt-get install ffmpeg"),
            std::string::npos)
      << missing.err;
}

}  // namespace
}  // namespace swarmpath::app

namespace swarmpath::app {
namespace {

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream s(line);
  std::string cell;
  while (std::getline(s, cell, ',')) cells.push_back(cell);
  return cells;
}

TEST(View, TableRecordsItsFailedRunsAndOnlyThose) {
  const std::string dir = temp_dir("table");
  const auto r = cli({"table", "--scenarios", source("tests/data/short_chain.toml"), "--robots", "20",
                      "--seeds", "3", "--ticks", "1420", "--mode", "pf", "--threads", "2", "--csv",
                      dir + "/runs.csv", "--record-failures", dir + "/failed"});
  ASSERT_EQ(r.code, 0) << r.err;
  // each run that did not form its path (runs.csv says which) has its recording, with its state hash
  std::ifstream csv(dir + "/runs.csv");
  std::string line;
  std::getline(csv, line);
  const std::vector<std::string> head = split(line);
  const auto col = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(head.begin(), head.end(), name) - head.begin());
  };
  int failed = 0;
  while (std::getline(csv, line)) {
    const std::vector<std::string> cells = split(line);
    if (cells.at(col("success")) != "0") continue;
    ++failed;
    const std::string file = dir + "/failed/short_chain-n20-pf-s" + cells.at(col("seed")) + ".swrec";
    ASSERT_TRUE(std::filesystem::exists(file)) << file;
    const sim::Recording rec = read_recording_file(file);
    EXPECT_FALSE(rec.success);
    EXPECT_EQ(sim::to_hex(rec.state_hash), cells.at(col("state_hash")));
  }
  EXPECT_GE(failed, 1) << "1420 ticks leave some of the three runs without a path";
  EXPECT_LE(failed, 2) << "... and some with one";
  std::size_t files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir + "/failed")) ++files;
  EXPECT_EQ(files, static_cast<std::size_t>(failed));
}

}  // namespace
}  // namespace swarmpath::app
