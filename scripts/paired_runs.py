#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Compare `swarmpath table --json` outputs run by run: candidates against a baseline on the same runs.

    scripts/paired_runs.py BASE.json CAND.json [CAND.json ...] [--mode pf|ta]

Runs are paired by (scenario, robots, seed, mode). For each file: success per arena family (the
scenario's name without its trailing -N), runs formed, the success difference CAND - BASE in points
with a 95 % interval (normal approximation over the paired runs), the same difference with its
interval over the arenas (each arena's mean difference over its runs, a Student-t interval over the
arenas: runs on one arena share its walls, so an effect that rests on a few arenas shows in this
interval and not in the runs'), the difference in ticks to form where both formed, and, where BASE
holds task-allocation runs, the cases (scenario x robots) in which task allocation's mean time to
form is below path formation's (a case path formation never forms counts as faster; a case task
allocation never forms does not), the paper's "formed faster with TA". `benchmark --json` outputs
are read as the table of runs they hold.
A candidate without task-allocation runs is compared with BASE's (a switch of path formation's
leaves them bit for bit as they are). To run two params files side by side instead of comparing
outputs already written, `swarmpath evaluate --params A.toml --against B.toml` does both.
"""
import argparse
import json
import math
import sys


def fail(message):
    print(f"error: {message}", file=sys.stderr)
    sys.exit(2)


def load(path):
    """The runs of a `table --json` output, keyed by (scenario, robots, seed, mode)."""
    try:
        with open(path) as f:
            data = json.load(f)
    except (OSError, json.JSONDecodeError) as e:
        fail(f"{path}: {e}")
    if isinstance(data, dict) and isinstance(data.get("table"), dict) and "benchmark" in data:
        data = data["table"]  # `benchmark --json`: its runs are those of the table beside it
    if not isinstance(data, dict) or not isinstance(data.get("runs"), list):
        fail(f"{path}: not a `swarmpath table --json` output (no 'runs' list)")
    runs = {}
    for i, r in enumerate(data["runs"]):
        missing = [k for k in ("scenario", "robots", "seed", "mode", "success", "ticks_to_form")
                   if not isinstance(r, dict) or k not in r]
        if missing:
            fail(f"{path}: runs[{i}] lacks {', '.join(missing)}")
        runs[(r["scenario"], r["robots"], r["seed"], r["mode"])] = r
    return runs


def family(scenario):
    head, _, tail = scenario.rpartition("-")
    return head if head and tail.isdigit() else scenario


def interval(values):
    """Mean and 95 % half-width (normal approximation)."""
    n = len(values)
    if n == 0:
        return float("nan"), float("nan")
    m = sum(values) / n
    if n == 1:
        return m, 0.0
    sd = math.sqrt(sum((x - m) ** 2 for x in values) / (n - 1))
    return m, 1.96 * sd / math.sqrt(n)


def t95(df):
    """The two-sided 95 % quantile of Student's t with df degrees of freedom (a table up to 10, then
    the Cornish-Fisher expansion, within 0.001 of the exact value there)."""
    if df < 1:
        return float("nan")
    if df <= 10:
        return (12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228)[df - 1]
    z = 1.959964
    return (z + (z ** 3 + z) / (4 * df) + (5 * z ** 5 + 16 * z ** 3 + 3 * z) / (96 * df ** 2)
            + (3 * z ** 7 + 19 * z ** 5 + 17 * z ** 3 - 15 * z) / (384 * df ** 3))


def by_arena(diffs):
    """Mean and 95 % half-width over arenas of each arena's mean difference: diffs maps an arena to
    its runs' differences."""
    means = [sum(v) / len(v) for v in diffs.values()]
    n = len(means)
    if n == 0:
        return float("nan"), float("nan")
    m = sum(means) / n
    if n == 1:
        return m, float("nan")
    sd = math.sqrt(sum((x - m) ** 2 for x in means) / (n - 1))
    return m, t95(n - 1) * sd / math.sqrt(n)


