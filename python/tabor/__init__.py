"""tabor: adhesive impact of spheres, numpy in, numpy out.

Energy loss, coefficient of restitution and sticking velocity of central impacts of
two spheres (or a sphere on a half-space) with JKR, Maugis-Dugdale, elasto-plastic
and viscoelastic contact, computed by the Rust workspace ``tabor``. Equation numbers
(5.x) refer to Willert (2020): E. Willert, "Quasistatischer Normalstoß
axialsymmetrischer Körper", chapter 5 of *Stoßprobleme in Physik, Technik und
Medizin*, Springer Vieweg 2020, doi:10.1007/978-3-662-60296-6_5. The other sources
(the dimensionless FEM fit of ``plastic(model="dimensionless-fit")``, the numpedia
contact characteristic of ``penalty(law="characteristic")``) and the cited papers
are in docs/sources.md of the repository ("Sources", "Bibliography").

Conventions (as ContactEngineering's ``Adhesion`` package): module-level functions,
keyword arguments, SI units unless a name says otherwise; a name shared with
``Adhesion`` means the same there. Every numeric argument broadcasts with numpy;
array input gives arrays of the broadcast shape (results as columns: one array per
key), scalar input gives Python scalars. Batches run in parallel with the GIL
released (``threads=``, ``set_num_threads``, ``RAYON_NUM_THREADS``) and stop on
Ctrl-C. ``errors="raise"`` (default) raises on the first invalid point,
``errors="nan"`` returns NaN there with a count in an ``InvalidPointsWarning``.

Exceptions: ``InputError`` (a ``ValueError``: bad input, naming the parameter, its
value and the index), ``ModelValidityError`` (a ``ValueError``),
``ConvergenceError`` (a ``RuntimeError``), ``TypeError`` for wrong types. Validity
warnings are ``TaborWarning`` subclasses (``QuasiStaticWarning``,
``CoupledModelWarning``, ...) through Python's ``warnings`` module.
"""

from __future__ import annotations

import os as _os
from typing import Any, Dict, Optional, Tuple



from . import _core, _results, _tabor
from ._errors import (
    ConvergenceError,
    CoupledModelWarning,
    ElasticLimitWarning,
    InputError,
    InvalidPointsWarning,
    ModelValidityError,
    PlasticModelWarning,
    QuasiStaticWarning,
    StickingVelocityWarning,
    SuperposedLossesWarning,
    TaborError,
    TaborWarning,
)

__all__ = [
    "maugis_dugdale_loss",
    "maugis_dugdale_curve",
    "tabor_parameter_from_maugis",
    "tabor_parameter_from_tabor_mu",
    "maugis_parameter_from_tabor",
    "maugis_parameter",
    "force_displacement",
    "FORCE_DISPLACEMENT_MODELS",
    "SWEEP_PARAMETERS",
    "jkr_normalized_loss",
    "Scene",
    "effective",
    "jkr",
    "plastic",
    "visco",
    "penalty",
    "set_num_threads",
    "get_num_threads",
    "LAMBDA_PER_MAUGIS_PARAMETER",
    "MAUGIS_PER_TABOR_MU",
    "FAST_TIER_RELATIVE_ERROR",
    "MIN_MAUGIS_PARAMETER",
    "DEFAULT_TOLERANCE",
    "ACCURACY",
    "COSTLY_TOLERANCE",
    "TaborError",
    "InputError",
    "ModelValidityError",
    "ConvergenceError",
    "TaborWarning",
    "QuasiStaticWarning",
    "CoupledModelWarning",
    "ElasticLimitWarning",
    "StickingVelocityWarning",
    "SuperposedLossesWarning",
    "PlasticModelWarning",
    "InvalidPointsWarning",
]

#: The version of tabor (the Rust workspace and this package).
__version__: str = _tabor.VERSION

