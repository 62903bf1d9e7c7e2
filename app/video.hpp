// SPDX-License-Identifier: MIT
// Videos of a recorded run for papers and talks: frames drawn as the viewer draws them (arena,
// obstacles, paths, chain links, robots by LED with heading, a time bar) and encoded by ffmpeg.
#pragma once

#include <iosfwd>
#include <optional>
#include <string>

#include "raster.hpp"
#include "sim/recording.hpp"

namespace swarmpath::app {

enum class VideoFormat { kMp4, kGif };

struct VideoOptions {
  VideoFormat format = VideoFormat::kMp4;
  int fps = 25;
  int width = 960;     ///< pixels; the height follows the arena (both even)
  double speed = 0.0;  ///< simulated seconds per video second; 0: the whole run in about 30 s
};

/// The run at `tick` (interpolated between recorded frames), `width` pixels wide.
Raster render_frame(const sim::Recording& r, double tick, int width);

/// Where a world point lands in render_frame's picture of `r` at `width` pixels.
sim::Vec2 frame_pixel(const sim::Recording& r, int width, sim::Vec2 world);

/// The program's path on PATH, if there is one.
std::optional<std::string> find_program(const std::string& name);

/// Renders the run and pipes it to ffmpeg. Throws std::runtime_error saying how to install ffmpeg
/// when it is missing, and what went wrong when it fails.
void write_video(const sim::Recording& r, const std::string& path, const VideoOptions& o, std::ostream& err);

}  // namespace swarmpath::app
