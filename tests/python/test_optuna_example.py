# SPDX-License-Identifier: MIT
# examples/optuna_tune.py with Optuna itself (Debian's python3-optuna), a handful of trials of the
# tiny tuning problem: common random numbers, the base params first, the best re-evaluated on
# fresh seeds, and a best.toml that loads.
import csv
import json
import os
import subprocess
import sys

import pytest
from conftest import SOURCE, TINY_TUNE


@pytest.mark.parametrize("sampler", ["tpe", "cmaes"])
def test_optuna_example(sp, tmp_path, sampler):
    out = tmp_path / sampler
    p = subprocess.run([sys.executable, str(SOURCE / "examples/optuna_tune.py"), "--config", TINY_TUNE, "--sampler",
                        sampler, "--trials", "6", "--seed", "4", "--threads", "2", "--reevaluate-seeds", "2", "--out",
                        str(out)], capture_output=True, text=True, env=os.environ, timeout=300)
    assert p.returncode == 0, p.stderr[-3000:]
    result = json.loads((out / "result.json").read_text())
    trials = list(csv.DictReader(open(out / "trials.csv")))
    assert result["trials"] == 6 == len(trials) and result["simulations"] == 12
    config = sp.EvolveConfig.load(TINY_TUNE)
    assert float(trials[0]["T_explore0"]) == config.base["T_explore0"]  # the base params go first
    fitness = [float(t["fitness"]) for t in trials]
    assert result["best"]["fitness_on_trial_seeds"] == min(fitness)
    # every trial on the same seeds: the first trial's fitness is the base params' on generation 0's cases
    f = sp.Objective(config)
    assert fitness[0] == f.evaluate(config.base, f.generation_cases(0))["fitness"]
    best = sp.Params.load(str(out / "best.toml"))
    fresh = f.evaluate(best, f.reevaluation_cases(2))
    assert fresh["fitness"] == result["best"]["fresh"]["fitness"] and fresh["runs"] == 2
    assert result["base"]["fresh"]["fitness"] == f.evaluate(config.base, f.reevaluation_cases(2))["fitness"]
