# SPDX-License-Identifier: MIT
# swarmpath.Scenario: scenario files and dicts through the scenario parser.
import pytest
from conftest import SHORT_CHAIN, SOURCE, cli_error


def test_load_a_paper_arena(sp):
    s = sp.Scenario.load(str(SOURCE / "configs/scenarios/paper/env4.toml"))
    assert s.name == "env4" and s.env_class in ("open", "obstacle", "complex")
    assert s.robots > 0 and s.max_ticks == 36000
    assert s.with_robots(60).robots == 60
    assert s.astar8_tu() > 0


def test_from_dict_equals_the_file(sp):
    d = {
        "name": "short_chain", "class": "open", "nest": [-1.8, 0.0], "goal": [1.8, 0.0],
        "arena": {"size": [6.0, 4.0], "wall_thickness": 0.1},
        "deployment": {"size": [1.5, 1.5], "robots": 20}, "simulation": {"max_ticks": 20000},
    }
    a = sp.evaluate(sp.Params(), sp.Scenario.from_dict(d), seed=2)
    b = sp.evaluate(sp.Params(), sp.Scenario.load(SHORT_CHAIN), seed=2)
    assert a["state_hash"] == b["state_hash"] and a["ticks"] == b["ticks"]


def test_bad_scenario_names_file_line_key_as_the_cli(sp, tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(open(SHORT_CHAIN).read().replace("robots = 20", "robots = -3"))
    with pytest.raises(sp.ConfigError) as e:
        sp.Scenario.load(str(bad))
    assert e.value.file == str(bad) and e.value.line > 0 and e.value.key == "deployment.robots"
    assert str(e.value) == cli_error("simulate", "--scenario", bad)
    with pytest.raises(sp.ConfigError) as e:
        sp.Scenario.from_dict({"name": "x", "class": "open", "nest": [0, 0], "goal": [1, 0], "arena": {"sise": [4, 4]}})
    assert e.value.file == "<dict>" and e.value.key == "arena.sise" and e.value.line == 5
    with pytest.raises(sp.ConfigError) as e:
        sp.Scenario.load(SHORT_CHAIN).with_robots(100000)
    assert e.value.file == "robots"


def test_toml_text_and_pickle_round_trip(sp):
    import pickle

    s = sp.Scenario.load(str(SOURCE / "configs/scenarios/paper/env4.toml")).with_robots(30)
    for back in (sp.Scenario.parse(s.to_toml()), pickle.loads(pickle.dumps(s))):
        assert back.robots == 30 and back.name == s.name and back.max_ticks == s.max_ticks
        assert sp.evaluate(sp.Params(), back, seed=4, max_ticks=300) == {
            **sp.evaluate(sp.Params(), s, seed=4, max_ticks=300), "scenario_file": back.file}