#: Λ per Maugis' λ: Λ = π (9/4)^(1/3) / 6 · λ ≈ 0.6861 λ.
LAMBDA_PER_MAUGIS_PARAMETER: float = _tabor.LAMBDA_PER_MAUGIS_PARAMETER
#: Dugdale equivalence of Tabor's μ: λ ≈ 1.157 μ.
MAUGIS_PER_TABOR_MU: float = _tabor.MAUGIS_PER_TABOR_MU
#: Relative error bound of the fast tier of ``maugis_dugdale_loss`` (1e-10).
FAST_TIER_RELATIVE_ERROR: float = _tabor.FAST_TIER_RELATIVE_ERROR
#: The smallest Maugis λ of ``maugis_dugdale_curve`` (below it: ModelValidityError).
MIN_MAUGIS_PARAMETER: float = _tabor.MIN_MAUGIS_PARAMETER
#: The default relative tolerance of closed-form and quadrature models (1e-12; the
#: base of every default tolerance of tabor, ``tabor_numerics::tolerance``).
DEFAULT_TOLERANCE: float = _tabor.DEFAULT_TOLERANCE
#: The default requested accuracy of composite answers and of ``visco`` (1e-10).
ACCURACY: float = _tabor.ACCURACY
#: The default tolerance of the costliest integrations, ``Scene.trajectory`` (1e-9).
COSTLY_TOLERANCE: float = _tabor.COSTLY_TOLERANCE


def set_num_threads(threads: Optional[int] = None) -> None:
    """Sets the number of threads of every later batch (``None``: rayon's global
    pool, sized by the environment variable ``RAYON_NUM_THREADS`` when it is set
    before the first batch, else the number of cores). A call's ``threads=``
    overrides it."""
    _tabor.set_num_threads(_core.check_threads(threads))


def get_num_threads() -> int:
    """The number of threads a batch uses by default."""
    return int(_tabor.get_num_threads())


# --------------------------------------------------------------------------------
# Maugis-Dugdale


def maugis_dugdale_loss(tabor_parameter: Any, *, tolerance: Any = DEFAULT_TOLERANCE, fast: bool = False,
                        errors: str = _core.DEFAULT_ERRORS, threads: Optional[int] = None) -> Any:
    """The adhesive energy loss W(Λ) of a Maugis-Dugdale impact, in units of F_n d_n.

    Willert (2020) section 5.3.2, eq. (5.43): ``|ΔU_kin| = F_n d_n · W(Λ)`` with
    ``W = |∫_{-1/Λ}^{d̂_c} F̂ dd̂|`` along the equilibrium branch from the jump-in
    depth −1/Λ (5.40) to the displacement-controlled snap-off; case 1 (Λ ≤ 0.4496)
    is the closed form 17·2¹⁹Λ⁵/(3⁴π⁸) (5.44), case 2 adds (5.46). Scales:
    ``F_n = (3/2)πΔγR`` (N), ``d_n = a_c²/(3R)`` (m), ``a_c = (9πΔγR²/(8E*))^(1/3)``.
    ``W / jkr_normalized_loss()`` is the ordinate of Willert (2020) Fig. 5.2.

    Parameters
    ----------
    tabor_parameter : array_like
        Willert's (2020) Tabor parameter Λ = d_n/h > 0 (dimensionless; convert Maugis' λ
        or Tabor's μ with ``tabor_parameter_from_maugis`` /
        ``tabor_parameter_from_tabor_mu``).
    tolerance : array_like, optional
        Relative tolerance of the direct evaluation, in [1e-15, 0.5] (default
        ``DEFAULT_TOLERANCE``). Not used with ``fast=True``.
    fast : bool, optional
        Use the precomputed Chebyshev tier (relative error below
        ``FAST_TIER_RELATIVE_ERROR`` = 1e-10) instead of the direct quadrature.
    errors, threads
        As for every batch (module doc).

    Returns
    -------
    float or ndarray
        W (dimensionless, units of F_n d_n), shaped like the broadcast inputs.
    """
    fast = _core.check_bool("fast", fast)
    errors = _core.check_errors(errors)
    threads = _core.check_threads(threads)
    b = _core.Batch({"tabor_parameter": tabor_parameter, "tolerance": tolerance})
    (w,) = b.outs(_tabor.maugis_dugdale_loss(b["tabor_parameter"], b["tolerance"], fast, b.n, b.shape_list,
                                             errors, threads))
    return w


