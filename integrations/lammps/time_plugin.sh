#!/usr/bin/env bash
# LAMMPS timing of pair_style tabor with friction against pair_style granular (jkr +
# mindlin + sds + marshall) on a polydisperse cloud (time_plugin.py): builds the plugin, prints the times
# and the ratios plugin/granular (target <= 1.5) and plugin with tangential mindlin_deresiewicz/granular
# with mindlin (target <= 1.0), all in the same run. No assertion: wall-clock times
# depend on the machine. Environment: TIMING_GRAINS, TIMING_STEPS, TIMING_REPEATS, TIMING_RANKS.
set -euo pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
TARGET="${CARGO_TARGET_DIR:-$ROOT/target}"
export CARGO_TARGET_DIR="$TARGET"
PLUGIN="$(cd "$ROOT" && cargo xtask lammps-plugin | tail -n 1)"
VENV="$("$HERE/setup.sh")"
(cd "$ROOT" && cargo xtask binaries >/dev/null)
export TABOR="$TARGET/release/tabor" TABOR_PLUGIN="$PLUGIN" LAMMPS_VENV="$VENV"
export LD_LIBRARY_PATH="$VENV/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
"$VENV/bin/python" "$HERE/time_plugin.py" "$@"