def case_times(runs, mode):
    """Mean ticks to form per (scenario, robots) over the runs that formed; None where none did."""
    cases = {}
    for (sc, rb, _, m), r in runs.items():
        if m != mode:
            continue
        t = cases.setdefault((sc, rb), [])
        if r["success"]:
            t.append(r["ticks_to_form"])
    return {k: (sum(v) / len(v) if v else None) for k, v in cases.items()}


def ta_faster(ta_runs, pf_runs):
    ta, pf = case_times(ta_runs, "ta"), case_times(pf_runs, "pf")
    faster = 0
    for case, t in ta.items():
        if case in pf and t is not None and (pf[case] is None or t < pf[case]):
            faster += 1
    return faster, len([c for c in ta if c in pf])


def compare(base, cand, mode):
    keys = sorted(k for k in cand if k in base and (mode is None or k[3] == mode))
    fams = {}
    for k in keys:
        f = fams.setdefault(family(k[0]), [0, 0])
        f[0] += bool(cand[k]["success"])
        f[1] += 1
    diff = interval([float(cand[k]["success"]) - float(base[k]["success"]) for k in keys])
    arenas = {}
    for k in keys:
        arenas.setdefault(k[0], []).append(float(cand[k]["success"]) - float(base[k]["success"]))
    arena_diff = by_arena(arenas)
    both = [cand[k]["ticks_to_form"] - base[k]["ticks_to_form"] for k in keys
            if cand[k]["success"] and base[k]["success"]]
    out = {
        "runs": len(keys),
        "formed": sum(bool(cand[k]["success"]) for k in keys),
        "base_formed": sum(bool(base[k]["success"]) for k in keys),
        "families": fams,
        "success_points": (100 * diff[0], 100 * diff[1]),
        "arenas": len(arenas),
        "arena_points": (100 * arena_diff[0], 100 * arena_diff[1]),
        "ticks_both_formed": interval(both) + (len(both),),
    }
    ta_source = cand if any(k[3] == "ta" for k in cand) else base
    if any(k[3] == "ta" for k in ta_source):
        out["ta_faster"] = ta_faster(ta_source, cand)
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 epilog=__doc__.split("\n\n", 2)[2],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("base", help="the baseline's `table --json` output")
    ap.add_argument("candidates", nargs="+", help="candidates' outputs on the same runs")
    ap.add_argument("--mode", choices=["pf", "ta"], default=None,
                    help="compare only these runs (default: every mode both files hold)")
    a = ap.parse_args(argv)
    base = load(a.base)
    rows = [(p, compare(base, load(p), a.mode)) for p in a.candidates]
    for path, r in rows:
        if r["runs"] == 0:
            fail(f"{path}: no runs in common with {a.base}")
    fams = sorted({f for _, r in rows for f in r["families"]})
    print("| file | " + " | ".join(fams) + " | formed | vs base (points, 95 %) | by arena (points, 95 %, "
          "arenas) | ticks where both formed (95 %, runs) | TA faster (cases) |")
    print("|" + "---|" * (len(fams) + 6))
    for path, r in rows:
        cells = [f"{r['families'][f][0]}/{r['families'][f][1]}" if f in r["families"] else "-" for f in fams]
        m, h = r["success_points"]
        tm, th, tn = r["ticks_both_formed"]
        ticks = f"{tm:+.0f} [{tm - th:.0f}, {tm + th:.0f}] ({tn})" if tn else "-"
        fast = f"{r['ta_faster'][0]} of {r['ta_faster'][1]}" if "ta_faster" in r else "-"
        am, ah = r["arena_points"]
        arena = f"{am:+.1f} [{am - ah:.1f}, {am + ah:.1f}] ({r['arenas']})" if r["arenas"] > 1 else "-"
        print(f"| {path} | " + " | ".join(cells) +
              f" | {r['formed']}/{r['runs']} (base {r['base_formed']}) | {m:+.1f} [{m - h:.1f}, {m + h:.1f}] "
              f"| {arena} | {ticks} | {fast} |")


if __name__ == "__main__":
    main()
