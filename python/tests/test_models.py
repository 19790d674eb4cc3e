"""The single models (CLI subcommands) against closed forms and against the CLI's
own JSON output for the same flags."""

import math

import numpy as np
import pytest

import tabor
from conftest import assert_matches_cli


def test_effective_closed_forms():
    e, nu, r, rho = 54e9, 0.17, 1e-6, 2650.0
    out = tabor.effective(youngs_modulus=e, poisson_ratio=nu, radius=r, density=rho, target_radius=r)
    m = 4 / 3 * math.pi * r**3 * rho
    assert out["effective_modulus"] == pytest.approx(1 / (2 * (1 - nu**2) / e), rel=1e-14)
    assert out["effective_radius"] == pytest.approx(r / 2, rel=1e-14)
    assert out["effective_mass"] == pytest.approx(m / 2, rel=1e-14)
    half = tabor.effective(youngs_modulus=e, poisson_ratio=nu, radius=r, mass=m, rigid_target=True)
    assert half["effective_modulus"] == pytest.approx(e / (1 - nu**2), rel=1e-14)
    assert half["effective_radius"] == r and half["effective_mass"] == m


def test_jkr_closed_forms():
    e, r, w, m = 1e9, 1e-6, 0.05, 1e-14
    v = np.array([0.1, 0.5, 1.0, 3.0])
    out = tabor.jkr(contact_modulus=e, radius=r, work_of_adhesion=w, mass=m, speed=v)
    loss = (1 + 864 ** (1 / 3)) / 10 * (r**4 * (math.pi * w) ** 5 / e**2) ** (1 / 3)  # (5.36)
    v_c = math.sqrt(2 * loss / m)  # (5.38)
    np.testing.assert_allclose(out["energy_loss"], loss, rtol=1e-13)
    np.testing.assert_allclose(out["sticking_velocity"], v_c, rtol=1e-10)
    ref = np.sqrt(np.clip(1 - (v_c / v) ** 2, 0, None))  # (5.37)
    np.testing.assert_allclose(out["restitution"], ref, rtol=1e-10, atol=1e-12)
    np.testing.assert_array_equal(out["sticks"], v < v_c)
    # fixed grip separates at −(5/6)πΔγR, load control at −(3/2)πΔγR
    assert out["separation_force"][0] == pytest.approx(-5 / 6 * math.pi * w * r, rel=1e-12)
    lc = tabor.jkr(contact_modulus=e, radius=r, work_of_adhesion=w, mass=m, separation="load-controlled")
    assert lc["separation_force"] == pytest.approx(-1.5 * math.pi * w * r, rel=1e-12)
    assert "restitution" not in lc


def test_jkr_over_a_grid_of_speeds_and_masses():
    """The model is prepared once per distinct mass (consecutive or not) and each
    speed's fields computed on top: every element against (5.35)-(5.38) written out."""
    e, r, w = 1e9, 1e-6, 0.05
    m = np.array([1e-14, 3e-14, 1e-14, 3e-14, 2e-14])[:, None]  # repeats, not consecutive
    v = np.geomspace(0.01, 30.0, 41)[None, :]
    out = tabor.jkr(contact_modulus=e, radius=r, work_of_adhesion=w, mass=m, speed=v)
    assert out["restitution"].shape == (5, 41)
    loss = (1 + 864 ** (1 / 3)) / 10 * (r**4 * (math.pi * w) ** 5 / e**2) ** (1 / 3)  # (5.36)
    v_c = np.sqrt(2 * loss / m)  # (5.38)
    np.testing.assert_allclose(out["sticking_velocity"], np.broadcast_to(v_c, (5, 41)), rtol=1e-10)
    ref = np.sqrt(np.clip(1 - (v_c / v) ** 2, 0, None))  # (5.37)
    np.testing.assert_allclose(out["restitution"], ref, rtol=1e-10, atol=1e-12)
    np.testing.assert_array_equal(out["sticks"], v < v_c)
    np.testing.assert_array_equal(out["impact_speed"], np.broadcast_to(v, (5, 41)))
    # (5.35): m v²/2 = F_n d_n [(6/5) â⁵ − 4 â^(7/2) + 2 â² + (6/5)(4/3)^(4/3)], â = a/a_c
    a_c = (9 * math.pi * w * r**2 / (8 * e)) ** (1 / 3)
    energy = 1.5 * math.pi * w * r * a_c**2 / (3 * r)
    a = out["max_contact_radius"] / a_c
    offset = 1.2 * (4 / 3) ** (4 / 3)
    work = 1.2 * a**5 - 4 * a**3.5 + 2 * a**2 + offset
    kinetic = 0.5 * m * v**2 / energy
    assert np.all(np.abs(work - kinetic) / (kinetic + offset) < 1e-11)
    assert (out["model"] == out["model"][0, 0]).all() and (out["evaluations"] == 0).all()


