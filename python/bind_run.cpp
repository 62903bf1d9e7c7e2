// SPDX-License-Identifier: MIT
// swarmpath.evaluate, evaluate_many and table: sim::evaluate through the command line's own
// functions (the JSON of `simulate --json`, the parallel job runner, the table of `table --json`),
// with the GIL released while simulations run.
#include <map>
#include <optional>
#include <pybind11/stl.h>

#include <omp.h>

#include "app/common.hpp"
#include "app/experiment.hpp"
#include "app/table_run.hpp"
#include "bindings.hpp"
#include "evolve/batch.hpp"
#include "sim/config_error.hpp"
#include "sim/step.hpp"

namespace swarmpath::python {

namespace {

sim::Mode mode_named(const std::string& text, const std::string& where) {
  if (const auto m = sim::parse_mode(text)) return *m;
  std::string choices;
  for (const sim::Mode m : sim::kModes)
    choices += (choices.empty() ? "" : ", ") + std::string(sim::to_string(m));
  throw sim::ConfigError(where, 0, "mode", "unknown mode \"" + text + "\" (choices: " + choices + ")");
}

// a scenario with evaluate()'s robots and max_ticks applied
sim::Scenario with_overrides(const sim::Scenario& s, std::optional<std::int64_t> robots,
                             std::optional<std::int64_t> max_ticks) {
  sim::Scenario out = robots ? sim::with_robots(s, *robots, "robots") : s;
  if (max_ticks) out = sim::with_max_ticks(out, *max_ticks, "max_ticks");
  return out;
}

int threads_or_all(int threads, const std::string& where) {
  if (threads < 0 || threads > 1024)
    throw sim::ConfigError(where, 0, "threads", "must lie in [0, 1024] (0: all cores)");
  return threads > 0 ? threads : omp_get_max_threads();
}

py::dict evaluate(const sim::Params& p, const sim::Scenario& scenario, const std::string& mode,
                  std::uint64_t seed, std::optional<std::int64_t> robots,
                  std::optional<std::int64_t> max_ticks) {
  const sim::Mode md = mode_named(mode, "evaluate");
  const sim::Scenario s = with_overrides(scenario, robots, max_ticks);
  sim::Metrics m;
  std::optional<double> astar;
  {
    const py::gil_scoped_release free;
    astar = app::astar8_tu(s);
    m = sim::evaluate(p, s, md, seed);
  }
  return to_python(app::simulation_json(p, s, md, seed, m, astar));
}

struct Job {
  sim::Params params;
  sim::Scenario scenario;
  sim::Mode mode = sim::Mode::kPathFormation;
  std::uint64_t seed = 1;
  const sim::Scenario* arena = nullptr;  // the caller's scenario (its A* is shared by its jobs)
  py::object keep;                       // ... kept alive while the jobs run
};

Job job_from(py::handle h, std::size_t index) {
  const std::string where = "evaluate_many";
  const std::string at = "jobs[" + std::to_string(index) + "]";
  Job job;
  std::optional<std::int64_t> robots, max_ticks;
  std::string mode = "pf";
  if (py::isinstance<py::dict>(h)) {
    const py::dict d = h.cast<py::dict>();
    bool have_params = false, have_scenario = false;
    for (const auto& [k, v] : d) {
      const std::string key = py::str(k);
      if (key == "params") {
        job.params = v.cast<sim::Params>();
        have_params = true;
      } else if (key == "scenario") {
        job.arena = &v.cast<const sim::Scenario&>();
        job.keep = py::reinterpret_borrow<py::object>(v);
        have_scenario = true;
      } else if (key == "mode") {
        mode = v.cast<std::string>();
      } else if (key == "seed") {
        job.seed = v.cast<std::uint64_t>();
      } else if (key == "robots") {
        if (!v.is_none()) robots = v.cast<std::int64_t>();
      } else if (key == "max_ticks") {
        if (!v.is_none()) max_ticks = v.cast<std::int64_t>();
      } else {
        throw sim::ConfigError(where, 0, at + "." + key,
                               "unknown key (a job takes params, scenario, mode, seed, robots, max_ticks)");
      }
    }
    if (!have_params) throw sim::ConfigError(where, 0, at + ".params", "missing");
    if (!have_scenario) throw sim::ConfigError(where, 0, at + ".scenario", "missing");
  } else {
    const py::sequence t = h.cast<py::sequence>();
    if (t.size() < 2 || t.size() > 4)
      throw sim::ConfigError(where, 0, at, "a job is a dict or a tuple (params, scenario[, mode[, seed]])");
    job.params = t[0].cast<sim::Params>();
    job.arena = &t[1].cast<const sim::Scenario&>();
    job.keep = t[1];
    if (t.size() > 2) mode = t[2].cast<std::string>();
    if (t.size() > 3) job.seed = t[3].cast<std::uint64_t>();
  }
  job.mode = mode_named(mode, where + ": " + at);
  job.scenario = with_overrides(*job.arena, robots, max_ticks);
  return job;
}

py::list evaluate_many(const py::iterable& items, int threads) {
  const int n_threads = threads_or_all(threads, "evaluate_many");
  std::vector<Job> jobs;
  for (const py::handle h : items) jobs.push_back(job_from(h, jobs.size()));
  // one batch on this process's threads (the BatchEvaluator that table and evolve use)
  evolve::SimBatch batch;
  std::map<const sim::Scenario*, std::optional<double>> astar;
  for (const Job& j : jobs) {
    // one params set and one scenario per job; `jobs` outlives the batch, so the scenario is lent
    const std::uint32_t pi = batch.add_params(j.params);
    batch.scenarios.emplace_back(&j.scenario, [](const sim::Scenario*) {});
    batch.tasks.push_back({pi, static_cast<std::uint32_t>(batch.scenarios.size() - 1), j.mode, j.seed});
  }
  std::vector<sim::Metrics> metrics;
  {
    const py::gil_scoped_release free;
    for (const Job& j : jobs) {
      if (!astar.contains(j.arena)) astar[j.arena] = app::astar8_tu(j.scenario);
    }
    evolve::ThreadPool pool(n_threads);
    metrics = pool.run(batch);
  }
  py::list out;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    out.append(to_python(app::simulation_json(jobs[i].params, jobs[i].scenario, jobs[i].mode, jobs[i].seed,
                                              metrics[i], astar[jobs[i].arena])));
  }
  return out;
}

py::object table(const std::vector<std::string>& scenarios, const std::vector<int>& robots, int seeds,
                 std::uint64_t seed_base, const std::string& mode, const std::optional<sim::Params>& params,
                 std::optional<std::int64_t> max_ticks, int threads) {
  app::TableRequest r;
  r.scenarios = scenarios;
  r.robots = robots;
  r.seeds = seeds;
  r.seed_base = seed_base;
  r.mode = mode;
  r.params = params.value_or(sim::Params{});
  r.ticks = max_ticks;
  r.threads = threads_or_all(threads, "table");
  const app::TablePlan plan = app::plan_table(r);
  app::TableOutcome outcome;
  {
    const py::gil_scoped_release free;
    evolve::ThreadPool pool(plan.threads);
    outcome = app::run_table(plan, pool);
  }
  return to_python(outcome.json);
}

}  // namespace

