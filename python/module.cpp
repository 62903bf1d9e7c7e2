// SPDX-License-Identifier: MIT
#include "bindings.hpp"
#include "evolve/report.hpp"

namespace swarmpath::python {

py::object to_python(const nlohmann::ordered_json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

}  // namespace swarmpath::python

PYBIND11_MODULE(swarmpath, m) {
  namespace sp = swarmpath::python;
  namespace py = pybind11;
  m.doc() = R"(swarmpath: a fast, deterministic swarm simulator for the dynamic subgoal-based path
formation and task allocation of Ratnabala, Peter and Charles, and the tools to tune its controllers.

The same C++ as the `swarmpath` command line, so the same inputs give the same numbers:

    import swarmpath
    p = swarmpath.Params.load("genomes/default.toml").replace(v_max=25, T_explore0=1500)
    s = swarmpath.Scenario.load("configs/scenarios/paper/env4.toml")
    r = swarmpath.evaluate(p, s, mode="pf", seed=1, robots=60)   # the fields of `simulate --json`
    rs = swarmpath.evaluate_many([dict(params=p, scenario=s, seed=k) for k in range(8)], threads=2)
    t = swarmpath.table(["configs/scenarios/paper"], robots=[60], seeds=2)   # `table --json`

    c = swarmpath.EvolveConfig.load("configs/evolve/default.toml")
    f = swarmpath.Objective(c)                        # the config's scenarios, robots and fitness
    cand = c.decode({"T_explore0": 1500, "p_turn": 0.01})   # rounded to the grid, repaired
    stats = f.evaluate(cand, f.generation_cases(0), threads=2)   # stats["fitness"]: minimised

Bad input raises swarmpath.ConfigError (a ValueError) with .file, .line and .key, as the command
line prints them. Simulations release the GIL; evaluate_many, table and Objective.evaluate run
them in parallel on `threads` threads with results that do not depend on the thread count.
)";
  sp::bind_errors(m);
  sp::bind_params(m);
  sp::bind_scenario(m);
  sp::bind_run(m);
  sp::bind_evolve(m);
  const swarmpath::evolve::BuildInfo b = swarmpath::evolve::build_info();
  m.attr("__version__") = b.version;
  m.attr("build_info") = py::dict(py::arg("version") = b.version, py::arg("git_commit") = b.git_commit,
                                  py::arg("compiler") = b.compiler, py::arg("box2d") = b.box2d,
                                  py::arg("build_type") = b.build_type);
}