def maugis_dugdale_curve(*, contact_radius: Any, maugis_parameter: Any, errors: str = _core.DEFAULT_ERRORS,
                         threads: Optional[int] = None) -> Tuple[Any, Any]:
    """Load and penetration of the Maugis-Dugdale contact at a given contact radius,
    in Maugis' units (every branch, stable and unstable).

    The quantities of ``Adhesion.ReferenceSolutions.MaugisDugdale.
    _load_and_displacement(A, λ)``, with keyword arguments (so that the two can
    never be swapped). Computed on tabor's θ-parametrized contact branch (spec
    maugis-dugdale.md; Willert (2020) as used by (5.43)-(5.46)) and
    converted: ``A = (3/2)^(1/3) â``, ``P̄ = (3/2) F̂``, ``Δ̄ = (3/2)^(2/3)/3 · d̂``.

    Parameters
    ----------
    contact_radius : array_like
        A = a / (πΔγR²/K)^(1/3) ≥ 0, K = 4E*/3.
    maugis_parameter : array_like
        Maugis' λ = 2σ0 (R/(πΔγK²))^(1/3), at least ``MIN_MAUGIS_PARAMETER``
        (1e-10; below it the branch cannot be evaluated to full precision and a
        ``ModelValidityError`` points to the DMT limit).

    Returns
    -------
    load, penetration : float or ndarray
        ``P̄ = F/(πΔγR)`` (positive in compression) and
        ``Δ̄ = δ/(π²Δγ²R/K²)^(1/3)``, shaped like the broadcast inputs.
    """
    errors = _core.check_errors(errors)
    threads = _core.check_threads(threads)
    b = _core.Batch({"contact_radius": contact_radius, "maugis_parameter": maugis_parameter})
    load, penetration = b.outs(_tabor.maugis_dugdale_curve(b["contact_radius"], b["maugis_parameter"], b.n,
                                                           b.shape_list, errors, threads))
    return load, penetration


def _contact_modulus(function: str, contact_modulus: Any, extra: Dict[str, Any]) -> Any:
    """``contact_modulus``, or the same quantity under a renamed keyword in
    ``extra`` (``_core.RENAMED_KEYWORDS``, with a DeprecationWarning); any other
    keyword in ``extra`` is a TypeError."""
    given = _core.renamed(function, extra)
    unknown = sorted(k for k in given if k != "contact_modulus")
    if unknown:
        raise TypeError(f"{function}() got an unexpected keyword argument '{unknown[0]}'")
    if "contact_modulus" in given:
        if contact_modulus is not None:
            raise TypeError(f"{function}(): give contact_modulus once")
        contact_modulus = given["contact_modulus"]
    if contact_modulus is None:
        raise TypeError(f"{function}() missing required argument: 'contact_modulus'")
    return contact_modulus


def force_displacement(model: str, contact_radius: Any, *, radius: Any, contact_modulus: Any = None,
                       work_of_adhesion: Any, cohesive_stress: Any = None, errors: str = _core.DEFAULT_ERRORS,
                       threads: Optional[int] = None, **renamed: Any) -> Tuple[Any, Any]:
    """Force and penetration of an adhesive sphere-on-flat contact in SI units, at
    given contact radii, for ``model`` (the menu below, ``FORCE_DISPLACEMENT_MODELS``).

    The parameters of ``Adhesion`` (``radius`` R, ``contact_modulus`` the contact
    modulus E* = E/(1 − ν²) (for two bodies the effective modulus), K = 4E*/3,
    ``work_of_adhesion`` Δγ, ``cohesive_stress`` σ0 for Maugis-Dugdale only). JKR
    gives ``Adhesion.ReferenceSolutions.JKR.force`` and ``penetration``,
    Maugis-Dugdale ``maugis_dugdale_curve`` in SI units
    (``Adhesion.ReferenceSolutions.MaugisDugdale.load_and_displacement``).

    Returns ``(force, penetration)``: N (positive in compression) and m, shaped
    like the broadcast inputs.

    Models:
    """
    contact_modulus = _contact_modulus("force_displacement", contact_modulus, renamed)
    model = _core.check_str("model", model)
    errors = _core.check_errors(errors)
    threads = _core.check_threads(threads)
    b = _core.Batch({"contact_radius": contact_radius, "radius": radius, "contact_modulus": contact_modulus,
                     "work_of_adhesion": work_of_adhesion, "cohesive_stress": cohesive_stress})
    force, penetration = b.outs(_tabor.force_displacement(
        model, b["contact_radius"], b["radius"], b["contact_modulus"], b["work_of_adhesion"],
        b["cohesive_stress"], b.n, b.shape_list, errors, threads))
    return force, penetration


