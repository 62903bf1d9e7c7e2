#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""swarmpath as a hostile but realistic user would use it, against the real binary.

Four loops, every random choice drawn from one seed (so a failure reruns exactly):

  fuzz    mutated scenario, params and evolve files (numbers made huge, negative, fractional or
          of the wrong type, lines deleted or doubled, files cut short, control characters,
          random bytes): every run must exit 0 or 2 (2 with "error: " and the file or option named),
          never crash, never hang, never exit 1 for a bad input.
  kill    evolve runs killed with SIGKILL at random moments and resumed (again and again) until they
          finish: the folder must end byte-identical to an uninterrupted run's.
  lock    two evolve runs into one folder: the second exits 2 naming the first's pid.
  full    every command with its standard output, and each of its output files, on /dev/full, and a
          resume whose writes exceed RLIMIT_FSIZE: exit 1 naming the file, previous files intact.

  --quick   a bounded run: few iterations (about 30 s on 2 cores for a release build)
  default   a longer run for manual use (--fuzz N --kills N to size it)

Usage: scripts/hostile_user.py --binary build/release/swarmpath [--quick] [--seed 1]
"""

import argparse
import json
import os
import random
import resource
import shutil
import signal
import subprocess
import sys
import tempfile
import time

SOURCE = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
FAILURES = []
TIMEOUT = 60.0  # seconds: a run that takes longer counts as a hang


def fail(what):
    FAILURES.append(what)
    print("FAIL: " + what, file=sys.stderr)


def run(binary, args, timeout=TIMEOUT, **kw):
    """(returncode, stdout, stderr); returncode None on a hang."""
    try:
        if "stdout" not in kw:
            kw["stdout"] = subprocess.PIPE
        p = subprocess.run([binary] + args, stderr=subprocess.PIPE, text=True, timeout=timeout,
                           errors="replace", **kw)
        return p.returncode, p.stdout or "", p.stderr
    except subprocess.TimeoutExpired:
        return None, "", ""


def read(path):
    with open(path, "rb") as f:
        return f.read()


def write(path, data):
    with open(path, "wb" if isinstance(data, bytes) else "w") as f:
        f.write(data)


def tiny_evolve_config(optimizer="cmaes", generations=4):
    return (
        'name = "hostile"\nparams = "%s"\nmode = "pf"\nseed = 11\n\n[tune]\nw_away = {}\n'
        'p_turn = { lo = 0.002, hi = 0.2, log = true }\n\n[evaluation]\nscenarios = ["%s"]\n'
        "robots = [6]\nseeds = 1\nmax_ticks = 400\n\n[optimizer]\nname = \"%s\"\npopulation = 4\n\n"
        "[budget]\ngenerations = %d\n\n[reevaluate]\ntop_k = 2\nseeds = 1\n"
        % (os.path.join(SOURCE, "genomes", "default.toml"), os.path.join(SOURCE, "tests", "data", "short_chain.toml"),
           optimizer, generations))


# ---------------------------------------------------------------- fuzz

NASTY_NUMBERS = ["-1", "0", "0.0", "1.5", "-0.5", "1e308", "-1e308", "18446744073709551616", "9999999999",
                 "nan", "inf", "-inf", '"7"', "true", "[]", "[1.0]", "[1.0, 2.0, 3.0]", "{}", "0.001"]
NASTY_STRINGS = ['""', '"\\u0000"', '"a\\u0007b"', '".."', '"."', '"/"', '"\\u001b[31mred"', '"a,b|c<d>&\\"e"',
                 '"' + "x" * 300 + '"', "3", "[]"]


def mutate(text, rng):
    lines = text.split("\n")
    kind = rng.randrange(10)
    if kind == 0 and lines:  # delete a line
        del lines[rng.randrange(len(lines))]
    elif kind == 1 and lines:  # double a line (a key given twice)
        i = rng.randrange(len(lines))
        lines.insert(i, lines[i])
    elif kind in (2, 3, 4):  # a value made nasty
        candidates = [i for i, l in enumerate(lines) if "=" in l and not l.lstrip().startswith("#")]
        if candidates:
            i = rng.choice(candidates)
            key = lines[i].split("=", 1)[0]
            value = lines[i].split("=", 1)[1]
            pool = NASTY_STRINGS if '"' in value else NASTY_NUMBERS
            lines[i] = key + "= " + rng.choice(pool)
    elif kind == 5:  # cut short
        cut = rng.randrange(max(1, len(text)))
        return text[:cut]
    elif kind == 6:  # random bytes in the middle
        pos = rng.randrange(max(1, len(text)))
        junk = "".join(chr(rng.randrange(1, 256)) for _ in range(rng.randrange(1, 8)))
        return text[:pos] + junk + text[pos:]
    elif kind == 7:  # an obstacle anywhere, of any size
        lines.append("[[box]]\ncenter = [%s, %s]\nsize = [%s, %s]\n" % (tuple(
            rng.choice(["0.0", "1.8", "-1.8", "2.9", "1e6", "-3.0", "0.5"]) for _ in range(2)) +
            tuple(rng.choice(["0.1", "0.0", "-1", "5.9", "100", "0.165"]) for _ in range(2))))
    elif kind == 8:  # a key misspelt
        candidates = [i for i, l in enumerate(lines) if "=" in l]
        if candidates:
            i = rng.choice(candidates)
            lines[i] = "x" + lines[i].lstrip()
    else:  # a table header broken or repeated
        headers = [i for i, l in enumerate(lines) if l.startswith("[")]
        if headers:
            i = rng.choice(headers)
            lines.insert(rng.randrange(len(lines) + 1), lines[i])
    return "\n".join(lines)


def check_outcome(what, code, out, err):
    if code is None:
        fail(what + ": no answer within %d s (a hang)" % TIMEOUT)
        return
    if code < 0:
        fail(what + ": killed by signal %d\n%s" % (-code, err[-2000:]))
        return
    for crash in ("terminate called", "std::bad_alloc", "Segmentation", "AddressSanitizer", "runtime error:"):
        if crash in err:
            fail(what + ": " + crash + "\n" + err[-2000:])
            return
    if code == 0:
        return
    if code != 2:
        fail(what + ": exit %d for a bad input (bad input is exit 2)\n%s" % (code, err[-2000:]))
    elif not err.startswith("error: "):
        fail(what + ": exit 2 without an 'error: ' message\n" + err[-2000:])


def fuzz(binary, work, rng, count):
    scenarios = [read(os.path.join(SOURCE, p)).decode() for p in
                 ("tests/data/short_chain.toml", "configs/scenarios/paper/env4.toml")]
    params = read(os.path.join(SOURCE, "genomes", "default.toml")).decode()
    config = tiny_evolve_config("random", 1)
    started = time.time()
    for k in range(count):
        kind = rng.randrange(4)
        f = os.path.join(work, "fuzz%d.toml" % k)
        if kind <= 1:  # a scenario
            text = rng.choice(scenarios)
            for _ in range(rng.randrange(1, 4)):
                text = mutate(text, rng)
            write(f, text.encode("utf-8", "surrogateescape"))
            if kind == 0:
                args = ["simulate", "--scenario", f, "--robots", "4", "--ticks", "20", "--json"]
            else:
                args = ["astar", "--scenario", f, "--resolution", "0.05", "--json"]
        elif kind == 2:  # a params file
            text = params
            for _ in range(rng.randrange(1, 4)):
                text = mutate(text, rng)
            write(f, text.encode("utf-8", "surrogateescape"))
            args = ["simulate", "--scenario", os.path.join(SOURCE, "tests/data/short_chain.toml"), "--params", f,
                    "--robots", "4", "--ticks", "20", "--mode", "pf"]
        else:  # an evolve config
            text = config
            for _ in range(rng.randrange(1, 3)):
                text = mutate(text, rng)
            write(f, text.encode("utf-8", "surrogateescape"))
            args = ["evolve", "--config", f, "--out", os.path.join(work, "fuzz-run%d" % k), "--generations", "1",
                    "--threads", "2", "--no-wall-time"]
        code, out, err = run(binary, args)
        check_outcome("fuzz %d (%s)" % (k, " ".join(args[:1] + [os.path.basename(f)])), code, out, err)
    print("fuzz: %d mutated files in %.1f s" % (count, time.time() - started))


# ---------------------------------------------------------------- kill and resume

RUN_FILES = ("checkpoint.json", "log.csv", "fitness.svg", "best.toml")


def evolve_args(config, out, extra=()):
    return ["evolve", "--config", config, "--out", out, "--threads", "2", "--no-wall-time"] + list(extra)


def run_json_without_threads(path):
    j = json.loads(read(path))
    j.pop("threads", None)
    return json.dumps(j, sort_keys=True)


def same_run(a, b):
    for f in RUN_FILES:
        if read(os.path.join(a, f)) != read(os.path.join(b, f)):
            return f
    if run_json_without_threads(os.path.join(a, "run.json")) != run_json_without_threads(os.path.join(b, "run.json")):
        return "run.json"
    return None


def kill_loop(binary, work, rng, runs):
    config = os.path.join(work, "kill.toml")
    write(config, tiny_evolve_config("cmaes", 5))
    reference = os.path.join(work, "straight")
    started = time.time()
    code, _, err = run(binary, evolve_args(config, reference))
    if code != 0:
        fail("kill: the uninterrupted run failed\n" + err)
        return
    whole = time.time() - started
    kills = early = 0
    failures = len(FAILURES)
    for k in range(runs):
        out = os.path.join(work, "killed%d" % k)
        first = True
        for attempt in range(40):
            args = evolve_args(config, out, [] if first else ["--resume"])
            p = subprocess.Popen([binary] + args, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
            # the kill falls anywhere in the uninterrupted run's time; on a machine busier than when
            # that was measured the window doubles after 10 tries, so that every run finishes
            delay = rng.uniform(0.0, whole * 1.2) * 2.0 ** max(0, attempt - 9)
            try:
                p.wait(timeout=min(delay, TIMEOUT))
            except subprocess.TimeoutExpired:
                p.send_signal(signal.SIGKILL)
                p.wait()
                kills += 1
            err = p.stderr.read()
            if p.returncode == 0:
                break
            if p.returncode == -signal.SIGKILL:
                if os.path.exists(os.path.join(out, "log.csv")) and not os.path.exists(
                        os.path.join(out, "checkpoint.json")):
                    early += 1
                # as a user would: --resume once the run has written anything (a kill in the first
                # generation leaves its log.csv before any checkpoint.json; that resume starts over)
                first = not any(os.path.exists(os.path.join(out, f)) for f in RUN_FILES)
                continue
            fail("kill %d: exit %s after a kill\n%s" % (k, p.returncode, err[-2000:]))
            break
        else:
            fail("kill %d: never finished in 40 tries" % k)
            continue
        if p.returncode != 0:
            continue
        diff = same_run(reference, out)
        if diff:
            fail("kill %d: %s differs from the uninterrupted run's" % (k, diff))
        leftovers = [f for f in os.listdir(out) if f.endswith(".tmp")]
        if leftovers:
            fail("kill %d: temporary files left behind: %s" % (k, leftovers))
    print("kill: %d runs, %d kills with SIGKILL (%d in the first generation, before any checkpoint), %s, %.1f s"
          % (runs, kills, early, "every resume identical" if len(FAILURES) == failures else "FAILURES", time.time() - started))


# ---------------------------------------------------------------- lock

def lock_check(binary, work):
    config = os.path.join(work, "lock.toml")
    write(config, tiny_evolve_config("random", 200))
    out = os.path.join(work, "locked")
    first = subprocess.Popen([binary] + evolve_args(config, out), stdout=subprocess.DEVNULL,
                             stderr=subprocess.DEVNULL)
    for _ in range(200):  # until the first run holds the lock
        if os.path.exists(os.path.join(out, ".lock")) and os.path.getsize(os.path.join(out, ".lock")) > 0:
            break
        time.sleep(0.02)
    code, _, err = run(binary, evolve_args(config, out, ["--force"]))
    first.send_signal(signal.SIGKILL)
    first.wait()
    if code != 2 or ("pid %d on host" % first.pid) not in err:
        fail("lock: a second run into a locked folder: exit %s\n%s" % (code, err))
    # the kernel dropped the lock with its holder: the folder resumes
    code, _, err = run(binary, evolve_args(config, out, ["--resume", "--generations", "1"]))
    if code not in (0, 2) or "another run" in err:
        fail("lock: the lock outlived its holder: exit %s\n%s" % (code, err))
    print("lock: a second run exits 2 naming pid %d; the lock dies with its holder" % first.pid)


# ---------------------------------------------------------------- full disk

def full_disk(binary, work):
    chain = os.path.join(SOURCE, "tests", "data", "short_chain.toml")
    paper = os.path.join(SOURCE, "genomes", "default.toml")
    grid = ["--scenarios", chain, "--robots", "4", "--seeds", "1", "--ticks", "5"]
    commands = [
        ["--help"],
        ["simulate", "--scenario", chain, "--robots", "4", "--ticks", "5"],
        ["simulate", "--scenario", chain, "--robots", "4", "--ticks", "5", "--json"],
        ["astar", "--scenario", chain, "--json"],
        ["table"] + grid,
        ["evaluate", "--params", paper] + grid,
        ["export", "--format", "argos"],
    ]
    checked = 0
    with open("/dev/full", "w") as full:
        for args in commands:
            code, _, err = run(binary, args, stdout=full)
            checked += 1
            if code != 1 or "cannot write standard output" not in err:
                fail("full: %s > /dev/full: exit %s\n%s" % (" ".join(args), code, err))
    files = [
        ["simulate", "--scenario", chain, "--robots", "4", "--ticks", "5", "--svg", "/dev/full"],
        ["simulate", "--scenario", chain, "--robots", "4", "--ticks", "5", "--heatmap", "/dev/full"],
        ["astar", "--scenario", chain, "--svg", "/dev/full"],
        ["table"] + grid + ["--json", "/dev/full"],
        ["table"] + grid + ["--csv", "/dev/full"],
        ["table"] + grid + ["--md", "/dev/full"],
        ["evaluate", "--params", paper] + grid + ["--json", "/dev/full"],
        ["export", "--out", "/dev/full"],
    ]
    for args in files:
        code, _, err = run(binary, args, stdout=subprocess.DEVNULL)
        checked += 1
        if code != 1 or "cannot write /dev/full" not in err:
            fail("full: %s: exit %s\n%s" % (" ".join(args), code, err))
    # a disk that fills during a resume: the files stay those of the last checkpoint
    config = os.path.join(work, "full.toml")
    write(config, tiny_evolve_config("cmaes", 3))
    out = os.path.join(work, "filling")
    code, _, err = run(binary, evolve_args(config, out, ["--generations", "2"]))
    if code != 0:
        fail("full: the first run failed\n" + err)
        return
    before = {f: read(os.path.join(out, f)) for f in RUN_FILES}

    # SIGXFSZ as a shell leaves it (subprocess restores its default): the binary itself must turn
    # the limit into a failed write naming the file, not die of the signal
    def small_files():
        resource.setrlimit(resource.RLIMIT_FSIZE, (600, resource.RLIM_INFINITY))

    code, _, err = run(binary, evolve_args(config, out, ["--resume"]), preexec_fn=small_files)
    checked += 1
    if code != 1 or "cannot write " + out not in err:
        fail("full: a resume on a full disk: exit %s\n%s" % (code, err))
    after = {f: read(os.path.join(out, f)) for f in RUN_FILES}
    if read(os.path.join(out, "checkpoint.json")) != before["checkpoint.json"]:
        fail("full: the checkpoint changed although the generation's files could not be written")
    torn = [f for f in RUN_FILES if after[f] != before[f] and f != "log.csv" and f != "fitness.svg"]
    if torn:
        fail("full: %s changed on a full disk" % torn)
    code, _, err = run(binary, evolve_args(config, out, ["--resume"]))
    if code != 0:
        fail("full: the resume after the disk was freed failed\n" + err)
    print("full: %d commands on a full disk exit 1 naming what they could not write" % checked)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--binary", default=os.path.join(SOURCE, "build", "release", "swarmpath"))
    parser.add_argument("--quick", action="store_true", help="a bounded run (about a minute)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--fuzz", type=int, help="mutated files (quick: 120, default: 1500)")
    parser.add_argument("--kills", type=int, help="killed-and-resumed runs (quick: 20, default: 25)")
    parser.add_argument("--keep", action="store_true", help="keep the work folder")
    a = parser.parse_args()
    binary = os.path.abspath(a.binary)
    rng = random.Random(a.seed)
    work = tempfile.mkdtemp(prefix="swarmpath-hostile-")
    started = time.time()
    try:
        fuzz(binary, work, rng, a.fuzz if a.fuzz is not None else (120 if a.quick else 1500))
        kill_loop(binary, work, rng, a.kills if a.kills is not None else (20 if a.quick else 25))
        lock_check(binary, work)
        full_disk(binary, work)
    finally:
        if a.keep or FAILURES:
            print("work folder: " + work)
        else:
            shutil.rmtree(work, ignore_errors=True)
    print("hostile_user: seed %d, %.1f s, %d failures" % (a.seed, time.time() - started, len(FAILURES)))
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
