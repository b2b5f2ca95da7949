"""Type stubs of ``cagd.octave``: the thesis functions with Octave's layouts (points as columns)."""

from fractions import Fraction
from os import PathLike
from typing import Any, Tuple, Union

from numpy.typing import ArrayLike, NDArray

__all__ = [
    "deCasteljau",
    "ploskevB",
    "bilinearna",
    "tenzor",
    "krpaCoons",
    "vrednostCoons",
    "krpaGordon",
    "Lagrange",
    "load",
    "save",
]

_Number = Union[float, int, Fraction]
_Array = NDArray[Any]

def deCasteljau(kontrolneT: ArrayLike, N: int) -> _Array:
    """``T = deCasteljau(kontrolneT, N)``: ``d × (n+1)`` control points (columns) → ``d × N`` samples."""
def ploskevB(kontrolneT: ArrayLike, N: int) -> _Array:
    """``P = ploskevB(kontrolneT, N)``: packed net ``(m+1) × 3(n+1)`` → ``N × N × 3``."""
def bilinearna(B: ArrayLike, u: _Number, v: _Number, N: int) -> _Array:
    """``L = bilinearna(B, u, v, N)``: the point ``x(u, v)`` as ``1 × 1 × 3``."""
def tenzor(B: ArrayLike) -> _Array:
    """``A = tenzor(B)``: ``(m+1) × 3(n+1)`` → ``(m+1) × (n+1) × 3``."""
def krpaCoons(c1: ArrayLike, c2: ArrayLike, d1: ArrayLike, d2: ArrayLike, P1: ArrayLike, P2: ArrayLike, P3: ArrayLike, P4: ArrayLike) -> Tuple[_Array, _Array]:
    """``R, P = krpaCoons(...)``: ``R`` packed ``N × 3N``, ``P`` ``N × N × 3``."""
def vrednostCoons(u: _Number, v: _Number, c1: ArrayLike, c2: ArrayLike, d1: ArrayLike, d2: ArrayLike, P1: ArrayLike, P2: ArrayLike, P3: ArrayLike, P4: ArrayLike) -> Tuple[_Array, _Array, _Array, _Array]:
    """``T, rc, rd, rcd = vrednostCoons(...)``, each ``d × 1``."""
def krpaGordon(g_u: ArrayLike, g_v: ArrayLike, g_uv: ArrayLike, x_u: ArrayLike, x_v: ArrayLike, N: int) -> Tuple[_Array, _Array]:
    """``R, P = krpaGordon(...)``: ``R`` packed ``N × 3N``, ``P`` ``N × N × 3``."""
def Lagrange(x: ArrayLike, m: int, u: Union[_Number, ArrayLike]) -> Any:
    """``v = Lagrange(x, m, u)``: the ``m``-th (from 1) Lagrange basis polynomial at ``u``."""
def load(path: Union[str, PathLike[str]]) -> dict[str, Any]:
    """The variables of an Octave text file (``save -text``)."""
def save(path: Union[str, PathLike[str]], **variables: ArrayLike) -> None:
    """Writes the variables as an Octave text file (``save -text``)."""