#: The models of ``force_displacement``: their names (from the Rust menu
#: ``tabor_maugis::CurveModel``).
FORCE_DISPLACEMENT_MODELS: Tuple[str, ...] = tuple(name for name, _ in _tabor.FORCE_DISPLACEMENT_MODELS)
force_displacement.__doc__ = (force_displacement.__doc__ or "") + "".join(
    f'\n    - ``"{name}"``: {about}' for name, about in _tabor.FORCE_DISPLACEMENT_MODELS
) + "\n"
#: The parameters ``Scene.sweep`` can vary (from the Rust ``tabor_scene::SweepParameter``).
SWEEP_PARAMETERS: Tuple[str, ...] = tuple(_tabor.SWEEP_PARAMETERS)


def maugis_parameter(radius: Any, contact_modulus: Any = None, work_of_adhesion: Any = None,
                     cohesive_stress: Any = None, *, errors: str = _core.DEFAULT_ERRORS,
                     threads: Optional[int] = None, **renamed: Any) -> Any:
    """Maugis' λ = 2σ0 / (πΔγK²/R)^(1/3), K = 4E*/3, from SI quantities: the
    arguments and meaning of ``Adhesion.ReferenceSolutions.MaugisDugdale.
    maugis_parameter(radius, elastic_modulus, work_of_adhesion, cohesive_stress)``
    (its ``elastic_modulus`` is the contact modulus E*, here ``contact_modulus``). Λ of
    Willert (2020) is ``tabor_parameter_from_maugis(λ)``."""
    contact_modulus = _contact_modulus("maugis_parameter", contact_modulus, renamed)
    for name, value in (("work_of_adhesion", work_of_adhesion), ("cohesive_stress", cohesive_stress)):
        if value is None:
            raise TypeError(f"maugis_parameter() missing required argument: '{name}'")
    errors = _core.check_errors(errors)
    threads = _core.check_threads(threads)
    b = _core.Batch({"radius": radius, "contact_modulus": contact_modulus, "work_of_adhesion": work_of_adhesion,
                     "cohesive_stress": cohesive_stress})
    (lam,) = b.outs(_tabor.maugis_parameter(b["radius"], b["contact_modulus"], b["work_of_adhesion"],
                                            b["cohesive_stress"], b.n, b.shape_list, errors, threads))
    return lam


def _unary(native: Any, name: str, value: Any, errors: str, threads: Optional[int]) -> Any:
    errors = _core.check_errors(errors)
    threads = _core.check_threads(threads)
    b = _core.Batch({name: value})
    (out,) = b.outs(native(b[name], b.n, b.shape_list, errors, threads))
    return out


def tabor_parameter_from_maugis(maugis_parameter: Any, *, errors: str = _core.DEFAULT_ERRORS,
                                threads: Optional[int] = None) -> Any:
    """Willert's (2020) Λ from Maugis' λ: ``Λ = π(9/4)^(1/3)/6 · λ ≈ 0.6861 λ``."""
    return _unary(_tabor.tabor_parameter_from_maugis, "maugis_parameter", maugis_parameter, errors, threads)


def tabor_parameter_from_tabor_mu(tabor_mu: Any, *, errors: str = _core.DEFAULT_ERRORS, threads: Optional[int] = None) -> Any:
    """Willert's (2020) Λ from Tabor's μ = (RΔγ²/(E*² z0³))^(1/3), through the Dugdale
    equivalence λ ≈ 1.157 μ (an approximation): ``Λ ≈ 0.7938 μ``. So Λ = 4 is
    μ ≈ 5 (Willert 2020, after (5.46))."""
    return _unary(_tabor.tabor_parameter_from_tabor_mu, "tabor_mu", tabor_mu, errors, threads)


