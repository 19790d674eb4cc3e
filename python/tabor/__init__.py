"""tabor: adhesive impact of spheres, numpy in, numpy out.

Energy loss, coefficient of restitution and sticking velocity of central impacts of
two spheres (or a sphere on a half-space) with JKR, Maugis-Dugdale, elasto-plastic
and viscoelastic contact, computed by the Rust workspace ``tabor``. Equation numbers
refer to seed 000 (section 5.3, eqs. (5.33)-(5.126)).

Conventions (as ContactEngineering's ``Adhesion`` package): module-level functions,
keyword arguments, SI units unless a name says otherwise. Every numeric argument
broadcasts with numpy; array input gives float64 arrays of the broadcast shape,
scalar input gives a Python ``float``. Batches release the GIL and run in parallel.
Bad input raises ``ValueError`` naming the parameter and its value (and, for an
array, the index of the first bad element).

Functions
---------
maugis_dugdale_loss      W(Λ), the Maugis-Dugdale impact loss in units of F_n d_n
maugis_dugdale_curve     load and penetration over contact radius, Maugis' units
tabor_parameter_from_maugis, tabor_parameter_from_tabor_mu, maugis_parameter
                         conversions between Λ, Maugis' λ and Tabor's μ
Scene                    a collision described once (TOML/JSON scene file)
effective, jkr, plastic, visco, penalty
                         the single models of the CLI subcommands of the same names
"""

from __future__ import annotations

from typing import Any, Dict, Optional, Sequence, Tuple, Union

import numpy as np

from . import _tabor

__all__ = [
    "maugis_dugdale_loss",
    "maugis_dugdale_curve",
    "tabor_parameter_from_maugis",
    "tabor_parameter_from_tabor_mu",
    "maugis_parameter",
    "jkr_normalized_loss",
    "Scene",
    "effective",
    "jkr",
    "plastic",
    "visco",
    "penalty",
    "LAMBDA_PER_MAUGIS_PARAMETER",
    "MAUGIS_PER_TABOR_MU",
    "FAST_TIER_RELATIVE_ERROR",
]

#: The version of tabor (the Rust workspace) this package was built from.
__version__: str = _tabor.VERSION

#: Λ per Maugis' λ: Λ = π (9/4)^(1/3) / 6 · λ ≈ 0.6861 λ.
LAMBDA_PER_MAUGIS_PARAMETER: float = _tabor.LAMBDA_PER_MAUGIS_PARAMETER
#: Dugdale equivalence of Tabor's μ: λ ≈ 1.157 μ.
MAUGIS_PER_TABOR_MU: float = _tabor.MAUGIS_PER_TABOR_MU
#: Relative error bound of the fast tier of ``maugis_dugdale_loss`` (1e-10).
FAST_TIER_RELATIVE_ERROR: float = _tabor.FAST_TIER_RELATIVE_ERROR

ArrayLike = Union[float, Sequence[float], np.ndarray]


# --------------------------------------------------------------------------------
# broadcasting helpers


def _float_array(name: str, value: Any) -> np.ndarray:
    if value is None:
        raise ValueError(f"invalid {name} = None: a number or an array of numbers is required")
    try:
        a = np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError) as e:
        raise ValueError(f"invalid {name} = {value!r}: not a number or an array of numbers ({e})") from None
    return a


