// SPDX-License-Identifier: MIT
// swarmpath export: a params file as a params file (TOML), as JSON (name -> value, with units),
// or as the attribute block of an ARGoS controller's <params> element.
#include <memory>
#include <ostream>
#include <sstream>

#include <CLI/CLI.hpp>

#include "cli.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "evolve/atomic_write.hpp"
#include "evolve/params_export.hpp"
#include "evolve/path_collision.hpp"
#include "sim/config_error.hpp"

namespace swarmpath::app {

namespace {

struct ExportOptions {
  std::string params;
  std::string format = "toml";
  std::string out;
};

int run_export(const ExportOptions& o, std::ostream& out, std::ostream& err) {
  if (o.format != "toml" && o.format != "json" && o.format != "argos") {
    throw sim::ConfigError("--format", 0, "",
                           "unknown format \"" + o.format + "\" (choices: toml, json, argos)");
  }
  evolve::check_output_paths({{"--params", o.params}}, {{"--out", o.out}});
  const sim::Params p = params_or_defaults(o.params);
  const std::string source = o.params.empty() ? "the paper's defaults (SPEC 7)" : o.params;
  std::ostringstream text;
  if (o.format == "toml") {
    sim::write_params_toml(text, p, "# swarmpath export of " + source + "\n\n");
  } else if (o.format == "json") {
    text << evolve::params_export_json(p).dump(2) << "\n";
  } else {
    evolve::write_argos_params(text, p, source);
  }
  if (o.out.empty()) {
    out << text.str();
    return kExitOk;
  }
  evolve::write_file_atomic(o.out, text.str());
  err << "wrote " << o.out << "\n";
  return kExitOk;
}

}  // namespace

Runner add_export(CLI::App& app) {
  auto o = std::make_shared<ExportOptions>();
  app.add_option("--params", o->params, "Params file (default: the paper's defaults)");
  app.add_option(
         "--format", o->format,
         "toml (a params file), json (name -> {value, unit, row, meaning}) or argos (the attributes of "
         "an ARGoS controller's <params> element, SPEC 7 names)")
      ->capture_default_str();
  app.add_option("--out", o->out, "Write to this file (default: standard output)");
  return [o](std::ostream& out, std::ostream& err) { return run_export(*o, out, err); };
}

}  // namespace swarmpath::app