void bind_run(py::module_& m) {
  m.def("evaluate", &evaluate, py::arg("params"), py::arg("scenario"), py::arg("mode") = "pf",
        py::arg("seed") = 1, py::arg("robots") = py::none(), py::arg("max_ticks") = py::none(),
        R"(One simulation: `swarmpath simulate --json` as a dict.

params: Params; scenario: Scenario; mode: 'pf' (path formation), 'ta' (task allocation, then path
formation) or 'diffusion'; seed: the deployment and every robot's random stream derive from it;
robots, max_ticks: override the scenario's (as --robots and --ticks do).

Returns every field `simulate --json` prints but the wall-clock ones (wall_seconds,
robot_ticks_per_second), which would make equal runs differ: scenario, scenario_file, env_class,
mode, robots, seed, ticks, max_ticks, state_hash, distance_m, mean_speed_cm_s, astar8_tu, and for
pf and ta success, ticks_to_form, path_length_tu (1 TU = 10 cm), subgoal/opt1 path lengths,
path_robots, ticks_to_chain, ticks_to_opt1, ticks_to_goal, the chain counts and, with task
allocation, allocated, resource_reduction_pct, ticks_to_allocate, recruited. Values that were
never reached are None. The GIL is released while it runs.)");
  m.def("evaluate_many", &evaluate_many, py::arg("jobs"), py::arg("threads") = 0,
        R"(Many simulations in parallel: a list of evaluate() dicts, in job order.

jobs: dicts with evaluate()'s arguments (params and scenario required; mode, seed, robots,
max_ticks optional) or tuples (params, scenario[, mode[, seed]]). threads: 0 uses every core.
The simulations run on C++ threads with the GIL released; each result goes to its own slot, so
the results are the same at any thread count and equal to evaluate()'s one by one.)");
  m.def("table", &table, py::arg("scenarios") = std::vector<std::string>{"configs/scenarios/paper"},
        py::arg("robots") = std::vector<int>{60, 70, 80, 90, 100}, py::arg("seeds") = 10,
        py::arg("seed_base") = 1, py::arg("mode") = "pf", py::arg("params") = py::none(),
        py::arg("max_ticks") = py::none(), py::arg("threads") = 0,
        R"(The paper's experiment table: `swarmpath table --json` as a dict.

scenarios: scenario files or folders of *.toml; robots: robot counts; seeds per (scenario, robots,
mode), seed_base ... seed_base + seeds - 1; mode: pf, ta or both (each case with and without task
allocation on the same seeds); params: Params (default: the defaults); max_ticks overrides every
scenario's; threads: 0 uses every core (the results do not depend on it). The GIL is released
while the grid runs.)");
}

}  // namespace swarmpath::python