def test_jkr_over_many_sorted_speeds():
    """Many chunks of one prepared model: the shared columns filled (object
    columns of one value, zero columns left zeroed), each speed's maximum contact
    radius warm-started from its neighbour's equal to the cold start of a scalar
    call to rounding, and every element against (5.35)-(5.38) written out."""
    e, r, w, m = 1e9, 1e-6, 0.05, 1e-14
    v = np.geomspace(0.01, 30.0, 20_000)
    out = tabor.jkr(contact_modulus=e, radius=r, work_of_adhesion=w, mass=m, speed=v)
    loss = (1 + 864 ** (1 / 3)) / 10 * (r**4 * (math.pi * w) ** 5 / e**2) ** (1 / 3)  # (5.36)
    v_c = math.sqrt(2 * loss / m)  # (5.38)
    ref = np.sqrt(np.clip(1 - (v_c / v) ** 2, 0, None))  # (5.37)
    np.testing.assert_allclose(out["restitution"], ref, rtol=1e-10, atol=1e-12)
    a_c = (9 * math.pi * w * r**2 / (8 * e)) ** (1 / 3)
    energy = 1.5 * math.pi * w * r * a_c**2 / (3 * r)
    a = out["max_contact_radius"] / a_c
    offset = 1.2 * (4 / 3) ** (4 / 3)
    kinetic = 0.5 * m * v**2 / energy
    work = 1.2 * a**5 - 4 * a**3.5 + 2 * a**2 + offset
    assert np.all(np.abs(work - kinetic) / (kinetic + offset) < 1e-11)
    for i in (0, 1, 4095, 4096, 4097, 12_345, 19_999):  # cold starts, one element each
        cold = tabor.jkr(contact_modulus=e, radius=r, work_of_adhesion=w, mass=m, speed=v[i])
        assert out["max_contact_radius"][i] == pytest.approx(cold["max_contact_radius"], rel=4 * np.finfo(float).eps)
        assert out["model"][i] == cold["model"] and out["branch"][i] == cold["branch"]
    assert out["model"].dtype == object and all(type(x) is str for x in out["model"][::997])
    assert (out["model"] == out["model"][0]).all() and (out["separation"] == "fixed-grip").all()
    assert (out["evaluations"] == 0).all() and (out["energy_loss_error"] == 0.0).all()
    assert (out["energy_loss"] == out["energy_loss"][0]).all()
    assert out["energy_loss"][0] == pytest.approx(loss, rel=1e-13)
    assert out["energy_loss"].flags.writeable and out["model"].flags.writeable


def test_jkr_over_speeds_with_invalid_points():
    e, r, w = 1e9, 1e-6, 0.05
    m = np.array([1e-14, -1.0, 1e-14])[:, None]
    v = np.array([[0.5, -2.0, 1.0]])
    with pytest.warns(tabor.InvalidPointsWarning, match=r"5 of 9 points invalid.*\(at index \(0, 1\)\)"):
        out = tabor.jkr(contact_modulus=e, radius=r, work_of_adhesion=w, mass=m, speed=v, errors="nan")
    valid = np.array([[True, False, True], [False] * 3, [True, False, True]])
    np.testing.assert_array_equal(out["valid"], valid)
    assert np.isnan(out["restitution"][~valid]).all() and (out["evaluations"][~valid] == -1).all()
    assert (out["model"][~valid] == None).all() and (out["model"][valid] != None).all()  # noqa: E711
    assert out["restitution"][2, 2] == tabor.jkr(contact_modulus=e, radius=r, work_of_adhesion=w, mass=1e-14,
                                                  speed=1.0)["restitution"]
    with pytest.raises(tabor.InputError, match=r"invalid speed = -2.*\(at index \(0, 1\)\)"):
        tabor.jkr(contact_modulus=e, radius=r, work_of_adhesion=w, mass=m, speed=v)


