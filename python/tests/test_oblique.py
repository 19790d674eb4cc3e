"""The oblique impact from Python (`Scene.outcome(speed, angle=...)`): LAMMPS's
limit of the reference case, the round trip against `tabor impact --angle --json`
for a flat and a pair, spins in any direction, twisting, fixed grip, and
Mindlin-Deresiewicz micro-slip against an independent integration written here."""

import math

import numpy as np
import pytest

import tabor
from conftest import SCENES

SILICA = """
name = "silica"
[sphere]
radius = 1e-6
density = 2650
youngs_modulus = 54e9
poisson_ratio = 0.17
[target]
{target}
youngs_modulus = 54e9
poisson_ratio = 0.17
[adhesion]
work_of_adhesion = 0.05
separation = "{rule}"
[friction]
coefficient = 0.3
tangential = "{tangential}"
rolling = {{ stiffness = 50.0, damping = 0.0, coefficient = 0.1 }}
twisting = {twisting}
[impact]
speed = 0.3
sphere_spin = {spin}
"""

PAIR = "radius = 1e-6\ndensity = 2650"


def scene(target=PAIR, rule="load-controlled", tangential="mindlin", twisting='"marshall"',
          spin=(0.0, 0.0, 0.0)):
    return tabor.Scene.from_toml(SILICA.format(target=target, rule=rule, tangential=tangential,
                                               twisting=twisting, spin=list(spin)))


def test_lammps_reference_case():
    """LAMMPS's `pair granular` (jkr + mindlin + sds + marshall, 10 degrees, 0.3 m/s)
    extrapolated to dt -> 0 from four time steps (tabor-tangential's
    tests/lammps_reference.rs gives the runs): the sphere's CoM-frame velocity and
    spin, within three times the extrapolation's error plus the scene's
    integration error (1e-9 of the speed and spin scales)."""
    o = tabor.Scene.from_path(SCENES / "silica_oblique.toml").outcome(0.3, angle=10.0)
    for key in ("normal_restitution", "tangential_restitution", "rebound_angle",
                "energy_lost_by_mechanism", "after"):
        assert key in o
    v = o["after"]["sphere"]["velocity"]
    w = o["after"]["sphere"]["angular_velocity"]
    speed_tol, spin_tol = 3 * 1.1e-10 + 1e-9 * 0.3, 3 * 2.7e-4 + 1e-9 * 0.3 / 1e-6
    assert abs(v[0] + 0.14455059915576807) < speed_tol, v
    assert abs(v[1] - 0.01749231278134705) < speed_tol, v
    assert abs(w[2] + 21453.23668880072) < spin_tol, w
    # angle 0 without friction is today's outcome
    plain = tabor.Scene.from_path(SCENES / "silica.toml")
    assert plain.outcome(angle=0.0) == plain.outcome()


CASES = {
    "pair, spin about z": dict(spin=(0.0, 0.0, 2e5)),
    "pair, spin in any direction": dict(spin=(1e5, -2e5, 3e4)),
    "flat, spin about the normal (twisting)": dict(target="", spin=(3e5, 0.0, 0.0)),
    "fixed grip, twisting sds": dict(rule="fixed-grip",
                                     twisting="{ stiffness = 1e-9, damping = 0.0, coefficient = 1e-7 }"),
    "micro-slip on a flat": dict(target="", tangential="mindlin_deresiewicz", spin=(0.0, 1e5, 0.0)),
}


