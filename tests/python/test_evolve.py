# SPDX-License-Identifier: MIT
# swarmpath.EvolveConfig and Objective: an evolve config's genome, cases and fitness, scored by the
# runner's own batch evaluation.
import json

import pytest
from conftest import TINY_TUNE, run_cli


@pytest.fixture(scope="module")
def config(sp):
    return sp.EvolveConfig.load(TINY_TUNE)


def test_genes_budget_and_decoding(sp, config):
    assert [g["name"] for g in config.genes] == ["T_explore0", "p_turn"]
    assert config.genes[1]["log"] and config.genes[0]["step"] == 50
    assert config.simulation_budget() == dict(population=6, candidates=48, cases_per_candidate=2, reevaluation=6,
                                              total=102)
    c = config.decode({"T_explore0": 761, "p_turn": 0.0123})
    assert c.valid and c.params["T_explore0"] == 750 and c.params["p_turn"] == 0.0123
    assert config.decode([4000, 1.0]).params["T_explore0"] == 3000  # clamped into the bounds
    assert config.decode_unit(config.encode(config.base)).params == config.base
    with pytest.raises(sp.ConfigError) as e:
        config.decode({"v_max": 10})
    assert e.value.key == "v_max"


def test_objective_scores_as_the_evolve_run_did(sp, config, tmp_path):
    run_cli("evolve", "--config", TINY_TUNE, "--out", tmp_path, "--generations", 1, "--no-wall-time", "--threads", 2)
    elite = json.loads((tmp_path / "checkpoint.json").read_text())["elites"][0]
    f = sp.Objective(config)
    assert [s["scenario"] for s in f.settings] == ["short_chain"]
    cases = f.generation_cases(0)
    assert len(cases) == 2 and cases[0].seed != cases[1].seed
    stats = f.evaluate(config.decode_unit(elite["x"]), cases, threads=1)
    assert stats["fitness"] == elite["stats"]["fitness"]  # bit for bit
    assert stats["success_rate"] == elite["stats"]["success_rate"] and stats["runs"] == 2


def test_objective_is_the_same_at_1_and_2_threads(sp, config):
    f = sp.Objective(config)
    cands = [config.decode({"T_explore0": t}) for t in (300, 900, 2000)] + [config.base]
    cases = f.reevaluation_cases(seeds=2)
    one = f.evaluate(cands, cases, threads=1)
    assert one == f.evaluate(cands, cases, threads=2)
    assert len(one) == 4 and all(len(s["scores"]) == 2 for s in one)
    assert one[0]["fitness"] == sum(r["fitness"] for r in one[0]["scores"]) / 2
