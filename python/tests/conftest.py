"""Shared fixtures: the repository paths and the `tabor` CLI of the same tree."""

import json
import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
SCENES = ROOT / "examples" / "scenes"


def run_cli(*args):
    """Runs the `tabor` CLI built from this tree (TABOR_CLI, set by `cargo xtask
    test`, else `cargo run -p tabor-cli`) and returns its parsed JSON output."""
    cli = os.environ.get("TABOR_CLI")
    if cli:
        cmd = [cli, *args]
    else:
        cmd = ["cargo", "run", "--quiet", "--package", "tabor-cli", "--", *args]
    done = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise AssertionError(f"{' '.join(cmd)} failed ({done.returncode}): {done.stderr}")
    return json.loads(done.stdout)


@pytest.fixture(scope="session")
def cli():
    return run_cli


def assert_matches_cli(py, ref):
    """A model function's result against the CLI's `--json` for the same flags: every
    CLI key (but `tabor_version`: `tabor.__version__`) with an equal value (floats to
    1e-12 relative, the CLI being a debug build); the keys the CLI leaves out where
    they do not apply are NaN or None in Python (a fixed set of keys per call)."""
    import math

    ref = dict(ref)
    assert ref.pop("tabor_version") == __import__("tabor").__version__
    assert set(ref) <= set(py), f"missing {set(ref) - set(py)}"
    for k, v in ref.items():
        if isinstance(v, float):
            assert py[k] == pytest.approx(v, rel=1e-12), k
        else:
            assert py[k] == v and type(py[k]) is type(v), k
    for k in set(py) - set(ref):
        assert py[k] is None or (isinstance(py[k], float) and math.isnan(py[k])), (k, py[k])
