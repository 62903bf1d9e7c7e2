// SPDX-License-Identifier: MIT
// swarmpath view: a recorded run (.swrec) as one self-contained web page that plays it, a video
// through ffmpeg, one frame as JSON, or a census of the run as JSON.
#include <filesystem>
#include <fstream>
#include <memory>
#include <ostream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "census.hpp"
#include "cli.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "evolve/atomic_write.hpp"
#include "evolve/path_collision.hpp"
#include "recording_file.hpp"
#include "sim/config_error.hpp"
#include "video.hpp"
#include "web_page.hpp"

namespace swarmpath::app {

namespace {

struct ViewOptions {
  std::vector<std::string> recordings;
  std::string out;
  std::string title;
  std::string mp4;
  std::string gif;
  double video_speed = 0;
  int fps = 25;
  int width = 960;
  std::optional<std::int64_t> frame_json;
  bool census = false;
};

std::string title_of(const sim::Recording& r) {
  return r.scenario_name + ", " + std::to_string(r.robots) + " robots, " +
         std::string(sim::to_string(r.mode)) + ", seed " + std::to_string(r.seed);
}

// the last frame at or before `tick`
std::size_t frame_at(const sim::Recording& r, std::int64_t tick) {
  std::size_t f = 0;
  while (f + 1 < r.frame_count() && r.frame_ticks[f + 1] <= tick) ++f;
  return f;
}

nlohmann::ordered_json frame_json(const sim::Recording& r, std::size_t f) {
  nlohmann::ordered_json robots = nlohmann::ordered_json::array();
  for (int i = 0; i < r.robots; ++i) {
    const std::size_t k = f * static_cast<std::size_t>(r.robots) + static_cast<std::size_t>(i);
    const sim::Vec2 p = r.position(f, i);
    const sim::LedName& led = r.leds.at(r.led[k]);
    robots.push_back({{"id", i},
                      {"x", p.x},
                      {"y", p.y},
                      {"yaw", r.yaw(f, i)},
                      {"led", led.name},
                      {"rgb", {led.rgb.r, led.rgb.g, led.rgb.b}},
                      {"state", std::string(r.state_name(r.state[k]))},
                      {"parent", r.parent[k]},
                      {"child", r.child[k]}});
  }
  return {{"tick", r.frame_ticks[f]}, {"frame", f}, {"robot_radius", r.robot_radius}, {"robots", robots}};
}

int run_view(const ViewOptions& o, std::ostream& out, std::ostream& err) {
  if (o.out.empty() && o.mp4.empty() && o.gif.empty() && !o.frame_json && !o.census)
    throw sim::ConfigError(
        "view", 0, "",
        "say what to write: --out page.html, --mp4 run.mp4, --gif run.gif, --frame-json TICK or --census");
  if ((!o.mp4.empty() || !o.gif.empty() || o.frame_json || o.census) && o.recordings.size() != 1)
    throw sim::ConfigError("view", 0, "", "--mp4, --gif, --frame-json and --census take one recording");
  if (o.frame_json && o.census) throw sim::ConfigError("view", 0, "", "--frame-json or --census, not both");
  std::vector<evolve::NamedPath> inputs;
  for (const std::string& path : o.recordings) inputs.push_back({"recording", path});
  evolve::check_output_paths(inputs, {{"--out", o.out}, {"--mp4", o.mp4}, {"--gif", o.gif}});
  std::vector<sim::Recording> recs;
  std::vector<PageRecording> pages;
  for (const std::string& path : o.recordings) {
    std::string bytes = read_file_bytes(path);
    recs.push_back(sim::decode_recording(bytes, path));  // checked here, so that the page never gets bad data
    pages.push_back({title_of(recs.back()), std::move(bytes)});
  }
  if (o.frame_json) {
    out << frame_json(recs[0], frame_at(recs[0], *o.frame_json)).dump(2) << "\n";
    return kExitOk;
  }
  if (o.census) {
    out << census(recs[0]).dump(2) << "\n";
    return kExitOk;
  }
  if (!o.out.empty()) {
    const std::string title = !o.title.empty()   ? o.title
                              : recs.size() == 1 ? title_of(recs[0])
                                                 : "swarmpath runs";
    const std::string page = viewer_page(title, pages);
    evolve::write_file_atomic(o.out, page);
    std::size_t total = 0;
    for (const PageRecording& p : pages) total += p.bytes.size();
    out << "wrote " << o.out << " (" << fixed(static_cast<double>(page.size()) / 1e6, 2) << " MB; "
        << recs.size() << (recs.size() == 1 ? " recording" : " recordings") << ", "
        << fixed(static_cast<double>(total) / 1e6, 2) << " MB): open it in a browser\n";
  }
  VideoOptions v;
  v.fps = o.fps;
  v.width = o.width;
  v.speed = o.video_speed;
  if (!o.mp4.empty()) {
    v.format = VideoFormat::kMp4;
    write_video(recs[0], o.mp4, v, err);
    out << "wrote " << o.mp4 << "\n";
  }
  if (!o.gif.empty()) {
    v.format = VideoFormat::kGif;
    write_video(recs[0], o.gif, v, err);
    out << "wrote " << o.gif << "\n";
  }
  return kExitOk;
}

}  // namespace

Runner add_view(CLI::App& app) {
  auto o = std::make_shared<ViewOptions>();
  app.add_option(
         "recordings", o->recordings,
         "Recordings (.swrec) from 'simulate --record' or 'table --record-failures'; several make one "
         "page with a picker")
      ->required()
      ->check(CLI::ExistingFile);
  app.add_option(
      "--out", o->out,
      "Write the player: one self-contained HTML file (no network, no server) to open in a browser");
  app.add_option("--title", o->title, "The page's title (default: scenario, robots, mode and seed)");
  app.add_option("--mp4", o->mp4, "Write an H.264 video of the run (needs ffmpeg: apt-get install ffmpeg)");
  app.add_option("--gif", o->gif, "Write an animated GIF of the run (needs ffmpeg)");
  app.add_option("--video-speed", o->video_speed,
                 "Simulated seconds per video second (default: the whole run in about 30 s)");
  app.add_option("--fps", o->fps, "Video frames per second")->capture_default_str()->check(CLI::Range(1, 60));
  app.add_option("--width", o->width, "Video width in pixels (the height follows the arena)")
      ->capture_default_str()
      ->check(CLI::Range(64, 3840));
  app.add_option(
      "--frame-json", o->frame_json,
      "Print the recorded frame at or before this tick as JSON (robots' positions, LEDs, states, links)");
  app.add_flag("--census", o->census,
               "Print a census of the run as JSON: robot-ticks in each controller state, the table rows "
               "that fired, the trips (each stay in one exploring state): count, median ticks, the "
               "state each ended in, and the stalls (robots within 25 cm for 2000 ticks or more where "
               "they were meant to move)");
  return [o](std::ostream& out, std::ostream& err) { return run_view(*o, out, err); };
}

}  // namespace swarmpath::app
