#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Compare tuners on one problem with one simulation budget: swarmpath's own optimisers, irace and
Optuna (TPE and CMA-ES), several tuner seeds each; every tuner's pick and the untuned base params
scored on the same fresh runs with the same fitness; a table with 95 % intervals and an SVG plot.

    cd <repository root>; export PYTHONPATH=build/release/python
    /usr/bin/python3 bench/tuners/compare.py run --tuners swarmpath-cmaes,irace --seeds 1-4
    /usr/bin/python3 bench/tuners/compare.py finals --final-seeds 20
    /usr/bin/python3 bench/tuners/compare.py report --docs docs

The problem is an evolve config (--problem, default bench/tuners/problem.toml; another problem's results go
to results/tuners-NAME for problem-NAME.toml, and a results folder holds one problem's runs only). Every tuner gets the
simulations the config's own run spends to choose its best (EvolveConfig.simulation_budget():
candidates x runs each, plus the finalists' re-evaluation), threads simulations at once, and the
base params as its starting point:
  swarmpath-<optimiser>  `swarmpath evolve` with the config (optimiser replaced, population kept),
                          master seed = tuner seed; the pick is its best.toml.
  swarmpath-cmaes-capped  the same with `[evaluation] capping = true` (docs/racing.md).
  swarmpath-cmaes-finalist  the same with `[reevaluate] keep_base = false` and one more finalist: the
                          best finalist is the pick even when it is no better than the base params.
  swarmpath-cmaes-sigma015, -one-finalist, -race-base  sigma0 0.15; one finalist and the base params on
                          the same fresh runs in all; the finalists raced against the base params.
  swarmpath-cmaes-crn     `[evaluation] fixed_seeds = true` and sigma0 0.15: every generation on the same
                          seeds (common random numbers), as Optuna's CMA-ES runs.
  swarmpath-cmaes-mean    `[reevaluate] mean_finalist = true`: the last finalist is CMA-ES's
                          distribution mean after the last generation.
  swarmpath-cmaes-mean-only  the mean as the only finalist (top_k 1) with the base params on the
                          fresh runs of all the finalists (one-finalist's split).
  swarmpath-cmaes-rank, -mean-only-rank  those two with keep_base_test = "signed-rank".
  irace                   `swarmpath irace` scenario, irace's seed = tuner seed, maxExperiments =
                          the budget; the pick is irace's best (elite 1), `swarmpath irace import`.
  optuna-<sampler>        examples/optuna_tune.py's study: budget / runs-per-trial trials, every
                          trial on the same seeds (the config's generation 0 with master seed =
                          tuner seed); the pick is the best trial.
Finals: the picks and the base params on the same fresh seeds (final-seeds per setting, seeds no
tuner saw), scored by swarmpath.Objective. Each tuning run is a child process timed by wall clock
and by CPU time (its own and that of everything it waited for); --jobs runs several at once on a
machine with the cores for it. Each step keeps its results under --out, and a tuning run that
finished is not run again, so the steps can be split over several sittings; finals reuse a pick's
runs from an earlier finals on the same cases (runs/NAME/final.json), so adding tuners or seeds later
runs only the new picks.
"""
import argparse
import json
import math
import os
import pathlib
import re
import shutil
import subprocess
import sys
import time

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "examples"))
sys.path.append(str(ROOT / "build" / "release" / "python"))  # the module, unless PYTHONPATH has one

# swarmpath's optimisers with switches of the problem config turned on: name -> (optimiser, {section: lines
# set in it (a key already there is replaced)}); the problem itself (params, settings, fitness, budget)
# stays as it is
VARIANTS = {
    # adaptive capping (docs/racing.md): a generation's runs first go to half of T_max; the candidates
    # that cannot reach the top are stopped there, so the same finalists for fewer simulated ticks
    "swarmpath-cmaes-capped": ("cmaes", {"evaluation": ["capping = true"]}),
    # the pick as before keep_base (docs/tuners.md): always the best finalist by its fresh-seed mean; the
    # base params' fresh runs then choose nothing, so a third finalist takes their share of the budget
    "swarmpath-cmaes-finalist": ("cmaes", {"reevaluate": ["keep_base = false", lambda body: "top_k = {}".format(
        int((re.search(r"(?m)^top_k = (\d+)", body) or [0, 3])[1]) + 1)]}),
    # a smaller first step: CMA-ES's sigma0 at half of the problem's 0.3 (Optuna's CMA-ES starts at a sixth
    # of each range, 0.167 of the unit box), its samples nearer the tuned base params
    "swarmpath-cmaes-sigma015": ("cmaes", {"optimizer": ["sigma0 = 0.15"]}),
    # another split of the same re-evaluation runs: one finalist and the base params on half again as many
    # fresh runs each (top_k + 1 candidates x seeds stays the same), so one test of more pairs and no
    # Bonferroni split
    "swarmpath-cmaes-one-finalist": ("cmaes", {"reevaluate": [lambda body: one_finalist(body)]}),
    # the finalists raced against the base params (docs/racing.md): a finalist worse than them is dropped
    # and its fresh runs go to more paired runs of the rest; with every finalist dropped it stops early
    "swarmpath-cmaes-race-base": ("cmaes", {"reevaluate": ["race_base = true"]}),
    # Optuna's CMA-ES setup: every generation on generation 0's seeds (common random numbers, so candidates
    # differ by their params, not by their luck) and a first step near Optuna's (0.15 of the unit box)
    "swarmpath-cmaes-crn": ("cmaes", {"evaluation": ["fixed_seeds = true"], "optimizer": ["sigma0 = 0.15"]}),
    # the last finalist is CMA-ES's distribution mean after the last generation instead of the next-best
    # candidate (evolve/README.md, mean_finalist): the same generations and fresh runs
    "swarmpath-cmaes-mean": ("cmaes", {"reevaluate": ["mean_finalist = true"]}),
    # the mean as the only finalist, on the fresh runs that the finalists and the base params share: one
    # keep_base test of more pairs with no Bonferroni split, of a candidate no run's luck chose
    "swarmpath-cmaes-mean-only": ("cmaes", {"reevaluate": ["mean_finalist = true",
                                                           lambda body: one_finalist(body)]}),
    # keep_base's decision by the signed-rank test (ranks, not sizes: one failed run is one pair lost), with
    # the problem's finalists and with the mean alone
    "swarmpath-cmaes-rank": ("cmaes", {"reevaluate": ['keep_base_test = "signed-rank"']}),
    "swarmpath-cmaes-mean-only-rank": ("cmaes", {"reevaluate": ["mean_finalist = true", lambda body: one_finalist(body),
                                                                'keep_base_test = "signed-rank"']}),
}

# the variants that change only how swarmpath-cmaes picks among what its generations found: with the same
# tuner seed their generations are swarmpath-cmaes's bit for bit, so the report pairs them seed by seed
SAME_GENERATIONS = ("swarmpath-cmaes-finalist", "swarmpath-cmaes-one-finalist", "swarmpath-cmaes-race-base",
                    "swarmpath-cmaes-mean", "swarmpath-cmaes-mean-only", "swarmpath-cmaes-rank",
                    "swarmpath-cmaes-mean-only-rank")


def one_finalist(body):
    """[reevaluate]'s lines for one finalist on the fresh runs that top_k finalists and the base params
    share now: top_k = 1 and seeds = (top_k + 1) seeds / 2 (the same simulations)."""
    k = int((re.search(r"(?m)^top_k = (\d+)", body) or [0, 3])[1])
    n = int((re.search(r"(?m)^seeds = (\d+)", body) or [0, 4])[1])
    assert (k + 1) * n % 2 == 0, "one finalist and the base params need an even share of the fresh runs"
    return ["top_k = 1", f"seeds = {(k + 1) * n // 2}"]
TUNERS = ["swarmpath-cmaes", "swarmpath-ga", "swarmpath-random", *VARIANTS, "irace", "optuna-tpe", "optuna-cmaes"]
FINAL_SEED_BASE = 7_000_000_000  # final seeds 7e9 + k: no tuner draws these (evolve mixes 64-bit seeds,
# irace's are below 2^31)


def seeds_of(text):
    out = []
    for part in text.split(","):
        a, _, b = part.partition("-")
        out += list(range(int(a), int(b or a) + 1))
    return out


def config_copy(problem, tuner, seed, out):
    """The problem with the tuner's master seed (and optimiser), written next to the results."""
    text = pathlib.Path(problem).read_text()
    # the files it names, as absolute paths (found as swarmpath finds them: the config's folder first)
    def absolute(m):
        for base in (pathlib.Path(problem).resolve().parent, pathlib.Path.cwd()):
            if (base / m.group(1)).exists():
                return '"' + str((base / m.group(1)).resolve()) + '"'
        return m.group(0)

    text = re.sub(r'"([^"]+\.toml)"', absolute, text)
    text, n = re.subn(r"(?m)^seed = \d+$", f"seed = {seed}", text)
    assert n == 1, "the problem config needs one top-level `seed = N` line"
    text = re.sub(r'(?m)^name = "[^"]*"$', f'name = "{tuner}-s{seed}"', text, count=1)
    if tuner.startswith("swarmpath-"):
        optimiser, added = VARIANTS.get(tuner, (tuner[len("swarmpath-"):], {}))
        for section, lines in added.items():
            head = re.search(rf"(?m)^\[{section}\]$", text)
            assert head, f"the problem config needs one [{section}] section"
            end = re.compile(r"(?m)^\[").search(text, head.end())
            end = end.start() if end else len(text)
            body = text[head.end():end]
            for item in lines:
                item = item(body) if callable(item) else item
                for line in [item] if isinstance(item, str) else item:
                    key = line.split("=")[0].strip()
                    body, n = re.subn(rf"(?m)^{key} = .*$", line, body)
                    if n == 0:
                        body = "\n" + line + body
            text = text[:head.end()] + body + text[end:]
        if optimiser != "cmaes":
            # the same candidates per generation as CMA-ES, so the same generations fit the budget
            import swarmpath

            population = swarmpath.EvolveConfig.load(problem).simulation_budget()["population"]
            text, n = re.subn(r'(?m)^name = "cmaes"$', f'name = "{optimiser}"\npopulation = {population}', text)
            assert n == 1, 'the problem config needs `name = "cmaes"` in [optimizer]'
    path = out / "configs" / f"{tuner}-s{seed}.toml"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(f"# {tuner}, tuner seed {seed}: {problem} with its seed (and optimiser) replaced\n" + text)
    return path


DEFAULT_PROBLEM = "bench/tuners/problem.toml"


def default_out(problem):
    """results/tuners for the default problem, results/tuners-NAME for bench/tuners/problem-NAME.toml (any
    other config: results/tuners-<its file name>), so that two problems' runs never share a folder."""
    if pathlib.Path(problem).resolve() == (ROOT / DEFAULT_PROBLEM).resolve():
        return "results/tuners"
    stem = pathlib.Path(problem).stem
    return "results/tuners-" + (stem[len("problem-"):] if stem.startswith("problem-") else stem)


def claim(out, problem):
    """The results folder belongs to one problem (its config hash, everything but [budget], with the base
    params' values): the first run or finals there records it in problem.json, a later one with another
    problem is refused, so two problems' runs and picks are never mixed in one table."""
    import swarmpath

    mine = {"problem": str(problem), "hash": swarmpath.EvolveConfig.load(str(problem)).hash}
    f = pathlib.Path(out) / "problem.json"
    if f.exists():
        theirs = json.loads(f.read_text())
        if theirs["hash"] != mine["hash"]:
            sys.exit(f"{out} holds the runs of {theirs['problem']} (config hash {theirs['hash']}), not of {problem} "
                     f"(hash {mine['hash']}): give another --out")
        return
    f.parent.mkdir(parents=True, exist_ok=True)
    f.write_text(json.dumps(mine, indent=2) + "\n")


def cli(*args, **kw):
    return subprocess.run([str(ROOT / "build/release/swarmpath"), *map(str, args)], check=True, **kw)


def run_swarmpath(config, tuner, seed, d, threads):
    with open(d / "evolve.log", "w") as log:
        cli("evolve", "--config", config, "--out", d / "evolve", "--threads", threads, stdout=log,
            stderr=subprocess.STDOUT)
    shutil.copy(d / "evolve" / "best.toml", d / "pick.toml")
    run = json.loads((d / "evolve" / "run.json").read_text())
    # the generations' runs and the finalists' on the fresh training cases, and the base params' there
    # when they may be the pick (keep_base; without it their reference runs choose nothing and are left
    # out, as for the other tuners)
    fresh = sum(1 for k in run["seeds"]["reevaluation"] if not k["held_out"])
    selection = run.get("selection", {"keep_base": False, "base_kept": False})
    chosen_from = len(run["finalists"]) + (1 if selection["keep_base"] else 0)
    chose = run["racing"]["simulations"] if "racing" in run else chosen_from * fresh  # racing: what it ran
    meta = {"simulations": run["runs"] + chose, "generations": run["generations"],
            "selection": selection}
    if "capping" in run:  # runs stopped at the cap count as runs, runs started again count twice
        meta["capping"] = run["capping"]
    return meta


def run_irace(config, tuner, seed, d, threads):
    cli("irace", "--config", config, "--out", d / "irace", "--threads", threads, "--seed", seed,
        stdout=subprocess.DEVNULL)
    with open(d / "irace.log", "w") as log:
        subprocess.run([str(d / "irace" / "run-irace")], check=True, stdout=log, stderr=subprocess.STDOUT)
    cli("irace", "import", d / "irace", "--out", d / "pick.toml", stdout=subprocess.DEVNULL)
    rows = (d / "irace" / "elites.csv").read_text().splitlines()
    return {"simulations": int(rows[1].split(",")[rows[0].split(",").index("experiments")])}


def run_optuna(config, tuner, seed, d, threads):
    import optuna
    import optuna_tune
    import swarmpath

    optuna.logging.set_verbosity(optuna.logging.WARNING)
    c = swarmpath.EvolveConfig.load(str(config))
    f = swarmpath.Objective(c)
    study, best, spent = optuna_tune.tune(c, f, tuner[len("optuna-"):], None, seed, threads)
    best.params.save(str(d / "pick.toml"), f"# {tuner}, tuner seed {seed}: the best of {len(study.trials)} trials\n")
    return {"simulations": spent, "trials": len(study.trials), "best_trial_fitness": study.best_value}


def cmd_one(a):
    """One tuning run (a child of `run`, which times it): its pick and what it spent."""
    out = pathlib.Path(a.out)
    d = out / "runs" / f"{a.tuner}-s{a.seed}"
    config = config_copy(a.problem, a.tuner, a.seed, out)
    runner = run_swarmpath if a.tuner.startswith("swarmpath-") else run_irace if a.tuner == "irace" else run_optuna
    meta = runner(config, a.tuner, a.seed, d, a.threads)
    meta.update(tuner=a.tuner, seed=a.seed, config=str(config), threads=a.threads)
    (d / "spent.json").write_text(json.dumps(meta, indent=2))


def cmd_run(a):
    """Every (tuner, seed) run not done yet, each in a child process timed by wall clock and by the CPU
    time of it and everything it waited for (irace's R and target runners, the simulations' threads);
    up to --jobs at a time."""
    out = pathlib.Path(a.out)
    claim(out, a.problem)
    todo = []
    for tuner in a.tuners.split(","):
        if tuner not in TUNERS:
            sys.exit(f"unknown tuner {tuner} (choices: {', '.join(TUNERS)})")
        for seed in seeds_of(a.seeds):
            d = out / "runs" / f"{tuner}-s{seed}"
            if (d / "meta.json").exists():
                print(f"{tuner} seed {seed}: done before", flush=True)
                continue
            shutil.rmtree(d, ignore_errors=True)
            d.mkdir(parents=True)
            todo.append((tuner, seed, d))
    running = {}
    failed = 0
    while todo or running:
        while todo and len(running) < a.jobs:
            tuner, seed, d = todo.pop(0)
            cmd = [sys.executable, str(pathlib.Path(__file__).resolve()), "one", "--tuner", tuner, "--seed", str(seed),
                   "--config", a.problem, "--out", a.out, "--threads", str(a.threads)]
            log = open(d / "run.log", "w")
            p = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT)
            running[p.pid] = (p, tuner, seed, d, time.perf_counter(), log)
        pid, status, usage = os.wait4(-1, 0)
        if pid not in running:
            continue
        p, tuner, seed, d, t0, log = running.pop(pid)
        p.returncode = os.waitstatus_to_exitcode(status)  # reaped here, not by Popen
        log.close()
        wall = time.perf_counter() - t0
        if p.returncode != 0:
            failed += 1
            print(f"{tuner} seed {seed}: FAILED, see {d / 'run.log'}", flush=True)
            continue
        meta = json.loads((d / "spent.json").read_text())
        meta.update(wall_seconds=wall, cpu_seconds=usage.ru_utime + usage.ru_stime, jobs=a.jobs)
        (d / "meta.json").write_text(json.dumps(meta, indent=2))
        print(f"{tuner} seed {seed}: {wall:.0f} s wall, {meta['cpu_seconds']:.0f} s CPU, "
              f"{meta['simulations']} simulations", flush=True)
    if failed:
        sys.exit(f"{failed} runs failed")


def cmd_finals(a):
    """Every pick and the base params on the same fresh cases. A pick's runs are kept next to it
    (final.json, with the cases and its full params): a later finals with the same cases and the same
    params reuses them (the runs are deterministic), so adding tuners or seeds runs only the new picks."""
    import swarmpath

    out = pathlib.Path(a.out)
    claim(out, a.problem)
    c = swarmpath.EvolveConfig.load(a.problem)
    f = swarmpath.Objective(c)
    train = [i for i, s in enumerate(f.settings) if not s["held_out"]]
    cases = [swarmpath.Case(s, k, FINAL_SEED_BASE + i * a.final_seeds + k) for i, s in enumerate(train)
             for k in range(a.final_seeds)]
    case_list = [[x.setting, x.seed] for x in cases]
    picks = {"base": c.base}
    cache = {"base": out / "base-final.json"}
    for d in sorted((out / "runs").glob("*/meta.json")):
        picks[d.parent.name] = swarmpath.Params.load(str(d.parent / "pick.toml"))
        cache[d.parent.name] = d.parent / "final.json"
    results, todo, as_base = {}, [], []
    for name, params in picks.items():
        old = json.loads(cache[name].read_text()) if cache[name].exists() else None
        if old and old["cases"] == case_list and old["params"] == params.to_dict():
            results[name] = old["result"]
        elif name != "base" and params.to_dict() == c.base.to_dict():
            as_base.append(name)  # the base params themselves (keep_base): their runs, not run twice
        else:
            todo.append(name)
    t0 = time.perf_counter()
    stats = f.evaluate([picks[n] for n in todo], cases, threads=a.threads) if todo else []
    seconds = time.perf_counter() - t0
    for name, s in zip(todo, stats):
        results[name] = {"fitness": s["fitness"], "success_rate": s["success_rate"], "mean_ticks": s["mean_ticks"],
                         "runs": [r["fitness"] for r in s["scores"]],
                         "values": {g["name"]: picks[name][g["name"]] for g in c.genes}}
        cache[name].write_text(json.dumps({"cases": case_list, "params": picks[name].to_dict(),
                                           "result": results[name]}))
    for name in as_base:
        results[name] = results["base"]
        cache[name].write_text(json.dumps({"cases": case_list, "params": picks[name].to_dict(),
                                           "result": results[name]}))
    finals = {"cases": case_list, "seconds": seconds, "evaluated": todo, "picks": {n: results[n] for n in picks}}
    (out / "finals.json").write_text(json.dumps(finals, indent=1))
    print(f"finals: {len(todo)} picks x {len(cases)} fresh runs in {seconds:.0f} s "
          f"({len(as_base)} the base params themselves, {len(picks) - len(todo) - len(as_base)} more from earlier "
          "finals on the same runs)")


# Student's t quantile (0.975) for small samples, then the normal's
T975 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447, 7: 2.365, 8: 2.306, 9: 2.262, 10: 2.228,
        12: 2.179, 15: 2.131, 20: 2.086, 30: 2.042}


