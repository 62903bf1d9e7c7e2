# SPDX-License-Identifier: MIT
# `swarmpath irace`: the scenario it writes, its target runner and the import of irace's elites,
# checked without R (irace itself runs in test_irace_real.py).
import os
import subprocess

import pytest
from conftest import SHORT_CHAIN, TINY_TUNE, run_cli


@pytest.fixture(scope="module")
def scenario(tmp_path_factory):
    d = tmp_path_factory.mktemp("irace")
    run_cli("irace", "--config", TINY_TUNE, "--out", d, "--threads", 3, "--seed", 11)
    return d


def test_scenario_files(scenario):
    names = {"parameters.txt", "instances.txt", "configurations.txt", "target-runner", "scenario.txt", "run-irace",
             "export-elites.R", "swarmpath-irace.json"}
    assert names <= set(os.listdir(scenario))
    params = [l for l in (scenario / "parameters.txt").read_text().splitlines() if not l.startswith("#")]
    assert params[0].split()[:4] == ["T_explore0", '"--T_explore0="', "i", "(200,"]
    assert params[1].split()[:4] == ["p_turn", '"--p_turn="', "r,log", "(0.002,"]
    assert (scenario / "instances.txt").read_text().splitlines()[1] == os.path.realpath(SHORT_CHAIN) + " --robots 20"
    text = (scenario / "scenario.txt").read_text()
    assert "maxExperiments = 102\n" in text and "parallel = 3\n" in text and "seed = 11\n" in text
    assert (scenario / "configurations.txt").read_text().splitlines()[-1].split() == ["1000", "0.02"]
    assert os.access(scenario / "target-runner", os.X_OK) and os.access(scenario / "run-irace", os.X_OK)


def test_target_runner_prints_the_objectives_fitness(sp, scenario):
    # as irace calls it: id, instance id, seed, instance (with its --robots), the switches
    out = subprocess.run([str(scenario / "target-runner"), "7", "1", "12345", os.path.realpath(SHORT_CHAIN),
                          "--robots", "20", "--T_explore0=761", "--p_turn=0.0123"], capture_output=True, text=True)
    assert out.returncode == 0 and out.stderr == ""
    config = sp.EvolveConfig.load(TINY_TUNE)
    expected = sp.Objective(config).evaluate(config.decode({"T_explore0": 761, "p_turn": 0.0123}),
                                             [sp.Case(0, 0, 12345)])
    assert float(out.stdout) == expected["fitness"]
    bad = subprocess.run([str(scenario / "target-runner"), "7", "1", "1", SHORT_CHAIN, "--robots", "21",
                          "--T_explore0=761"], capture_output=True, text=True)
    assert bad.returncode == 2 and "not a training scenario" in bad.stderr


def test_import_writes_irace_best_with_provenance(sp, scenario, tmp_path):
    (scenario / "elites.csv").write_text(
        "rank,id,T_explore0,p_turn,mean_cost,runs,experiments,irace_version,irace_seed\n"
        "1,12,761,0.0029166,0.9049,8,96,3.5.6863679,11\n"
        "2,4,315,0.0127214,0.8926,8,96,3.5.6863679,11\n")
    best = tmp_path / "best.toml"
    run_cli("irace", "import", scenario, "--out", best)
    p = sp.Params.load(str(best))
    assert p["T_explore0"] == 750 and p["p_turn"] == 0.0029166  # rounded to the config's grid
    head = best.read_text().split("\n\n")[0]
    assert "irace 3.5.6863679: elite 1 (configuration 12" in head and "irace seed 11" in head
    assert sp.EvolveConfig.load(TINY_TUNE).hash in head
    second = tmp_path / "second.toml"
    run_cli("irace", "import", scenario, "--out", second, "--rank", 2)
    assert sp.Params.load(str(second))["T_explore0"] == 300
    code, _, err = run_cli("irace", "import", scenario, "--out", second, "--rank", 3, check=False)
    assert code == 2 and "--rank" in err


def test_errors(scenario, tmp_path):
    code, _, err = run_cli("irace", "import", tmp_path, "--out", tmp_path / "x.toml", check=False)
    assert code == 2 and "swarmpath-irace.json" in err
    code, _, err = run_cli("irace", "--out", tmp_path / "s", check=False)
    assert code == 2 and "--config" in err
    code, _, err = run_cli("irace", "run", "--config", TINY_TUNE, "--seed", 1, SHORT_CHAIN, "--robots", 20,
                           "--v_max=10", check=False)
    assert code == 2 and "v_max" in err