def test_jkr_matches_cli(cli):
    py = tabor.jkr(contact_modulus=1e9, radius=1e-6, work_of_adhesion=0.05, mass=1e-14, speed=0.7)
    ref = cli("jkr", "--modulus", "1e9", "--radius", "1e-6", "--work-of-adhesion", "0.05",
              "--mass", "1e-14", "--speed", "0.7", "--json")
    assert_matches_cli(py, ref)


@pytest.mark.parametrize(
    "kwargs, flags",
    [
        (dict(model="thornton"), ["--model", "thornton"]),
        (dict(model="interpolation"), ["--model", "interpolation"]),
        (dict(model="dimensionless-fit", density=7800.0), ["--model", "dimensionless-fit", "--density", "7800"]),
        (dict(model="adhesive-interpolation", work_of_adhesion=0.5),
         ["--model", "adhesive-interpolation", "--work-of-adhesion", "0.5"]),
        (dict(model="superposition", work_of_adhesion=0.5, plastic_model="thornton"),
         ["--model", "superposition", "--work-of-adhesion", "0.5", "--plastic-model", "thornton"]),
    ],
)
def test_plastic_matches_cli(cli, kwargs, flags):
    base = dict(contact_modulus=1e11, radius=1e-4, mass=1e-8, yield_stress=1e9, speed=1.0)
    py = tabor.plastic(**base, **kwargs)
    ref = cli("plastic", "--modulus", "1e11", "--radius", "1e-4", "--mass", "1e-8",
              "--yield-stress", "1e9", "--speed", "1", *flags, "--json")
    assert_matches_cli(py, ref)


@pytest.mark.parametrize(
    "kwargs, flags",
    [
        (dict(model="kelvin-voigt-flat", damping_ratio=0.2), ["--model", "kelvin-voigt-flat", "--damping-ratio", "0.2"]),
        (dict(model="kuwabara-kono", viscous_parameter=0.1), ["--model", "kuwabara-kono", "--viscous-parameter", "0.1"]),
        (dict(model="hunt-crossley", damping=0.3), ["--model", "hunt-crossley", "--damping", "0.3"]),
        (dict(model="standard-flat", modulus_ratio=2.0, viscous_parameter=0.5),
         ["--model", "standard-flat", "--modulus-ratio", "2", "--viscous-parameter", "0.5"]),
    ],
)
def test_visco_matches_cli(cli, kwargs, flags):
    py = tabor.visco(**kwargs)
    ref = cli("visco", *flags, "--json")
    assert_matches_cli(py, ref)


def test_kelvin_voigt_flat_small_damping():
    # a lightly damped linear oscillator: ε ≈ exp(−πD) to first order in D
    d = np.array([1e-4, 1e-3])
    e = tabor.visco(model="kelvin-voigt-flat", damping_ratio=d)["restitution"]
    np.testing.assert_allclose(np.log(e) / (-math.pi * d), 1.0, rtol=1e-2)


@pytest.mark.parametrize("law", ["hunt-crossley", "lankarani-nikravesh", "flores", "characteristic"])
def test_penalty(cli, law):
    py = tabor.penalty(law=law, restitution=0.8)
    ref = cli("penalty", "--law", law, "--restitution", "0.8", "--json")
    assert_matches_cli(py, ref)
    # the simulated impact achieves the law's closed-form restitution
    assert py["achieved_restitution"] == pytest.approx(py["closed_form_restitution"], rel=1e-6)


def test_penalty_broadcasts():
    out = tabor.penalty(law="hunt-crossley", restitution=[[0.5], [0.9]], speed=[1.0, 2.0, 3.0])
    assert out["achieved_restitution"].shape == (2, 3)
    assert out["law"].shape == (2, 3)