def t975(df):
    if df <= 0:
        return math.inf
    best = min((k for k in T975 if k >= df), default=None)
    return T975[best] if best is not None else 1.96


def mean_ci(xs):
    n = len(xs)
    m = sum(xs) / n
    if n < 2:
        return m, math.inf
    sd = math.sqrt(sum((x - m) ** 2 for x in xs) / (n - 1))
    return m, t975(n - 1) * sd / math.sqrt(n)


def welch(a, b):
    """Difference of means a - b with a Welch 95 % half-width."""
    ma, mb = sum(a) / len(a), sum(b) / len(b)
    if len(a) < 2 or len(b) < 2:
        return ma - mb, math.inf
    va = sum((x - ma) ** 2 for x in a) / (len(a) - 1)
    vb = sum((x - mb) ** 2 for x in b) / (len(b) - 1)
    se2 = va / len(a) + vb / len(b)
    if se2 == 0:
        return ma - mb, 0.0
    df = se2 ** 2 / ((va / len(a)) ** 2 / (len(a) - 1) + (vb / len(b)) ** 2 / (len(b) - 1))
    return ma - mb, t975(math.floor(df)) * math.sqrt(se2)


def paired(a, b):
    """a - b over the tuner seeds both ran ({seed: value}), with a Student-t 95 % half-width and the pairs."""
    common = sorted(set(a) & set(b))
    if not common:
        return None
    m, h = mean_ci([a[k] - b[k] for k in common])
    return m, h, len(common)


