# SPDX-License-Identifier: MIT
# bench/tuners/compare.py end to end on the tiny tuning problem (one tuner seed each): every tuner
# spends at most the config's simulation budget, the finals score every pick and the base params on
# the same fresh runs, and the report's table and plot come out.
import json
import os
import subprocess
import sys

from conftest import SOURCE, TINY_TUNE

SCRIPT = str(SOURCE / "bench/tuners/compare.py")


def compare(*args):
    p = subprocess.run([sys.executable, SCRIPT, *args, "--config", TINY_TUNE], capture_output=True, text=True,
                       env=os.environ, timeout=400)
    assert p.returncode == 0, p.stdout[-2000:] + p.stderr[-3000:]
    return p.stdout


def test_compare_runs_every_tuner_on_one_budget(sp, tmp_path):
    out = str(tmp_path / "tuners")
    tuners = "swarmpath-cmaes,irace,optuna-tpe,optuna-cmaes"
    compare("run", "--out", out, "--tuners", tuners, "--seeds", "1")
    assert "done before" in compare("run", "--out", out, "--tuners", "swarmpath-cmaes", "--seeds", "1")
    compare("finals", "--out", out, "--final-seeds", "3")
    report = compare("report", "--out", out, "--docs", str(tmp_path / "docs"))
    budget = sp.EvolveConfig.load(TINY_TUNE).simulation_budget()["total"]
    for t in tuners.split(","):
        meta = json.loads(open(os.path.join(out, "runs", f"{t}-s1", "meta.json")).read())
        assert 0 < meta["simulations"] <= budget, (t, meta)
        assert f"| {t} | 1 |" in report
    finals = json.loads(open(os.path.join(out, "finals.json")).read())
    assert set(finals["picks"]) == {"base"} | {f"{t}-s1" for t in tuners.split(",")}
    # the base params on the final cases, as the Objective scores them
    config = sp.EvolveConfig.load(TINY_TUNE)
    cases = [sp.Case(s, k, seed) for k, (s, seed) in enumerate(finals["cases"])]
    assert sp.Objective(config).evaluate(config.base, cases)["fitness"] == finals["picks"]["base"]["fitness"]
    svg = open(tmp_path / "docs" / "tuners.svg").read()
    assert svg.startswith("<svg") and "base params" in svg and "irace" in svg


def test_capped_variant_keeps_the_pick_and_finals_reuse_earlier_runs(sp, tmp_path):
    out = str(tmp_path / "tuners")
    compare("run", "--out", out, "--tuners", "swarmpath-cmaes,swarmpath-cmaes-capped", "--seeds", "1", "--threads", "1")
    config = open(os.path.join(out, "configs", "swarmpath-cmaes-capped-s1.toml")).read()
    assert "[evaluation]\ncapping = true\n" in config
    meta = json.loads(open(os.path.join(out, "runs", "swarmpath-cmaes-capped-s1", "meta.json")).read())
    assert meta["capping"]["capped_runs"] > 0, meta  # capping stopped runs on this problem
    # capping keeps the finalists, so the reported best is the same params
    picks = [sp.Params.load(os.path.join(out, "runs", f"{t}-s1", "pick.toml")).to_dict()
             for t in ("swarmpath-cmaes", "swarmpath-cmaes-capped")]
    assert picks[0] == picks[1]
    # a pick that is the base params (keep_base) takes the base params' runs instead of running them again
    base = sp.EvolveConfig.load(TINY_TUNE).base.to_dict()
    new = 1 + 2 * (picks[0] != base)
    assert f"{new} picks x 3 fresh runs" in compare("finals", "--out", out, "--final-seeds", "3", "--threads", "1")
    first = json.loads(open(os.path.join(out, "finals.json")).read())
    if picks[0] == base:
        assert first["picks"]["swarmpath-cmaes-s1"] == first["picks"]["base"]
        assert first["evaluated"] == ["base"]
    # the same cases again: every pick's runs are reused, with the same results
    assert "0 picks x 3 fresh runs" in compare("finals", "--out", out, "--final-seeds", "3", "--threads", "1")
    again = json.loads(open(os.path.join(out, "finals.json")).read())
    assert again["picks"] == first["picks"] and again["evaluated"] == []
    # other cases (more final seeds): every pick runs again
    assert f"{new} picks x 4 fresh runs" in compare("finals", "--out", out, "--final-seeds", "4", "--threads", "1")


