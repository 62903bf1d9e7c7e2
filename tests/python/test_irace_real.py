# SPDX-License-Identifier: MIT
# irace itself (Debian's r-cran-irace) on the tiny tuning problem: the scenario `swarmpath irace`
# writes runs as written, and irace's best comes back as a params file that loads and evaluates.
import shutil
import subprocess

from conftest import SHORT_CHAIN, TINY_TUNE, run_cli


def test_irace_tunes_and_its_best_loads_and_evaluates(sp, tmp_path):
    assert shutil.which("Rscript"), "Rscript missing: install r-cran-irace (scripts/install-deps.sh)"
    d = tmp_path / "irace"
    run_cli("irace", "--config", TINY_TUNE, "--out", d, "--threads", 2)
    p = subprocess.run([str(d / "run-irace")], capture_output=True, text=True, timeout=240)
    assert p.returncode == 0, p.stdout[-3000:] + p.stderr[-3000:]
    assert "Best configurations" in p.stdout
    elites = (d / "elites.csv").read_text().splitlines()
    assert elites[0].startswith("rank,id,T_explore0,p_turn,mean_cost,runs,experiments") and len(elites) >= 2
    experiments = int(elites[1].split(",")[6])
    assert 0 < experiments <= 102  # irace kept to the config's budget
    best = tmp_path / "best.toml"
    run_cli("irace", "import", d, "--out", best)
    params = sp.Params.load(str(best))
    config = sp.EvolveConfig.load(TINY_TUNE)
    tuned = dict(zip(("T_explore0", "p_turn"), elites[1].split(",")[2:4]))
    assert params == config.decode({k: float(v) for k, v in tuned.items()}).params
    r = sp.evaluate(params, sp.Scenario.load(SHORT_CHAIN), seed=99, robots=20, max_ticks=3000)
    assert r["ticks"] > 0 and r["robots"] == 20