def summary(out):
    finals = json.loads((out / "finals.json").read_text())
    base = finals["picks"]["base"]
    rows = {}
    for name, p in finals["picks"].items():
        if name == "base":
            continue
        tuner, seed = name.rsplit("-s", 1)
        meta = json.loads((out / "runs" / name / "meta.json").read_text())
        r = rows.setdefault(tuner, {"seeds": [], "fitness": [], "vs_base": [], "success": [], "wall": [], "cpu": [],
                                    "sims": []})
        r["seeds"].append(int(seed))
        r["fitness"].append(p["fitness"])
        r["vs_base"].append(sum(x - y for x, y in zip(p["runs"], base["runs"])) / len(base["runs"]))
        r["success"].append(p["success_rate"])
        r["wall"].append(meta["wall_seconds"])
        r["cpu"].append(meta["cpu_seconds"])
        r["sims"].append(meta["simulations"])
    return finals, base, rows


def cmd_report(a):
    out = pathlib.Path(a.out)
    finals, base, rows = summary(out)
    order = sorted(rows, key=lambda t: sum(rows[t]["fitness"]) / len(rows[t]["fitness"]))
    lead = a.reference if a.reference in rows else order[0]
    lines = ["| tuner | tuner seeds | final fitness (mean, 95 % CI) | vs base params | success | "
             f"{lead} - tuner | wall time per run | CPU time per run | simulations per run |",
             "|---|---|---|---|---|---|---|---|---|"]
    for t in order:
        r = rows[t]
        m, h = mean_ci(r["fitness"])
        dm, dh = mean_ci(r["vs_base"])
        sm, _ = mean_ci(r["success"])
        wm, _ = mean_ci(r["wall"])
        cm, _ = mean_ci(r["cpu"])
        diff = "-" if t == lead else "{:+.3f} +- {:.3f}".format(*welch(rows[lead]["fitness"], r["fitness"]))
        lines.append(f"| {t} | {len(r['fitness'])} | {m:.3f} +- {h:.3f} | {dm:+.3f} +- {dh:.3f} | {100 * sm:.0f} % | "
                     f"{diff} | {wm:.0f} s | {cm:.0f} s | {sum(r['sims']) / len(r['sims']):.0f} |")
    nruns = len(base["runs"])
    kept = {t: sum(1 for name in finals["picks"] if name.rsplit("-s", 1)[0] == t and
                   json.loads((out / "runs" / name / "meta.json").read_text()).get("selection", {}).get("base_kept"))
            for t in rows}
    lines.append(f"| base params (untuned) | - | {base['fitness']:.3f} | 0 | {100 * base['success_rate']:.0f} % | - | - | - "
                 "| - |")
    table = "\n".join(lines) + "\n"
    note = (f"\nFinal fitness: each tuner run's pick on the same {nruns} fresh runs (minimised); mean over tuner "
            f"seeds with a Student-t 95 % interval. vs base params: the pick minus the base params, run by run on the "
            f"same fresh runs, averaged over tuner seeds. {lead} - tuner: the difference of the two tuners' mean "
            "final fitness with a Welch 95 % interval (negative: the first is better). Wall time: the tuning run "
            "start to end; CPU time: its process and everything it waited for (R, target runners, simulation "
            "threads), which other work on the machine disturbs less.\n")
    same = [t for t in order if t in SAME_GENERATIONS and lead == "swarmpath-cmaes"]
    pairs = {t: paired(dict(zip(rows[lead]["seeds"], rows[lead]["fitness"])),
                       dict(zip(rows[t]["seeds"], rows[t]["fitness"]))) for t in same}
    pairs = {t: p for t, p in pairs.items() if p}
    if pairs:
        note += (f"\nVariants that change only the pick (their generations are {lead}'s, seed by seed), {lead} - "
                 "variant paired by tuner seed (Student-t 95 %; positive: the variant is better): " +
                 "; ".join(f"{t} {m:+.3f} +- {h:.3f} ({n} seeds)" for t, (m, h, n) in pairs.items()) + ".\n")
    kept_note = "; ".join(f"{t} {k} of {len(rows[t]['fitness'])}" for t, k in kept.items() if k)
    if kept_note:
        note += f"\nPicks that are the base params (keep_base: no finalist beat them on the fresh runs): {kept_note}.\n"
    print(table + note)
    docs = pathlib.Path(a.docs or ".")
    (out / "table.md").write_text(table + note)
    svg = plot(rows, order, base)
    (out / "tuners.svg").write_text(svg)
    if a.docs:  # named after the results folder: tuners.svg, tuners-naive.svg for results/tuners-naive
        docs.mkdir(parents=True, exist_ok=True)
        (docs / f"{out.name}.svg").write_text(svg)
    print(f"files: {out}/table.md, {out}/tuners.svg" + (f", {docs}/{out.name}.svg" if a.docs else ""))


