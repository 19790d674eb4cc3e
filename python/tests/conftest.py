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
