"""Type stubs of the Python package `tabor` (see __init__.py for the docs)."""

from os import PathLike
from typing import Any, Dict, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str
__all__: list

LAMBDA_PER_MAUGIS_PARAMETER: float
MAUGIS_PER_TABOR_MU: float
FAST_TIER_RELATIVE_ERROR: float

ArrayLike = Union[float, Sequence[float], npt.NDArray[Any]]
FloatOrArray = Union[float, npt.NDArray[np.float64]]

@overload
def maugis_dugdale_loss(tabor_parameter: float, *, tolerance: float = ..., fast: bool = ...) -> float: ...
@overload
def maugis_dugdale_loss(
    tabor_parameter: ArrayLike, *, tolerance: ArrayLike = ..., fast: bool = ...
) -> FloatOrArray: ...
@overload
def maugis_dugdale_curve(maugis_parameter: float, contact_radius: float) -> Tuple[float, float]: ...
@overload
def maugis_dugdale_curve(
    maugis_parameter: ArrayLike, contact_radius: ArrayLike
) -> Tuple[FloatOrArray, FloatOrArray]: ...
@overload
def tabor_parameter_from_maugis(maugis_parameter: float) -> float: ...
@overload
def tabor_parameter_from_maugis(maugis_parameter: ArrayLike) -> FloatOrArray: ...
@overload
def tabor_parameter_from_tabor_mu(tabor_mu: float) -> float: ...
@overload
def tabor_parameter_from_tabor_mu(tabor_mu: ArrayLike) -> FloatOrArray: ...
@overload
def maugis_parameter(tabor_parameter: float) -> float: ...
@overload
def maugis_parameter(tabor_parameter: ArrayLike) -> FloatOrArray: ...
def jkr_normalized_loss() -> float: ...

class Scene:
    @classmethod
    def from_toml(cls, text: str) -> Scene: ...
    @classmethod
    def from_json(cls, text: str) -> Scene: ...
    @classmethod
    def from_path(cls, path: Union[str, PathLike]) -> Scene: ...
    @property
    def name(self) -> str: ...
    @property
    def speed(self) -> Optional[float]: ...
    @property
    def tabor_parameter(self) -> Optional[float]: ...
    def outcome(self, speed: Optional[float] = ...) -> Dict[str, Any]: ...
    @overload
    def restitution(self, speeds: float) -> float: ...
    @overload
    def restitution(self, speeds: ArrayLike) -> FloatOrArray: ...
    def sticking_velocity(self) -> Optional[float]: ...
    def sweep(self, parameter: str, values: ArrayLike) -> Dict[str, Any]: ...
    def trajectory(self, speed: Optional[float] = ..., *, tolerance: float = ...) -> Dict[str, Any]: ...

def effective(
    *,
    youngs_modulus: ArrayLike,
    poisson_ratio: ArrayLike,
    radius: ArrayLike,
    density: Optional[ArrayLike] = ...,
    mass: Optional[ArrayLike] = ...,
    target_youngs_modulus: Optional[ArrayLike] = ...,
    target_poisson_ratio: Optional[ArrayLike] = ...,
    rigid_target: bool = ...,
    target_radius: Optional[ArrayLike] = ...,
    target_density: Optional[ArrayLike] = ...,
    target_mass: Optional[ArrayLike] = ...,
) -> Dict[str, Any]: ...
def jkr(
    *,
    modulus: ArrayLike,
    radius: ArrayLike,
    work_of_adhesion: ArrayLike,
    mass: ArrayLike,
    speed: Optional[ArrayLike] = ...,
    separation: str = ...,
    tolerance: ArrayLike = ...,
) -> Dict[str, Any]: ...
def plastic(
    *,
    model: str,
    modulus: ArrayLike,
    radius: ArrayLike,
    mass: ArrayLike,
    yield_stress: ArrayLike,
    speed: ArrayLike,
    poisson_ratio: Optional[ArrayLike] = ...,
    density: Optional[ArrayLike] = ...,
    work_of_adhesion: Optional[ArrayLike] = ...,
    adhesion_parameter: Optional[ArrayLike] = ...,
    plastic_model: str = ...,
) -> Dict[str, Any]: ...
def visco(
    *,
    model: str,
    damping_ratio: Optional[ArrayLike] = ...,
    viscous_parameter: Optional[ArrayLike] = ...,
    modulus_ratio: Optional[ArrayLike] = ...,
    damping: Optional[ArrayLike] = ...,
    damping_exponent: Optional[ArrayLike] = ...,
    alpha: Optional[ArrayLike] = ...,
    poisson_ratio: Optional[ArrayLike] = ...,
    bulk_damping_ratio: Optional[ArrayLike] = ...,
    tolerance: ArrayLike = ...,
) -> Dict[str, Any]: ...
def penalty(
    *,
    law: str,
    restitution: ArrayLike,
    stiffness: ArrayLike = ...,
    exponent: Optional[ArrayLike] = ...,
    rounding: ArrayLike = ...,
    mass: ArrayLike = ...,
    speed: ArrayLike = ...,
) -> Dict[str, Any]: ...
