// SPDX-License-Identifier: MIT
#include "video.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <numbers>
#include <ostream>
#include <sstream>

namespace swarmpath::app {

namespace {

constexpr int kTimeBar = 22;  // pixels under the arena for the time bar

constexpr sim::Rgb kFloor{251, 251, 248};
constexpr sim::Rgb kObstacle{107, 107, 102};
constexpr sim::Rgb kOutline{26, 26, 26};

sim::Rgb path_colour(const std::string& name) {
  if (name == "astar") return {224, 0, 0};
  if (name == "subgoal") return {31, 79, 255};
  if (name == "opt1") return {155, 48, 208};
  return {0, 166, 81};
}

int even(double v) { return std::max(2, 2 * static_cast<int>(std::lround(v / 2.0))); }

int height_for(const sim::Recording& r, int width) {
  return even(width * r.arena_size.y / r.arena_size.x) + kTimeBar;
}

std::string shell_quote(const std::string& s) {
  std::string out = "'";
  for (const char ch : s) out += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return out + "'";
}

}  // namespace

sim::Vec2 frame_pixel(const sim::Recording& r, int width, sim::Vec2 world) {
  const double scale = even(width) / r.arena_size.x;
  return {(world.x + r.arena_size.x / 2) * scale, (r.arena_size.y / 2 - world.y) * scale};
}

Raster render_frame(const sim::Recording& r, double tick, int width) {
  width = even(width);
  Raster img(width, height_for(r, width));
  img.clear({230, 230, 224});
  const double scale = width / r.arena_size.x;
  const auto at = [&](sim::Vec2 w) { return frame_pixel(r, width, w); };
  const std::array<sim::Vec2, 4> floor{at(-0.5 * r.arena_size), at({r.arena_size.x / 2, -r.arena_size.y / 2}),
                                       at(0.5 * r.arena_size), at({-r.arena_size.x / 2, r.arena_size.y / 2})};
  img.fill_convex(floor, kFloor);
  for (const sim::Shape& s : r.obstacles) {
    if (s.kind == sim::ShapeKind::kCircle) {
      img.fill_circle(at(s.center), s.radius * scale, kObstacle);
      continue;
    }
    std::array<sim::Vec2, 4> q;
    const std::array<sim::Vec2, 4> local{
        {{-s.half.x, -s.half.y}, {s.half.x, -s.half.y}, {s.half.x, s.half.y}, {-s.half.x, s.half.y}}};
    for (std::size_t i = 0; i < 4; ++i)
      q[i] =
          at(s.center + sim::Vec2{s.c * local[i].x - s.s * local[i].y, s.s * local[i].x + s.c * local[i].y});
    img.fill_convex(q, kObstacle);
  }
  const double beacon = std::max(4.0, 0.12 * scale);
  img.fill_circle(at(r.nest), beacon + 1.5, kOutline);
  img.fill_circle(at(r.nest), beacon, {0, 0, 255});
  img.fill_circle(at(r.goal), beacon + 1.5, kOutline);
  img.fill_circle(at(r.goal), beacon, {255, 255, 0});

  // the recorded frames around `tick`
  std::size_t f = 0;
  while (f + 1 < r.frame_count() && static_cast<double>(r.frame_ticks[f + 1]) <= tick) ++f;
  const bool between = f + 1 < r.frame_count() && tick > static_cast<double>(r.frame_ticks[f]);
  const double a = between ? (tick - static_cast<double>(r.frame_ticks[f])) /
                                 static_cast<double>(r.frame_ticks[f + 1] - r.frame_ticks[f])
                           : 0.0;
  const auto n = static_cast<std::size_t>(r.robots);
  std::vector<sim::Vec2> pos(n);
  std::vector<double> yaw(n);
  for (int i = 0; i < r.robots; ++i) {
    const auto k = static_cast<std::size_t>(i);
    pos[k] = r.position(f, i);
    yaw[k] = r.yaw(f, i);
    if (a > 0.0) {
      pos[k] = pos[k] + a * (r.position(f + 1, i) - pos[k]);
      const double d = std::remainder(r.yaw(f + 1, i) - yaw[k], 2 * std::numbers::pi);
      yaw[k] += a * d;
    }
  }
  for (const sim::RecordedPath& p : r.paths) {
    if (static_cast<double>(p.tick) > tick) continue;
    for (std::size_t i = 1; i < p.points.size(); ++i)
      img.line(at(p.points[i - 1]), at(p.points[i]), 2.2, path_colour(p.name), 0.8);
  }
  const std::size_t k0 = f * n;
  for (std::size_t i = 0; i < n; ++i) {
    const int to = r.parent[k0 + i];
    const sim::Vec2 end = to == sim::kGoalEmitter ? r.goal : to == sim::kNestEmitter ? r.nest : sim::Vec2{};
    if (to >= 0 && to < r.robots)
      img.line(at(pos[i]), at(pos[static_cast<std::size_t>(to)]), 1.6, {25, 25, 25}, 0.7);
    if (to == sim::kGoalEmitter || to == sim::kNestEmitter)
      img.line(at(pos[i]), at(end), 1.6, {25, 25, 25}, 0.7);
  }
  const double rad = std::max(2.5, r.robot_radius * scale);
  for (std::size_t i = 0; i < n; ++i) {
    const sim::Rgb c = r.leds.at(r.led[k0 + i]).rgb;
    const sim::Vec2 p = at(pos[i]);
    img.fill_circle(p, rad + 0.8, kOutline);
    img.fill_circle(p, rad, c);
    const bool dark = 0.299 * c.r + 0.587 * c.g + 0.114 * c.b < 110;
    const sim::Vec2 tip = p + sim::Vec2{rad * std::cos(yaw[i]), -rad * std::sin(yaw[i])};
    img.line(p, tip, std::max(1.0, 0.25 * rad), dark ? sim::Rgb{240, 240, 240} : sim::Rgb{17, 17, 17});
  }

  // the time bar: progress, milestones, the tick
  const double top = img.height() - kTimeBar;
  const double last = std::max<double>(1.0, static_cast<double>(r.frame_ticks.back()));
  const std::array<sim::Vec2, 4> track{{{0, top},
                                        {static_cast<double>(width), top},
                                        {static_cast<double>(width), static_cast<double>(img.height())},
                                        {0, static_cast<double>(img.height())}}};
  img.fill_convex(track, {255, 255, 255});
  const double done = width * std::clamp(tick / last, 0.0, 1.0);
  const std::array<sim::Vec2, 4> bar{{{0, top + 15}, {done, top + 15}, {done, top + 20}, {0, top + 20}}};
  img.fill_convex(bar, {240, 160, 80});
  for (const sim::Milestone& m : r.milestones) {
    const double x = width * static_cast<double>(m.tick) / last;
    img.line({x, top + 13}, {x, top + 22}, 2.0,
             static_cast<double>(m.tick) <= tick ? sim::Rgb{0, 140, 70} : sim::Rgb{150, 150, 150});
  }
  std::ostringstream label;
  label << static_cast<std::int64_t>(tick) << " / " << r.frame_ticks.back();
  img.text({6, top + 3}, label.str(), 2, {29, 29, 27});
  return img;
}

std::optional<std::string> find_program(const std::string& name) {
  const char* path = std::getenv("PATH");
  if (path == nullptr) return std::nullopt;
  std::stringstream dirs(path);
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    if (dir.empty()) continue;
    const std::filesystem::path p = std::filesystem::path(dir) / name;
    std::error_code ec;
    if (std::filesystem::is_regular_file(p, ec) &&
        (std::filesystem::status(p, ec).permissions() & std::filesystem::perms::owner_exec) !=
            std::filesystem::perms::none)
      return p.string();
  }
  return std::nullopt;
}