class _Batch:
    """Broadcasts named arguments; hands flat columns to the native core."""

    def __init__(self, optional: Tuple[str, ...] = (), **arguments: Any) -> None:
        arrays = {
            k: _float_array(k, v) for k, v in arguments.items() if not (v is None and k in optional)
        }
        try:
            self.shape: Tuple[int, ...] = np.broadcast_shapes(*(a.shape for a in arrays.values()))
        except ValueError:
            shapes = ", ".join(f"{k} {a.shape}" for k, a in arrays.items())
            raise ValueError(f"the arguments do not broadcast together: {shapes}") from None
        self.scalar = all(a.ndim == 0 for a in arrays.values())
        self.columns: Dict[str, Optional[np.ndarray]] = {k: None for k in arguments}
        for k, a in arrays.items():
            if a.size == 1:
                self.columns[k] = a.reshape(1)
            else:
                self.columns[k] = np.ascontiguousarray(np.broadcast_to(a, self.shape)).reshape(-1)

    def __getitem__(self, name: str) -> Optional[np.ndarray]:
        return self.columns[name]

    @property
    def shape_list(self) -> list:
        return [] if self.scalar else list(self.shape)

    def out(self, flat: np.ndarray) -> Union[float, np.ndarray]:
        if self.scalar:
            return float(flat[0])
        return flat.reshape(self.shape)

    def out_dict(self, columns: Dict[str, Any]) -> Dict[str, Any]:
        # every result carries the tabor version once, as the CLI's JSON does
        result: Dict[str, Any] = {"tabor_version": __version__}
        for k, v in columns.items():
            if isinstance(v, np.ndarray):
                if self.scalar:
                    x = v[0]
                    result[k] = bool(x) if v.dtype == np.bool_ else float(x)
                else:
                    result[k] = v.reshape(self.shape)
            else:  # a list: strings, lists of warnings, None
                if self.scalar:
                    result[k] = v[0]
                else:
                    a = np.empty(len(v), dtype=object)
                    a[:] = v
                    result[k] = a.reshape(self.shape)
        return result


# --------------------------------------------------------------------------------
# Maugis-Dugdale


def maugis_dugdale_loss(
    tabor_parameter: ArrayLike, *, tolerance: ArrayLike = 1e-12, fast: bool = False
) -> Union[float, np.ndarray]:
    """The adhesive energy loss W(Λ) of a Maugis-Dugdale impact, in units of F_n d_n.

    Seed 000 section 5.3.2, eq. (5.43): ``|ΔU_kin| = F_n d_n · W(Λ)`` with
    ``W = |∫_{-1/Λ}^{d̂_c} F̂ dd̂|`` along the equilibrium branch from the jump-in
    depth −1/Λ (5.40) to the displacement-controlled snap-off; case 1 (Λ ≤ 0.4496)
    is the closed form 17·2¹⁹Λ⁵/(3⁴π⁸) (5.44), case 2 adds (5.46). Scales:
    ``F_n = (3/2)πΔγR`` (N), ``d_n = a_c²/(3R)`` (m), ``a_c = (9πΔγR²/(8E*))^(1/3)``.
    ``W / jkr_normalized_loss()`` is the ordinate of seed 000 Fig. 5.2.

    Parameters
    ----------
    tabor_parameter : array_like
        The seed's Tabor parameter Λ = d_n/h > 0 (dimensionless; convert Maugis' λ
        or Tabor's μ with ``tabor_parameter_from_maugis`` /
        ``tabor_parameter_from_tabor_mu``).
    tolerance : array_like, optional
        Relative tolerance of the direct evaluation, in [1e-15, 0.5] (default
        1e-12). Not used with ``fast=True``.
    fast : bool, optional
        Use the precomputed Chebyshev tier (relative error below
        ``FAST_TIER_RELATIVE_ERROR`` = 1e-10; see the README for timings) instead of
        the direct quadrature.

    Returns
    -------
    float or ndarray
        W (dimensionless, units of F_n d_n), shaped like the broadcast inputs.
    """
    b = _Batch(tabor_parameter=tabor_parameter, tolerance=tolerance)
    return b.out(_tabor.maugis_dugdale_loss(b["tabor_parameter"], b["tolerance"], bool(fast), b.shape_list))


