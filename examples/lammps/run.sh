#!/usr/bin/env bash
# Runs the MPI example: installs LAMMPS if needed, builds tabor, exports the
# silica Maugis-Dugdale scene, runs 1000 pair collisions on 2 MPI ranks and
# compares the fraction that sticks with tabor's prediction. Outputs in
# target/lammps-cloud (report.txt, cloud_restitution.svg).
set -euo pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
TARGET="${CARGO_TARGET_DIR:-$ROOT/target}"
export LAMMPS_VENV="$("$ROOT/integrations/lammps/setup.sh")"
(cd "$ROOT" && CARGO_TARGET_DIR="$TARGET" cargo xtask binaries >/dev/null)
export TABOR="$TARGET/release/tabor"
export CLOUD_OUT="${CLOUD_OUT:-$TARGET/lammps-cloud}"
export LD_LIBRARY_PATH="$LAMMPS_VENV/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export PATH="$LAMMPS_VENV/bin:$PATH"
"$LAMMPS_VENV/bin/python" "$HERE/cloud.py"