void write_video(const sim::Recording& r, const std::string& path, const VideoOptions& o, std::ostream& err) {
  const std::optional<std::string> ffmpeg = find_program("ffmpeg");
  if (!ffmpeg) {
    throw std::runtime_error(
        "writing " + path +
        " needs ffmpeg, which is not installed: apt-get install ffmpeg (or use --out for the "
        "web page)");
  }
  const double seconds = static_cast<double>(r.frame_ticks.back()) / r.ticks_per_second;
  const double speed = o.speed > 0 ? o.speed : std::max(1.0, seconds / 30.0);
  const auto frames = static_cast<std::int64_t>(std::ceil(seconds / speed * o.fps)) + 1;
  const int width = even(o.width);
  const int height = height_for(r, width);
  std::ostringstream cmd;
  cmd << shell_quote(*ffmpeg) << " -hide_banner -loglevel error -y -f rawvideo -pix_fmt rgb24 -s " << width
      << "x" << height << " -r " << o.fps << " -i -";
  if (o.format == VideoFormat::kMp4)
    cmd << " -c:v libx264 -pix_fmt yuv420p -crf 20 -movflags +faststart";
  else
    cmd << " -vf 'split[a][b];[a]palettegen=max_colors=64[p];[b][p]paletteuse=dither=none' -loop 0";
  cmd << " " << shell_quote(path);
  err << "swarmpath view: " << frames << " frames, " << width << "x" << height << ", " << speed
      << " simulated seconds a second, through ffmpeg\n";

  // a dead ffmpeg must not kill us with SIGPIPE: the write fails and pclose says why
  const auto old = std::signal(SIGPIPE, SIG_IGN);
  FILE* pipe = popen(cmd.str().c_str(), "w");
  if (pipe == nullptr) {
    std::signal(SIGPIPE, old);
    throw std::runtime_error("cannot start ffmpeg");
  }
  bool written = true;
  for (std::int64_t k = 0; k < frames && written; ++k) {
    const double tick = std::min(static_cast<double>(r.frame_ticks.back()),
                                 static_cast<double>(k) * speed * r.ticks_per_second / o.fps);
    const Raster img = render_frame(r, tick, width);
    written = std::fwrite(img.rgb().data(), 1, img.rgb().size(), pipe) == img.rgb().size();
  }
  const int status = pclose(pipe);
  std::signal(SIGPIPE, old);
  if (!written || status != 0)
    throw std::runtime_error("ffmpeg could not write " + path + " (exit status " + std::to_string(status) +
                             ")");
}

}  // namespace swarmpath::app