def maugis_dugdale_curve(
    maugis_parameter: ArrayLike, contact_radius: ArrayLike
) -> Tuple[Union[float, np.ndarray], Union[float, np.ndarray]]:
    """Load and penetration of the Maugis-Dugdale contact at a given contact radius.

    Maugis (1992) in Maugis' units, every branch (stable and unstable): a drop-in
    for ``Adhesion.ReferenceSolutions.MaugisDugdale._load_and_displacement(A, λ)``.
    Computed on tabor's θ-parametrized contact branch (spec maugis-dugdale.md,
    seed 000 section 3.3.3 as used by (5.43)-(5.46)) and converted:
    ``A = (3/2)^(1/3) â``, ``P̄ = (3/2) F̂``, ``Δ̄ = (3/2)^(2/3)/3 · d̂``.

    Parameters
    ----------
    maugis_parameter : array_like
        Maugis' λ = 2σ0 (R/(πΔγK²))^(1/3) > 0, K = 4E*/3.
    contact_radius : array_like
        A = a / (πΔγR²/K)^(1/3) ≥ 0.

    Returns
    -------
    load, penetration : float or ndarray
        ``P̄ = F/(πΔγR)`` (positive in compression) and
        ``Δ̄ = δ/(π²Δγ²R/K²)^(1/3)``, shaped like the broadcast inputs.
    """
    b = _Batch(maugis_parameter=maugis_parameter, contact_radius=contact_radius)
    load, penetration = _tabor.maugis_dugdale_curve(b["maugis_parameter"], b["contact_radius"], b.shape_list)
    return b.out(load), b.out(penetration)


def tabor_parameter_from_maugis(maugis_parameter: ArrayLike) -> Union[float, np.ndarray]:
    """The seed's Λ from Maugis' λ: ``Λ = π(9/4)^(1/3)/6 · λ ≈ 0.6861 λ``."""
    b = _Batch(maugis_parameter=maugis_parameter)
    return b.out(_tabor.tabor_parameter_from_maugis(b["maugis_parameter"], b.shape_list))


def tabor_parameter_from_tabor_mu(tabor_mu: ArrayLike) -> Union[float, np.ndarray]:
    """The seed's Λ from Tabor's μ = (RΔγ²/(E*² z0³))^(1/3), through the Dugdale
    equivalence λ ≈ 1.157 μ (an approximation): ``Λ ≈ 0.7938 μ``. So Λ = 4 is
    μ ≈ 5 (seed 000, after (5.46))."""
    b = _Batch(tabor_mu=tabor_mu)
    return b.out(_tabor.tabor_parameter_from_tabor_mu(b["tabor_mu"], b.shape_list))


def maugis_parameter(tabor_parameter: ArrayLike) -> Union[float, np.ndarray]:
    """Maugis' λ from the seed's Λ: ``λ = Λ / 0.6861…`` (inverse of
    ``tabor_parameter_from_maugis``)."""
    b = _Batch(tabor_parameter=tabor_parameter)
    return b.out(_tabor.maugis_parameter(b["tabor_parameter"], b.shape_list))


def jkr_normalized_loss() -> float:
    """The JKR (fixed-grip) loss (5.36) in units of F_n d_n:
    ``(1 + 864^(1/3))/10 · 8/(3·3^(1/3)) ≈ 1.9459``; the Λ → ∞ limit of W(Λ)."""
    return float(_tabor.jkr_normalized_loss())


# --------------------------------------------------------------------------------
# scenes


