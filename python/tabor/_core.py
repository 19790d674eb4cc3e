"""Argument checking, broadcasting and result assembly shared by every function
(private: the public API is in ``tabor/__init__.py``)."""

from __future__ import annotations

import inspect
import itertools
import numbers
import os
import warnings
from typing import Any, Callable, Dict, List, Optional, Sequence, Tuple

import numpy as np

from . import _tabor
from ._errors import InvalidPointsWarning, stacklevel


def check_bool(name: str, value: Any) -> bool:
    """``True`` or ``False`` (numpy's bool too); anything else is a TypeError."""
    if isinstance(value, (bool, np.bool_)):
        return bool(value)
    raise TypeError(f"{name} must be True or False, not {type(value).__name__}")


def check_str(name: str, value: Any) -> str:
    if isinstance(value, str):
        return value
    raise TypeError(f"{name} must be a str, not {type(value).__name__}")


#: The default of every ``errors=`` (``"raise"``; the values: ``_tabor.ERRORS``).
DEFAULT_ERRORS: str = _tabor.ERRORS[0]


def check_errors(errors: Any) -> str:
    check_str("errors", errors)
    if errors not in _tabor.ERRORS:
        from ._errors import InputError

        expected = " or ".join(f'"{e}"' for e in _tabor.ERRORS)
        raise InputError(f'invalid errors = "{errors}": expected {expected}')
    return errors


def check_threads(threads: Any) -> Optional[int]:
    if threads is None:
        return None
    if isinstance(threads, bool) or not isinstance(threads, numbers.Integral):
        raise TypeError(f"threads must be an int or None, not {type(threads).__name__}")
    if threads < 1 or threads > MAX_THREADS:
        from ._errors import InputError

        raise InputError(f"invalid threads = {threads}: must be >= 1 and <= {MAX_THREADS}")
    return int(threads)


#: The most threads a batch may use (checked before any is spawned): 2**63 threads
#: stalled the machine, 100000 took 11 s to fail.
MAX_THREADS = 1024


def float_scalar(name: str, value: Any) -> float:
    """One real number (a Python or numpy scalar, or an array of one element); an
    array of several is a TypeError naming `name`."""
    a = float_array(name, value)
    if a.size != 1:
        raise TypeError(f"{name} must be one real number, not an array of shape {a.shape}")
    return float(a.reshape(()))


def float_array(name: str, value: Any) -> np.ndarray:
    """A float64 array of a real number or an array_like of real numbers; None,
    strings, complex numbers and bools are a TypeError."""
    if value is None or isinstance(value, (str, bytes, bool, np.bool_)):
        raise TypeError(f"{name} must be a real number or an array of real numbers, not {type(value).__name__}")
    try:
        a = np.asarray(value)
    except (TypeError, ValueError) as e:
        raise TypeError(f"{name} must be a real number or an array of real numbers ({e})") from None
    if a.dtype.kind not in "iuf":
        what = {"c": "complex", "b": "bool", "U": "str", "S": "bytes", "O": "object"}.get(a.dtype.kind, str(a.dtype))
        raise TypeError(f"{name} must be a real number or an array of real numbers, not an array of {what}")
    check_elements(name, a.size)
    return a.astype(np.float64, copy=False)


