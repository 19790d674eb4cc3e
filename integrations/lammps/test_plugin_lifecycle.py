"""The edges of an atom's life in pair_style tabor (issue 33, "LAMMPS lifecycle"):
every refusal is one `ERROR:` line of error->all (never `ERROR on proc N`, never
MPI_Abort), checked on the real `lmp` binary's output.

1. A point particle (radius 0) is refused at setup, naming the atom, on 1 and on
   2 ranks (the check is an MPI reduction over all atoms).
2. Absurd coefficients are refused at pair_coeff (where the probe contact is
   built): a Kuwabara-Kono damping time of 1e300 s, a Tabor parameter of 1e-300,
   an effective modulus of 1.7e308 Pa for Hertz.
3. A corrupted restart record of fix tabor/history (record layout from its
   pack_restart: [length, partner count, (partner ID as ubuf, width doubles) per
   partner], the doubles of a restart file's per-atom section): a partner count of
   NaN, -5, 2^31, 3 or 1000, a partner ID of 0 or -7, a non-finite history value,
   a NaN length: each refused naming the atom and what is wrong; the intact file
   reads back.

Needs TABOR_PLUGIN, LAMMPS_VENV (test_plugin.sh sets them).
"""

import math
import os
import struct
import subprocess
import sys
import tempfile

PLUGIN = os.environ["TABOR_PLUGIN"]
VENV = os.environ["LAMMPS_VENV"]
LMP = os.path.join(VENV, "bin", "lmp")
MPIRUN = os.path.join(VENV, "bin", "mpirun")

R = 1e-6
E_STAR, W = 2.78e10, 0.05
JKR = f"pair_coeff * * jkr/load-controlled {E_STAR} {W}"

HEAD = ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
        "comm_modify vel yes", "region box block -1e-5 1e-5 -1e-5 1e-5 -1e-5 1e-5",
        "create_box 1 box"]
TAIL = [f"plugin load {PLUGIN}", "pair_style tabor", JKR, f"neighbor {0.2 * R} bin",
        "neigh_modify every 1 delay 0 check yes", "fix integrate all nve/sphere", "timestep 1e-10"]


def lmp(lines, ranks=1, cwd=None):
    """Runs `lines` in the lmp binary; returns (exit status, output)."""
    with tempfile.NamedTemporaryFile("w", suffix=".in", delete=False, dir=cwd) as f:
        f.write("\n".join(lines) + "\n")
        path = f.name
    try:
        cmd = [LMP, "-in", path, "-log", "none", "-nocite"]
        if ranks > 1:
            cmd = [MPIRUN, "-np", str(ranks)] + cmd
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=120, cwd=cwd)
        return r.returncode, r.stdout + r.stderr
    finally:
        os.unlink(path)


def error_line(out):
    lines = [line for line in out.splitlines() if line.startswith("ERROR")]
    return lines[0] if lines else None


def refused(what, lines, words, failures, ranks=1):
    """`lines` must stop with one `ERROR:` line (error->all) containing `words`."""
    status, out = lmp(lines, ranks)
    line = error_line(out)
    print(f"  {what} ({ranks} rank{'s' if ranks > 1 else ''}): {line}")
    if status == 0 or line is None:
        failures.append(f"{what}: not refused (exit {status})")
    elif not line.startswith("ERROR: ") or "on proc" in out or "MPI_Abort" in out:
        failures.append(f"{what}: not a clean error->all: {line}")
    elif not all(w in line for w in words):
        failures.append(f"{what}: the error does not say {words}: {line}")


def point_particle(failures):
    lines = HEAD + ["create_atoms 1 single -1.5e-6 0 0", "create_atoms 1 single 1.5e-6 0 0",
                    "create_atoms 1 single 0 4e-6 0",
                    f"set atom 1*3 diameter {2 * R} density 2650", "set atom 2 diameter 0"] + TAIL + ["run 0"]
    for ranks in (1, 2):
        refused("point particle", lines, ["pair tabor: atom 2 (type 1) has radius 0"], failures, ranks)