def test_keep_base_counts_the_base_params_and_the_finalist_variant_spends_the_same(sp, tmp_path):
    out = str(tmp_path / "tuners")
    compare("run", "--out", out, "--tuners", "swarmpath-cmaes,swarmpath-cmaes-finalist", "--seeds", "1",
            "--threads", "1")
    config = open(os.path.join(out, "configs", "swarmpath-cmaes-finalist-s1.toml")).read()
    assert "[reevaluate]\nkeep_base = false\ntop_k = 2\n" in config  # one finalist more than tiny_tune's 1
    budget = sp.EvolveConfig.load(TINY_TUNE).simulation_budget()["total"]
    metas = {t: json.loads(open(os.path.join(out, "runs", f"{t}-s1", "meta.json")).read())
             for t in ("swarmpath-cmaes", "swarmpath-cmaes-finalist")}
    # keep_base: 1 finalist + the base params on the fresh seeds; the variant: 2 finalists
    assert metas["swarmpath-cmaes"]["simulations"] == budget == metas["swarmpath-cmaes-finalist"]["simulations"]
    selection = metas["swarmpath-cmaes"]["selection"]
    assert selection["keep_base"] and not metas["swarmpath-cmaes-finalist"]["selection"]["keep_base"]
    pick = sp.Params.load(os.path.join(out, "runs", "swarmpath-cmaes-s1", "pick.toml")).to_dict()
    base = sp.EvolveConfig.load(TINY_TUNE).base.to_dict()
    assert (pick == base) == selection["base_kept"]


def test_variants_of_the_pick_spend_the_same_budget(sp, tmp_path):
    out = str(tmp_path / "tuners")
    tuners = ("swarmpath-cmaes-sigma015", "swarmpath-cmaes-one-finalist", "swarmpath-cmaes-race-base",
              "swarmpath-cmaes-mean", "swarmpath-cmaes-mean-only", "swarmpath-cmaes-mean-only-rank")
    compare("run", "--out", out, "--tuners", ",".join(tuners), "--seeds", "1", "--threads", "1")
    config = {t: open(os.path.join(out, "configs", f"{t}-s1.toml")).read() for t in tuners}
    assert "[optimizer]\nsigma0 = 0.15\n" in config["swarmpath-cmaes-sigma015"]  # tiny_tune has none: added
    # tiny_tune re-evaluates 1 finalist and the base params on 3 seeds: one finalist of (1 + 1) x 3 / 2
    assert "[reevaluate]\ntop_k = 1\nseeds = 3\n" in config["swarmpath-cmaes-one-finalist"]
    assert "race_base = true" in config["swarmpath-cmaes-race-base"]
    budget = sp.EvolveConfig.load(TINY_TUNE).simulation_budget()["total"]
    for t in tuners:
        meta = json.loads(open(os.path.join(out, "runs", f"{t}-s1", "meta.json")).read())
        assert 0 < meta["simulations"] <= budget, (t, meta)
    run = json.loads(open(os.path.join(out, "runs", "swarmpath-cmaes-race-base-s1", "evolve", "run.json")).read())
    assert run["racing"]["against"] == "base params"
    assert run["racing"]["simulations"] <= 2 * 3
    # tiny_tune's one finalist is CMA-ES's distribution mean, on the same fresh runs
    assert "[reevaluate]\nmean_finalist = true\n" in config["swarmpath-cmaes-mean"]
    run = json.loads(open(os.path.join(out, "runs", "swarmpath-cmaes-mean-s1", "evolve", "run.json")).read())
    assert [f["distribution_mean"] for f in run["finalists"]] == [True]
    # the mean alone, on the one-finalist split of the same fresh runs
    assert "[reevaluate]\nmean_finalist = true\ntop_k = 1\nseeds = 3\n" in config["swarmpath-cmaes-mean-only"]
    run = json.loads(open(os.path.join(out, "runs", "swarmpath-cmaes-mean-only-s1", "evolve", "run.json")).read())
    assert [f["distribution_mean"] for f in run["finalists"]] == [True]
    # and with keep_base's signed-rank test, which run.json names
    assert 'keep_base_test = "signed-rank"' in config["swarmpath-cmaes-mean-only-rank"]
    run = json.loads(open(os.path.join(out, "runs", "swarmpath-cmaes-mean-only-rank-s1", "evolve", "run.json")).read())
    assert run["selection"]["test"] == "signed-rank"