class Scene:
    """A collision described once: bodies, interface, accuracy, impact speed.

    Build one with ``Scene.from_toml(text)``, ``Scene.from_json(text)`` or
    ``Scene.from_path(path)`` (format: examples/scenes/README.md of the tabor
    repository; SI units). The scene computes only the effects it calls for
    (elasticity, adhesion JKR/Maugis-Dugdale, plasticity, viscoelasticity) and says
    why, exactly as ``tabor impact`` does.
    """

    __slots__ = ("_core",)

    def __init__(self, core: "_tabor.Scene") -> None:
        if not isinstance(core, _tabor.Scene):
            raise TypeError("use Scene.from_toml, Scene.from_json or Scene.from_path")
        self._core = core

    @classmethod
    def from_toml(cls, text: str) -> "Scene":
        """A scene from TOML text. Raises ValueError naming the line, field and rule."""
        return cls(_tabor.Scene.from_toml(text))

    @classmethod
    def from_json(cls, text: str) -> "Scene":
        """A scene from JSON text (same keys as the TOML format)."""
        return cls(_tabor.Scene.from_json(text))

    @classmethod
    def from_path(cls, path: Any) -> "Scene":
        """A scene from a file: ``.json`` is JSON, anything else TOML."""
        import os

        return cls(_tabor.Scene.from_path(os.fspath(path)))

    @property
    def name(self) -> str:
        """The scene's name (default: the file stem)."""
        return self._core.name

    @property
    def speed(self) -> Optional[float]:
        """The scene's impact speed (m/s) from ``[impact] speed``, or None."""
        return self._core.speed

    @property
    def tabor_parameter(self) -> Optional[float]:
        """The seed's Tabor parameter Λ when the interface has a range, else None."""
        return self._core.tabor_parameter

    def outcome(self, speed: Optional[float] = None) -> Dict[str, Any]:
        """The outcome of the impact as a dict with the keys of ``tabor impact --json``.

        Keys include ``restitution`` (5.37), ``sticks``, ``sticking_velocity`` (m/s
        or None), ``energy_loss`` and ``kinetic_energy`` (J), ``model``, ``branch``,
        ``tabor_parameter``, ``effects`` (list of dicts with name/used/reason/...),
        ``accuracy``, ``energy_loss_error`` (J), ``cost``, ``warnings``. New fields
        of the library appear here unchanged.

        Parameters
        ----------
        speed : float, optional
            Impact speed (m/s); default the scene's ``[impact] speed``.
        """
        return self._core.outcome(None if speed is None else float(speed))

    def restitution(self, speeds: ArrayLike) -> Union[float, np.ndarray]:
        """The coefficient of restitution (5.37) at each impact speed (m/s), in parallel.

        Same model and combination rule as ``outcome(speed)["restitution"]``.
        Returns a float for a scalar speed, else a float64 array of its shape.
        """
        b = _Batch(speed=speeds)
        return b.out(self._core.restitution(b["speed"], b.shape_list))

    def sticking_velocity(self) -> Optional[float]:
        """The sticking velocity (m/s) of the full model ((5.38) for JKR), or None
        when the bodies never stick."""
        return self._core.sticking_velocity()

    def sweep(self, parameter: str, values: ArrayLike) -> Dict[str, Any]:
        """Outcomes over values of one scene parameter, computed in parallel.

        Parameters
        ----------
        parameter : str
            ``"speed"`` (m/s), ``"sphere_radius"`` (m), ``"work_of_adhesion"``
            (J/m²), ``"tabor_parameter"`` (Λ, replaces any range) or
            ``"yield_stress"`` (Pa); hyphens as in ``tabor sweep`` work too.
        values : array_like
            The values (use ``numpy.linspace``/``numpy.geomspace`` for ranges).

        Returns
        -------
        dict
            The keys of ``outcome()``, each an array of the shape of ``values``:
            float64 for numbers (NaN where None), bool for flags, object arrays
            for strings and lists; plus ``parameter`` and ``values``.
        """
        b = _Batch(values=values)
        result = b.out_dict(self._core.sweep(str(parameter), b["values"], b.shape_list))
        result["parameter"] = str(parameter)
        result["values"] = b.out(b["values"])
        return result

    def trajectory(self, speed: Optional[float] = None, *, tolerance: float = 1e-9) -> Dict[str, Any]:
        """The impact simulated in the time domain (like ``tabor trajectory``).

        Returns a dict of arrays ``t`` (s), ``d`` (overlap, m), ``d_dot`` (m/s),
        ``F`` (force, N, positive in compression), ``a`` (contact radius, m),
        ``contact_work`` (J), and the summary ``law``, ``impact_speed``,
        ``restitution`` (simulated), ``restitution_analytic``, ``contact_time``
        (s or None), ``sticks``, ``max_overlap``, ``max_force``, ``energy_loss``,
        ``energy_error``, ``points``.

        Parameters
        ----------
        speed : float, optional
            Impact speed (m/s); default the scene's ``[impact] speed``.
        tolerance : float, optional
            Requested relative accuracy of the simulated outcome (default 1e-9).
        """
        return self._core.trajectory(None if speed is None else float(speed), float(tolerance))

    def __repr__(self) -> str:
        return f"tabor.Scene(name={self.name!r})"


