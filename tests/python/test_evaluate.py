# SPDX-License-Identifier: MIT
# swarmpath.evaluate, evaluate_many and table: the command line's numbers, in parallel, without the GIL.
import threading
import time

import pytest
from conftest import SHORT_CHAIN, SOURCE, WALL_CLOCK_FIELDS, cli_json


def without_wall_clock(j):
    return {k: v for k, v in j.items() if k not in WALL_CLOCK_FIELDS}


@pytest.mark.parametrize("mode,seed,extra", [("pf", 1, {}), ("ta", 2, {}), ("diffusion", 3, {"max_ticks": 300})])
def test_evaluate_equals_simulate_json(sp, tmp_path, mode, seed, extra):
    params = sp.Params.defaults().replace(T_explore0=800, p_turn=0.03)
    path = tmp_path / "p.toml"
    params.save(str(path))
    args = ["simulate", "--scenario", SHORT_CHAIN, "--params", path, "--mode", mode, "--seed", seed,
            "--robots", 18, "--json"]
    if "max_ticks" in extra:
        args += ["--ticks", extra["max_ticks"]]
    expected = without_wall_clock(cli_json(*args))
    got = sp.evaluate(params, sp.Scenario.load(SHORT_CHAIN), mode=mode, seed=seed, robots=18, **extra)
    assert got == expected
    assert list(got) == list(expected)  # the same fields in the same order


def test_evaluate_many_is_the_same_at_1_and_2_threads_and_one_by_one(sp):
    s = sp.Scenario.load(SHORT_CHAIN)
    p = sp.Params.defaults()
    jobs = [dict(params=p.replace(T_explore0=500 + 100 * k), scenario=s, seed=k, max_ticks=4000) for k in range(6)]
    jobs.append((p, s, "ta", 9))
    one = sp.evaluate_many(jobs, threads=1)
    two = sp.evaluate_many(jobs, threads=2)
    assert one == two
    assert len({r["state_hash"] for r in one}) == len(one)  # different runs really
    assert one[0] == sp.evaluate(jobs[0]["params"], s, seed=0, max_ticks=4000)
    assert one[-1] == sp.evaluate(p, s, mode="ta", seed=9)


def test_evaluate_many_releases_the_gil(sp):
    s = sp.Scenario.load(SHORT_CHAIN)
    jobs = [dict(params=sp.Params(), scenario=s, seed=k, mode="diffusion", max_ticks=1500) for k in range(8)]
    box = {}

    def work():
        t0 = time.perf_counter()
        sp.evaluate_many(jobs, threads=1)
        box["seconds"] = time.perf_counter() - t0

    worker = threading.Thread(target=work)
    stamps = []
    worker.start()
    while worker.is_alive():
        stamps.append(time.perf_counter())
    worker.join()
    gaps = [b - a for a, b in zip(stamps, stamps[1:])]
    # holding the GIL for the whole batch would stop this loop for about that long
    assert box["seconds"] > 0.05 and len(stamps) > 10
    assert max(gaps) < 0.5 * box["seconds"]


def test_bad_arguments_raise_config_errors(sp):
    s = sp.Scenario.load(SHORT_CHAIN)
    with pytest.raises(sp.ConfigError) as e:
        sp.evaluate(sp.Params(), s, mode="walk")
    assert e.value.key == "mode" and "pf" in str(e.value)
    with pytest.raises(sp.ConfigError) as e:
        sp.evaluate_many([dict(params=sp.Params(), scenario=s, sed=1)])
    assert e.value.key == "jobs[0].sed"
    with pytest.raises(sp.ConfigError):
        sp.evaluate(sp.Params(), s, robots=0)


def test_table_equals_table_json(sp, tmp_path):
    out = tmp_path / "t.json"
    from conftest import run_cli

    run_cli("table", "--scenarios", SHORT_CHAIN, "--robots", "16,20", "--seeds", 2, "--seed-base", 5, "--mode",
            "both", "--ticks", 5000, "--threads", 2, "--json", out)
    import json

    expected = json.loads(out.read_text())
    got = sp.table([SHORT_CHAIN], robots=[16, 20], seeds=2, seed_base=5, mode="both", max_ticks=5000, threads=1)
    assert got == expected
    with pytest.raises(sp.ConfigError) as e:
        sp.table([SHORT_CHAIN], seeds=0)
    assert e.value.file == "--seeds"