def test_crn_variant_and_a_second_problem_in_its_own_folder(sp, tmp_path):
    out = str(tmp_path / "tuners")
    compare("run", "--out", out, "--tuners", "swarmpath-cmaes,swarmpath-cmaes-crn", "--seeds", "1", "--threads", "1")
    config = {t: open(os.path.join(out, "configs", f"{t}-s1.toml")).read()
              for t in ("swarmpath-cmaes", "swarmpath-cmaes-crn")}
    assert "[evaluation]\nfixed_seeds = true\n" in config["swarmpath-cmaes-crn"]
    assert "[optimizer]\nsigma0 = 0.15\n" in config["swarmpath-cmaes-crn"]
    assert "fixed_seeds" not in config["swarmpath-cmaes"] and "sigma0" not in config["swarmpath-cmaes"]
    # on: every generation on generation 0's seeds; off: new seeds each generation
    for t, same in (("swarmpath-cmaes-crn", True), ("swarmpath-cmaes", False)):
        run = json.loads(open(os.path.join(out, "runs", f"{t}-s1", "evolve", "run.json")).read())
        assert run["config"]["evaluation"]["fixed_seeds"] == same
        seeds = run["seeds"]["generations"]
        assert len(seeds) > 1 and (all(r == seeds[0] for r in seeds) == same), (t, seeds[:2])
    # another problem (the same one started elsewhere) is refused in this folder and runs in its own
    other = tmp_path / "tiny-naive.toml"
    text = open(TINY_TUNE).read().replace('"../short_chain.toml"', f'"{SOURCE}/tests/data/short_chain.toml"')
    other.write_text(text.replace('name = "tiny-tune"', 'name = "tiny-tune"\nparams = "naive.toml"'))
    base = sp.EvolveConfig.load(TINY_TUNE).base
    base.save(str(tmp_path / "naive.toml"), "# tiny_tune's base with T_explore0 at the middle of its range\n")
    (tmp_path / "naive.toml").write_text((tmp_path / "naive.toml").read_text().replace(
        f"T_explore0 = {base['T_explore0']:g}", "T_explore0 = 1600"))
    assert sp.EvolveConfig.load(str(other)).base["T_explore0"] == 1600
    for step in (["run", "--tuners", "swarmpath-cmaes", "--seeds", "2"], ["finals", "--final-seeds", "2"]):
        p = subprocess.run([sys.executable, SCRIPT, *step, "--out", out, "--problem", str(other)], capture_output=True,
                           text=True, timeout=400)
        assert p.returncode != 0 and "holds the runs of" in p.stderr, p.stderr
    assert not os.path.exists(os.path.join(out, "runs", "swarmpath-cmaes-s2"))
    naive = str(tmp_path / "tuners-naive")
    for step in (["run", "--tuners", "swarmpath-cmaes-crn", "--seeds", "1", "--threads", "1"],
                 ["finals", "--final-seeds", "2", "--threads", "1"], ["report", "--docs", str(tmp_path / "docs")]):
        p = subprocess.run([sys.executable, SCRIPT, *step, "--out", naive, "--problem", str(other)],
                           capture_output=True, text=True, timeout=400)
        assert p.returncode == 0, p.stdout[-2000:] + p.stderr[-3000:]
    assert json.loads(open(os.path.join(naive, "problem.json")).read())["hash"] == sp.EvolveConfig.load(str(other)).hash
    finals = json.loads(open(os.path.join(naive, "finals.json")).read())
    assert finals["picks"]["base"]["values"]["T_explore0"] == 1600  # the other problem's base params
    assert os.path.exists(tmp_path / "docs" / "tuners-naive.svg")  # the plot is named after its folder
    # the default results folders: one per problem
    sys.path.insert(0, str(SOURCE / "bench" / "tuners"))
    import compare as c

    assert c.default_out("bench/tuners/problem.toml") == "results/tuners"
    assert c.default_out("bench/tuners/problem-naive.toml") == "results/tuners-naive"


def test_paired_differences_use_the_tuner_seeds_both_ran():
    sys.path.insert(0, str(SOURCE / "bench/tuners"))
    import compare

    # seeds 1 and 2 in common: differences 0.10 and 0.02, mean 0.06, sd 0.0566, t(1) 12.706
    m, h, n = compare.paired({1: 0.9, 2: 0.8, 3: 0.85}, {1: 0.8, 2: 0.78, 4: 0.7})
    assert n == 2 and abs(m - 0.06) < 1e-12 and abs(h - 12.706 * 0.04) < 1e-9
    assert compare.paired({1: 1.0}, {2: 1.0}) is None
    assert all(t in compare.VARIANTS for t in compare.SAME_GENERATIONS)