# --------------------------------------------------------------------------------
# single models (the CLI subcommands)


def effective(
    *,
    youngs_modulus: ArrayLike,
    poisson_ratio: ArrayLike,
    radius: ArrayLike,
    density: Optional[ArrayLike] = None,
    mass: Optional[ArrayLike] = None,
    target_youngs_modulus: Optional[ArrayLike] = None,
    target_poisson_ratio: Optional[ArrayLike] = None,
    rigid_target: bool = False,
    target_radius: Optional[ArrayLike] = None,
    target_density: Optional[ArrayLike] = None,
    target_mass: Optional[ArrayLike] = None,
) -> Dict[str, Any]:
    """Effective modulus, radius and mass of a two-body collision (``tabor effective``).

    ``1/E* = (1-ν1²)/E1 + (1-ν2²)/E2``, ``1/R = 1/R1 + 1/R2``,
    ``m = m1 m2/(m1 + m2)`` (seed 000 section 5.1).

    Keyword arguments (CLI flag in brackets):
      youngs_modulus [--youngs-modulus]  Young's modulus of the sphere (Pa)
      poisson_ratio [--poisson-ratio]    Poisson's ratio of the sphere
      radius [--radius]                  radius of the sphere (m)
      density [--density]                density of the sphere (kg/m³); or give mass
      mass [--mass]                      mass of the sphere (kg)
      target_youngs_modulus [--target-youngs-modulus]  (Pa); default: the sphere's
      target_poisson_ratio [--target-poisson-ratio]    default: the sphere's
      rigid_target [--rigid-target]      the target is rigid (bool)
      target_radius [--target-radius]    (m); omit for a flat half-space
      target_density [--target-density]  (kg/m³); default the sphere's density
      target_mass [--target-mass]        (kg); omit for an immovable target

    Returns a dict of ``effective_modulus`` (Pa), ``effective_radius`` (m),
    ``effective_mass`` (kg): floats for scalar input, else arrays of the broadcast
    shape.
    """
    b = _Batch(
        optional=("density", "mass", "target_youngs_modulus", "target_poisson_ratio", "target_radius", "target_density", "target_mass"),
        youngs_modulus=youngs_modulus,
        poisson_ratio=poisson_ratio,
        radius=radius,
        density=density,
        mass=mass,
        target_youngs_modulus=target_youngs_modulus,
        target_poisson_ratio=target_poisson_ratio,
        target_radius=target_radius,
        target_density=target_density,
        target_mass=target_mass,
    )
    return b.out_dict(
        _tabor.effective(
            b["youngs_modulus"],
            b["poisson_ratio"],
            b["radius"],
            b["density"],
            b["mass"],
            b["target_youngs_modulus"],
            b["target_poisson_ratio"],
            bool(rigid_target),
            b["target_radius"],
            b["target_density"],
            b["target_mass"],
            b.shape_list,
        )
    )


