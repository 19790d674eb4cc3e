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
4. Recycled atom IDs: a grain stuck to another is deleted and a new one created
   (it gets the same ID) 1.5 nm away: the new pair starts clean (force 0, as the
   same geometry built fresh), and the survivor keeps no record of the deleted
   grain (fix tabor/history's creation stamps, and the records of partners
   absent from a rebuilt neighbor list dropped).

Needs TABOR_PLUGIN, LAMMPS_VENV (test_plugin.sh sets them).
"""

import math
import os
import struct
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from lammps_case import PLUGIN, error_line, lmp_output, report  # noqa: E402

# a soft, sticky pair whose JKR snap-off gap (about 17 nm at R* = 5 um) is well
# beyond the 1.5 nm of the recycled-ID case: a stale contact would pull there
R = 1e-5
E_STAR, W = 1e9, 0.5
JKR = f"pair_coeff * * jkr/load-controlled {E_STAR} {W}"

HEAD = ["units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
        "comm_modify vel yes", "region box block -1e-4 1e-4 -1e-4 1e-4 -1e-4 1e-4",
        "create_box 1 box"]
TAIL = [f"plugin load {PLUGIN}", "pair_style tabor", JKR, f"neighbor {0.2 * R} bin",
        "neigh_modify every 1 delay 0 check yes", "fix integrate all nve/sphere", "timestep 1e-10"]


def refused(what, lines, words, failures, ranks=1):
    """`lines` must stop with one `ERROR:` line (error->all) containing `words`."""
    status, out = lmp_output(lines, ranks)
    line = error_line(out)
    print(f"  {what} ({ranks} rank{'s' if ranks > 1 else ''}): {line}")
    if status == 0 or line is None:
        failures.append(f"{what}: not refused (exit {status})")
    elif not line.startswith("ERROR: ") or "on proc" in out or "MPI_Abort" in out:
        failures.append(f"{what}: not a clean error->all: {line}")
    elif not all(w in line for w in words):
        failures.append(f"{what}: the error does not say {words}: {line}")


def point_particle(failures):
    lines = HEAD + ["create_atoms 1 single -1.5e-5 0 0", "create_atoms 1 single 1.5e-5 0 0",
                    "create_atoms 1 single 0 4e-5 0",
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
    status, out = lmp_output(base + [f"{JKR} damping 1e-9", "run 0"])
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
        status, out = lmp_output(HEAD + [f"create_atoms 1 single {-gap} 0 0", f"create_atoms 1 single {gap} 0 0",
                                         f"set atom 1*2 diameter {2 * R} density 2650"] + TAIL
                                 + ["run 20", f"write_restart {file}"])
        if status != 0:
            failures.append(f"restart: writing failed: {error_line(out)}")
            return
        data = open(file, "rb").read()
        # [length 16, -1 (stamped layout), 1 partner, stamp 0, ID 2, its stamp 0, flag 1, ...]
        record = struct.pack("<dddd", 16.0, -1.0, 1.0, 0.0) + ubuf(2) + struct.pack("<dd", 0.0, 1.0)
        at = data.find(record)
        if at < 0 or data.find(record, at + 1) >= 0:
            failures.append("restart: the record of atom 1 (16 values, 1 contact with atom 2) not found once")
            return
        read = ["units si", f"plugin load {PLUGIN}", f"read_restart {file}"] + TAIL[1:] + ["run 0"]
        status, out = lmp_output(read)
        print(f"  intact restart: exit {status}")
        if status != 0:
            failures.append(f"restart: the intact file is refused: {error_line(out)}")
        cases = [
            ("partner count NaN", 16, struct.pack("<d", math.nan), "partner count of nan"),
            ("partner count -5", 16, struct.pack("<d", -5.0), "partner count of -5"),
            ("partner count 2^31", 16, struct.pack("<d", 2.0 ** 31), "partner count of 2147483648"),
            ("partner count 3", 16, struct.pack("<d", 3.0), "contact 2 of 3"),
            ("partner count 1000", 16, struct.pack("<d", 1000.0), "partner count of 1000"),
            ("partner ID 0", 32, ubuf(0), "partner ID 0"),
            ("partner ID -7", 32, ubuf(-7), "partner ID -7"),
            ("own stamp NaN", 24, struct.pack("<d", math.nan), "creation stamp nan"),
            ("partner stamp -1", 40, struct.pack("<d", -1.0), "partner stamp -1"),
            ("contact flag NaN", 48, struct.pack("<d", math.nan), "non-finite value nan (double 0"),
            ("turning point inf", 56, struct.pack("<d", math.inf), "non-finite value inf (double 1"),
            ("contact flag 0.5", 48, struct.pack("<d", 0.5), "contact flag 0.5"),
            ("record length NaN", 0, struct.pack("<d", math.nan), "length of nan"),
        ]
        for what, offset, value, words in cases:
            bad = bytearray(data)
            bad[at + offset:at + offset + 8] = value
            with open(file, "wb") as f:
                f.write(bad)
            refused(f"restart, {what}", read, ["restart record of atom 1", words], failures)


def wall_restart(failures):
    """A grain stuck on a fix wall/tabor plate, written to a restart file; its
    wall record [length 14, width 10, 1 contact, wall index, 10 doubles]
    corrupted field by field: one clean error->all, never a crash."""
    wall = f"fix plate all wall/tabor jkr/load-controlled {E_STAR} {W} zplane 0.0 NULL"
    with tempfile.TemporaryDirectory() as tmp:
        file = os.path.join(tmp, "wall.restart")
        status, out = lmp_output(HEAD + [f"create_atoms 1 single 0 0 {R - 0.5e-9}",
                                         f"set atom 1 diameter {2 * R} density 2650", f"plugin load {PLUGIN}", wall,
                                         "fix integrate all nve/sphere", "timestep 1e-10", "run 20",
                                         f"write_restart {file}"])
        if status != 0:
            failures.append(f"wall restart: writing failed: {error_line(out)}")
            return
        data = open(file, "rb").read()
        record = struct.pack("<ddd", 14.0, 10.0, 1.0)
        at = data.find(record)
        if at < 0 or data.find(record, at + 1) >= 0:
            failures.append("wall restart: the record (14 values, 1 contact of 10 doubles) not found once")
            return
        read = ["units si", f"plugin load {PLUGIN}", f"read_restart {file}", wall, "fix integrate all nve/sphere",
                "timestep 1e-10", "run 0"]
        status, out = lmp_output(read)
        print(f"  intact wall restart: exit {status}")
        if status != 0:
            failures.append(f"wall restart: the intact file is refused: {error_line(out)}")
        for what, offset, value, words in [
            ("contact count NaN", 16, struct.pack("<d", math.nan), "holds nan wall contacts"),
            ("contact count 2^31", 16, struct.pack("<d", 2.0 ** 31), "holds 2147483648 wall contacts"),
            ("width -1", 8, struct.pack("<d", -1.0), "wall contacts of -1 doubles"),
            ("length NaN", 0, struct.pack("<d", math.nan), "length of nan"),
            ("contact flag NaN", 32, struct.pack("<d", math.nan), "non-finite history value nan"),
        ]:
            bad = bytearray(data)
            bad[at + offset:at + offset + 8] = value
            with open(file, "wb") as f:
                f.write(bad)
            refused(f"wall restart, {what}", read, ["fix wall/tabor: the restart record of atom 1", words], failures)


def force_on_1(lines):
    """fx of atom 1 after `lines` (a `run 0` at the end), and the exit status."""
    status, out = lmp_output(lines + ["variable fx equal fx[1]", 'print "FX ${fx}"'])
    values = [line.split()[1] for line in out.splitlines() if line.startswith("FX ")]
    return (float(values[-1]) if values else None), status, out


def survivor_restart(stuck, ranks=1):
    """`stuck` (a stuck pair, atoms 1 and 2), atom 2 deleted, a `run 0`, then
    write_restart: (exit status, the restart file's bytes, empty on failure)."""
    with tempfile.TemporaryDirectory() as tmp:
        file = os.path.join(tmp, "survivor.restart")
        status, _ = lmp_output(stuck + ["group gone id 2", "delete_atoms group gone", "run 0", f"write_restart {file}"],
                               ranks)
        return status, (open(file, "rb").read() if status == 0 else b"")


def recycled_ids(failures):
    """delete_atoms a grain stuck to another, create_atoms a new one (it gets the
    same ID, 2) 1.5 nm away: the new pair starts clean (force 0, as the same
    geometry built fresh: a JKR contact forms only at overlap >= 0), and the
    survivor keeps no record of the deleted grain (its restart record: 0 partners)."""
    gap = R - 0.5e-9    # overlap 1 nm: stuck
    stuck = HEAD + [f"create_atoms 1 single {-gap} 0 0", f"create_atoms 1 single {gap} 0 0",
                    f"set atom 1*2 diameter {2 * R} density 2650"] + TAIL + ["run 20"]
    far = -gap + 2 * R + 1.5e-9
    new = [f"create_atoms 1 single {far} 0 0", f"set atom 2 diameter {2 * R} density 2650",
           "velocity all set 0 0 0"]
    before, _, _ = force_on_1(stuck)
    recycled, status, out = force_on_1(stuck + ["group gone id 2", "delete_atoms group gone"] + new + ["run 0"])
    fresh, _, _ = force_on_1(HEAD + [f"create_atoms 1 single {-gap} 0 0", f"set atom 1 diameter {2 * R} density 2650"]
                             + new + TAIL + ["run 0"])
    print(f"  stuck pair: fx[1] = {before} N; recycled ID 2 at 1.5 nm: {recycled} N; fresh: {fresh} N")
    if status != 0 or recycled is None:
        failures.append(f"recycled ID: the run failed: {error_line(out)}")
    elif not (before is not None and before != 0.0):
        failures.append(f"recycled ID: the stuck pair has no force ({before})")
    elif recycled != 0.0 or fresh != 0.0:
        failures.append(f"recycled ID: force {recycled} N on the new pair, {fresh} N fresh (both must be 0)")
    status, data = survivor_restart(stuck)
    empty = struct.pack("<dddd", 4.0, -1.0, 0.0, 0.0)
    stale = struct.pack("<dddd", 16.0, -1.0, 1.0, 0.0) + ubuf(2)
    print(f"  survivor's record after delete_atoms: {'empty' if empty in data else 'not empty'}"
          f"{', stale contact with atom 2' if stale in data else ''}")
    if status != 0 or empty not in data or stale in data:
        failures.append(f"recycled ID: the survivor keeps a record of the deleted atom (exit {status})")


def main():
    failures = []
    print("point particles:")
    point_particle(failures)
    print("absurd coefficients:")
    absurd_coefficients(failures)
    print("corrupted restart records:")
    restart(failures)
    wall_restart(failures)
    print("recycled atom IDs:")
    recycled_ids(failures)
    return report(failures, "lifecycle: all passed")


if __name__ == "__main__":
    sys.exit(main())
