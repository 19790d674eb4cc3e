"""Two more edges of an atom's life in pair_style tabor (issue 33), beside
test_plugin_lifecycle.py:

1. A restart file of an older build: fix tabor/history records without creation
   stamps ([length, partner count, (partner ID, values) per partner], the layout
   before the stamps; the current one is [length, -1, partner count, stamp,
   (partner ID, partner stamp, values) per partner]). The file written by this
   build is rewritten here into the old layout record by record (the atoms'
   buffer lengths and the section's count of doubles adjusted); read back, every
   contact gets its state (every stamp 0): the force on every atom after `run 0`
   equals the force read from the file as written, and a 50-step run continues
   identically.
   A file of the build before the spring bed (Thornton's incremental form, 16
   doubles per contact, a reversal force and a mode in doubles 13 and 14) read
   by a run with tangential mindlin_deresiewicz stops with the message that names
   Thornton's form (it was refused as a corrupted micro-slip bed header, whose
   check also read past a shorter record).
2. A recycled atom ID across two MPI ranks: the one-rank case of
   test_plugin_lifecycle.py (a grain stuck to another deleted, a new one created
   with the same ID 1.5 nm away) with the two grains on different ranks
   (`processors 2 1 1`, the sub-domain boundary between them): the new pair
   starts clean (force 0) and the survivor keeps no record of the deleted grain.

Needs TABOR_PLUGIN, LAMMPS_VENV (test_plugin.sh sets them).
"""

import os
import struct
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import lammps_case  # noqa: E402
from lammps_case import FIELDS, PLUGIN, error_line, lmp_output, report  # noqa: E402
from test_plugin_lifecycle import HEAD, R, TAIL, survivor_restart, ubuf  # noqa: E402

FRICTION = "poisson 0.17 tangential mindlin NULL 0.5 0.3 rolling sds 50 0 0.1 twisting marshall"
PAIR = TAIL[:2] + [TAIL[2] + " " + FRICTION] + TAIL[3:]
# three grains: 1 and 2 stuck and sliding, 3 pressed against 2 and spinning
GRAINS = [f"create_atoms 1 single {-(R - 0.5e-9)!r} 0 0", f"create_atoms 1 single {R - 0.5e-9!r} 0 0",
          f"create_atoms 1 single {3 * R - 1.5e-9!r} 0 0", f"set atom 1*3 diameter {2 * R} density 2650",
          "set atom 1 vy 0.02", "set atom 3 omega 0 0 2e4"]
PRINT = [f'print "F{i} ${{f{i}x}} ${{f{i}y}} ${{f{i}z}}"' for i in (1, 2, 3)]
FORCES = [f"variable f{i}{c} equal f{c}[{i}]" for i in (1, 2, 3) for c in "xyz"] + PRINT


def forces(out):
    return [line.split()[1:] for line in out.splitlines() if line[:2] in ("F1", "F2", "F3") and line[2] == " "]


def atom_buffers(data):
    """lammps_case.atom_buffers of this file's grains (radius R, buffers under 1e5
    doubles); the int before the first buffer holds the section's count of doubles."""
    return lammps_case.atom_buffers(data, R, 1e5)


def without_stamps(data):
    """The restart file `data` with every fix tabor/history record (the atom's only
    fix record) rewritten into the layout before creation stamps."""
    starts, end = atom_buffers(data)
    count = struct.unpack_from("<i", data, starts[0] - 4)[0]
    assert len(starts) == 3 and count * 8 == end - starts[0], "the per-atom section is not where expected"
    section = b""
    for a in starts:
        m = int(struct.unpack_from("<d", data, a)[0])
        values = list(struct.unpack_from(f"<{m}d", data, a))
        rec = values[FIELDS:]
        assert rec[0] == len(rec) and rec[1] == -1.0, f"not a stamped record: {rec[:4]}"
        n = int(rec[2])
        width = (len(rec) - 4) // n - 2 if n else 0
        old = [0.0, float(n)]
        for k in range(n):
            entry = rec[4 + k * (2 + width):4 + (k + 1) * (2 + width)]
            old += [entry[0]] + entry[2:]           # the partner ID (as ubuf bits), its values
        old[0] = float(len(old))
        fields = values[:FIELDS]
        fields[0] = float(FIELDS + len(old))
        # the partner IDs are ubuf bits: pack them back bit for bit
        packed = struct.pack(f"<{FIELDS}d", *fields) + struct.pack("<2d", *old[:2])
        k0 = 2
        for k in range(n):
            packed += struct.pack("<d", old[k0]) + struct.pack(f"<{width}d", *old[k0 + 1:k0 + 1 + width])
            k0 += 1 + width
        section += packed
    new_count = len(section) // 8
    return data[:starts[0] - 4] + struct.pack("<i", new_count) + section + data[end:]