def jkr(
    *,
    modulus: ArrayLike,
    radius: ArrayLike,
    work_of_adhesion: ArrayLike,
    mass: ArrayLike,
    speed: Optional[ArrayLike] = None,
    separation: str = "fixed-grip",
    tolerance: ArrayLike = 1e-12,
) -> Dict[str, Any]:
    """JKR adhesive impact of a sphere (``tabor jkr``), seed 000 (5.33)-(5.38).

    Energy loss (5.36) ``|ΔU| = (1 + 864^(1/3))/10 · [R⁴(πΔγ)⁵/E*²]^(1/3)`` (fixed
    grip), sticking velocity (5.38) ``v_c = √(2|ΔU|/m)``, and at a given speed the
    maximum contact radius (5.35) and the restitution (5.37) ``ε = √(1 − v_c²/v0²)``.
    Inputs are the effective quantities of the collision (see ``effective``).

    Keyword arguments (CLI flag in brackets):
      modulus [--modulus]                effective modulus E* (Pa)
      radius [--radius]                  effective radius R (m)
      work_of_adhesion [--work-of-adhesion]  Δγ (J/m²)
      mass [--mass]                      effective (reduced) mass m (kg)
      speed [--speed]                    impact speed v0 (m/s), optional: adds
                                         max_contact_radius, restitution, sticks
      separation [--separation]          "fixed-grip" (default; force −(5/6)πΔγR)
                                         or "load-controlled" (−(3/2)πΔγR)
      tolerance [--tolerance]            relative tolerance, in [1e-15, 0.5]

    Returns a dict: ``model``, ``branch``, ``separation`` (str), ``energy_loss``,
    ``energy_loss_error`` (J), ``sticking_velocity`` (m/s), ``separation_force``
    (N, negative), ``separation_contact_radius``, ``first_touch_contact_radius``
    (m), ``evaluations``, and with ``speed``: ``impact_speed``,
    ``max_contact_radius`` (m), ``restitution``, ``sticks``.
    """
    b = _Batch(
        optional=("speed",),
        modulus=modulus,
        radius=radius,
        work_of_adhesion=work_of_adhesion,
        mass=mass,
        speed=speed,
        tolerance=tolerance,
    )
    return b.out_dict(
        _tabor.jkr(
            b["modulus"],
            b["radius"],
            b["work_of_adhesion"],
            b["mass"],
            b["speed"],
            str(separation),
            b["tolerance"],
            b.shape_list,
        )
    )


def plastic(
    *,
    model: str,
    modulus: ArrayLike,
    radius: ArrayLike,
    mass: ArrayLike,
    yield_stress: ArrayLike,
    speed: ArrayLike,
    poisson_ratio: Optional[ArrayLike] = None,
    density: Optional[ArrayLike] = None,
    work_of_adhesion: Optional[ArrayLike] = None,
    adhesion_parameter: Optional[ArrayLike] = None,
    plastic_model: str = "interpolation",
) -> Dict[str, Any]:
    """Elasto-plastic impact with and without adhesion (``tabor plastic``).

    Seed 000 sections 5.5-5.6, (5.101)-(5.126); seed 001 eqs. (12), (18), (19).
    Inputs are the effective quantities of the collision and the yield stress of
    the softer (yielding) body.

    Keyword arguments (CLI flag in brackets):
      model [--model]          "thornton" (5.101)-(5.106), "interpolation" (5.107),
                               "jackson-green" (5.108, needs poisson_ratio),
                               "dimensionless-fit" (seed 001, needs density),
                               "adhesive-interpolation" (5.111)-(5.126, needs
                               work_of_adhesion or adhesion_parameter),
                               "superposition" (5.109)-(5.110, needs work_of_adhesion)
      modulus [--modulus]      effective modulus E* (Pa)
      radius [--radius]        effective radius R (m)
      mass [--mass]            effective (reduced) mass m (kg)
      yield_stress [--yield-stress]  σ_Y of the yielding body (Pa)
      speed [--speed]          impact speed v0 (m/s)
      poisson_ratio [--poisson-ratio]  of the yielding body (jackson-green)
      density [--density]      of the sphere, kg/m³ (dimensionless-fit)
      work_of_adhesion [--work-of-adhesion]  Δγ (J/m²)
      adhesion_parameter [--adhesion-parameter]  Φ, instead of computing it
      plastic_model [--plastic-model]  the non-adhesive model under superposition

    Returns a dict: ``model``, ``branch``, ``impact_speed``, ``restitution``,
    ``energy_loss`` (J), ``sticks``, ``yield_velocity`` (m/s), ``warnings``, and
    where they apply ``sticking_velocity``, ``elastic_sticking_velocity`` (m/s),
    ``adhesion_parameter``, ``clamping``.
    """
    b = _Batch(
        optional=("poisson_ratio", "density", "work_of_adhesion", "adhesion_parameter"),
        modulus=modulus,
        radius=radius,
        mass=mass,
        yield_stress=yield_stress,
        speed=speed,
        poisson_ratio=poisson_ratio,
        density=density,
        work_of_adhesion=work_of_adhesion,
        adhesion_parameter=adhesion_parameter,
    )
    return b.out_dict(
        _tabor.plastic(
            str(model),
            b["modulus"],
            b["radius"],
            b["mass"],
            b["yield_stress"],
            b["speed"],
            b["poisson_ratio"],
            b["density"],
            b["work_of_adhesion"],
            b["adhesion_parameter"],
            str(plastic_model),
            b.shape_list,
        )
    )


