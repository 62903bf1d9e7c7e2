// SPDX-License-Identifier: MIT
// swarmpath arena: draw arenas from the families of sim/arenas (`arena generate`) and list the
// families with their parameters and ranges (`arena families`).
#include <memory>
#include <ostream>

#include <CLI/CLI.hpp>

#include "cli.hpp"
#include "cli_options.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "evolve/atomic_write.hpp"
#include "evolve/path_collision.hpp"
#include "sim/arenas/registry.hpp"
#include "sim/astar.hpp"
#include "sim/config_error.hpp"
#include "sim/scenario_writer.hpp"
#include "svg.hpp"

namespace swarmpath::app {

namespace {

namespace arenas = sim::arenas;

struct GenerateOptions {
  std::string family;
  std::uint64_t seed = 1;
  std::vector<std::string> set;
  std::string out;
  std::string svg;
  double px_per_m = 30.0;
};

// the whole `arena families` listing (markdown; docs/arena-families.md holds the same text)
void write_families(std::ostream& out) {
  for (const arenas::Family& f : arenas::families()) {
    out << "### " << f.name << "\n\n" << f.description << ".\n\n";
    out << "| parameter | default | range | unit | meaning |\n|---|---|---|---|---|\n";
    for (const arenas::FamilyParam& q : arenas::all_params(f)) {
      out << "| " << q.name << " | " << sim::toml_number(q.fallback) << " | " << sim::toml_number(q.lo)
          << " - " << sim::toml_number(q.hi) << (q.integer ? " (whole)" : "") << " | "
          << (q.unit.empty() ? "-" : q.unit) << " | " << q.help << " |\n";
    }
    out << "\n";
  }
}

int run_generate(const GenerateOptions& o, std::ostream& out, std::ostream& err) {
  if (!(o.px_per_m >= 2.0 && o.px_per_m <= 500.0)) {
    throw sim::ConfigError("--px-per-m", 0, "", "must lie in [2, 500]");
  }
  if (arenas::find_family(o.family) == nullptr) {
    throw sim::ConfigError(
        "--family", 0, "",
        "unknown arena family \"" + o.family + "\" (families: " + arenas::family_names() + ")");
  }
  const arenas::ArenaSpec spec = arenas::spec_from_settings(o.family, o.set, "--set");
  if (arenas::is_benchmark_seed(o.seed)) {
    err << "note: seed " << o.seed << " lies in [" << arenas::kBenchmarkSeedLo << ", "
        << arenas::kBenchmarkSeedHi
        << "), the benchmarks' seeds: measure on this arena, never screen or tune on it "
           "(docs/arena-families.md)\n";
  }
  evolve::check_output_paths({}, {{"--out", o.out}, {"--svg", o.svg}});
  const arenas::GeneratedArena a = arenas::generate_arena(spec, o.seed);
  if (!o.svg.empty()) {
    const sim::AStarResult path = sim::astar(a.scenario);
    Picture pic;
    pic.scenario = &a.scenario;
    pic.px_per_m = o.px_per_m;
    pic.lines.push_back(
        {path.path, "#e00000", 2.0, "A* 8-connected: " + fixed(sim::to_tu(a.astar8_m), 1) + " TU", false});
    const std::string settings = spec.settings_text();
    pic.caption.push_back("family " + std::string(spec.family->name) + ", seed " + std::to_string(o.seed) +
                          (settings.empty() ? "" : " (" + settings + ")"));
    pic.caption.push_back("A* / A* without obstacles " +
                          fixed(a.astar8_m / arenas::empty_arena_astar8(a.scenario), 2) +
                          "; deployment region dashed");
    write_svg_file(o.svg, pic);
  }
  if (o.out.empty()) {
    out << a.toml;
    return kExitOk;
  }
  evolve::write_file_atomic(o.out, a.toml);
  out << "wrote " << o.out << ": " << a.scenario.name << ", class " << sim::to_string(a.scenario.env_class)
      << ", A*-8 " << fixed(sim::to_tu(a.astar8_m), 1) << " TU, " << a.scenario.boxes.size() << " boxes and "
      << a.scenario.cylinders.size() << " cylinders" << (o.svg.empty() ? "" : "; picture " + o.svg) << "\n";
  return kExitOk;
}

}  // namespace

Runner add_arena(CLI::App& app) {
  app.require_subcommand(1);
  auto g = std::make_shared<GenerateOptions>();
  CLI::App* gen = app.add_subcommand(
      "generate",
      "Draw one arena of a family (deterministic in family, parameters and seed) as a scenario file.");
  gen->add_option("--family", g->family, "Arena family (swarmpath arena families lists them)")->required();
  add_seed_option(*gen, "--seed", g->seed, "Arena seed: the same seed draws the same arena");
  gen->add_option("--set", g->set, "A family parameter, key=value (repeatable), e.g. --set walls=2");
  gen->add_option("--out", g->out, "Write the scenario file here (default: print it)");
  gen->add_option("--svg", g->svg, "Draw the arena with its A* path");
  gen->add_option("--px-per-m", g->px_per_m, "Picture scale [px per m]")->capture_default_str();
  CLI::App* list =
      app.add_subcommand("families", "List the arena families with their parameters, defaults and ranges.");
  return [g, gen, list](std::ostream& out, std::ostream& err) {
    if (list->parsed()) {
      write_families(out);
      return kExitOk;
    }
    if (gen->parsed()) return run_generate(*g, out, err);
    return kExitBadInput;
  };
}

}  // namespace swarmpath::app
