"""Hostile LAMMPS input for the plugin as a test suite (issue 33): generated
`pair_coeff` lines of pair_style tabor and `fix wall/tabor` (and wall/tabor/region)
lines with hostile numbers (NaN, inf, 1e308, 1e400, subnormal, negative, zero,
words, integer overflows), missing and extra arguments, unknown and duplicated
keywords, type ranges out of bounds and huge keyword counts; and restart files
written with pair_style tabor (fix tabor/history contacts, friction) and fix
wall/tabor contacts, corrupted at random (a hostile double or random bits in a
plugin record, random bytes in a plugin record, a hostile double anywhere in the
per-atom section).

Each case must end in a clean run (every command accepted, the run finished, every
position, velocity, force, spin and torque finite) or in one clean refusal (one
`ERROR: ` line of error->all, raised as LAMMPS's ordinary exception): never
`ERROR on proc` (error->one, an abort), a crash, a hang (TIME_LIMIT per case) or a
non-finite number. The cases run in one LAMMPS process (the lammps Python module,
`clear` between cases) that a watchdog restarts after a crash or a hang, so one
bad case does not hide the others. Seeded and deterministic (case k uses the
generator seeded with SEED and k alone); the counts are printed.

The short variant runs with the plugin suite (`TABOR_HOSTILE_CASES`, default 300
input cases and 100 restart corruptions, about 2 s); the campaign is opt-in:

    TABOR_HOSTILE_CASES=3000 TABOR_HOSTILE_ONLY=1 bash integrations/lammps/test_plugin.sh

(`TABOR_HOSTILE_RESTARTS` sets the restart cases apart, `TABOR_HOSTILE_SEED` the
seed, default 33.)

Needs TABOR_PLUGIN, LAMMPS_VENV, LD_LIBRARY_PATH=<venv>/lib.
"""

import json
import math
import os
import random
import select
import struct
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import lammps_case  # noqa: E402
from lammps_case import FIELDS, PLUGIN, lmp_new, report  # noqa: E402

