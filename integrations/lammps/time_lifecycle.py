"""The per-step cost of pair_style tabor's lifecycle checks (issue 33), measured
by LAMMPS's own timer breakdown against a build without them.

The checks: fix tabor/history's creation stamps (every history lookup compares
the partner's stamp, a record of another stamp dies) and, after each neighbor
list build, the forward communication of the stamps to the ghosts and the
dropping of records whose partner is gone. The build without them is the
plugin's source copied and patched here (the stamp comparison and the two calls
after a neighbor build removed; each patch must find its anchor text), built
with the CMake configuration of the regular build (target/lammps-plugin).

The cloud of test_plugin_cloud.py (TIMING_GRAINS, default 10^4 grains, JKR +
mindlin + sds + marshall), TIMING_STEPS steps, run alternately with both builds
TIMING_REPEATS times, without neighbor list builds (the cloud's default) and
with one every 10 steps (`neigh_modify every 10 delay 0 check no`); the fastest
"Pair" and loop times of each, and the ratios with/without. No assertion:
wall-clock times depend on the machine (measured: see the README table).

Needs TABOR_PLUGIN, LAMMPS_VENV, CMAKE (time_lifecycle.sh sets them).
"""

import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import test_plugin_cloud as cloud  # noqa: E402

PLUGIN = os.environ["TABOR_PLUGIN"]
GRAINS = int(os.environ.get("TIMING_GRAINS", "10000"))
STEPS = int(os.environ.get("TIMING_STEPS", "1000"))
REPEATS = int(os.environ.get("TIMING_REPEATS", "5"))

PATCHES = {  # file: (anchor, replacement)
    "pair_tabor.cpp": ("    comm->forward_comm(fix_history);\n    fix_history->drop_orphans(inum, ilist, numneigh, "
                       "firstneigh);\n", ""),
    "fix_tabor_history.cpp": ("      if (ps[k] == st) return values + ((bigint) i * capacity + k) * dnum;\n"
                              "      // the record of a deleted atom whose ID came back: it dies here\n"
                              "      remove(i, k);\n      return nullptr;\n",
                              "      (void) ps;\n      (void) st;\n"
                              "      return values + ((bigint) i * capacity + k) * dnum;\n"),
}


def build_without(tmp):
    """The plugin without the lifecycle checks: its path."""
    src = os.path.join(tmp, "plugin")
    shutil.copytree(os.path.join(HERE, "plugin"), src)
    for name, (anchor, replacement) in PATCHES.items():
        path = os.path.join(src, name)
        text = open(path).read()
        assert text.count(anchor) == 1, f"{name}: the lifecycle code to remove is not found once"
        open(path, "w").write(text.replace(anchor, replacement))
    cache = os.path.join(os.path.dirname(PLUGIN), "CMakeCache.txt")
    keys = ("CMAKE_BUILD_TYPE", "CMAKE_CXX_COMPILER", "LAMMPS_PYTHON_DIR", "TABOR_FFI_LIB", "TABOR_FFI_INCLUDE",
            "TABOR_LAMMPS_VERSION")
    defs = [f"-D{line.split(':', 1)[0]}={line.split('=', 1)[1].strip()}"
            for line in open(cache) if line.split(":", 1)[0] in keys]
    build = os.path.join(tmp, "build")
    cmake = os.environ.get("CMAKE", "cmake")
    subprocess.run([cmake, "-S", src, "-B", build, *defs], check=True, capture_output=True)
    subprocess.run([cmake, "--build", build], check=True, capture_output=True)
    return os.path.join(build, "taborplugin.so")


def main():
    with tempfile.TemporaryDirectory(prefix="tabor-lifecycle-") as tmp:
        builds = {"with the checks": PLUGIN, "without": build_without(tmp)}
        data = os.path.join(tmp, "cloud.data")
        cloud.make_cloud(data, GRAINS)
        for label, extra in (("no neighbor list build", []),
                             ("a neighbor list build every 10 steps", ["neigh_modify every 10 delay 0 check no"])):
            best = {}
            for rep in range(REPEATS):
                for n, (name, plugin) in enumerate(builds.items()):
                    lines = [line.replace(PLUGIN, plugin) for line in cloud.setup_lines("tabor")]
                    log = cloud.lammps([*cloud.HEAD, f"read_data {data}", *lines, *extra, "thermo 0", f"run {STEPS}"],
                                       tmp, 1, f"t{rep}.{n}")
                    pair = next(float(s.split("|")[2]) for s in log.splitlines() if s.startswith("Pair "))
                    loop = next(float(s.split()[3]) for s in log.splitlines() if s.startswith("Loop time of"))
                    old = best.get(name)
                    best[name] = (min(pair, old[0]), min(loop, old[1])) if old else (pair, loop)
            a, b = best["with the checks"], best["without"]
            print(f"{GRAINS} grains, {STEPS} steps, {label}, fastest of {REPEATS}: pair {a[0]:.3f} s with the "
                  f"checks, {b[0]:.3f} s without: ratio {a[0] / b[0]:.3f}; loop ratio {a[1] / b[1]:.3f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
