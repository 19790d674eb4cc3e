"""The keys and types of the results (the ``TypedDict`` of each function).

For a scalar call each value is a Python ``float`` / ``bool`` / ``int`` / ``str`` /
``None``; for array input an array of the broadcast shape (float64, bool, int64, or
an object array of ``str``/``None``). The keys do not depend on the values: empty
input gives empty columns with every key. A test checks these tables against the
records the library returns, so they cannot go stale.
"""

from __future__ import annotations

from typing import Dict

# The kind of each key: "float" (NaN where absent), "int" (-1 where absent),
# "bool", "str" (None where absent), "object" (None where absent). A key marked
# "+speed" is present only when the call gives a speed.

EFFECTIVE: Dict[str, str] = {
    "effective_modulus": "float",
    "effective_radius": "float",
    "effective_mass": "float",
}

JKR: Dict[str, str] = {
    "model": "str",
    "branch": "str",
    "separation": "str",
    "energy_loss": "float",
    "energy_loss_error": "float",
    "sticking_velocity": "float",
    "separation_force": "float",
    "separation_contact_radius": "float",
    "first_touch_contact_radius": "float",
    "impact_speed": "float+speed",
    "max_contact_radius": "float+speed",
    "restitution": "float+speed",
    "sticks": "bool+speed",
    "evaluations": "int",
}

PLASTIC: Dict[str, str] = {
    "model": "str",
    "branch": "str",
    "impact_speed": "float",
    "restitution": "float",
    "energy_loss": "float",
    "sticks": "bool",
    "yield_velocity": "float",
    "sticking_velocity": "float",
    "elastic_sticking_velocity": "float",
    "adhesion_parameter": "float",
    "clamping": "str",
    "warnings": "object",
}

VISCO: Dict[str, str] = {
    "model": "str",
    "restitution": "float",
    "contact_time": "float",
    "max_overlap": "float",
    "equivalent_kelvin_voigt_damping_ratio": "float",
    "equivalent_kelvin_voigt_restitution": "float",
    "first_order_restitution": "float",
    "evaluations": "int",
}

PENALTY: Dict[str, str] = {
    "law": "str",
    "nominal_restitution": "float",
    "achieved_restitution": "float",
    "closed_form_restitution": "float",
    "stiffness": "float",
    "exponent": "float",
    "effective_mass": "float",
    "impact_speed": "float",
    "damping_factor": "float",
    "damping_coefficient": "float",
    "exact_damping_factor": "float",
    "loss_speed": "float",
    "rounding": "float",
    "max_overlap": "float",
    "max_force": "float",
    "contact_time": "float",
    "energy_error": "float",
}

EFFECTS = ("elasticity", "adhesion", "plasticity", "viscoelasticity", "damping")

SWEEP: Dict[str, str] = {
    "scene": "str",
    "impact_speed": "float",
    "restitution": "float",
    "sticks": "bool",
    "sticking_velocity": "float",
    "energy_loss": "float",
    "kinetic_energy": "float",
    "model": "str",
    "branch": "str",
    "combination.rule": "str",
    "combination.effects": "object",
    "combination.source": "str",
    "tabor_parameter": "float",
    **{f"effects.{e}.{k}": kind for e in EFFECTS
       for k, kind in (("used", "bool"), ("reason", "str"), ("reason_values", "floats"), ("model", "str"),
                       ("energy_loss", "float"))},
    "accuracy": "float",
    "energy_loss_error": "float",
    "cost.evaluations": "int",
    "cost.iterations": "int",
    "warnings": "object",
}


def keys(schema: Dict[str, str], speed: bool = True) -> Dict[str, str]:
    """The schema of a call: ``+speed`` keys only when a speed is given."""
    out = {}
    for k, kind in schema.items():
        base, _, need = kind.partition("+")
        if need == "speed" and not speed:
            continue
        out[k] = base
    return out