def _max_elements() -> int:
    """The most elements a batch may have: the machine's memory over the bytes a
    batch needs per element (python/README: 10**7 elements peak at 1.15 GiB, about
    115 bytes each; 128 here)."""
    try:
        memory = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    except (AttributeError, ValueError, OSError):
        memory = 16 * 2**30
    return max(memory // 128, 10**6)


#: The most elements a batch may have (the machine's memory / 128 bytes): larger
#: inputs are refused before anything is copied (a zero-stride view of 3e9
#: elements was copied in full).
MAX_ELEMENTS = _max_elements()


def check_elements(name: str, size: int) -> None:
    """Refuses `size` elements beyond MAX_ELEMENTS, naming `name`."""
    if size > MAX_ELEMENTS:
        from ._errors import InputError

        raise InputError(
            f"invalid {name}: {size} elements, more than this machine's memory allows "
            f"(at most {MAX_ELEMENTS}, about 128 bytes each)"
        )


class Batch:
    """Named arguments broadcast together; flat columns for the native core."""

    def __init__(self, arguments: Dict[str, Any]) -> None:
        arrays = {k: float_array(k, v) for k, v in arguments.items() if v is not None}
        try:
            self.shape: Tuple[int, ...] = np.broadcast_shapes(*(a.shape for a in arrays.values()))
        except ValueError:
            from ._errors import InputError

            shapes = ", ".join(f"{k} {a.shape}" for k, a in arrays.items())
            raise InputError(f"the arguments do not broadcast together: {shapes}") from None
        self.scalar = all(a.ndim == 0 for a in arrays.values())
        self.n = int(np.prod(self.shape, dtype=object)) if self.shape else 1
        check_elements(", ".join(arrays) or "arguments", self.n)
        self.columns: Dict[str, Optional[np.ndarray]] = {k: None for k in arguments}
        for k, a in arrays.items():
            if a.size == 1:
                self.columns[k] = np.ascontiguousarray(a.reshape(1))
            else:
                self.columns[k] = np.ascontiguousarray(np.broadcast_to(a, self.shape)).reshape(-1)

    def __getitem__(self, name: str) -> Optional[np.ndarray]:
        return self.columns[name]

    @property
    def shape_list(self) -> List[int]:
        return [] if self.scalar else list(self.shape)

    def out(self, flat: np.ndarray) -> Any:
        if self.scalar:
            return float(flat[0])
        return flat.reshape(self.shape)

    def outs(self, result: Tuple[Tuple[np.ndarray, ...], Tuple[int, Optional[str]]]) -> Tuple[Any, ...]:
        arrays, report = result
        self.report(report)
        return tuple(self.out(a) for a in arrays)

    def report(self, report: Tuple[int, Optional[str]]) -> None:
        failed, first = report
        if failed:
            warnings.warn(
                f"{failed} of {self.n} points invalid, set to NaN; the first: {first}",
                InvalidPointsWarning,
                stacklevel=stacklevel(),
            )

    def column(self, value: Any) -> Any:
        """One column from the native core as an array of the broadcast shape (or
        a Python scalar for a scalar call)."""
        if isinstance(value, tuple):  # ("null", n): no element has a value
            flat = np.full(value[1], None, dtype=object)
        else:
            flat = value
        if self.scalar:
            x = flat[0] if len(flat) else None
            if isinstance(x, np.bool_):
                return bool(x)
            if isinstance(x, np.floating):
                return float(x)
            if isinstance(x, np.integer):
                return int(x)
            return x
        return flat.reshape(self.shape)

    def numbers(self, key: str, columns: Dict[str, Any]) -> np.ndarray:
        """The float columns ``key.0``, ``key.1``, ... (a reason's numbers) as one
        array with a last axis of their count (NaN where a point has fewer)."""
        parts = []
        while f"{key}.{len(parts)}" in columns:
            v = columns.pop(f"{key}.{len(parts)}")
            if isinstance(v, tuple):  # no point had this many numbers
                v = np.full(v[1], np.nan)
            parts.append(v)
        flat = np.stack(parts, axis=-1) if parts else np.empty((self.n, 0))
        if self.scalar:
            return flat[0] if len(flat) else np.empty(0)
        return flat.reshape(tuple(self.shape) + (flat.shape[-1],))

    def record_columns(self, result: Tuple[Dict[str, Any], Tuple[int, Optional[str]]],
                       schema: Dict[str, str], errors: str) -> Dict[str, Any]:
        columns, report = result
        self.report(report)
        # the schema's keys, then any other key (after the schema's have been popped)
        keys = itertools.chain(schema, iter(lambda: next(iter(columns), None), None))
        result_dict = {}
        for k in keys:
            kind = schema.get(k)
            if kind == "floats":
                result_dict[k] = self.numbers(k, columns)
                continue
            # popped one by one: a column's codes are freed once it is expanded
            v = columns.pop(k, ("null", self.n))
            if isinstance(v, tuple) and v[0] == "null" and kind in ("float", "int", "bool"):
                v = np.full(v[1], {"float": np.nan, "int": -1, "bool": False}[kind],
                            dtype={"float": np.float64, "int": np.int64, "bool": np.bool_}[kind])
            result_dict[k] = self.column(v)
        return result_dict


def signature(spec: Sequence[Tuple[str, str, Any, Any, str]], extra: Sequence[inspect.Parameter] = ()) -> inspect.Signature:
    """The keyword-only signature of a model function from its table."""
    params = []
    for name, kind, default, _choices, _help in spec:
        if kind == "optional":
            d = None
        elif kind == "flag":
            d = False
        else:
            d = inspect.Parameter.empty if default is None else default
        params.append(inspect.Parameter(name, inspect.Parameter.KEYWORD_ONLY, default=d))
    return inspect.Signature(params + list(extra))


def keyword_doc(spec: Sequence[Tuple[str, str, Any, Any, str]]) -> str:
    """The "Keyword arguments" section of a model function from its table."""
    lines = ["Keyword arguments (CLI flag in brackets):"]
    for name, kind, default, choices, help_ in spec:
        # the command line keeps its own name where Python renamed a keyword
        cli = {new: old for old, new in RENAMED_KEYWORDS.items() if old != "elastic_modulus"}.get(name, name)
        flag = "--" + cli.replace("_", "-")
        if kind == "choice":
            opts = "".join(f'\n      "{c}": {about}' for c, about in choices)
            tail = (f' Default "{default}".' if default else " Required.") + " One of:" + opts
        elif kind == "number" and default is not None:
            tail = f" Default {default!r}."
        elif kind == "optional":
            tail = " Optional."
        elif kind == "flag":
            tail = " True or False (default False)."
        else:
            tail = " Required."
        lines.append(f"  {name} [{flag}]: {help_}.{tail}")
    return "\n".join(lines)


COMMON = [
    inspect.Parameter("errors", inspect.Parameter.KEYWORD_ONLY, default=DEFAULT_ERRORS),
    inspect.Parameter("threads", inspect.Parameter.KEYWORD_ONLY, default=None),
]


#: Keywords renamed so that each quantity has one name across the package:
#: old name -> the name to use (the old one still works, with a DeprecationWarning).
RENAMED_KEYWORDS: Dict[str, str] = {"modulus": "contact_modulus", "elastic_modulus": "contact_modulus"}


def renamed(function: str, kwargs: Dict[str, Any]) -> Dict[str, Any]:
    """``kwargs`` with the renamed keywords (``RENAMED_KEYWORDS``) under their new
    names, each use warned once as a DeprecationWarning; both names at once is a
    TypeError."""
    out = dict(kwargs)
    for old, new in RENAMED_KEYWORDS.items():
        if old in out:
            if new in out:
                raise TypeError(f"{function}(): give {new} (the old name {old} as well is ambiguous)")
            warnings.warn(f"{function}(): {old}= is now {new}= (one name per quantity, as the Adhesion "
                          "package names it)", DeprecationWarning, stacklevel=3)
            out[new] = out.pop(old)
    return out


def model_function(name: str, summary: str, returns: str, schema: Dict[str, str]) -> Callable[..., Dict[str, Any]]:
    """A model function (``tabor.jkr``, …) built from its keyword table."""
    spec = _tabor.SPECS[name]
    kinds = {k: kind for k, kind, *_ in spec}
    sig = signature(spec, COMMON)

    def function(**kwargs: Any) -> Dict[str, Any]:
        kwargs = renamed(name, kwargs)
        try:
            bound = sig.bind(**kwargs)
        except TypeError as e:
            raise TypeError(f"{name}(): {e}") from None
        bound.apply_defaults()
        args = dict(bound.arguments)
        errors = check_errors(args.pop("errors"))
        threads = check_threads(args.pop("threads"))
        numbers_ = {k: v for k, v in args.items() if kinds[k] in ("number", "optional")}
        b = Batch(numbers_)
        native: Dict[str, Any] = {}
        for k, v in args.items():
            kind = kinds[k]
            if kind in ("number", "optional"):
                native[k] = b[k]
            elif kind == "flag":
                native[k] = check_bool(k, v)
            else:
                native[k] = check_str(k, v)
        return b.record_columns(_tabor.model(name, native, b.n, b.shape_list, errors, threads), schema, errors)

    function.__name__ = function.__qualname__ = name
    function.__module__ = "tabor"
    function.__signature__ = sig  # type: ignore[attr-defined]
    function.__doc__ = (
        f"{summary}\n\n{keyword_doc(spec)}\n"
        "  errors: \"raise\" (default) raises on the first invalid point; \"nan\" sets invalid\n"
        "    points to NaN (None, False, -1) with a count in an InvalidPointsWarning and adds\n"
        "    a bool column \"valid\".\n"
        "  threads: threads for this call (default: tabor.set_num_threads, else\n"
        "    RAYON_NUM_THREADS or all cores).\n\n"
        f"{returns}"
    )
    return function
