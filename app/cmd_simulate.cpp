// SPDX-License-Identifier: MIT
// swarmpath simulate: one run, summarised as text or JSON, optionally drawn as SVG.
#include <cmath>
#include <memory>
#include <ostream>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "cli_options.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "evolve/params_export.hpp"
#include "evolve/path_collision.hpp"
#include "fault_options.hpp"
#include "recording_file.hpp"
#include "sim/astar.hpp"
#include "sim/config_error.hpp"
#include "sim/hash.hpp"
#include "sim/step.hpp"
#include "svg.hpp"

namespace swarmpath::app {

namespace {

// the heat map's cells: 4 000 000 (2000 x 2000 m at 1 m) hold 32 MB of counts
constexpr std::int64_t kMaxHeatmapCells = 4'000'000;

struct SimulateOptions {
  std::string scenario;
  std::string params;
  std::optional<std::int64_t> robots;
  std::uint64_t seed = 1;
  std::optional<std::int64_t> ticks;
  std::string mode = "diffusion";
  bool keep_running = false;
  std::string svg;
  bool trails = false;
  std::string heatmap;
  std::string heatmap_led;
  double heatmap_cell_cm = 25.0;
  bool json = false;
  std::string record;
  std::int64_t record_every = 0;
  FaultOptions faults;
};

// the paper's figure colours: subgoal path blue, optimisation 1 purple, optimisation 2 green, A* red
void add_path_lines(Picture& pic, const sim::Metrics& m, const sim::AStarResult* a8) {
  if (a8 != nullptr && a8->found) {
    pic.lines.push_back(
        {a8->path, "#e00000", 2.0, "A* (8-connected): " + fixed(sim::to_tu(a8->length_m), 1) + " TU", false});
  }
  const auto add = [&](const sim::PathSnapshot& snap, const char* color, const std::string& what) {
    if (snap.tick < 0) return;
    pic.lines.push_back({snap.points, color, 2.0,
                         what + ": " + fixed(sim::to_tu(snap.length_m), 1) + " TU at tick " +
                             std::to_string(snap.tick) + " (" + std::to_string(snap.robots.size()) +
                             " robots)",
                         true});
  };
  add(m.subgoal_path, "#1f4fff", "subgoal path");
  add(m.opt1_path, "#9b30d0", "optimisation-1 path");
  add(m.final_path, "#00a651", "optimisation-2 (final) path");
}

int run_simulate(const SimulateOptions& o, std::ostream& out, std::ostream& err) {
  evolve::check_output_paths({{"--scenario", o.scenario}, {"--params", o.params}},
                             {{"--svg", o.svg}, {"--heatmap", o.heatmap}, {"--record", o.record}});
  sim::Scenario s = with_fault_options(scenario_with_overrides(o.scenario, o.robots, o.ticks), o.faults);
  if (o.keep_running) s.sim.stop_when_complete = false;
  const sim::Params p = params_or_defaults(o.params);
  const sim::Mode mode = mode_from_option(o.mode);

  // trails: one sample per robot every `every` ticks, at most ~1500 samples per robot
  const std::int64_t every = std::max<std::int64_t>(1, s.sim.max_ticks / 1500);
  std::vector<std::vector<sim::Vec2>> trails;
  std::optional<sim::Occupancy> occupancy;
  if (!o.heatmap.empty()) {
    if (!(o.heatmap_cell_cm >= 1.0 && o.heatmap_cell_cm <= 500.0)) {
      throw sim::ConfigError("--heatmap-cell", 0, "", "must be within 1-500 cm");
    }
    std::optional<sim::Led> only;
    if (!o.heatmap_led.empty()) only = led_from_option("--heatmap-led", o.heatmap_led);
    // the heat map holds a count per cell: its size is the product of the arena's sides and the cell
    const double cell = o.heatmap_cell_cm / 100.0;
    const double cells = std::ceil(s.arena_size.x / cell - 1e-9) * std::ceil(s.arena_size.y / cell - 1e-9);
    if (cells > static_cast<double>(kMaxHeatmapCells)) {
      const double least = std::sqrt(s.arena_size.x * s.arena_size.y / static_cast<double>(kMaxHeatmapCells));
      throw sim::ConfigError("--heatmap-cell", 0, "",
                             fixed(o.heatmap_cell_cm, 0) + " cm cells over the " + fixed(s.arena_size.x, 0) +
                                 " x " + fixed(s.arena_size.y, 0) + " m arena (" + s.file +
                                 ": arena.size) make " + fixed(cells, 0) + " cells (limit " +
                                 std::to_string(kMaxHeatmapCells) +
                                 "): use --heatmap-cell >= " + fixed(std::ceil(least * 100.0), 0));
    }
    occupancy.emplace(s.arena_bounds(), cell, only);
  }
  // the recorder only reads the world after each tick: the run is the same with or without it
  std::optional<sim::Recorder> recorder;
  if (!o.record.empty()) recorder.emplace(p, s, mode, o.seed, record_every(s, o.record_every));
  const bool progress = stderr_is_terminal();
  const Stopwatch clock;
  double next_report = 1.0;
  const sim::TickObserver observe = [&](const sim::World& w) {
    if (recorder) recorder->observe(w);
    if (o.trails && w.tick % every == 0) {
      trails.resize(w.poses.size());
      for (std::size_t i = 0; i < w.poses.size(); ++i) trails[i].push_back(w.poses[i].p);
    }
    if (occupancy) occupancy->add(w.poses, w.leds);
    if (progress && w.tick % 256 == 0 && clock.seconds() > next_report) {
      next_report = clock.seconds() + 0.5;
      err << "\r  tick " << w.tick << " / " << s.sim.max_ticks << " (" << (100 * w.tick / s.sim.max_ticks)
          << " %)" << std::flush;
    }
    return false;
  };
  sim::World world;
  const sim::Metrics m = sim::run(p, s, mode, o.seed, observe, &world);
  const double seconds = clock.seconds();
  if (progress && seconds > 1.0) err << "\r" << std::string(40, ' ') << "\r";

  // A* baseline for the picture and the summary (skipped for arenas too large for its grid)
  std::optional<sim::AStarResult> a8;
  try {
    a8 = sim::astar(s, {sim::Connectivity::kEight});
    if (!a8->found) err << "note: " << sim::kNoAStarPath << "\n";
  } catch (const sim::ConfigError& e) {
    err << "note: no A* baseline: " << e.what() << "\n";
  }
  std::size_t recorded_frames = 0;
  if (recorder) {
    sim::Recording r = recorder->finish(world, m, a8 ? &*a8 : nullptr);
    complete_recording(r, s);
    recorded_frames = r.frame_count();
    write_recording_file(o.record, r);
  }
  const double robot_ticks_per_s =
      seconds > 0 ? static_cast<double>(m.robots) * static_cast<double>(m.ticks) / seconds : 0.0;
  const bool pf = mode == sim::Mode::kPathFormation || mode == sim::Mode::kTaskAllocation;
  const bool ta = mode == sim::Mode::kTaskAllocation;

  // both pictures: the run in the caption, the A* and the formed paths drawn
  const auto picture = [&](const std::string& what) {
    Picture pic;
    pic.scenario = &s;
    pic.caption.push_back(what + std::to_string(m.robots) + " robots, seed " + std::to_string(o.seed) +
                          ", mode " + std::string(sim::to_string(mode)) + ", tick " +
                          std::to_string(m.ticks) + ", state_hash " + sim::to_hex(m.state_hash));
    if (pf) {
      pic.caption.push_back(m.success ? "path complete at tick " + std::to_string(m.ticks_to_form)
                                      : std::string("path not complete"));
    }
    add_path_lines(pic, m, a8 ? &*a8 : nullptr);
    return pic;
  };
  if (!o.svg.empty()) {
    Picture pic = picture("");
    pic.world = &world;
    pic.trails = std::move(trails);
    write_svg_file(o.svg, pic);
  }
  if (occupancy) {
    Picture pic = picture("where the robots were until the end: ");
    pic.occupancy = &*occupancy;
    write_svg_file(o.heatmap, pic);
  }

  if (o.json) {
    const std::optional<double> astar8 =
        a8 && a8->found ? std::optional<double>(sim::to_tu(a8->length_m)) : std::nullopt;
    nlohmann::ordered_json j = simulation_json(p, s, mode, o.seed, m, astar8);
    j["wall_seconds"] = seconds;
    j["robot_ticks_per_second"] = robot_ticks_per_s;
    if (!o.svg.empty()) j["svg"] = o.svg;
    if (!o.heatmap.empty()) j["heatmap"] = o.heatmap;
    if (!o.record.empty()) j["recording"] = {{"file", o.record}, {"frames", recorded_frames}};
    out << j.dump(2) << "\n";
    return kExitOk;
  }
  out << "swarmpath simulate: " << s.name << " (" << sim::to_string(s.env_class) << "), " << m.robots
      << " robots, seed " << o.seed << ", mode " << sim::to_string(mode) << "\n";
  out << "  ticks         " << m.ticks << " (" << fixed(static_cast<double>(m.ticks) * s.sim.dt(), 1)
      << " s simulated)\n";
  out << "  state_hash    " << sim::to_hex(m.state_hash) << "\n";
  out << "  mean speed    " << fixed(m.mean_speed_cm_s, 2) << " cm/s\n";
  if (a8 && a8->found) out << "  A*-8          " << fixed(sim::to_tu(a8->length_m), 1) << " TU\n";
  if (pf) {
    const auto length = [](double tu) { return std::isnan(tu) ? std::string("-") : fixed(tu, 1) + " TU"; };
    out << "  success       " << (m.success ? "yes" : "no") << "\n";
    out << "  T_chain       " << m.ticks_to_chain << " ticks, subgoal path "
        << length(m.subgoal_path_length_tu) << "\n";
    out << "  T_opt1        " << m.ticks_to_opt1 << " ticks, optimisation-1 path "
        << length(m.opt1_path_length_tu) << "\n";
    out << "  T_form        " << m.ticks_to_form << " ticks, final path " << length(m.path_length_tu) << " ("
        << m.path_robots << " robots)\n";
    out << "  links         " << m.chain.subgoals_laid << " subgoals laid, " << m.chain.subgoals_laid_goalward
        << " goal-ward of their parent; " << m.chain.forming_from_goal_side
        << " robots began forming from the goal side of their target\n";
    if (ta) {
      out << "  allocation    "
          << (m.allocated >= 0
                  ? std::to_string(m.allocated) + " robots at tick " + std::to_string(m.ticks_to_allocate) +
                        ", resource reduction " + fixed(m.resource_reduction_pct, 1) + " %"
                  : std::string("none"))
          << "\n";
    }
  }
  if (s.faults.any()) {
    out << "  faults        " << faults_text(s.faults) << "\n";
    out << "  failures      " << m.failures << " robots failed, " << m.chain_failures
        << " of them holding a chain link\n";
  }
  out << "  wall time     " << fixed(seconds, 3) << " s (" << fixed(robot_ticks_per_s / 1e6, 2)
      << " M robot-ticks/s)\n";
  if (!o.svg.empty()) out << "  picture       " << o.svg << "\n";
  if (!o.heatmap.empty()) out << "  heat map      " << o.heatmap << "\n";
  if (!o.record.empty()) {
    out << "  recording     " << o.record << " (" << recorded_frames << " frames; swarmpath view " << o.record
        << " --out run.html)\n";
  }
  return kExitOk;
}

}  // namespace

Runner add_simulate(CLI::App& app) {
  auto o = std::make_shared<SimulateOptions>();
  app.add_option("--scenario", o->scenario, "Scenario file (TOML), e.g. configs/scenarios/paper/env4.toml")
      ->required();
  app.add_option("--params", o->params, "Params file (TOML, SPEC 7 names); default: the paper's defaults");
  app.add_option("--robots", o->robots, "Number of robots (default: the scenario's deployment.robots)");
  add_seed_option(app, "--seed", o->seed, "Random seed: deployment and every robot's stream derive from it");
  app.add_option("--ticks", o->ticks,
                 "Ticks to simulate (default: the scenario's max_ticks; 10 ticks = 1 s)");
  app.add_option(
         "--mode", o->mode,
         "Controller: diffusion (random walk with obstacle avoidance), pf (the paper's path formation) or ta "
         "(task allocation, then path formation)")
      ->capture_default_str();
  app.add_flag("--keep-running", o->keep_running, "pf: keep simulating after the path is complete");
  app.add_option("--svg", o->svg,
                 "Write a picture of the final state: robots by LED colour; A* red, subgoal path blue, "
                 "optimisation-1 purple, optimisation-2 green");
  app.add_flag("--trails", o->trails, "Draw every robot's trail in the SVG");
  app.add_option(
      "--heatmap", o->heatmap,
      "Write a heat map of where the robots spent the run (SVG): robot-ticks per cell on a log colour "
      "scale, with the A* and the formed paths");
  app.add_option("--heatmap-led", o->heatmap_led,
                 "Count only robots showing this LED colour in the heat map, e.g. green (exploring), red "
                 "(subgoals), gray50 (returning), black (resting); default: all robots");
  app.add_option("--heatmap-cell", o->heatmap_cell_cm, "Heat-map cell side in cm (1-500)")
      ->capture_default_str();
  app.add_flag("--json", o->json, "Print one JSON object instead of the text summary");
  app.add_option(
      "--record", o->record,
      "Record the run (.swrec): poses, LEDs, states and chain links every --record-every ticks, every "
      "state change, the milestones and paths; play it with 'swarmpath view'");
  app.add_option("--record-every", o->record_every,
                 "Ticks between recorded frames (default: one second of simulated time, 10 ticks)");
  add_fault_options(app, o->faults);
  return [o](std::ostream& out, std::ostream& err) { return run_simulate(*o, out, err); };
}

}  // namespace swarmpath::app
