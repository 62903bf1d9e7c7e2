# SPDX-License-Identifier: MIT
# swarmpath.Params: the params-file parser's checks and messages, from Python.
import pickle

import pytest
from conftest import SOURCE, cli_error


def test_defaults_are_the_struct_defaults_and_paper_values(sp):
    p = sp.Params.defaults()
    assert p == sp.Params()
    assert p["v_max"] == 20 and p["T_explore0"] == 1000 and p["t_source"] == "budget"
    table = sp.param_table()
    assert [e["name"] for e in table] == sp.Params.names()
    assert all(p[e["name"]] == e["default"] for e in table)


def test_replace_changes_only_the_named_values(sp):
    p = sp.Params.defaults()
    q = p.replace(v_max=25, T_explore0=1500, t_source="elapsed", revert_orphans=True)
    changed = {k for k, v in q.to_dict().items() if v != p.to_dict()[k]}
    assert changed == {"v_max", "T_explore0", "t_source", "revert_orphans"}
    assert q["v_max"] == 25.0 and q["t_source"] == "elapsed" and q["revert_orphans"] is True
    assert p["v_max"] == 20  # the original is left as it was


def test_out_of_range_value_names_the_key_and_matches_the_cli(sp, tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text("T_lost = 4\nv_max = 99\n")
    with pytest.raises(sp.ConfigError) as e:
        sp.Params.load(str(bad))
    assert isinstance(e.value, ValueError)
    assert (e.value.file, e.value.line, e.value.key) == (str(bad), 2, "v_max")
    assert str(e.value) == cli_error("simulate", "--scenario", SOURCE / "tests/data/short_chain.toml", "--params",
                                     bad, "--ticks", 1)
    with pytest.raises(sp.ConfigError) as r:
        sp.Params.defaults().replace(T_lost=4, v_max=99)
    assert (r.value.file, r.value.line, r.value.key) == ("Params.replace", 2, "v_max")
    assert str(r.value).split(": ", 2)[2] == str(e.value).split(": ", 2)[2]  # the same message


def test_unknown_key_wrong_type_and_cross_constraint(sp):
    with pytest.raises(sp.ConfigError) as e:
        sp.Params.defaults().replace(v_maxx=10)
    assert e.value.key == "v_maxx" and "v_max" in str(e.value)  # did you mean
    with pytest.raises(sp.ConfigError) as e:
        sp.Params.defaults().replace(v_max="fast")
    assert e.value.key == "v_max"
    with pytest.raises(sp.ConfigError) as e:
        sp.Params.defaults().replace(theta_hard=80, theta_soft=85)
    assert e.value.key == "theta_soft" and "theta_hard" in str(e.value)
    with pytest.raises(sp.ConfigError) as e:
        sp.Params.from_dict({"T_lost": 2.5})  # an integer parameter
    assert (e.value.line, e.value.key) == (1, "T_lost")


def test_round_trips_dict_file_text_and_pickle(sp, tmp_path):
    p = sp.Params.defaults().replace(p_turn=0.0123456789, dphi_max=33, w_rw=1.05)
    assert sp.Params.from_dict(p.to_dict()) == p
    path = tmp_path / "p.toml"
    p.save(str(path), header="# from a test\n")
    assert path.read_text().startswith("# from a test\n")
    assert sp.Params.load(str(path)) == p
    assert sp.Params.parse(p.to_toml()) == p
    assert pickle.loads(pickle.dumps(p)) == p
    assert p != sp.Params.defaults()
    assert "p_turn=0.0123456789" in repr(p)