def visco(
    *,
    model: str,
    damping_ratio: Optional[ArrayLike] = None,
    viscous_parameter: Optional[ArrayLike] = None,
    modulus_ratio: Optional[ArrayLike] = None,
    damping: Optional[ArrayLike] = None,
    damping_exponent: Optional[ArrayLike] = None,
    alpha: Optional[ArrayLike] = None,
    poisson_ratio: Optional[ArrayLike] = None,
    bulk_damping_ratio: Optional[ArrayLike] = None,
    tolerance: ArrayLike = 1e-10,
) -> Dict[str, Any]:
    """Viscoelastic impact without adhesion (``tabor visco``), seed 000 section 5.4.

    All parameters are dimensionless: D = η√(2a/(mG)) (5.55); δ = η(Rv0/(m²G³))^(1/5)
    for spheres (5.68), (5.90), (5.92), δ = η√(8a/(mG∞)) for the standard flat punch
    (5.79); β = G∞/G1; γ = λ d0^(b+1)/(m v0) (5.72).

    Keyword arguments (CLI flag in brackets):
      model [--model]   "kelvin-voigt-flat" (5.61)-(5.63, damping_ratio),
                        "kuwabara-kono" (5.66, viscous_parameter),
                        "kelvin-voigt-sphere" (5.64)-(5.67, viscous_parameter),
                        "lee-herrmann" (5.72, damping), "tsuji" (5.73, alpha),
                        "hunt-crossley" (5.72, damping),
                        "power-damping" (5.72, damping_exponent, damping),
                        "standard-flat" (5.76)-(5.83), "standard-sphere"
                        (5.84)-(5.90), "kelvin-maxwell-sphere" (5.91)-(5.92)
                        (modulus_ratio, viscous_parameter),
                        "compressible-flat" (5.96)-(5.100, poisson_ratio,
                        damping_ratio, optional bulk_damping_ratio)
      damping_ratio [--damping-ratio]          D (> 0)
      viscous_parameter [--viscous-parameter]  δ (> 0)
      modulus_ratio [--modulus-ratio]          β = G∞/G1, in [1e-5, 1e4]
      damping [--damping]                      γ of (5.72), in (0, 1e3]
      damping_exponent [--damping-exponent]    β of (5.72), in [0, 1.5]
      alpha [--alpha]                          Tsuji's α of (5.73), > 0
      poisson_ratio [--poisson-ratio]          static ν, in (-1, 0.5)
      bulk_damping_ratio [--bulk-damping-ratio]  D2; default (5.100)
      tolerance [--tolerance]                  relative, in [1e-15, 0.5]

    Returns a dict: ``model``, ``restitution``, ``evaluations`` and where they
    apply ``contact_time``, ``max_overlap`` (scaled), ``first_order_restitution``,
    ``equivalent_kelvin_voigt_damping_ratio``,
    ``equivalent_kelvin_voigt_restitution``.
    """
    b = _Batch(
        optional=("damping_ratio", "viscous_parameter", "modulus_ratio", "damping", "damping_exponent", "alpha", "poisson_ratio", "bulk_damping_ratio"),
        damping_ratio=damping_ratio,
        viscous_parameter=viscous_parameter,
        modulus_ratio=modulus_ratio,
        damping=damping,
        damping_exponent=damping_exponent,
        alpha=alpha,
        poisson_ratio=poisson_ratio,
        bulk_damping_ratio=bulk_damping_ratio,
        tolerance=tolerance,
    )
    return b.out_dict(
        _tabor.visco(
            str(model),
            b["damping_ratio"],
            b["viscous_parameter"],
            b["modulus_ratio"],
            b["damping"],
            b["damping_exponent"],
            b["alpha"],
            b["poisson_ratio"],
            b["bulk_damping_ratio"],
            b["tolerance"],
            b.shape_list,
        )
    )