def thornton_layout(data):
    """The restart file `data` with every contact of every fix tabor/history
    record widened to Thornton's 16 doubles, doubles 10-15 a state of its
    incremental form (reversal force -2e-7 N in double 13, mode 2: reloading)."""
    starts, end = atom_buffers(data)
    section = b""
    for a in starts:
        m = int(struct.unpack_from("<d", data, a)[0])
        raw = data[a:a + 8 * m]
        rec = list(struct.unpack_from(f"<{m - FIELDS}d", raw, 8 * FIELDS))
        n = int(rec[2])
        width = (len(rec) - 4) // n - 2 if n else 0
        assert width in (0, 10), f"not a 10-double record: {width}"
        out = struct.pack("<4d", 0.0, -1.0, float(n), rec[3])
        for k in range(n):
            at = 8 * (FIELDS + 4 + k * (2 + width))
            out += raw[at:at + 16] + raw[at + 16:at + 16 + 8 * width]
            out += struct.pack("<6d", 0.0, 0.0, 0.0, -2e-7, 2.0, 0.0)
        out = struct.pack("<d", float(len(out) // 8)) + out[8:]
        fields = list(struct.unpack_from(f"<{FIELDS}d", raw))
        fields[0] = float(FIELDS + len(out) // 8)
        section += struct.pack("<d", fields[0]) + raw[8:8 * FIELDS] + out
    return data[:starts[0] - 4] + struct.pack("<i", len(section) // 8) + section + data[end:]


def thornton_restart(failures):
    with tempfile.TemporaryDirectory() as tmp:
        file = os.path.join(tmp, "bed10.restart")
        status, out = lmp_output(HEAD + GRAINS + PAIR + ["run 20", f"write_restart {file}"])
        if status != 0:
            failures.append(f"Thornton restart: writing failed: {error_line(out)}")
            return
        old = os.path.join(tmp, "thornton.restart")
        with open(old, "wb") as f:
            f.write(thornton_layout(open(file, "rb").read()))
        micro = [line.replace("tangential mindlin NULL", "tangential mindlin_deresiewicz NULL") for line in PAIR[1:]]
        status, out = lmp_output(["units si", f"plugin load {PLUGIN}", f"read_restart {old}"] + micro + ["run 0"])
        line = error_line(out)
        print(f"  Thornton's 16 doubles read with mindlin_deresiewicz: exit {status}: {line[:150]}")
        if status == 0 or "Thornton's incremental form" not in line or "ERROR on proc" in out:
            failures.append(f"Thornton restart: not refused by name (exit {status}): {line}")


def record_of(data, tag):
    """The fix record (the doubles after the 16 fields) of atom `tag`."""
    for a in atom_buffers(data)[0]:
        m = int(struct.unpack_from("<d", data, a)[0])
        values = list(struct.unpack_from(f"<{m}d", data, a))
        if data[a + 32:a + 40] == ubuf(tag):
            return values[FIELDS:]
    return []


def older_build(failures):
    with tempfile.TemporaryDirectory() as tmp:
        file = os.path.join(tmp, "stamped.restart")
        status, out = lmp_output(HEAD + GRAINS + PAIR + ["run 20", f"write_restart {file}"])
        if status != 0:
            failures.append(f"older build: writing failed: {error_line(out)}")
            return
        data = open(file, "rb").read()
        old = without_stamps(data)
        legacy = os.path.join(tmp, "legacy.restart")
        with open(legacy, "wb") as f:
            f.write(old)
        # atom 1's record of its one contact (with atom 2), stamped and old
        if struct.pack("<ddd", -1.0, 1.0, 0.0) + ubuf(2) not in data or record_of(old, 1)[1:2] != [1.0] or \
                record_of(old, 1)[2] != struct.unpack("<d", ubuf(2))[0]:
            failures.append("older build: atom 1's record of its contact with atom 2 not found")
        runs = {}
        for name, path in (("as written", file), ("older layout", legacy)):
            read = ["units si", f"plugin load {PLUGIN}", f"read_restart {path}"] + PAIR[1:]
            status, out = lmp_output(read + ["run 0"] + FORCES + ["run 50"] + FORCES)
            runs[name] = forces(out) if status == 0 else None
            print(f"  {name}: {len(old) if name != 'as written' else len(data)} bytes, exit {status}, "
                  f"F1 after run 0 {runs[name][0] if runs[name] else error_line(out)}")
        a, b = runs["as written"], runs["older layout"]
        if not a or not b or len(a) != 6:
            failures.append(f"older build: a run failed ({a}, {b})")
        elif a != b:
            failures.append(f"older build: forces differ: {a} vs {b}")
        elif float(a[0][1]) == 0.0:
            # a fresh JKR contact at this overlap has the same normal force: only the
            # tangential force (the stored displacement) shows the history came back
            failures.append("older build: no tangential force on atom 1 (the contact history was not restored)")


def recycled_two_ranks(failures):
    head = HEAD[:5] + ["processors 2 1 1"] + HEAD[5:]
    gap = R - 0.5e-9
    stuck = head + [f"create_atoms 1 single {-gap} 0 0", f"create_atoms 1 single {gap} 0 0",
                    f"set atom 1*2 diameter {2 * R} density 2650"] + TAIL + ["run 20"]
    new = [f"create_atoms 1 single {-gap + 2 * R + 1.5e-9} 0 0", f"set atom 2 diameter {2 * R} density 2650",
           "velocity all set 0 0 0"]
    fx = ["variable fx equal fx[1]", 'print "FX ${fx}"']
    status, out = lmp_output(stuck + fx, ranks=2)
    before = [line.split()[1] for line in out.splitlines() if line.startswith("FX ")]
    status2, out2 = lmp_output(stuck + ["group gone id 2", "delete_atoms group gone"] + new + ["run 0"] + fx, ranks=2)
    after = [line.split()[1] for line in out2.splitlines() if line.startswith("FX ")]
    # the two grains on different ranks: each rank owns one atom
    owned = [line for line in out.splitlines() if "Nlocal:" in line]
    print(f"  2 ranks: stuck fx[1] {before}; recycled ID 2 at 1.5 nm: {after}; {owned[:1]}")
    if status != 0 or status2 != 0 or not before or not after:
        failures.append(f"recycled ID on 2 ranks: a run failed ({error_line(out)}, {error_line(out2)})")
    elif float(before[-1]) == 0.0:
        failures.append("recycled ID on 2 ranks: the stuck pair has no force")
    elif float(after[-1]) != 0.0:
        failures.append(f"recycled ID on 2 ranks: force {after[-1]} N on the new pair (must be 0)")
    elif not owned or "1 ave           1 max           1 min" not in owned[0]:
        failures.append(f"recycled ID on 2 ranks: the grains are not one per rank ({owned[:1]})")
    status, data = survivor_restart(stuck, ranks=2)
    empty = struct.pack("<dddd", 4.0, -1.0, 0.0, 0.0)
    print(f"  2 ranks: survivor's record after delete_atoms: {'empty' if empty in data else 'not empty'}")
    if status != 0 or empty not in data:
        failures.append(f"recycled ID on 2 ranks: the survivor keeps a record of the deleted atom (exit {status})")


def main():
    failures = []
    print("a restart file of an older build (no creation stamps):")
    older_build(failures)
    thornton_restart(failures)
    print("a recycled atom ID across two MPI ranks:")
    recycled_two_ranks(failures)
    return report(failures, "lifecycle (older restart, recycled ID on 2 ranks): all passed")


if __name__ == "__main__":
    sys.exit(main())