def absurd_coefficients(failures):
    base = HEAD + ["create_atoms 1 single 0 0 0", f"set atom 1 diameter {2 * R} density 2650",
                   f"plugin load {PLUGIN}", "pair_style tabor"]
    for coeff, words in [
        (f"{JKR} damping 1e300", ["pair_coeff", "invalid damping_time = 1e300"]),
        (f"pair_coeff * * maugis {E_STAR} {W} 1e-300", ["pair_coeff", "tabor_parameter = 1e-300"]),
        ("pair_coeff * * hertz 1.7e308", ["pair_coeff", "effective_modulus = 1.7e308"]),
    ]:
        refused(coeff.split(" ", 3)[-1], base + [coeff], words, failures)
    status, out = lmp(base + [f"{JKR} damping 1e-9", "run 0"])
    if status != 0:
        failures.append(f"a physical damping time refused: {error_line(out)}")


def ubuf(tag):
    return struct.pack("<q", tag)


def restart(failures):
    """Two grains in adhesive contact, written to a restart file; the record of
    atom 1 (one contact with atom 2, 10 doubles) corrupted field by field."""
    with tempfile.TemporaryDirectory() as tmp:
        file = os.path.join(tmp, "stuck.restart")
        # overlap 1 nm at rest: the JKR contact forms and stays (adhesion)
        gap = R - 0.5e-9
        status, out = lmp(HEAD + [f"create_atoms 1 single {-gap} 0 0", f"create_atoms 1 single {gap} 0 0",
                                  f"set atom 1*2 diameter {2 * R} density 2650"] + TAIL
                          + ["run 20", f"write_restart {file}"])
        if status != 0:
            failures.append(f"restart: writing failed: {error_line(out)}")
            return
        data = open(file, "rb").read()
        record = struct.pack("<dd", 13.0, 1.0) + ubuf(2) + struct.pack("<d", 1.0)
        at = data.find(record)
        if at < 0 or data.find(record, at + 1) >= 0:
            failures.append("restart: the record of atom 1 (13 values, 1 contact with atom 2) not found once")
            return
        read = ["units si", f"plugin load {PLUGIN}", f"read_restart {file}"] + TAIL[1:] + ["run 0"]
        status, out = lmp(read)
        print(f"  intact restart: exit {status}")
        if status != 0:
            failures.append(f"restart: the intact file is refused: {error_line(out)}")
        cases = [
            ("partner count NaN", 8, struct.pack("<d", math.nan), "partner count of nan"),
            ("partner count -5", 8, struct.pack("<d", -5.0), "partner count of -5"),
            ("partner count 2^31", 8, struct.pack("<d", 2.0 ** 31), "partner count of 2147483648"),
            ("partner count 3", 8, struct.pack("<d", 3.0), "cannot hold 3 contacts"),
            ("partner count 1000", 8, struct.pack("<d", 1000.0), "partner count of 1000"),
            ("partner ID 0", 16, ubuf(0), "partner ID 0"),
            ("partner ID -7", 16, ubuf(-7), "partner ID -7"),
            ("contact flag NaN", 24, struct.pack("<d", math.nan), "non-finite value nan (double 0"),
            ("turning point inf", 32, struct.pack("<d", math.inf), "non-finite value inf (double 1"),
            ("contact flag 0.5", 24, struct.pack("<d", 0.5), "contact flag 0.5"),
            ("record length NaN", 0, struct.pack("<d", math.nan), "length of nan"),
        ]
        for what, offset, value, words in cases:
            bad = bytearray(data)
            bad[at + offset:at + offset + 8] = value
            with open(file, "wb") as f:
                f.write(bad)
            refused(f"restart, {what}", read, ["restart record of atom 1", words], failures)


def main():
    failures = []
    print("point particles:")
    point_particle(failures)
    print("absurd coefficients:")
    absurd_coefficients(failures)
    print("corrupted restart records:")
    restart(failures)
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        sys.exit(1)
    print("lifecycle: all passed")


if __name__ == "__main__":
    main()
