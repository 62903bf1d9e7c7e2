# SPDX-License-Identifier: MIT
# scripts/paired_runs.py: candidates against a baseline run by run, on `table --json` outputs.
import json
import subprocess
import sys

from conftest import SOURCE, SHORT_CHAIN, run_cli

SCRIPT = str(SOURCE / "scripts" / "paired_runs.py")


def paired(*args):
    p = subprocess.run([sys.executable, SCRIPT, *map(str, args)], capture_output=True, text=True)
    return p.returncode, p.stdout, p.stderr


def row(out, name):
    lines = [line for line in out.splitlines() if line.startswith(f"| {name}")]
    assert len(lines) == 1, out
    return [c.strip() for c in lines[0].strip("|").split("|")]


def run(scenario, seed, mode, success, ticks=None, robots=60):
    return {"scenario": scenario, "robots": robots, "seed": seed, "mode": mode, "success": success,
            "ticks_to_form": ticks if success else None}


def write(path, runs):
    path.write_text(json.dumps({"runs": runs}))
    return path


def test_pairs_runs_by_case_and_seed_and_counts_families(tmp_path):
    base = write(tmp_path / "base.json", [
        run("wall-gap-1", 1, "pf", True, 1000), run("wall-gap-1", 2, "pf", False),
        run("serpentine-2", 1, "pf", False), run("serpentine-2", 2, "pf", True, 3000),
        run("wall-gap-1", 1, "ta", True, 900), run("wall-gap-1", 2, "ta", True, 1100),
        run("serpentine-2", 1, "ta", True, 5000), run("serpentine-2", 2, "ta", False)])
    cand = write(tmp_path / "cand.json", [
        run("wall-gap-1", 1, "pf", True, 800), run("wall-gap-1", 2, "pf", True, 1200),
        run("serpentine-2", 1, "pf", True, 4000), run("serpentine-2", 2, "pf", True, 2000),
        run("env8", 1, "pf", True, 100)])  # a run the baseline lacks is not paired
    code, out, err = paired(base, cand, "--mode", "pf")
    assert code == 0, err
    cells = row(out, str(cand))
    header = [c.strip() for c in out.splitlines()[0].strip("|").split("|")]
    col = dict(zip(header, cells))
    assert col["wall-gap"] == "2/2" and col["serpentine"] == "2/2" and "env8" not in col
    assert col["formed"] == "4/4 (base 2)"
    # success +1, +1 on two runs of four: mean +50 points, sd 57.7, half-width 1.96 * 57.7 / 2
    assert col["vs base (points, 95 %)"] == "+50.0 [-6.6, 106.6]"
    # both formed: wall-gap-1 seed 1 (-200) and serpentine-2 seed 2 (-1000)
    assert col["ticks where both formed (95 %, runs)"].startswith("-600 [") and col[
        "ticks where both formed (95 %, runs)"].endswith("(2)")
    # TA from the baseline: wall-gap-1 ta 1000 vs the candidate's pf 1000 (not below); serpentine-2
    # ta 5000 vs pf 3000: path formation faster in both cases
    assert col["TA faster (cases)"] == "0 of 2"


def test_a_case_path_formation_never_forms_counts_as_faster_with_task_allocation(tmp_path):
    base = write(tmp_path / "base.json", [run("rooms-1", 1, "pf", True, 100), run("rooms-1", 1, "ta", True, 9000)])
    cand = write(tmp_path / "cand.json", [run("rooms-1", 1, "pf", False)])
    code, out, err = paired(base, cand)
    assert code == 0, err
    assert row(out, str(cand))[-1] == "1 of 1"


def test_reads_what_table_json_writes(tmp_path):
    out_json = tmp_path / "t.json"
    run_cli("table", "--scenarios", SHORT_CHAIN, "--robots", 20, "--seeds", 2, "--mode", "both",
            "--json", out_json, "--threads", 1)
    code, out, err = paired(out_json, out_json)
    assert code == 0, err
    formed = sum(r["success"] for r in json.loads(out_json.read_text())["runs"])
    # file | short_chain | formed | vs base | ticks | TA faster: pf and ta runs, 2 seeds each
    cells = row(out, str(out_json))
    assert cells[1] == f"{formed}/4" and cells[2] == f"{formed}/4 (base {formed})", out
    assert cells[3] == "+0.0 [0.0, 0.0]"


def test_bad_input_says_which_file(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text("{\"cases\": []}")
    code, _, err = paired(bad, bad)
    assert code == 2 and err.startswith("error: ") and "bad.json" in err and "runs" in err


def test_a_run_without_its_fields_and_files_without_common_runs_are_bad_input(tmp_path):
    good = write(tmp_path / "good.json", [run("u-trap-1", 1, "pf", True, 500)])
    other = write(tmp_path / "other.json", [run("u-trap-1", 2, "pf", True, 500)])
    lacking = tmp_path / "lacking.json"
    lacking.write_text(json.dumps({"runs": [{"scenario": "u-trap-1", "robots": 60, "seed": 1}]}))
    code, out, err = paired(good, lacking)
    assert code == 2 and "lacking.json: runs[0] lacks mode, success, ticks_to_form" in err, err
    code, out, err = paired(good, other)
    assert code == 2 and "no runs in common" in err and out == "", (out, err)


def test_an_effect_on_one_arena_of_three_is_significant_by_runs_and_not_by_arenas(tmp_path):
    # rooms-1 forms 4 more runs with the candidate, rooms-2 and rooms-3 the same
    base, cand = [], []
    for arena in ("rooms-1", "rooms-2", "rooms-3"):
        for seed in (1, 2, 3, 4):
            base.append(run(arena, seed, "pf", arena != "rooms-1", 1000))
            cand.append(run(arena, seed, "pf", True, 1000))
    # the benchmark's shape: its runs under "table"
    b = tmp_path / "base.json"
    b.write_text(json.dumps({"benchmark": {"name": "validation"}, "table": {"runs": base}}))
    c = write(tmp_path / "cand.json", cand)
    code, out, err = paired(b, c)
    assert code == 0, err
    header = [h.strip() for h in out.splitlines()[0].strip("|").split("|")]
    col = dict(zip(header, row(out, str(c))))
    # runs: 4 of 12 differ by +1: mean 33.3, sd 49.2, half-width 1.96 * 49.2 / sqrt(12) = 27.9
    assert col["vs base (points, 95 %)"] == "+33.3 [5.5, 61.2]"
    # arenas: means 1, 0, 0: sd 57.7, t(2) = 4.303, half-width 4.303 * 57.7 / sqrt(3) = 143.4
    assert col["by arena (points, 95 %, arenas)"] == "+33.3 [-110.1, 176.8] (3)"