@pytest.mark.parametrize("case", CASES, ids=list(CASES))
def test_round_trip_against_the_cli(case, cli, tmp_path):
    """Python's answer is the CLI's, key by key, for a flat and a pair, spins in any
    direction, both twisting models, both separation rules and micro-slip."""
    kwargs = CASES[case]
    s = scene(**kwargs)
    path = tmp_path / "scene.toml"
    path.write_text(SILICA.format(**{**dict(target=PAIR, rule="load-controlled", tangential="mindlin",
                                              twisting='"marshall"', spin=[0.0, 0.0, 0.0]),
                                     **{k: (list(v) if k == "spin" else v) for k, v in kwargs.items()}}))
    for angle in (10.0, 50.0):
        py = s.outcome(0.3, angle=angle)
        ref = cli("impact", str(path), "--speed", "0.3", "--angle", repr(angle), "--json")
        ref.pop("tabor_version")
        for key in ("normal_restitution", "tangential_restitution", "rebound_angle"):
            if ref[key] is None:
                assert py[key] is None, key
            else:
                assert py[key] == pytest.approx(ref[key], rel=1e-12), key
        for body in ("sphere", "target"):
            for q in ("velocity", "angular_velocity"):
                assert py["after"][body][q] == pytest.approx(ref["after"][body][q], rel=1e-12, abs=1e-300)
        assert py["energy_lost_by_mechanism"] == pytest.approx(ref["energy_lost_by_mechanism"], rel=1e-12)
        assert py["oblique"]["energy_error"] < 1e-6


def reference_beta(psi, cells, steps):
    """Maw, Barber & Fawcett's steel sphere on a steel flat (nu = 0.3, mu = 0.3)
    integrated independently: a uniform bed of springs in x (midpoints), each
    incremented by the contact point's slip of the step and capped at its Coulomb
    limit mu E* (a^2 - x^2)/(R k'), released outside the contact; symplectic Euler
    with `steps` steps per Hertz contact time (first order in the step)."""
    r, rho, e, nu, mu = 1e-3, 7800.0, 200e9, 0.3, 0.3
    e_star = e / (2 * (1 - nu * nu))
    g_star = 1 / (2 * 2 * (2 - nu) * (1 + nu) / e)
    kappa = 4 * g_star / e_star
    alpha = math.atan(psi * mu / kappa)
    m = 4 / 3 * math.pi * rho * r ** 3
    chi = 3.5
    k_line = 4 * g_star
    vn, c = math.cos(alpha), math.sin(alpha)
    c0 = c
    stiff = 4 / 3 * e_star * math.sqrt(r)
    d_max = (1.25 * m * vn * vn / stiff) ** 0.4
    dt = 2.9432 * d_max / vn / steps
    dx = 1.2 * math.sqrt(r * d_max) / cells
    x2 = ((np.arange(cells) + 0.5) * dx) ** 2
    w = np.zeros(cells)
    d = 0.0
    while True:
        d += vn * dt
        if d <= 0:
            break
        inside = x2 < r * d
        cap = np.where(inside, mu * e_star * (r * d - x2) / (r * k_line), 0.0)
        w = np.clip(np.where(inside, w + c * dt, 0.0), -cap, cap)
        f_t = -2 * k_line * w.sum() * dx
        vn -= stiff * d ** 1.5 / m * dt
        c += chi * f_t / m * dt
    return -c / c0


@pytest.mark.parametrize("psi", [0.3, 2.0])
def test_micro_slip_against_an_independent_integration(psi):
    """`tangential = "mindlin_deresiewicz"` (examples/scenes/steel_micro_slip.toml at
    MBF's Psi) against `reference_beta`, extrapolated in the step, within twice its
    own error plus the library's micro-slip error (2e-5 at 1024 nodes)."""
    s = tabor.Scene.from_path(SCENES / "steel_micro_slip.toml")
    g_star = 1 / (2 * 2 * (2 - 0.3) * (1 + 0.3) / 200e9)
    kappa = 4 * g_star / (200e9 / (2 * (1 - 0.09)))
    angle = math.degrees(math.atan(psi * 0.3 / kappa))
    o = s.outcome(1.0, angle=angle)
    assert o["energy_lost_by_mechanism"]["micro_slip"] > 0
    coarse, fine = reference_beta(psi, 600, 3000), reference_beta(psi, 1200, 6000)
    expected, own = 2 * fine - coarse, abs(fine - coarse)
    assert abs(o["tangential_restitution"] - expected) < 2 * own + 2e-5, (o["tangential_restitution"], expected, own)
