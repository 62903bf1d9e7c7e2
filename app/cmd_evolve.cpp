// SPDX-License-Identifier: MIT
// swarmpath evolve: tune controller parameters as an evolve config says, with a progress line,
// a checkpoint after every generation and --resume.
#include <cmath>
#include <filesystem>
#include <memory>
#include <ostream>

#include <CLI/CLI.hpp>

#include "cli.hpp"
#include "cli_options.hpp"
#include "commands.hpp"
#include "common.hpp"
#include "evolve/evolve_config.hpp"
#include "evolve/folder_lock.hpp"
#include "evolve/objective.hpp"
#include "evolve/pareto_report.hpp"
#include "evolve/pareto_runner.hpp"
#include "evolve/run_folder.hpp"
#include "evolve/runner.hpp"
#include "sim/config_error.hpp"

namespace swarmpath::app {

namespace {

struct EvolveOptions {
  std::string config;
  std::string out;
  std::optional<int> threads;
  std::optional<int> generations;
  bool resume = false;
  bool force = false;
  bool no_wall_time = false;
};

std::string num(double v) {
  if (std::isnan(v)) return "-";
  return fixed(v, std::fabs(v) >= 100.0 ? 0 : 4);
}

std::string budget_text(const evolve::Budget& b) {
  std::string s;
  const auto add = [&](const std::string& t) { s += (s.empty() ? "" : ", ") + t; };
  if (b.generations > 0) add(std::to_string(b.generations) + " generations");
  if (b.evaluations > 0) add(std::to_string(b.evaluations) + " evaluations");
  if (b.wall_seconds > 0) add(fixed(b.wall_seconds, 0) + " s");
  return s;
}

// the remaining wall time, from the pace of this process
double eta_seconds(const evolve::Budget& b, const evolve::RunState& st, std::int64_t gen0, std::int64_t eval0,
                   double elapsed) {
  const double gens = static_cast<double>(st.generation - gen0);
  if (gens <= 0) return 0.0;
  double eta = 0.0;
  if (b.generations > 0) eta = elapsed / gens * static_cast<double>(b.generations - st.generation);
  if (b.evaluations > 0) {
    const double evals = static_cast<double>(st.evaluations - eval0);
    const double e =
        elapsed / evals * static_cast<double>(std::max<std::int64_t>(0, b.evaluations - st.evaluations));
    eta = b.generations > 0 ? std::min(eta, e) : e;
  }
  if (b.wall_seconds > 0) {
    const double w = std::max(0.0, b.wall_seconds - elapsed);
    eta = (b.generations > 0 || b.evaluations > 0) ? std::min(eta, w) : w;
  }
  return std::max(0.0, eta);
}

void print_stats_row(std::ostream& out, const std::string& label, const std::string& found,
                     const evolve::CandidateStats& gen, const evolve::CandidateStats& fresh,
                     const evolve::CandidateStats& held) {
  out << "| " << label << " | " << found << " | " << (gen.runs > 0 ? num(gen.fitness) : "-") << " | "
      << num(fresh.fitness) << " | " << (held.runs > 0 ? num(held.fitness) : "-") << " | "
      << fixed(100.0 * fresh.success_rate, 0) << " % | " << fixed(fresh.mean_ticks, 0) << " | "
      << num(fresh.mean_path_ratio) << " | " << fixed(fresh.mean_robots, 1) << " |\n";
}

// the front on fresh seeds, the base params under it
void print_pareto_summary(std::ostream& out, const evolve::EvolveConfig& c, const evolve::ParetoResult& r,
                          const std::string& dir) {
  out << "run " << c.name << ": " << r.state.generation << " generations, " << r.state.evaluations
      << " evaluations, " << r.state.runs << " training runs; hypervolume " << num(r.hypervolume)
      << " (re-evaluated " << num(r.reevaluated_hypervolume) << "); the " << r.front.size()
      << " front points re-evaluated on " << r.reevaluation_cases.size()
      << " fresh cases each (mean +- 95 % CI)\n\n";
  out << "| point | found | success |";
  for (const evolve::ObjectiveKind k : c.multi.objectives) out << ' ' << evolve::objective_title(k) << " |";
  out << " note |\n|---|---|---|";
  for (std::size_t k = 0; k < c.multi.objectives.size(); ++k) out << "---|";
  out << "---|\n";
  const auto row = [&](const std::string& label, const std::string& found, const evolve::FrontPoint& p,
                       const std::string& note) {
    out << "| " << label << " | " << found << " | " << fixed(100.0 * p.reevaluated.success_rate, 0) << " % |";
    for (std::size_t k = 0; k < c.multi.objectives.size(); ++k) {
      out << ' ' << evolve::interval_text(c.multi.objectives[k], p.intervals[k]) << " |";
    }
    out << ' ' << note << " |\n";
  };
  std::size_t dominating = 0;
  for (std::size_t i = 0; i < r.front.size(); ++i) {
    const evolve::FrontPoint& p = r.front[i];
    std::string note;
    if (p.reevaluated_violation > 0.0)
      note = "infeasible after re-evaluation";
    else if (p.dominated_after_reevaluation)
      note = "dominated after re-evaluation";
    if (p.dominates_base) note += std::string(note.empty() ? "" : "; ") + "dominates the base params";
    dominating += p.dominates_base ? 1 : 0;
    row(std::to_string(i),
        "gen " + std::to_string(p.elite.generation) + " #" + std::to_string(p.elite.candidate), p, note);
  }
  row("base params", c.params_written.empty() ? "paper defaults" : c.params_written, r.base, "");
  out << "\n"
      << dominating << " of " << r.front.size() << " front points dominate the base params on the fresh seeds"
      << (dominating > 0 ? "; their differences, paired on the same runs (mean +- 95 % CI):\n" : "\n");
  for (std::size_t i = 0; i < r.front.size(); ++i) {
    if (!r.front[i].dominates_base) continue;
    out << "  point " << i << " - base:";
    for (std::size_t k = 0; k < c.multi.objectives.size(); ++k) {
      out << (k ? ", " : " ") << evolve::objective_name(c.multi.objectives[k]) << ' '
          << evolve::interval_text(c.multi.objectives[k], r.front[i].versus_base[k]);
    }
    out << '\n';
  }
  out << "wrote " << dir << "/{pareto.csv, pareto.svg, front/000.toml.."
      << (r.front.empty() ? "" : evolve::front_file_name(r.front.size() - 1))
      << ", log.csv, hypervolume.svg, run.json, checkpoint.json}\n";
}

int run_evolve(const EvolveOptions& o, const evolve::EvaluatorFactory& evaluators, std::ostream& out,
               std::ostream& err) {
  const evolve::EvolveConfig c = evolve::load_evolve_config(o.config);
  if (o.generations && *o.generations < 1) throw sim::ConfigError("--generations", 0, "", "must be >= 1");
  const int threads = threads_or_all(o.threads);
  const std::string dir =
      o.out.empty() ? (std::filesystem::path("results") / "evolve" / c.name).string() : o.out;
  if (o.resume && o.force) {
    throw sim::ConfigError("--force", 0, "",
                           "--resume continues the run in the folder, --force replaces it: give one");
  }
  evolve::check_output_folder("--out", dir);
  evolve::check_run_inputs(c, dir);
  const evolve::SwarmObjective objective(c);
  const evolve::Budget budget = evolve::effective_budget(c, o.generations);
  const std::unique_ptr<evolve::BatchEvaluator> evaluator = evaluators(threads);

  std::size_t training = 0, families = 0;
  for (const evolve::EvalSetting& s : objective.settings()) {
    training += s.held_out || s.family >= 0 ? 0 : 1;
    families += s.family >= 0 ? 1 : 0;
  }
  const std::size_t runs = evolve::first_cases(c, objective.settings()).size();
  std::string names;
  for (const evolve::Gene& g : c.genome.genes)
    names += (names.empty() ? "" : " ") + std::string(g.info->name);
  err << "swarmpath evolve: " << c.name << " (" << c.file << "), mode " << sim::to_string(c.mode) << ", "
      << c.genome.dim() << " parameters (" << names << "), " << runs << " runs per candidate (" << training
      << " scenario x robots settings x " << c.evaluation.seeds << " seeds"
      << (families > 0
              ? ", " + std::to_string(families) + " family x robots settings on fresh arenas every generation"
              : std::string())
      << "), optimiser " << c.optimizer.name << ", budget " << budget_text(budget) << ", "
      << evaluator->describe() << " -> " << dir << "\n";

  const bool tty = stderr_is_terminal();
  const Stopwatch clock;
  std::int64_t gen0 = 0, eval0 = 0;  // where this process starts (for the ETA)
  if (o.resume) {
    const std::string ck = (std::filesystem::path(dir) / "checkpoint.json").string();
    if (std::filesystem::exists(ck)) {
      const evolve::RunState s = evolve::read_checkpoint(ck);
      gen0 = s.generation;
      eval0 = s.evaluations;
    }
  }
  std::int64_t in_flight = gen0;
  double best_so_far = std::nan("");
  evolve::RunOptions ro;
  ro.out_dir = dir;
  ro.threads = threads;
  ro.evaluator = evaluator.get();
  ro.generations = o.generations;
  ro.resume = o.resume;
  ro.force = o.force;
  ro.wall_time = !o.no_wall_time;
  ro.note = [&](const std::string& s) {
    if (tty) err << "\r\033[K";
    err << "  " << s << "\n";
  };
  ro.progress = [&](std::size_t done, std::size_t total) {
    if (!tty) return;
    err << "\r\033[K  generation " << in_flight << ": " << done << " / " << total << " runs, "
        << (c.multi_objective() ? "hypervolume " : "best so far ") << num(best_so_far) << ", "
        << fixed(clock.seconds(), 0) << " s" << std::flush;
  };
  ro.callbacks.push_back([&](const evolve::GenerationRecord& r, const evolve::RunState& st) {
    best_so_far = c.multi_objective() ? r.hypervolume : r.best_so_far;
    in_flight = r.generation + 1;
    const double t = clock.seconds();
    if (tty) err << "\r\033[K";
    err << "  generation " << r.generation
        << (budget.generations > 0 ? "/" + std::to_string(budget.generations) : "") << ": ";
    if (c.multi_objective()) {
      err << "hypervolume " << num(r.hypervolume) << ", front " << r.front_size << ", feasible " << r.feasible
          << ", best success " << fixed(100.0 * r.best_success_rate, 0) << " %";
    } else {
      err << "best " << num(r.best) << " (success " << fixed(100.0 * r.best_success_rate, 0) << " %), mean "
          << num(r.mean) << " +- " << num(r.std) << ", best so far " << num(r.best_so_far);
      if (r.validation_runs > 0) {
        err << ", best on validation " << num(r.validation_fitness) << " (success "
            << fixed(100.0 * r.validation_success_rate, 0) << " %)";
      }
    }
    err << ", " << r.evaluations << " evaluations, " << fixed(t, 0) << " s, ETA "
        << fixed(eta_seconds(budget, st, gen0, eval0, t), 0) << " s\n";
    return false;
  });
  if (c.multi_objective()) {
    const evolve::ParetoResult r = evolve::run_pareto(c, objective, ro);
    if (tty) err << "\r\033[K";
    err << "  done in " << fixed(clock.seconds(), 1) << " s (stopped by " << r.stop_reason
        << "): " << evaluator->summary() << "\n";
    print_pareto_summary(out, c, r, dir);
    return kExitOk;
  }
  const evolve::RunResult r = evolve::run_evolution(c, objective, ro);
  if (tty) err << "\r\033[K";
  err << "  done in " << fixed(clock.seconds(), 1) << " s (stopped by " << r.stop_reason
      << "): " << evaluator->summary() << "\n";

  // the finalists on fresh seeds, the base params beside them
  const evolve::Finalist& best = r.finalists[r.best];
  out << "run " << c.name << ": " << r.state.generation << " generations, " << r.state.evaluations
      << " evaluations, " << r.state.runs << " training runs; finalists re-evaluated on "
      << r.reevaluation_cases.size() << " fresh cases each\n\n";
  out << "| candidate | found | generation fitness | fresh fitness | held-out fitness | success | ticks | "
         "path/A* "
         "| robots |\n|---|---|---|---|---|---|---|---|---|\n";
  for (std::size_t i = 0; i < r.finalists.size(); ++i) {
    const evolve::Finalist& f = r.finalists[i];
    print_stats_row(out, (i == r.best ? "**" + std::to_string(i) + " (best)**" : std::to_string(i)),
                    evolve::elite_origin(f.elite, true), f.elite.stats, f.reevaluated, f.held_out);
  }
  print_stats_row(out, "base params", c.params_written.empty() ? "paper defaults" : c.params_written,
                  evolve::CandidateStats{}, r.base.reevaluated, r.base.held_out);
  if (best.arenas.runs > 0) {
    out << "\non the " << best.arenas.runs << " validation arena runs alone: best "
        << num(best.arenas.fitness) << " (success " << fixed(100.0 * best.arenas.success_rate, 0)
        << " %), base params " << num(r.base.arenas.fitness) << " (success "
        << fixed(100.0 * r.base.arenas.success_rate, 0) << " %)\n";
  }
  if (r.selection.on) {
    const evolve::BaseSelection& s = r.selection;
    out << "\nkeep_base: base minus best finalist " << num(s.mean_difference) << " +- "
        << num(s.sd_difference) << " (sd) over " << s.pairs
        << " paired runs, one-sided p = " << num(s.p_value) << (s.base_kept ? " >= " : " < ")
        << num(s.threshold) << " (level " << num(s.level) << " / " << s.finalists << " finalists)\n";
  }
  if (r.selection.base_kept) {
    out << "\npick: the base params, kept (validation-set fitness " << num(r.base.reevaluated.fitness)
        << "; best finalist " << num(best.reevaluated.fitness) << ")\n";
  } else {
    out << "\nbest (validation-set fitness " << num(best.reevaluated.fitness) << " vs base "
        << num(r.base.reevaluated.fitness) << "):\n";
  }
  for (const evolve::Gene& g : c.genome.genes) {
    out << "  " << g.info->name << " = " << sim::format_value(r.pick(), *g.info) << "   (base "
        << sim::format_value(c.genome.base, *g.info) << ")\n";
  }
  out << "wrote " << dir << "/{best.toml, log.csv, fitness.svg, run.json, checkpoint.json}\n";
  return kExitOk;
}

}  // namespace

Runner add_evolve(CLI::App& app, const evolve::EvaluatorFactory& evaluators) {
  auto o = std::make_shared<EvolveOptions>();
  app.add_option("--config", o->config,
                 "Evolve config (TOML), e.g. configs/evolve/default.toml (CMA-ES, one best params file) or "
                 "configs/evolve/paper-ta-pareto.toml (NSGA-II, a Pareto front)")
      ->required();
  app.add_option("--out", o->out, "Output folder (default: results/evolve/<config name>)");
  add_threads_option(app, o->threads);
  app.add_option("--generations", o->generations,
                 "Run this many generations in all (replaces the config's budget; with --resume, the total)");
  app.add_flag("--resume", o->resume, "Continue the run in the output folder from its checkpoint.json");
  app.add_flag("--force", o->force,
               "Start afresh in an output folder that holds an earlier run (its files move to "
               "<out>/replaced/<time>/); without --resume or --force such a folder is refused");
  app.add_flag("--no-wall-time", o->no_wall_time,
               "Record 0 for every wall time (log.csv, checkpoint) so that runs compare bit for bit");
  return
      [o, evaluators](std::ostream& out, std::ostream& err) { return run_evolve(*o, evaluators, out, err); };
}

}  // namespace swarmpath::app
