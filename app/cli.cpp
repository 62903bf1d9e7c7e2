// SPDX-License-Identifier: MIT
#include "cli.hpp"

#include <exception>
#include <ostream>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "sim/config_error.hpp"
#include "sim/edit_distance.hpp"
#include "standard_output.hpp"

namespace swarmpath::app {

namespace {

int dispatch(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
             const evolve::EvaluatorFactory& evaluators) {
  CLI::App app{
      "swarmpath: a fast, deterministic swarm simulator for dynamic subgoal-based path formation and task "
      "allocation (Ratnabala, Peter, Charles), and the tools to tune its controllers.",
      "swarmpath"};
  app.require_subcommand(1);
  app.fallthrough(false);

  struct Entry {
    CLI::App* cmd;
    Runner run;
  };

  std::vector<Entry> commands;
  {
    CLI::App* c = app.add_subcommand("simulate", "Run one simulation and summarise it (text, JSON, SVG).");
    commands.push_back({c, add_simulate(*c)});
  }
  {
    CLI::App* c = app.add_subcommand("astar", "A* baseline path lengths of a scenario (SPEC 4.5).");
    commands.push_back({c, add_astar(*c)});
  }
  {
    CLI::App* c = app.add_subcommand(
        "table", "Run a grid of scenario x robots x seed in parallel and write the paper's results table.");
    commands.push_back({c, add_table(*c, evaluators)});
  }
  {
    CLI::App* c = app.add_subcommand(
        "ablate",
        "The default controller with each addition beyond SPEC switched off in turn, and the paper-literal "
        "one "
        "with each switched on, on the same seeds: paired differences with 95 % intervals (markdown, JSON, "
        "SVG).");
    commands.push_back({c, add_ablate(*c, evaluators)});
  }
  {
    CLI::App* c = app.add_subcommand(
        "robustness",
        "Success, time and path against robots failing and packet loss, with and without task allocation.");
    commands.push_back({c, add_robustness(*c, evaluators)});
  }
  {
    CLI::App* c = app.add_subcommand(
        "evolve",
        "Tune controller parameters with an optimiser, or evolve a Pareto front with nsga2 (evolve config; "
        "checkpoints; --resume).");
    commands.push_back({c, add_evolve(*c, evaluators)});
  }
  {
    CLI::App* c = app.add_subcommand(
        "evaluate", "The experiment table of one params file, optionally beside another on the same seeds.");
    commands.push_back({c, add_evaluate(*c, evaluators)});
  }
  {
    CLI::App* c =
        app.add_subcommand("export", "Write a params file as TOML, JSON or an ARGoS <params> block.");
    commands.push_back({c, add_export(*c)});
  }
  {
    CLI::App* c = app.add_subcommand("arena", "Draw arenas from families (generate) and list the families.");
    commands.push_back({c, add_arena(*c)});
  }
  {
    CLI::App* c = app.add_subcommand(
        "benchmark",
        "Measure a params file (or two) on a benchmark of generated arenas and the paper arenas.");
    commands.push_back({c, add_benchmark(*c, evaluators)});
  }
  {
    CLI::App* c = app.add_subcommand(
        "verify", "Re-run each shipped tuned genome against the default on fresh seeds: does it still win?");
    commands.push_back({c, add_verify(*c, evaluators)});
  }

  {
    CLI::App* c = app.add_subcommand(
        "view",
        "Play a recorded run (simulate --record): one self-contained web page, a video or a frame as JSON.");
    commands.push_back({c, add_view(*c)});
  }

  {
    CLI::App* c = app.add_subcommand(
        "report", "A tuning run (evolve's output folder) as one self-contained web page, with replays.");
    commands.push_back({c, add_report(*c)});
  }
  {
    CLI::App* c = app.add_subcommand(
        "irace", "Tune with irace: write an irace scenario from an evolve config, import irace's best.");
    commands.push_back({c, add_irace(*c)});
  }

  // an unknown command: named, with the nearest one (CLI11 would only say that one is required)
  if (!args.empty() && !args[0].empty() && args[0][0] != '-') {
    std::string nearest;
    std::size_t best = 4;
    bool known = false;
    for (const Entry& c : commands) {
      const std::string& name = c.cmd->get_name();
      known = known || name == args[0];
      const std::size_t d = sim::edit_distance(args[0], name);
      if (d < best || (name.rfind(args[0], 0) == 0 && best > 1)) {
        best = name.rfind(args[0], 0) == 0 ? 1 : d;
        nearest = name;
      }
    }
    if (!known) {
      err << "error: unknown command '" << args[0] << "'"
          << (nearest.empty() ? std::string() : " (did you mean '" + nearest + "'?)")
          << "\nRun 'swarmpath --help' for the commands.\n";
      return kExitBadInput;
    }
  }

  // CLI11 wants argv order with the program name first and parses from the back
  std::vector<std::string> reversed(args.rbegin(), args.rend());
  try {
    app.parse(reversed);
  } catch (const CLI::CallForHelp&) {
    out << app.help();  // delegates to the subcommand given --help
    return kExitOk;
  } catch (const CLI::CallForAllHelp&) {
    out << app.help("", CLI::AppFormatMode::All);
    return kExitOk;
  } catch (const CLI::ParseError& e) {
    err << "error: " << e.what() << "\n";
    if (args.empty())
      err << app.help();
    else
      err << "Run 'swarmpath --help' or 'swarmpath <command> --help' for usage.\n";
    return kExitBadInput;
  }

  for (const Entry& c : commands) {
    if (!c.cmd->parsed()) continue;
    try {
      return c.run(out, err);
    } catch (const sim::ConfigError& e) {
      err << "error: " << e.what() << "\n";
      return kExitBadInput;
    } catch (const std::exception& e) {
      err << "error: " << e.what() << "\n";
      return kExitFailure;
    }
  }
  return kExitBadInput;
}

}  // namespace

int run_cli(const std::vector<std::string>& args, std::ostream& out, std::ostream& err,
            const evolve::EvaluatorFactory& evaluators) {
  return checked_standard_output(out, err, dispatch(args, out, err, evaluators));
}

}  // namespace swarmpath::app
