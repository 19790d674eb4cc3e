#!/usr/bin/env bash
# LAMMPS timing of fix wall/tabor against fix wall/gran granular jkr (same
# sub-models) on the deposition run (time_wall.py): builds the plugin, prints the
# wall's Modify time per variant and the ratio (target <= 1.0). No assertion:
# wall-clock times depend on the machine. Environment: TIMING_GRAINS, TIMING_REPEATS.
set -euo pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
TARGET="${CARGO_TARGET_DIR:-$ROOT/target}"
export CARGO_TARGET_DIR="$TARGET"
export TABOR_PLUGIN="${TABOR_PLUGIN:-$(cd "$ROOT" && cargo xtask lammps-plugin | tail -n 1)}"
export LAMMPS_VENV="$("$HERE/setup.sh")"
(cd "$ROOT" && cargo xtask binaries >/dev/null)
export TABOR="$TARGET/release/tabor" TABOR_FFI_LIB="$TARGET/release/libtabor_ffi.so"
export LD_LIBRARY_PATH="$LAMMPS_VENV/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export PATH="$LAMMPS_VENV/bin:$PATH"
"$LAMMPS_VENV/bin/python" "$HERE/time_wall.py" "$@"
