"""cagd — Bézier, Coons and Gordon patches, B-splines and NURBS, exact where the maths is rational.

A thin Python front end over the Rust library ``cagd`` (the same mathematics as its command
line, its Octave package and its web page):

- ``cagd.octave``: the eight functions of the thesis (``deCasteljau``, ``ploskevB``,
  ``bilinearna``, ``tenzor``, ``krpaCoons``, ``vrednostCoons``, ``krpaGordon``, ``Lagrange``),
  fixed, with the arguments and array layouts of the Octave code (points as columns);
- classes for the course, points as rows (numpy's convention): ``BezierCurve``,
  ``BezierPatch``, ``CoonsPatch``, ``GordonSurface``, ``Lagrange``, ``HermiteCubic``,
  ``CubicSpline``, ``BSplineCurve``, ``BSplineSurface``, ``NurbsCurve``, ``NurbsSurface``, …;
- ``cagd.BSpline``: a drop-in for evaluating ``scipy.interpolate.BSpline``.

Exact arithmetic: pass ``fractions.Fraction`` values (or ``dtype=object`` arrays) and every
result is exact, as ``Fraction``\\ s.

Errors: every input cagd cannot use raises ``cagd.CagdError`` (a ``ValueError``) with
``kind`` and ``argument``.

>>> import cagd
>>> from fractions import Fraction as F
>>> c = cagd.BezierCurve([[0, 0, 0], [0, 2, 2], [8, 2, 0], [4, 0, 0]], exact=True)
>>> c(F(1, 2)).tolist()
[Fraction(7, 2), Fraction(3, 2), Fraction(3, 4)]
"""

from ._cagd import (
    CagdError,
    limits,
    set_limit,
    Steps,
    BezierCurve,
    BezierPatch,
    BSplineCurve,
    BSplineSurface,
    NurbsCurve,
    NurbsSurface,
    HermiteCubic,
    CubicSpline,
    Lagrange,
    CoonsPatch,
    GordonSurface,
    discrete_coons,
    bernstein,
    conversion_matrix,
    convert_cubic,
    continuity,
)
from . import octave
from ._bspline import BSpline

__all__ = [
    "CagdError",
    "limits",
    "set_limit",
    "Steps",
    "BezierCurve",
    "BezierPatch",
    "BSplineCurve",
    "BSplineSurface",
    "NurbsCurve",
    "NurbsSurface",
    "HermiteCubic",
    "CubicSpline",
    "Lagrange",
    "CoonsPatch",
    "GordonSurface",
    "discrete_coons",
    "bernstein",
    "conversion_matrix",
    "convert_cubic",
    "continuity",
    "octave",
    "BSpline",
]
__version__ = "0.1.0"