def maugis_parameter_from_tabor(tabor_parameter: Any, *, errors: str = _core.DEFAULT_ERRORS,
                                threads: Optional[int] = None) -> Any:
    """Maugis' λ from Willert's (2020) Λ: ``λ = Λ / 0.6861…`` (inverse of
    ``tabor_parameter_from_maugis``; ``maugis_parameter`` computes λ from SI
    quantities, as in ``Adhesion``)."""
    return _unary(_tabor.maugis_parameter_from_tabor, "tabor_parameter", tabor_parameter, errors, threads)


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
        """A scene from TOML text. Raises InputError naming the line, field and rule."""
        return cls(_tabor.Scene.from_toml(_core.check_str("text", text)))

    @classmethod
    def from_json(cls, text: str) -> "Scene":
        """A scene from JSON text (same keys as the TOML format)."""
        return cls(_tabor.Scene.from_json(_core.check_str("text", text)))

    @classmethod
    def from_path(cls, path: Any) -> "Scene":
        """A scene from a file: ``.json`` is JSON, anything else TOML. A missing
        file is a ``FileNotFoundError``."""
        path = _os.fspath(path)
        if not _os.path.exists(path):
            raise FileNotFoundError(2, "no such scene file", path)
        return cls(_tabor.Scene.from_path(path))

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
        """Willert's (2020) Tabor parameter Λ when the interface has a range, else None."""
        return self._core.tabor_parameter

    def outcome(self, speed: Optional[float] = None, angle: Optional[float] = None) -> Dict[str, Any]:
        """The outcome of the impact as a dict with the keys of ``tabor impact
        --json`` (without ``tabor_version``: see ``tabor.__version__``).

        Keys include ``restitution`` (5.37), ``sticks``, ``sticking_velocity`` (m/s
        or None), ``energy_loss`` and ``kinetic_energy`` (J), ``model``, ``branch``,
        ``combination``, ``tabor_parameter``, ``effects`` (list of dicts with
        name/used/reason/model/energy_loss), ``accuracy``, ``energy_loss_error``
        (J), ``cost``, ``warnings`` (list of dicts with code/message; each is also
        emitted as a ``TaborWarning``). New fields of the library appear here
        unchanged.

        Parameters
        ----------
        speed : float, optional
            Impact speed (m/s); default the scene's ``[impact] speed``.
        angle : float, optional
            Impact angle (degrees between the relative velocity and the line of
            centres, [0, 90)); default the scene's ``[impact] angle``. An oblique
            impact (an angle, a ``[friction]`` section or a spin) adds the keys of
            ``tabor impact --angle --json``: ``normal_restitution``,
            ``tangential_restitution``, ``rebound_angle``,
            ``energy_lost_by_mechanism``, ``after`` (``{"sphere": {"velocity",
            "angular_velocity"}, "target": {...}}``, SI, centre-of-mass frame) and
            ``oblique``; the central keys are then those of the normal speed
            ``speed * cos(angle)``.
        """
        return self._core.outcome(
            None if speed is None else _core.float_scalar("speed", speed),
            None if angle is None else _core.float_scalar("angle", angle),
        )

    def force(self, overlap: Any, *, speed: Optional[float] = None, overlap_rate: Any = 0.0,
              errors: str = _core.DEFAULT_ERRORS, threads: Optional[int] = None) -> Any:
        """The scene's force law F(d): the normal force (N, repulsive > 0) at each
        overlap d (m) and overlap rate (m/s, default 0; rate-dependent laws use it),
        in parallel.

        The law is the one the time-domain simulation (``trajectory``) integrates at
        ``speed`` (m/s, default the scene's ``[impact] speed``): the force law of the
        combination rule that answers there, on the branch the impact starts on
        (loading, or the approach of an adhesive contact). A rule without a force
        law of its own (a sum or bound of losses, a model solved without one) is a
        ``ModelValidityError`` naming why. Returns a float for scalar input, else a
        float64 array of the broadcast shape.
        """
        b = _core.Batch({"overlap": overlap, "overlap_rate": overlap_rate})
        speed = None if speed is None else _core.float_scalar("speed", speed)
        return b.outs(self._core.force(b["overlap"], b["overlap_rate"], speed, b.n, b.shape_list,
                                       _core.check_errors(errors), _core.check_threads(threads)))[0]

    def restitution(self, speeds: Any, *, errors: str = _core.DEFAULT_ERRORS, threads: Optional[int] = None) -> Any:
        """The coefficient of restitution (5.37) at each impact speed (m/s), in parallel.

        Same model and combination rule as ``outcome(speed)["restitution"]``.
        Returns a float for a scalar speed, else a float64 array of its shape. The
        validity warnings of the slowest and the fastest speed are emitted.
        """
        errors = _core.check_errors(errors)
        threads = _core.check_threads(threads)
        b = _core.Batch({"speed": speeds})
        (eps,) = b.outs(self._core.restitution(b["speed"], b.n, b.shape_list, errors, threads))
        return eps

    def sticking_velocity(self) -> Optional[float]:
        """The sticking velocity (m/s) of the full model ((5.38) for JKR), or None
        when the bodies never stick."""
        return self._core.sticking_velocity()

    def sweep(self, parameter: str, values: Any, *, errors: str = _core.DEFAULT_ERRORS,
              threads: Optional[int] = None) -> Dict[str, Any]:
        """Outcomes over values of one scene parameter, computed in parallel, as
        columns.

        Parameters
        ----------
        parameter : str
            One of ``tabor.SWEEP_PARAMETERS``: the impact speed (m/s), the
            sphere's radius (m), the work of adhesion (J/m², needs an
            ``[adhesion]`` section), the Tabor parameter Λ (replaces any range;
            needs ``[adhesion]``), the yield stress (Pa; needs one) or the impact
            angle (degrees); a parameter the scene lacks is an InputError.
        values : array_like
            The values (use ``numpy.linspace``/``numpy.geomspace`` for ranges).

        Returns
        -------
        dict
            One array of the shape of ``values`` per key of ``outcome()``, nested
            keys flattened with dots (``cost.evaluations``, ``combination.rule``),
            the effects by name (``effects.adhesion.used``,
            ``effects.adhesion.energy_loss``, ...); ``warnings`` holds the warning
            codes of each point (the messages are emitted as ``TaborWarning``);
            plus ``parameter`` and ``values``. An effect's ``reason`` is a
            template and ``reason_values`` its numbers (a float array with a last
            axis, NaN-padded), so that a sweep stores one string per kind of
            reason, not one per point: ``reason.format(*reason_values)`` is the
            text of ``outcome()`` (numbers printed Python's way).
        """
        parameter = _core.check_str("parameter", parameter)
        errors = _core.check_errors(errors)
        threads = _core.check_threads(threads)
        b = _core.Batch({"values": values})
        result = b.record_columns(self._core.sweep(parameter, b["values"], b.n, b.shape_list, errors, threads),
                                  _results.SWEEP, errors)
        result["parameter"] = parameter
        result["values"] = b.out(b["values"])
        return result

    def trajectory(self, speed: Optional[float] = None, *, tolerance: float = COSTLY_TOLERANCE) -> Dict[str, Any]:
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
            Requested relative accuracy of the simulated outcome (default
            ``COSTLY_TOLERANCE``).
        """
        v = None if speed is None else _core.float_scalar("speed", speed)
        return self._core.trajectory(v, _core.float_scalar("tolerance", tolerance))

    def __repr__(self) -> str:
        return f"tabor.Scene(name={self.name!r})"


# --------------------------------------------------------------------------------
# single models (the CLI subcommands), built from the keyword tables of the native
# core (python/src/models/tables.rs): each keyword is written once, there


effective = _core.model_function(
    "effective",
    "Effective modulus, radius and mass of a two-body collision (``tabor effective``).\n\n"
    "``1/E* = (1-ν1²)/E1 + (1-ν2²)/E2``, ``1/R = 1/R1 + 1/R2``, ``m = m1 m2/(m1 + m2)``\n"
    "(Willert 2020, section 5.1).",
    "Returns a dict of ``effective_modulus`` (Pa), ``effective_radius`` (m), ``effective_mass`` (kg).",
    _results.keys(_results.EFFECTIVE),
)

_jkr = _core.model_function(
    "jkr",
    "JKR adhesive impact of a sphere (``tabor jkr``), Willert (2020) (5.33)-(5.38).\n\n"
    "Energy loss (5.36) ``|ΔU| = (1 + 864^(1/3))/10 · [R⁴(πΔγ)⁵/E*²]^(1/3)`` (fixed grip),\n"
    "sticking velocity (5.38) ``v_c = √(2|ΔU|/m)``, and at a given speed the maximum contact\n"
    "radius (5.35) and the restitution (5.37) ``ε = √(1 − v_c²/v0²)``. Inputs are the\n"
    "effective quantities of the collision (see ``effective``).",
    "Returns a dict: ``model``, ``branch``, ``separation`` (str), ``energy_loss``,\n"
    "``energy_loss_error`` (J), ``sticking_velocity`` (m/s), ``separation_force`` (N,\n"
    "negative), ``separation_contact_radius``, ``first_touch_contact_radius`` (m),\n"
    "``evaluations`` (int), and with ``speed``: ``impact_speed``, ``max_contact_radius`` (m),\n"
    "``restitution``, ``sticks``.",
    _results.keys(_results.JKR),
)
_jkr_no_speed = _results.keys(_results.JKR, speed=False)


def jkr(**kwargs: Any) -> Dict[str, Any]:  # noqa: D103 (the doc is the table's)
    result = _jkr(**kwargs)
    if kwargs.get("speed") is None:
        for k in list(result):
            if k not in _jkr_no_speed and k != "valid" and k in _results.JKR:
                del result[k]
    return result


jkr.__doc__ = _jkr.__doc__
jkr.__signature__ = _jkr.__signature__  # type: ignore[attr-defined]

plastic = _core.model_function(
    "plastic",
    "Elasto-plastic impact with and without adhesion (``tabor plastic``).\n\n"
    "Willert (2020) sections 5.5-5.6, (5.101)-(5.126); the dimensionless FEM fit (docs/sources.md)\n"
    "eqs. (12), (18), (19). Inputs are\n"
    "the effective quantities of the collision and the yield stress of the softer body.",
    "Returns a dict: ``model``, ``branch``, ``impact_speed``, ``restitution``, ``energy_loss``\n"
    "(J), ``sticks``, ``yield_velocity`` (m/s), ``sticking_velocity``,\n"
    "``elastic_sticking_velocity`` (m/s; NaN for the non-adhesive models),\n"
    "``adhesion_parameter`` (NaN unless adhesive-interpolation), ``clamping`` (None unless\n"
    "dimensionless-fit), ``warnings`` (the notes of each point, also emitted as\n"
    "``PlasticModelWarning``).",
    _results.keys(_results.PLASTIC),
)

visco = _core.model_function(
    "visco",
    "Viscoelastic impact without adhesion (``tabor visco``), Willert (2020) section 5.4.\n\n"
    "All parameters are dimensionless: D = η√(2a/(mG)) (5.55); δ = η(Rv0/(m²G³))^(1/5) for\n"
    "spheres (5.68), (5.90), (5.92), δ = η√(8a/(mG∞)) for the standard flat punch (5.79);\n"
    "β = G∞/G1; γ = λ d0^(b+1)/(m v0) (5.72).",
    "Returns a dict: ``model``, ``restitution``, ``evaluations`` (int) and, NaN where they do\n"
    "not apply, ``contact_time``, ``max_overlap`` (scaled), ``first_order_restitution``,\n"
    "``equivalent_kelvin_voigt_damping_ratio``, ``equivalent_kelvin_voigt_restitution``.",
    _results.keys(_results.VISCO),
)

penalty = _core.model_function(
    "penalty",
    "Penalty contact laws for multibody codes (``tabor penalty``): the parameters for a\n"
    "nominal restitution and what a simulated impact achieves.\n\n"
    "Laws: numpedia's contact characteristic (docs/sources.md) ``F = k κ(h, ε) l(v, V)`` with the loss speed V\n"
    "calibrated exactly; ``F = K δⁿ (1 + χ δ̇)`` with χ = 3(1 − e)/(2v0) (Hunt-Crossley),\n"
    "3(1 − e²)/(4v0) (Lankarani-Nikravesh), 8(1 − e)/(5 e v0) (Flores).",
    "Returns a dict: ``law``, ``nominal_restitution``, ``achieved_restitution`` (simulated),\n"
    "``closed_form_restitution``, ``stiffness``, ``exponent``, ``effective_mass``,\n"
    "``impact_speed``, ``max_overlap`` (m), ``max_force`` (N), ``contact_time`` (s),\n"
    "``energy_error``, and (NaN where they do not apply) ``damping_factor`` (s/m),\n"
    "``damping_coefficient``, ``exact_damping_factor``, ``loss_speed`` (m/s), ``rounding``.",
    _results.keys(_results.PENALTY),
)


del Any, Dict, Optional, Tuple, annotations
