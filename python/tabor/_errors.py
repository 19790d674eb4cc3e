"""The exceptions and warnings of ``tabor`` (raised and emitted by the native core).

Exceptions: every error of the library is a :class:`TaborError`; bad input is an
:class:`InputError` (a ``ValueError``), valid input outside a model's validity a
:class:`ModelValidityError` (also a ``ValueError``), a numerical method that did not
converge a :class:`ConvergenceError` (a ``RuntimeError``). A wrong type is a
``TypeError``.

Warnings: every validity warning of the library is a :class:`TaborWarning`, with one
subclass per warning code of the library (``quasi-static`` is
:class:`QuasiStaticWarning`, …); filter them with the ``warnings`` module as usual
(``warnings.simplefilter("error", tabor.QuasiStaticWarning)``).
"""

from __future__ import annotations

import os
import sys
import warnings
from typing import Dict, Optional, Type

_PACKAGE = os.path.dirname(os.path.abspath(__file__))


def stacklevel() -> int:
    """The stack level of the first frame outside this package, seen from the
    caller of this function (so that a warning points at the user's call)."""
    frame = sys._getframe(1)
    level = 1
    while frame is not None and os.path.abspath(frame.f_code.co_filename).startswith(_PACKAGE):
        frame = frame.f_back
        level += 1
    return level

__all__ = [
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


class TaborError(Exception):
    """Base of every error raised by the library."""


class InputError(TaborError, ValueError):
    """Bad input: the message names the parameter, its value and (in a batch) the
    index of the first bad element."""


class ModelValidityError(TaborError, ValueError):
    """Valid input for which the model does not hold (small strain exceeded, a
    parameter outside the range the model was derived for, ...)."""


class ConvergenceError(TaborError, RuntimeError):
    """A root search, quadrature or integration did not reach its tolerance."""


class TaborWarning(UserWarning):
    """Base of every validity warning of the library."""


class QuasiStaticWarning(TaborWarning):
    """The impact speed is not small against the elastic wave speed (Willert
    2020, eq. (5.4)): energy radiated as elastic waves is neglected."""


class CoupledModelWarning(TaborWarning):
    """A coupled model of ours (adhesion with viscoelasticity) answers: no
    published reference checks it."""


class ElasticLimitWarning(TaborWarning):
    """The contact yields at this speed (Willert 2020, eq. (5.13)): an elastic model
    overestimates the restitution."""


class StickingVelocityWarning(TaborWarning):
    """The sticking velocity lies where the quasi-static assumption fails."""


class SuperposedLossesWarning(TaborWarning):
    """The losses of the effects are added (a bound, not a coupled model)."""


class PlasticModelWarning(TaborWarning):
    """A note of the elasto-plastic models (elastic impact below the yield
    velocity, a clamped fit, a parameter given directly)."""


class InvalidPointsWarning(TaborWarning):
    """``errors="nan"``: some points were invalid and are NaN (None, False) in the
    result; the message gives the count and the first failure."""


_BY_CODE: Dict[str, Type[TaborWarning]] = {
    "quasi-static": QuasiStaticWarning,
    "coupled-model": CoupledModelWarning,
    "elastic-limit": ElasticLimitWarning,
    "sticking-velocity-not-quasi-static": StickingVelocityWarning,
    "superposed-losses": SuperposedLossesWarning,
}


def category(code: str) -> Type[TaborWarning]:
    """The warning class of a library warning code (a new code of the library gets
    a ``TaborWarning`` subclass named after it, created once)."""
    cls = _BY_CODE.get(code)
    if cls is None:
        if " " in code or not code:  # a plain sentence (the plastic model's notes)
            return PlasticModelWarning
        name = "".join(part.capitalize() for part in code.replace("_", "-").split("-")) + "Warning"
        cls = type(name, (TaborWarning,), {"__doc__": f"The library's warning {code!r}.", "__module__": "tabor"})
        _BY_CODE[code] = cls
    return cls


def _warn(code: str, message: str, count: int, total: int, first: Optional[str]) -> None:
    """Emits one warning for ``count`` of ``total`` elements (called by the native
    core once per code and call)."""
    if total > 1 or first:
        where = f" at {first}" if first and not first[0].isdigit() and not first.startswith("(") else (
            f" (first at index {first})" if first else ""
        )
        text = f"{message} [{count} of {total} points{where}]" if total > 1 else f"{message}{where}"
    else:
        text = message
    warnings.warn(text, category(code), stacklevel=stacklevel())
