// SPDX-License-Identifier: MIT
// swarmpath.EvolveConfig, Candidate, Case and Objective: an evolve config's genome, cases and
// fitness for outside tuners (Optuna, pycma, ...), scored by the runner's own batch evaluation.
#include <pybind11/stl.h>

#include <omp.h>

#include "bindings.hpp"
#include "evolve/evolve_config.hpp"
#include "evolve/genome.hpp"
#include "evolve/objective.hpp"
#include "evolve/runner.hpp"
#include "evolve/simulation_budget.hpp"
#include "sim/config_error.hpp"

namespace swarmpath::python {

namespace {

using evolve::Decoded;
using evolve::EvalCase;
using evolve::EvolveConfig;
using evolve::Genome;

// an evolve config with its objective (the simulator and the config's fitness)
struct Objective {
  explicit Objective(const evolve::EvolveConfig& c) : config(c), f(c) {}

  evolve::EvolveConfig config;
  evolve::SwarmObjective f;
};

// an integer-valued real parameter (integer = true) counts as an integer
const char* gene_type(const evolve::Gene& g) {
  return g.integer && g.info->type == sim::ParamType::kReal ? "integer" : type_name(g.info->type);
}

py::list genes(const EvolveConfig& c) {
  py::list out;
  for (const evolve::Gene& g : c.genome.genes) {
    py::dict e;
    e["name"] = std::string(g.info->name);
    e["type"] = gene_type(g);
    e["lo"] = g.lo;
    e["hi"] = g.hi;
    e["step"] = g.step;
    e["log"] = g.log;
    if (g.info->type == sim::ParamType::kChoice) {
      e["choices"] = py::make_tuple(std::string(g.info->choices[0]), std::string(g.info->choices[1]));
    }
    out.append(e);
  }
  return out;
}

// a tuned value from Python: numbers, bools, or a choice's name
double gene_number(const evolve::Gene& g, py::handle v) {
  const std::string name(g.info->name);
  if (g.info->type == sim::ParamType::kChoice && py::isinstance<py::str>(v)) {
    const std::string text = v.cast<std::string>();
    if (text == g.info->choices[0]) return 0.0;
    if (text == g.info->choices[1]) return 1.0;
    throw sim::ConfigError("EvolveConfig.decode", 0, name,
                           "must be \"" + std::string(g.info->choices[0]) + "\" or \"" +
                               std::string(g.info->choices[1]) + "\", got \"" + text + "\"");
  }
  if (py::isinstance<py::str>(v)) throw sim::ConfigError("EvolveConfig.decode", 0, name, "must be a number");
  return py::float_(py::reinterpret_borrow<py::object>(v)).cast<double>();
}

Decoded decode_values(const EvolveConfig& c, const py::object& values) {
  const Genome& g = c.genome;
  std::vector<double> v(g.genes.size());
  for (std::size_t i = 0; i < g.genes.size(); ++i) v[i] = sim::get_value(g.base, *g.genes[i].info);
  if (py::isinstance<py::dict>(values)) {
    for (const auto& [k, x] : values.cast<py::dict>()) {
      const std::string key = py::str(k);
      std::size_t i = 0;
      while (i < g.genes.size() && g.genes[i].info->name != key) ++i;
      if (i == g.genes.size())
        throw sim::ConfigError("EvolveConfig.decode", 0, key, "not a tuned parameter of " + c.file);
      v[i] = gene_number(g.genes[i], x);
    }
  } else {
    const py::sequence s = values.cast<py::sequence>();
    if (s.size() != g.genes.size()) {
      throw sim::ConfigError("EvolveConfig.decode", 0, "",
                             "give " + std::to_string(g.genes.size()) +
                                 " values (one per tuned parameter), got " + std::to_string(s.size()));
    }
    for (std::size_t i = 0; i < g.genes.size(); ++i) v[i] = gene_number(g.genes[i], s[i]);
  }
  return evolve::decode_values(g, v);
}

Decoded as_candidate(py::handle h) {
  if (py::isinstance<Decoded>(h)) return h.cast<Decoded>();
  return Decoded{h.cast<sim::Params>(), false, {}};
}

py::dict score_dict(const evolve::RunScore& s) {
  py::dict d;
  d["fitness"] = s.fitness;
  d["success"] = s.success;
  d["ticks"] = s.ticks;
  d["path_ratio"] = std::isnan(s.path_ratio) ? py::object(py::none()) : py::object(py::float_(s.path_ratio));
  d["robots_used"] = s.robots_used;
  d["robots_fraction"] = s.robots_fraction;
  return d;
}

py::dict stats_dict(const evolve::CandidateStats& st, std::span<const evolve::RunScore> runs) {
  py::dict d;
  d["fitness"] = st.fitness;
  d["success_rate"] = st.success_rate;
  d["mean_ticks"] = st.mean_ticks;
  d["mean_path_ratio"] =
      std::isnan(st.mean_path_ratio) ? py::object(py::none()) : py::object(py::float_(st.mean_path_ratio));
  d["mean_robots"] = st.mean_robots;
  d["mean_robots_fraction"] = st.mean_robots_fraction;
  d["runs"] = st.runs;
  py::list scores;
  for (const evolve::RunScore& s : runs) scores.append(score_dict(s));
  d["scores"] = scores;
  return d;
}

py::object evaluate(const Objective& o, const py::object& candidates, const std::vector<EvalCase>& cases,
                    int threads) {
  if (threads < 0 || threads > 1024)
    throw sim::ConfigError("Objective.evaluate", 0, "threads", "must lie in [0, 1024] (0: all cores)");
  const bool one = py::isinstance<Decoded>(candidates) || py::isinstance<sim::Params>(candidates);
  std::vector<Decoded> list;
  if (one) {
    list.push_back(as_candidate(candidates));
  } else {
    for (const py::handle h : candidates) list.push_back(as_candidate(h));
  }
  const evolve::SwarmObjective& f = o.f;
  for (const EvalCase& c : cases) {
    if (c.setting >= f.settings().size()) {
      throw sim::ConfigError("Objective.evaluate", 0, "cases",
                             "setting " + std::to_string(c.setting) + " does not exist (the objective has " +
                                 std::to_string(f.settings().size()) + ")");
    }
  }
  std::vector<evolve::RunScore> scores;
  {
    const py::gil_scoped_release free;
    scores = evolve::evaluate_batch(f, list, cases, threads > 0 ? threads : omp_get_max_threads());
  }
  const std::vector<evolve::CandidateStats> stats = evolve::candidate_stats(scores, list.size());
  py::list out;
  for (std::size_t i = 0; i < list.size(); ++i) {
    out.append(stats_dict(stats[i],
                          std::span<const evolve::RunScore>(scores.data() + i * cases.size(), cases.size())));
  }
  return one ? out[0] : py::object(out);
}

}  // namespace

void bind_evolve(py::module_& m) {
  py::class_<Decoded>(m, "Candidate",
                      "Tuned values made into params: rounded to each parameter's grid, cross constraints "
                      "repaired (as the evolve runner decodes its optimisers' candidates).")
      .def(py::init([](const sim::Params& p) {
             return Decoded{p, false, {}};
           }),
           py::arg("params"))
      .def_readonly("params", &Decoded::params)
      .def_readonly("repaired", &Decoded::repaired, "A cross constraint was repaired.")
      .def_readonly(
          "violation", &Decoded::violation,
          "Non-empty when still invalid after repair: such a candidate is not simulated and scores the "
          "penalty (a failure in every term) on every case.")
      .def_property_readonly("valid", [](const Decoded& d) { return d.violation.empty(); })
      .def("__repr__", [](const Decoded& d) {
        return std::string("Candidate(") + (d.violation.empty() ? "valid" : "invalid: " + d.violation) +
               (d.repaired ? ", repaired" : "") + ")";
      });

  py::class_<EvalCase>(m, "Case", "One simulation of a candidate: a setting (scenario x robots) and a seed.")
      .def(py::init([](std::size_t setting, int replicate, std::uint64_t seed) {
             return EvalCase{setting, replicate, seed};
           }),
           py::arg("setting"), py::arg("replicate") = 0, py::arg("seed") = 1)
      .def_readwrite("setting", &EvalCase::setting, "Index into Objective.settings.")
      .def_readwrite("replicate", &EvalCase::replicate, "k-th seed of the setting.")
      .def_readwrite("seed", &EvalCase::seed, "The simulation seed.")
      .def("__repr__", [](const EvalCase& c) {
        return "Case(setting=" + std::to_string(c.setting) + ", replicate=" + std::to_string(c.replicate) +
               ", seed=" + std::to_string(c.seed) + ")";
      });

  py::class_<EvolveConfig>(
      m, "EvolveConfig",
      "An evolve config (configs/evolve/*.toml): base params, tuned parameters and their "
      "bounds, evaluation set, mode, fitness weights, optimiser, budget, re-evaluation.")
      .def_static(
          "load", &evolve::load_evolve_config, py::arg("path"),
          "Loads and checks an evolve config (and the scenario and params files it names); ConfigError "
          "naming file, line and key, as `swarmpath evolve` reports it.")
      .def_readonly("file", &EvolveConfig::file)
      .def_readonly("name", &EvolveConfig::name)
      .def_property_readonly("mode",
                             [](const EvolveConfig& c) { return std::string(sim::to_string(c.mode)); })
      .def_readonly("seed", &EvolveConfig::seed, "The master seed.")
      .def_property_readonly(
          "base", [](const EvolveConfig& c) { return c.genome.base; }, "The base params (the start point).")
      .def_property_readonly(
          "genes", &genes,
          "The tuned parameters in gene order: dicts with name, type (real, integer, bool, "
          "choice), lo, hi, step (0: continuous), log and, for choices, choices.")
      .def_property_readonly(
          "hash", [](const EvolveConfig& c) { return evolve::config_hash(c); },
          "The config hash a checkpoint remembers (everything but [budget]).")
      .def(
          "to_dict", [](const EvolveConfig& c) { return to_python(evolve::config_json(c)); },
          "The whole config with every default filled in (as run.json records it).")
      .def(
          "simulation_budget",
          [](const EvolveConfig& c) -> py::object {
            const auto b = evolve::simulation_budget(c);
            if (!b) return py::none();
            py::dict d;
            d["population"] = b->population;
            d["candidates"] = b->candidates;
            d["cases_per_candidate"] = b->cases_per_candidate;
            d["reevaluation"] = b->reevaluation;
            d["total"] = b->total;
            return d;
          },
          "The simulations the config's own run spends to choose its best (candidates x cases each + the "
          "finalists' and, with keep_base, the base params' re-evaluation): what an outside tuner should get "
          "for a fair comparison. None for a "
          "wall-time budget.")
      .def("decode", &decode_values, py::arg("values"),
           "A Candidate from tuned values: a dict {name: value} (names not given keep the base value) or a "
           "sequence in gene order; choices by name or 0/1, bools as bool. Values are clamped into the "
           "bounds and "
           "rounded to the grid; cross constraints are repaired.")
      .def(
          "decode_unit",
          [](const EvolveConfig& c, const std::vector<double>& x) {
            if (x.size() != c.genome.genes.size()) {
              throw sim::ConfigError("EvolveConfig.decode_unit", 0, "",
                                     "give " + std::to_string(c.genome.genes.size()) + " coordinates, got " +
                                         std::to_string(x.size()));
            }
            return evolve::decode(c.genome, x);
          },
          py::arg("x"),
          "A Candidate from coordinates in [0, 1]^n (the space swarmpath's optimisers search: linear or log "
          "between the bounds), as the evolve runner decodes them.")
      .def(
          "encode", [](const EvolveConfig& c, const sim::Params& p) { return evolve::encode(c.genome, p); },
          py::arg("params"), "The [0, 1]^n coordinates of params' tuned values (base: the start point).")
      .def("__repr__", [](const EvolveConfig& c) {
        return "EvolveConfig(" + c.name + ", " + std::to_string(c.genome.genes.size()) + " tuned, file " +
               c.file + ")";
      });

  py::class_<Objective>(
      m, "Objective",
      "An evolve config's objective: its training (and held-out) settings, scenario x robot "
      "count, each run scored with the config's [fitness].")
      .def(py::init<const EvolveConfig&>(), py::arg("config"), "Loads the scenarios and computes A* once.")
      .def_readonly("config", &Objective::config)
      .def_property_readonly(
          "settings",
          [](const Objective& o) {
            py::list out;
            for (std::size_t i = 0; i < o.f.settings().size(); ++i) {
              const evolve::EvalSetting& s = o.f.settings()[i];
              py::dict d;
              d["scenario"] = s.scenario;
              d["robots"] = s.robots;
              d["held_out"] = s.held_out;
              d["astar8_tu"] = o.f.astar_tu(i);
              out.append(d);
            }
            return out;
          },
          "Training settings first, then held-out ones: dicts with scenario, robots, held_out, astar8_tu.")
      .def(
          "scenario", [](const Objective& o, std::size_t i) { return o.f.scenario(i); }, py::arg("setting"),
          "The Scenario of a setting (robot count and max_ticks applied).")
      .def(
          "generation_cases",
          [](const Objective& o, std::int64_t generation) {
            const EvolveConfig& c = o.config;
            return evolve::generation_cases(o.f.settings(), c.evaluation.seeds, c.seed, generation,
                                            c.evaluation.fixed_seeds);
          },
          py::arg("generation") = 0,
          "The cases `swarmpath evolve` scores generation `generation` on: every training setting x "
          "[evaluation].seeds seeds, setting-major, the same for every candidate of the generation (common "
          "random "
          "numbers; with fixed_seeds every generation has generation 0's).")
      .def(
          "reevaluation_cases",
          [](const Objective& o, std::optional<int> seeds) {
            return evolve::reevaluation_cases(o.f.settings(), seeds.value_or(o.config.reevaluate.seeds),
                                              o.config.seed);
          },
          py::arg("seeds") = py::none(),
          "The fresh cases `swarmpath evolve` re-evaluates its finalists on: every setting (held-out ones "
          "too) x "
          "`seeds` seeds (default: [reevaluate].seeds), from seeds no generation uses.")
      .def("evaluate", &evaluate, py::arg("candidates"), py::arg("cases"), py::arg("threads") = 0,
           R"(Scores candidates on cases with the config's fitness (minimised), in parallel.

candidates: a Candidate or Params, or a list of them; cases: a list of Case. Returns, per
candidate (a dict for one, a list for a list): fitness (the mean over the cases, summed in case
order), success_rate, mean_ticks (a failure counts max_ticks), mean_path_ratio (path / A* over
the successful runs; None without one), mean_robots, mean_robots_fraction, runs and scores (one
dict per case: fitness, success, ticks, path_ratio, robots_used, robots_fraction). An invalid
Candidate scores the penalty. The runner's batch evaluation with the GIL released: the same
numbers at any thread count, and as `swarmpath evolve` computes them.)");
}

}  // namespace swarmpath::python