def penalty(
    *,
    law: str,
    restitution: ArrayLike,
    stiffness: ArrayLike = 1e7,
    exponent: Optional[ArrayLike] = None,
    rounding: ArrayLike = 0.0,
    mass: ArrayLike = 1.0,
    speed: ArrayLike = 1.0,
) -> Dict[str, Any]:
    """Penalty contact laws for multibody codes (``tabor penalty``): the parameters
    for a nominal restitution and what a simulated impact achieves.

    Laws: seed 002's contact characteristic ``F = k κ(h, ε) l(v, V)`` with the loss
    speed V calibrated exactly; ``F = K δⁿ (1 + χ δ̇)`` with χ = 3(1 − e)/(2v0)
    (Hunt-Crossley), 3(1 − e²)/(4v0) (Lankarani-Nikravesh), 8(1 − e)/(5 e v0)
    (Flores).

    Keyword arguments (CLI flag in brackets):
      law [--law]                "characteristic", "hunt-crossley",
                                 "lankarani-nikravesh" or "flores"
      restitution [--restitution]  nominal e, in (0, 1]
      stiffness [--stiffness]    K (N/m^n; N/m for the characteristic), default 1e7
      exponent [--exponent]      n of K δⁿ (default 1.5; the characteristic is linear)
      rounding [--rounding]      rounding half-width ε of the characteristic (m)
      mass [--mass]              effective mass (kg), default 1
      speed [--speed]            impact speed v0 (m/s), default 1

    Returns a dict: ``law``, ``nominal_restitution``, ``achieved_restitution``
    (simulated), ``closed_form_restitution``, ``stiffness``, ``exponent``,
    ``effective_mass``, ``impact_speed``, ``max_overlap`` (m), ``max_force`` (N),
    ``contact_time`` (s), ``energy_error``, and per law ``damping_factor`` (s/m),
    ``damping_coefficient``, ``exact_damping_factor``, ``loss_speed`` (m/s),
    ``rounding``.
    """
    b = _Batch(
        optional=("exponent",),
        restitution=restitution,
        stiffness=stiffness,
        exponent=exponent,
        rounding=rounding,
        mass=mass,
        speed=speed,
    )
    return b.out_dict(
        _tabor.penalty(
            str(law),
            b["restitution"],
            b["stiffness"],
            b["exponent"],
            b["rounding"],
            b["mass"],
            b["speed"],
            b.shape_list,
        )
    )
