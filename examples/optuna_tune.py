#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Tune an evolve config's parameters with Optuna (TPE or CMA-ES) through the swarmpath module.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/optuna_tune.py \
        --config configs/evolve/default.toml --sampler tpe --threads 2 --out results/optuna/default

What it takes from the evolve config: the tuned parameters and their bounds, log scales and
steps ([tune]) as Optuna's search space; the base params as the first trial (where swarmpath's
optimisers start); the scenarios, robot counts and seeds ([evaluation]) and the fitness weights
([fitness]) through swarmpath.Objective, which scores a trial exactly as `swarmpath evolve` scores
a candidate; and by default as many trials as the config's own run spends simulations
(EvolveConfig.simulation_budget(), in runs of a trial).

Seeds are common random numbers: every trial runs on the same seeds (the config's generation-0
cases), so two trials differ by their parameters, not by luckier deployments. A best trial
chosen on those seeds is flattered by them, so it is run again, beside the base params, on the
config's fresh re-evaluation seeds, and that is what gets reported. Writes best.toml (a params
file with its provenance), trials.csv and result.json into --out.
"""
import argparse
import csv
import json
import math
import os
import sys
import time

import optuna

try:
    import swarmpath
except ImportError:  # not installed: the module of this checkout's release build
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "build", "release", "python"))
    import swarmpath


def suggest(trial, gene):
    """One tuned parameter as an Optuna distribution: the config's bounds, log scale and step."""
    name, lo, hi, step, log = gene["name"], gene["lo"], gene["hi"], gene["step"], gene["log"]
    if gene["type"] == "bool":
        return trial.suggest_categorical(name, [False, True])
    if gene["type"] == "choice":
        return trial.suggest_categorical(name, list(gene["choices"]))
    if gene["type"] == "integer" or (step and float(step).is_integer() and float(lo).is_integer() and not log):
        # integer steps; Optuna takes no step with a log scale (the decoding rounds to the grid)
        return trial.suggest_int(name, math.ceil(lo), math.floor(hi), step=1 if log else max(1, int(step or 1)),
                                 log=log)
    # a step that is not whole: Optuna's own grid starts at lo as the config's does
    return trial.suggest_float(name, lo, hi, log=log, step=None if log or not step else step)


def base_values(config):
    base = config.base
    return {g["name"]: base[g["name"]] for g in config.genes}


def make_sampler(name, seed, config):
    if name == "tpe":
        return optuna.samplers.TPESampler(seed=seed)
    if name == "cmaes":
        return optuna.samplers.CmaEsSampler(seed=seed, x0=base_values(config), warn_independent_sampling=False)
    if name == "random":
        return optuna.samplers.RandomSampler(seed=seed)
    raise ValueError(f"unknown sampler {name!r} (tpe, cmaes, random)")