CASES = int(os.environ.get("TABOR_HOSTILE_CASES", "300"))
RESTARTS = int(os.environ.get("TABOR_HOSTILE_RESTARTS", str(max(16, CASES // 3))))
SEED = int(os.environ.get("TABOR_HOSTILE_SEED", "33"))
TIME_LIMIT = 60.0   # seconds per case (a Maugis-Dugdale Lambda table takes under 1 s)

R = 1e-6
# numbers as hostile users and programs write them
HOSTILE = ["nan", "NaN", "inf", "-inf", "1e308", "-1e308", "1.7976931348623157e308", "1e400", "-1e400",
           "1e-320", "5e-324", "0", "-0", "-1", "-2.5e-10", "1e-300", "1e300", "2147483648", "-2147483649",
           "9223372036854775808", "0x10", "1e", "", "abc", "NULL", "*", "1,5", "3.0.1", "+-1"]
MODELS = ["hertz", "jkr/fixed-grip", "jkr/load-controlled", "maugis"]
WALLSTYLES = ["xplane", "yplane", "zplane", "zcylinder"]

# the system of every input case: two types, pairs overlapping, approaching and
# sliding, atom 5 between atom 1 and the plane x = -3e-6 (the walls' base)
SETUP = [
    "units si", "atom_style sphere", "atom_modify map array", "boundary f f f", "comm_modify vel yes",
    "region box block -1e-5 1e-5 -1e-5 1e-5 -1e-5 1e-5", "create_box 2 box",
    "create_atoms 1 single 0 0 0", "create_atoms 2 single 1.99e-6 0 0",
    "create_atoms 1 single 0 3e-6 0", "create_atoms 2 single 2.005e-6 3e-6 0",
    "create_atoms 1 single -1.9995e-6 0 0", "create_atoms 2 single 0 -4e-6 0",
    "set atom * diameter 2e-6 density 2650", "set atom 1 vy 0.05", "set atom 3 vx 0.3",
    "set atom 4 vx -0.3 vz 0.1", "set atom 5 vx -0.2", "set atom 2 omega 0 0 1e4",
    "neighbor 3e-7 bin", "neigh_modify every 1 delay 0 check yes", "fix integrate all nve/sphere",
    "timestep 1e-10",
]
RUN = "run 60"


def number(rng, good):
    """`good` (a valid value), or a hostile token at the case's rate `rng.rate`."""
    return rng.choice(HOSTILE) if rng.random() < rng.rate else good


def keywords(rng, wall):
    """Zero or more keywords with their values, possibly duplicated, truncated,
    extended or unknown."""
    pool = [
        lambda: ["poisson", number(rng, "0.17")],
        lambda: ["damping", number(rng, "1e-10")],
        lambda: ["damping", rng.choice(["viscoelastic", "tsuji", "coeff_restitution", "velocity", "bogus"]),
                 number(rng, "0.8")],
        lambda: ["tangential", rng.choice(["mindlin", "mindlin_rescale", "mindlin_deresiewicz", "linear_history",
                                           "linear_nohistory"]),
                 rng.choice(["NULL", number(rng, "2e4")]), number(rng, "0.5"), number(rng, "0.3")],
        lambda: ["rolling", rng.choice(["sds", "none"]), number(rng, "50"), number(rng, "0"), number(rng, "0.1")],
        lambda: ["twisting", "marshall"],
        lambda: ["twisting", "sds", number(rng, "1e-12"), number(rng, "0"), number(rng, "0.05")],
        lambda: [rng.choice(["range", "stress"]), number(rng, "3e-10" if rng.random() < 0.5 else "1.6e8")],
        lambda: ["wall_material", number(rng, "200e9"), number(rng, "0.3"), number(rng, "0.01")],
        lambda: [rng.choice(["bogus", "cutoff", "limit_damping", "material", "heat"]), number(rng, "1")],
    ]
    out = []
    for _ in range(rng.choice([0, 1, 2, 3, 4])):
        kw = rng.choice(pool)()
        r = rng.random()
        if r < 0.1:
            kw = kw[:rng.randrange(len(kw))]                  # missing values
        elif r < 0.2:
            kw = kw + [number(rng, "1")]                       # an extra value
        elif r < 0.27:
            kw = kw * rng.choice([2, 3])                       # duplicated
        out += kw
    if rng.random() < 0.04:
        out += ["twisting", "marshall"] * rng.choice([1000, 20000])   # a huge count
    return out


def coherent(rng, wall, model, material, lam):
    """Keywords that fit together (so that, without hostile numbers, the line runs)."""
    out = []
    tangential = rng.random() < 0.6
    if tangential:
        t = rng.choice(["mindlin", "mindlin_rescale", "mindlin_deresiewicz", "linear_history"])
        k = "NULL" if t != "linear_history" and rng.random() < 0.6 else number(rng, "2e4")
        out += ["tangential", t, k, number(rng, "0.5"), number(rng, "0.3")]
        if k == "NULL" and not material:
            out += ["poisson", number(rng, "0.17")]
        if rng.random() < 0.5:
            out += ["rolling", "sds", number(rng, "50"), number(rng, "0"), number(rng, "0.1")]
        if rng.random() < 0.5:
            out += rng.choice([["twisting", "marshall"],
                               ["twisting", "sds", number(rng, "1e-12"), number(rng, "0"), number(rng, "0.05")]])
    if rng.random() < 0.5:
        out += rng.choice([["damping", number(rng, "1e-10")], ["damping", "viscoelastic", number(rng, "1e15")],
                           ["damping", rng.choice(["tsuji", "coeff_restitution"]), number(rng, "0.8")]])
    if model == "maugis" and not lam:
        out += rng.choice([["range", number(rng, "3e-10")], ["stress", number(rng, "1.6e8")]])
    if wall and material and rng.random() < 0.4:
        out += ["wall_material", number(rng, "200e9"), number(rng, "0.3"),
                number(rng, "0" if model == "hertz" else "0.01")]
    return out


def coefficients(rng, wall=False):
    """MODEL ARGS [KEYWORDS] in the E*/w or the material form: coherent keywords
    (with the case's rate of hostile numbers, and one structural mutation at most)
    or keywords drawn at random."""
    model = rng.choice(MODELS) if rng.random() < 0.95 else rng.choice(["dmt", "jkr", "material", "", "HERTZ"])
    material = rng.random() < 0.4
    args = []
    if material:
        args += ["material", number(rng, "54e9"), number(rng, "0.17"),
                 number(rng, "0" if model == "hertz" else "0.025"), model]
    else:
        args += [model, number(rng, "2.78e10")]
        if model != "hertz":
            args.append(number(rng, "0.05"))
    lam = model == "maugis" and rng.random() < 0.5
    if lam:
        args.append(number(rng, rng.choice(["0.5", "2.0", "0.05"])))
    if rng.random() < 0.6:
        args += coherent(rng, wall, model, material, lam)
        if rng.random() < 0.3:
            r = rng.random()
            if r < 0.3 and len(args) > 1:
                del args[rng.randrange(1, len(args))]                       # one argument lost
            elif r < 0.6:
                at = rng.randrange(1, len(args) + 1)
                args[at:at] = [rng.choice(["bogus", "1", "NULL", "twisting", "marshall"])]   # one too many
            else:
                args += coherent(rng, wall, model, material, lam)          # keywords given twice
    else:
        args += keywords(rng, wall)
    return args


def types(rng):
    good = rng.choice(["* *", "* *", "1 1", "2 2", "1 2", "1*2 2", "* 2"])
    if rng.random() < 0.05:
        return rng.choice(["0 1", "3 3", "1 3", "-1 *", "2147483648 1", "1*100 *", "* 0", "a b", "2*1 1"])
    return good


def pair_case(rng):
    lines = ["pair_style tabor" if rng.random() < 0.97 else rng.choice(["pair_style tabor 1", "pair_style tabor x"])]
    for _ in range(rng.choice([1, 1, 2, 3])):
        lines.append(f"pair_coeff {types(rng)} " + " ".join(coefficients(rng)))
    if rng.random() < 0.3:   # types 1 and 2 of two materials, mixed, or each line alone
        lines += [f"pair_coeff {t} {t} " + " ".join(coefficients(rng)) for t in (1, 2)]
    return lines


def wall_case(rng):
    lines = ["pair_style tabor", "pair_coeff * * jkr/load-controlled 2.78e10 0.05"]
    if rng.random() < 0.25:
        lo = [number(rng, "-3e-6") for _ in range(6)]
        lines.append(f"region cell block {' '.join(lo[:2])} -9e-6 9e-6 -9e-6 9e-6")
        tail = ["cell"] + (["contacts"] if rng.random() < 0.5 else [])
        lines.append("fix w all wall/tabor/region " + " ".join(coefficients(rng, wall=True) + tail))
        return lines
    style = rng.choice(WALLSTYLES)
    if style == "zcylinder":
        geometry = [style, number(rng, "9e-6")]
    else:
        geometry = [style, rng.choice(["NULL", number(rng, "-3e-6")]), rng.choice(["NULL", number(rng, "3e-6")])]
        if style != "xplane":
            geometry[1:] = [number(rng, "-9e-6"), number(rng, "9e-6")]
    extra = []
    for _ in range(rng.choice([0, 0, 1, 2])):
        extra += rng.choice([["wiggle", rng.choice(["x", "y", "z", "w"]), number(rng, "1e-8"), number(rng, "1e-9")],
                             ["shear", rng.choice(["x", "y", "z"]), number(rng, "0.01")], ["contacts"],
                             ["bogus"]])
    lines.append("fix w all wall/tabor " + " ".join(coefficients(rng, wall=True) + geometry + extra))
    return lines


def input_case(k):
    rng = random.Random(f"{SEED}:input:{k}")
    # how hostile the numbers of this case are: none (only the structure varies) to 40 %
    rng.rate = rng.choice([0.0, 0.0, 0.03, 0.1, 0.4])
    return {"kind": "input", "id": k, "lines": wall_case(rng) if rng.random() < 0.35 else pair_case(rng)}


# ---- restart files: written once, corrupted per case
BASE_PAIR = ["pair_style tabor",
             "pair_coeff * * material 54e9 0.17 0.025 jkr/load-controlled tangential mindlin NULL 0.3 0.3 "
             "rolling sds 50 0 0.1 twisting marshall"]
BASE_WALL = ["fix w all wall/tabor jkr/load-controlled 2.78e10 0.05 poisson 0.17 tangential mindlin NULL 0 0.3 "
             "xplane -2.999e-6 NULL contacts"]
READ_TAIL = ["comm_modify vel yes", "neighbor 3e-7 bin", "neigh_modify every 1 delay 0 check yes",
             *BASE_PAIR, *BASE_WALL, "fix integrate all nve/sphere", "timestep 1e-10", RUN]
DOUBLES = [math.nan, -math.nan, math.inf, -math.inf, 1e308, -1e308, 5e-324, 0.0, -0.0, -1.0, 0.5, 2.0 ** 31,
           2.0 ** 53, 1e9, 3.0, 10.0, 79.0]


def atom_buffers(data):
    """[offset of each atom buffer]: the buffers [m, 16 fields of atom_style sphere,
    fix records] of the per-atom section, found by walking their lengths from the
    first radius 1e-6 (field 11); None unless there are the 6 atoms of SETUP."""
    starts, at = lammps_case.atom_buffers(data, R, 1e4)
    return starts if len(starts) == 6 and at <= len(data) else None


def record_doubles(data, starts):
    """The byte offsets of every double of the plugin's per-atom records (fix
    wall/tabor, fix tabor/history), walked by their own lengths."""
    out = []
    for a in starts:
        m = int(struct.unpack_from("<d", data, a)[0])
        k = FIELDS
        while k < m:
            n = int(struct.unpack_from("<d", data, a + 8 * k)[0])
            out += [a + 8 * (k + j) for j in range(n)]
            k += n
    return out


def corrupt(data, starts, k):
    """Case k's corruption of the restart file `data`: (what, corrupted bytes)."""
    rng = random.Random(f"{SEED}:restart:{k}")
    bad = bytearray(data)
    records = record_doubles(data, starts)
    mode = k % 3
    if mode == 0:     # a hostile double, or random bits, in a plugin record
        at = rng.choice(records)
        value = struct.pack("<d", rng.choice(DOUBLES)) if rng.random() < 0.7 else rng.randbytes(8)
        bad[at:at + 8] = value
        what = f"record double at byte {at} := {struct.unpack('<d', value)[0]!r}"
    elif mode == 1:   # random bytes in the records
        spots = sorted(rng.choice(records) + rng.randrange(8) for _ in range(rng.choice([1, 2, 4, 16])))
        for at in spots:
            bad[at] = rng.randrange(256)
        what = f"random bytes in records at {spots[:4]}{'...' if len(spots) > 4 else ''}"
    else:             # a hostile double anywhere in the per-atom section (atom fields too)
        # but the length that opens each atom's buffer: LAMMPS's read_restart uses it
        # unchecked and crashes on a corrupted one whatever the pair style (pair
        # granular alike: a segfault at 2^31, 1e9, inf or 1e308)
        end = starts[-1] + 8 * int(struct.unpack_from("<d", data, starts[-1])[0])
        at = starts[0]
        while at in starts:
            at = starts[0] + 8 * rng.randrange((end - starts[0]) // 8)
        value = rng.choice(DOUBLES)
        bad[at:at + 8] = struct.pack("<d", value)
        what = f"per-atom double at byte {at} := {value!r}"
    return what, bytes(bad)


# ---- regressions: each crash or `ERROR on proc` the generator found, fixed in the
# plugin, as a fixed case with the words its clean refusal must hold
REGRESSION_INPUTS = [
    ("a tangential stiffness whose force overflows (was error->one in the run)",
     ["pair_style tabor", "pair_coeff * * jkr/load-controlled 1e308 0.05 tangential mindlin "
      "1.7976931348623157e308 0.5 0.3"], ["pair_coeff: the friction model", "k_t = 1.7976931348623157e+308"]),
    ("an atom's centre on the wall at the start (was error->one)",
     ["pair_style tabor", "pair_coeff * * jkr/load-controlled 2.78e10 0.05",
      "fix w all wall/tabor jkr/load-controlled 2.78e10 0.05 xplane NULL 0"], ["centre of atom", "lies on the wall"]),
]


def wall_contact(data, starts):
    """The offset of the wall record of the first atom with a wall contact
    (record 0, 14 values: length, width 10, 1 contact, wall index, 10 doubles)."""
    for a in starts:
        if struct.unpack_from("<d", data, a + 8 * FIELDS)[0] == 14.0:
            return a + 8 * FIELDS
    raise AssertionError("no atom of the restart file touches the wall")


REGRESSION_RESTARTS = [  # (what, offset(data, starts), value, words)
    ("the wall record's length 2^53 before the history record (was a read out of bounds, a segfault)",
     wall_contact, 2.0 ** 53, ["the restart record of atom", "corrupted restart file"]),
    ("the wall record's length inf", wall_contact, math.inf, ["the restart record of atom"]),
    ("a wall contact flag of 10 (was error->one in the run)", lambda d, st: wall_contact(d, st) + 32, 10.0,
     ["fix wall/tabor: the restart record of atom", "contact flag 10"]),
    ("an atom type of 1e308's bits (was a read out of bounds)", lambda d, st: st[0] + 5 * 8, 1e308,
     ["pair tabor: atom", "has type"]),
    ("a NaN velocity (was error->one in the run)", lambda d, st: st[1] + 9 * 8, math.nan,
     ["pair tabor: atom", "has velocity (", "nan"]),
    ("a radius of 5e-324 (its spin became NaN)", lambda d, st: st[0] + 11 * 8, 5e-324,
     ["pair tabor: atom", "moment of inertia"]),
]


def regressions(dog, data, starts, tmp):
    failures = []
    cases = [({"kind": "input", "id": f"r{k}", "lines": lines}, label, words)
             for k, (label, lines, words) in enumerate(REGRESSION_INPUTS)]
    for k, (label, where, value, words) in enumerate(REGRESSION_RESTARTS):
        bad = bytearray(data)
        at = where(data, starts)
        bad[at:at + 8] = struct.pack("<d", value)
        path = os.path.join(tmp, f"regression{k}.restart")
        with open(path, "wb") as f:
            f.write(bad)
        cases.append(({"kind": "restart", "id": f"r{len(cases)}", "file": path, "what": label}, label, words))
    for case, label, words in cases:
        outcome, detail = dog.run(case)
        print(f"  regression: {label}: {outcome} {detail[:110]}")
        if outcome != "refused" or not all(w in detail for w in words):
            failures.append(f"regression {label}: {outcome} {detail} (expected a refusal saying {words})")
    return failures


# ---- the worker: runs cases in one LAMMPS instance, reports each on stdout
def finite_state(lmp):
    n = lmp.get_natoms()
    for name, width in (("x", 3), ("v", 3), ("f", 3), ("omega", 3), ("torque", 3)):
        values = lmp.gather_atoms(name, 1, width)
        bad = [values[i] for i in range(n * width) if not math.isfinite(values[i])]
        if bad:
            return f"non-finite {name} after the run: {bad[:3]}"
    return None


def run_case(lmp, case, workdir):
    """Returns (outcome, detail): ran | refused | abort | unclean | nonfinite."""
    from lammps import MPIAbortException
    lmp.command("clear")
    if case["kind"] == "input":
        lines = SETUP + case["lines"] + [RUN]
    else:
        lines = [f"read_restart {case['file']}", *READ_TAIL]
    for line in lines:
        try:
            lmp.command(line)
        except MPIAbortException as e:
            return "abort", str(e)
        except Exception as e:  # noqa: BLE001 (LAMMPS raises a plain Exception for error->all)
            text = str(e)
            errors = [x for x in text.splitlines() if x.startswith("ERROR")]
            if text.startswith("ERROR: ") and len(errors) == 1:
                return "refused", errors[0][:400]
            return "unclean", text[:300]
    bad = finite_state(lmp)
    return ("nonfinite", bad) if bad else ("ran", "")


def worker():
    lmp = lmp_new()
    lmp.command(f"plugin load {PLUGIN}")
    for text in sys.stdin:
        case = json.loads(text)
        if case["kind"] == "prepare":
            lmp.command("clear")
            lmp.commands_list(SETUP + BASE_PAIR + BASE_WALL + [RUN, f"write_restart {case['file']}"])
            outcome, detail = "ran", ""
        else:
            print(json.dumps({"begin": case["id"]}), flush=True)
            outcome, detail = run_case(lmp, case, os.path.dirname(case.get("file", ".")))
        print(json.dumps({"id": case["id"], "outcome": outcome, "detail": detail}), flush=True)
        if outcome == "abort":
            return   # an aborted instance is not reused: the watchdog starts another



# ---- the watchdog: feeds the cases to a worker, restarts it after a crash or hang
class Watchdog:
    def __init__(self):
        self.proc = None
        self.buffer = b""

    def start(self):
        self.proc = subprocess.Popen([sys.executable, os.path.abspath(__file__), "--worker"], stdin=subprocess.PIPE,
                                     stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, bufsize=1)
        self.buffer = b""

    def stop(self):
        if self.proc and self.proc.poll() is None:
            self.proc.kill()
        if self.proc:
            self.proc.wait()
        self.proc = None

    def line(self, deadline):
        """The worker's next line, or None at EOF (a crash) or past `deadline` (read
        from the pipe's descriptor: a buffered reader would hide lines from select)."""
        fd = self.proc.stdout.fileno()
        while b"\n" not in self.buffer:
            left = deadline - time.monotonic()
            if left <= 0:
                return None
            ready, _, _ = select.select([fd], [], [], left)
            if ready:
                chunk = os.read(fd, 1 << 16)
                if not chunk:
                    return None
                self.buffer += chunk
        text, self.buffer = self.buffer.split(b"\n", 1)
        return json.loads(text)

    def run(self, case):
        """(outcome, detail) of one case: also crash (the worker died) or hang."""
        if self.proc is None or self.proc.poll() is not None:
            self.stop()
            self.start()
        try:
            self.proc.stdin.write(json.dumps(case) + "\n")
            self.proc.stdin.flush()
        except BrokenPipeError:
            self.stop()
            return "crash", "the worker died before the case"
        deadline = time.monotonic() + TIME_LIMIT
        while True:
            reply = self.line(deadline)
            if reply is None:
                timed_out = time.monotonic() >= deadline
                self.stop()
                return ("hang", f"no answer in {TIME_LIMIT:.0f} s") if timed_out else \
                    ("crash", "the LAMMPS process died (segfault or abort)")
            if "outcome" in reply:
                if reply["outcome"] == "abort":
                    self.stop()
                return reply["outcome"], reply["detail"]


def main():
    t0 = time.monotonic()
    dog = Watchdog()
    counts, failures = {}, []

    def record(label, case, outcome, detail):
        counts.setdefault(label, {}).setdefault(outcome, 0)
        counts[label][outcome] += 1
        if outcome not in ("ran", "refused"):
            shown = case["lines"] if case["kind"] == "input" else case["what"]
            failures.append(f"{label} case {case['id']} ({outcome}): {detail}\n      {shown}")

    try:
        for k in range(CASES):
            case = input_case(k)
            outcome, detail = dog.run(case)
            record("input lines", case, outcome, detail)
        with tempfile.TemporaryDirectory() as tmp:
            base = os.path.join(tmp, "base.restart")
            outcome, detail = dog.run({"kind": "prepare", "id": -1, "file": base})
            data = open(base, "rb").read() if outcome == "ran" else b""
            starts = atom_buffers(data) if data else None
            if not starts or not record_doubles(data, starts):
                failures.append(f"restart: the base file was not written or its per-atom section not found "
                                f"({outcome} {detail})")
            else:
                intact = dog.run({"kind": "restart", "id": -1, "file": base, "what": "intact"})
                if intact[0] != "ran":
                    failures.append(f"restart: the intact file does not run: {intact}")
                failures += regressions(dog, data, starts, tmp)
                for k in range(RESTARTS):
                    what, bad = corrupt(data, starts, k)
                    path = os.path.join(tmp, f"case{k}.restart")
                    with open(path, "wb") as f:
                        f.write(bad)
                    case = {"kind": "restart", "id": k, "file": path, "what": what}
                    outcome, detail = dog.run(case)
                    record("corrupted restarts", case, outcome, detail)
                    os.unlink(path)
    finally:
        dog.stop()
    for label, c in counts.items():
        print(f"  {label}: {sum(c.values())} cases, " + ", ".join(f"{n} {o}" for o, n in sorted(c.items())))
    print(f"  seed {SEED}, {time.monotonic() - t0:.1f} s")
    return report(failures, "hostile LAMMPS input: every case ran cleanly or was refused with one ERROR line")


if __name__ == "__main__":
    if sys.argv[1:] == ["--worker"]:
        worker()
    else:
        sys.exit(main())
