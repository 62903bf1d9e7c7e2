# SPDX-License-Identifier: MIT
# Shared fixtures of the Python module's tests. ctest runs them with Debian's interpreter and
# PYTHONPATH=build/<preset>/python; SWARMPATH_CLI names the command line of the same build.
import json
import os
import pathlib
import subprocess

import pytest

SOURCE = pathlib.Path(os.environ.get("SWARMPATH_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
CLI = os.environ.get("SWARMPATH_CLI", str(SOURCE / "build" / "release" / "swarmpath"))
SHORT_CHAIN = str(SOURCE / "tests" / "data" / "short_chain.toml")
TINY_TUNE = str(SOURCE / "tests" / "data" / "tune" / "tiny_tune.toml")

# simulate --json fields that measure the machine, not the run
WALL_CLOCK_FIELDS = ("wall_seconds", "robot_ticks_per_second")


def run_cli(*args, check=True):
    """Runs the command line; returns (exit code, stdout, stderr)."""
    p = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True)
    if check and p.returncode != 0:
        raise AssertionError(f"swarmpath {' '.join(map(str, args))} failed ({p.returncode}): {p.stderr}")
    return p.returncode, p.stdout, p.stderr


def cli_json(*args):
    return json.loads(run_cli(*args)[1])


def cli_error(*args):
    """The message the command line prints for bad input (exit code 2), without 'error: '."""
    code, _, err = run_cli(*args, check=False)
    assert code == 2, f"expected exit code 2, got {code}: {err}"
    line = err.strip().splitlines()[0]
    assert line.startswith("error: ")
    return line[len("error: "):]


@pytest.fixture(scope="module")
def sp():
    import swarmpath

    return swarmpath
