#!/usr/bin/env bash
# The per-step cost of pair_style tabor's lifecycle checks (creation stamps, the
# records of gone partners dropped) against a build without them, by LAMMPS's
# timer breakdown (time_lifecycle.py). No assertion: wall-clock times depend on the
# machine. Environment: TIMING_GRAINS, TIMING_STEPS, TIMING_REPEATS.
set -euo pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
TARGET="${CARGO_TARGET_DIR:-$ROOT/target}"
export CARGO_TARGET_DIR="$TARGET"
PLUGIN="$(cd "$ROOT" && cargo xtask lammps-plugin | tail -n 1)"
VENV="$("$HERE/setup.sh")"
export TABOR_PLUGIN="$PLUGIN" LAMMPS_VENV="$VENV"
export CMAKE="$(command -v cmake || echo "$VENV/bin/cmake")"
export LD_LIBRARY_PATH="$VENV/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export PATH="$VENV/bin:$PATH"
"$VENV/bin/python" "$HERE/time_lifecycle.py" "$@"