def plot(rows, order, base):
    """Final fitness per tuner: each tuner seed's pick (dots), the mean and its 95 % interval (bar),
    the base params (dashed line); the wall time per run under each name."""
    h, left, right, top, bottom = 420, 80, 20, 40, 90
    w = max(760, left + right + 190 * len(order))  # room for each name and its figures under it
    values = [v for t in order for v in rows[t]["fitness"]] + [base["fitness"]]
    cis = [mean_ci(rows[t]["fitness"]) for t in order]
    lo = min(values + [m - c for m, c in cis if math.isfinite(c)])
    hi = max(values + [m + c for m, c in cis if math.isfinite(c)])
    pad = 0.08 * (hi - lo or 1)
    lo, hi = lo - pad, hi + pad
    y = lambda v: top + (hi - v) / (hi - lo) * (h - top - bottom)
    step = (w - left - right) / len(order)
    s = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{w}" height="{h}" font-family="sans-serif" font-size="12">',
         f'<rect width="{w}" height="{h}" fill="white"/>',
         f'<text x="{w / 2}" y="20" text-anchor="middle" font-size="14">Final fitness on the same fresh runs '
         '(lower is better): picks, mean and 95 % CI</text>',
         f'<line x1="{left}" y1="{top}" x2="{left}" y2="{h - bottom}" stroke="black"/>']
    for k in range(6):
        v = lo + (hi - lo) * k / 5
        s.append(f'<line x1="{left - 4}" y1="{y(v):.1f}" x2="{w - right}" y2="{y(v):.1f}" stroke="#ddd"/>')
        s.append(f'<text x="{left - 8}" y="{y(v) + 4:.1f}" text-anchor="end">{v:.3f}</text>')
    s.append(f'<line x1="{left}" y1="{y(base["fitness"]):.1f}" x2="{w - right}" y2="{y(base["fitness"]):.1f}" '
             'stroke="#c00" stroke-dasharray="6 4"/>')
    s.append(f'<text x="{w - right - 4}" y="{y(base["fitness"]) - 5:.1f}" text-anchor="end" fill="#c00">'
             f'base params {base["fitness"]:.3f}</text>')
    for i, t in enumerate(order):
        x = left + step * (i + 0.5)
        m, c = cis[i]
        for j, v in enumerate(rows[t]["fitness"]):
            s.append(f'<circle cx="{x - 14 + 28 * j / max(1, len(rows[t]["fitness"]) - 1):.1f}" cy="{y(v):.1f}" '
                     'r="3.5" fill="#888"/>')
        if math.isfinite(c):
            s.append(f'<line x1="{x + 22:.1f}" y1="{y(m - c):.1f}" x2="{x + 22:.1f}" y2="{y(m + c):.1f}" '
                     'stroke="#1f4fff" stroke-width="2"/>')
        s.append(f'<rect x="{x + 16:.1f}" y="{y(m) - 2:.1f}" width="12" height="4" fill="#1f4fff"/>')
        wall = sum(rows[t]["cpu"]) / len(rows[t]["cpu"])
        s.append(f'<text x="{x:.1f}" y="{h - bottom + 18}" text-anchor="middle">{t}</text>')
        s.append(f'<text x="{x:.1f}" y="{h - bottom + 34}" text-anchor="middle" fill="#555">{m:.3f}, {wall:.0f} s CPU/run'
                 '</text>')
    s.append(f'<text x="{left}" y="{h - 12}" fill="#555">grey: each tuner seed\'s pick; blue: mean and 95 % '
             'Student-t interval over tuner seeds; CPU time per tuning run</text>')
    s.append("</svg>")
    return "\n".join(s) + "\n"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    for name in ("run", "one", "finals", "report"):
        p = sub.add_parser(name)
        p.add_argument("--problem", "--config", dest="problem", default=DEFAULT_PROBLEM,
                       help="the problem (an evolve config; --config is the same switch)")
        p.add_argument("--out", default=None,
                       help="results folder (default results/tuners for the default problem, results/tuners-NAME "
                            "for bench/tuners/problem-NAME.toml)")
        p.add_argument("--threads", type=int, default=2, help="simulations at once, for every tuner")
        if name == "run":
            p.add_argument("--tuners", default="swarmpath-cmaes,irace,optuna-tpe,optuna-cmaes",
                           help=f"comma-separated, of {', '.join(TUNERS)}")
            p.add_argument("--seeds", default="1-4", help="tuner seeds, e.g. 1-4 or 1,3,5")
            p.add_argument("--jobs", type=int, default=1,
                           help="tuning runs at once (each with --threads simulations at once)")
        if name == "one":
            p.add_argument("--tuner", required=True, choices=TUNERS)
            p.add_argument("--seed", type=int, required=True)
        if name == "finals":
            p.add_argument("--final-seeds", type=int, default=20, help="fresh seeds per setting")
        if name == "report":
            p.add_argument("--docs", default="", help="also write the SVG into this folder")
            p.add_argument("--reference", default="swarmpath-cmaes", help="the tuner the others are compared with")
    a = ap.parse_args(argv)
    os.chdir(ROOT)
    a.out = a.out or default_out(a.problem)
    {"run": cmd_run, "one": cmd_one, "finals": cmd_finals, "report": cmd_report}[a.cmd](a)


if __name__ == "__main__":
    main()