def tune(config, objective, sampler="tpe", trials=None, seed=1, threads=0, progress=None):
    """Runs the study; returns (study, best Candidate, simulations spent)."""
    cases = objective.generation_cases(0)  # the same seeds for every trial
    if trials is None:
        budget = config.simulation_budget()
        trials = max(1, budget["total"] // len(cases))
    study = optuna.create_study(direction="minimize", sampler=make_sampler(sampler, seed, config))
    study.enqueue_trial(base_values(config))  # start where swarmpath's optimisers start

    def fitness(trial):
        values = {g["name"]: suggest(trial, g) for g in config.genes}
        candidate = config.decode(values)
        stats = objective.evaluate(candidate, cases, threads=threads)
        trial.set_user_attr("success_rate", stats["success_rate"])
        trial.set_user_attr("mean_ticks", stats["mean_ticks"])
        if progress:
            progress(trial.number + 1, trials, stats["fitness"])
        return stats["fitness"]

    study.optimize(fitness, n_trials=trials)
    best = config.decode({k: v for k, v in study.best_trial.params.items()})
    return study, best, trials * len(cases)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--config", required=True, help="evolve config (TOML)")
    ap.add_argument("--sampler", default="tpe", choices=["tpe", "cmaes", "random"], help="Optuna's sampler")
    ap.add_argument("--trials", type=int, default=None,
                    help="trials (default: the config's own simulation budget, in runs per trial)")
    ap.add_argument("--seed", type=int, default=1, help="the sampler's seed")
    ap.add_argument("--threads", type=int, default=0, help="simulations at once within a trial (0: all cores)")
    ap.add_argument("--reevaluate-seeds", type=int, default=None,
                    help="fresh seeds per setting for the best and the base params (default: the config's)")
    ap.add_argument("--out", default=None, help="output folder (default: results/optuna/<config name>-<sampler>)")
    a = ap.parse_args(argv)
    optuna.logging.set_verbosity(optuna.logging.WARNING)

    try:
        config = swarmpath.EvolveConfig.load(a.config)
    except swarmpath.ConfigError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    objective = swarmpath.Objective(config)
    out = a.out or os.path.join("results", "optuna", f"{config.name}-{a.sampler}")
    os.makedirs(out, exist_ok=True)

    def progress(done, total, f):
        print(f"\r  trial {done} / {total}: fitness {f:.4f}", end="", file=sys.stderr, flush=True)

    t0 = time.perf_counter()
    study, best, spent = tune(config, objective, a.sampler, a.trials, a.seed, a.threads, progress)
    seconds = time.perf_counter() - t0
    print(file=sys.stderr)

    # the best trial and the base params on the same fresh seeds
    fresh = objective.reevaluation_cases(a.reevaluate_seeds)
    best_fresh, base_fresh = objective.evaluate([best, config.base], fresh, threads=a.threads)
    tuned = {g["name"]: best.params[g["name"]] for g in config.genes}
    header = (f"# Optuna {optuna.__version__} ({a.sampler}, seed {a.seed}): the best of {len(study.trials)} trials "
              f"of the evolve config {config.file} (hash {config.hash}),\n"
              f"# each on the same {spent // len(study.trials)} runs (fitness {study.best_value:.6g}); on "
              f"{best_fresh['runs']} fresh runs fitness {best_fresh['fitness']:.6g}, success rate "
              f"{best_fresh['success_rate']:.3g} (base params {base_fresh['fitness']:.6g}).\n"
              f"# swarmpath {swarmpath.__version__}, git {swarmpath.build_info['git_commit']}; tuned: "
              + ", ".join(f"{k} = {v}" for k, v in tuned.items()) + ".\n\n")
    best.params.save(os.path.join(out, "best.toml"), header)
    with open(os.path.join(out, "trials.csv"), "w", newline="") as f:
        w = csv.writer(f)
        names = [g["name"] for g in config.genes]
        w.writerow(["trial", *names, "fitness", "success_rate", "mean_ticks"])
        for t in study.trials:
            w.writerow([t.number, *[t.params[n] for n in names], repr(t.value), t.user_attrs["success_rate"],
                        t.user_attrs["mean_ticks"]])
    result = {
        "tool": "examples/optuna_tune.py", "optuna": optuna.__version__, "sampler": a.sampler, "seed": a.seed,
        "config": config.file, "config_hash": config.hash, "trials": len(study.trials),
        "simulations": spent, "wall_seconds": seconds,
        "best": {"trial": study.best_trial.number, "values": tuned, "fitness_on_trial_seeds": study.best_value,
                 "fresh": {k: v for k, v in best_fresh.items() if k != "scores"}},
        "base": {"values": {g["name"]: config.base[g["name"]] for g in config.genes},
                 "fresh": {k: v for k, v in base_fresh.items() if k != "scores"}},
    }
    with open(os.path.join(out, "result.json"), "w") as f:
        json.dump(result, f, indent=2)
    print(f"best of {len(study.trials)} trials ({spent} simulations, {seconds:.1f} s): "
          + ", ".join(f"{k} = {v}" for k, v in tuned.items()))
    print(f"  fresh seeds ({best_fresh['runs']} runs): fitness {best_fresh['fitness']:.4f} "
          f"(success {100 * best_fresh['success_rate']:.0f} %), base params {base_fresh['fitness']:.4f} "
          f"(success {100 * base_fresh['success_rate']:.0f} %)")
    print(f"  files: {out}/best.toml, trials.csv, result.json")
    return 0


if __name__ == "__main__":
    sys.exit(main())
