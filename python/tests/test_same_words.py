"""The same bad input gives the same words in Python as on the command line, in the Octave
package and on the page: every rule is checked and worded once, in the operation layer
(cagd-ops), and the package only puts the Python name of the argument in front.

Each row: a call, the kind `CagdError.kind` carries (the library's error underneath, or the
operation layer's own kind), the argument it names, and the whole message. The words after
``NAME: `` are the operation layer's, as the command line prints them after its own name of the
argument (``cagd bspline ... --knots "[0 0 0 1 1 1]"`` prints ``--knots: knot vector: expected 7
knots ...``); a limit says how to raise it in Python's terms (``cagd.set_limit``) where the
command line names its option.
"""

from fractions import Fraction as F

import numpy as np
import pytest

import cagd

nan, inf = float("nan"), float("inf")

KNOTS_FORM = (
    "expected n + p + 1 non-decreasing knots for n control points of degree p (n ≥ p + 1), "
    "with u_(p+1) < u_(n+1)"
)
FINITE = "expected finite numbers"
WEIGHTS_FORM = "expected one positive weight per control point"
DEGREE_LIMIT = 'exceeds the limit of 1000 (raise it with cagd.set_limit("max_degree", VALUE))'
LOWER_DEGREE = "expected a lower degree (fewer control points or nodes)"

four = [[0, 0], [1, 1], [2, 0], [3, 1]]
three = [[0, 0], [1, 1], [2, 0]]
line = cagd.BezierCurve([[0, 0], [1, 0]])

ROWS = [
    # --- knots: count, order, finiteness, domain, control points for the degree
    (
        "one knot too few",
        lambda: cagd.BSplineCurve(2, [0, 0, 0, 1, 1, 1], four),
        "KnotCount",
        "knots",
        f"knots: knot vector: expected 7 knots (control points + degree + 1), got 6; {KNOTS_FORM}",
    ),
    (
        "one knot too many",
        lambda: cagd.BSplineCurve(2, [0, 0, 0, 0.5, 0.7, 1, 1, 1], four),
        "KnotCount",
        "knots",
        f"knots: knot vector: expected 7 knots (control points + degree + 1), got 8; {KNOTS_FORM}",
    ),
    (
        "a knot falling back",
        lambda: cagd.BSplineCurve(2, [0, 0, 0.5, 0.2, 1, 1, 1], four),
        "DecreasingKnots",
        "knots",
        "knots: knot vector: knot 4 (0.2) is below the knot before it (0.5); knots must be "
        f"non-decreasing; {KNOTS_FORM}",
    ),
    (
        "a NaN knot",
        lambda: cagd.BSplineCurve(2, [0, 0, nan, 0.5, 1, 1, 1], four),
        "NonFinite",
        "knots",
        f"knots: value 3 is not finite (NaN); {FINITE}",
    ),
    (
        "an empty domain inside repeated knots",
        lambda: cagd.BSplineCurve(2, [0, 0, 1, 1, 1, 2, 2], four),
        "EmptyInterval",
        "knots",
        f"knots: knot domain [u_(p+1), u_(n+1)]: interval [1, 1] is empty (expected a < b); {KNOTS_FORM}",
    ),
    (
        "too few control points for the degree",
        lambda: cagd.BSplineCurve(3, [0, 0, 0, 0, 1, 1], [[0, 0], [1, 1]]),
        "TooFewControlPoints",
        "points",
        "points: control points: degree 3 needs at least 4 control point(s), got 2; "
        f"{KNOTS_FORM}",
    ),
    (
        "NURBS knots one too few",
        lambda: cagd.NurbsCurve(2, [0, 0, 0, 1, 1], three, [1, 1, 1]),
        "KnotCount",
        "knots",
        f"knots: knot vector: expected 6 knots (control points + degree + 1), got 5; {KNOTS_FORM}",
    ),
    (
        "surface knots along u one too few",
        lambda: cagd.BSplineSurface((1, 1), [0, 0, 1], [0, 0, 1, 1], np.zeros((2, 2, 3))),
        "KnotCount",
        "knots_u",
        "knots_u: knot vector along u: expected 4 knots (control points + degree + 1), got 3; "
        f"{KNOTS_FORM}",
    ),
    # --- weights
    (
        "a negative weight",
        lambda: cagd.NurbsCurve(2, [0, 0, 0, 1, 1, 1], three, [1, -1, 1]),
        "NonPositiveWeight",
        "weights",
        f"weights: NURBS weights: weight 2 is -1; weights must be positive; {WEIGHTS_FORM}",
    ),
    (
        "a zero weight",
        lambda: cagd.NurbsCurve(2, [0, 0, 0, 1, 1, 1], three, [1, 0, 1]),
        "NonPositiveWeight",
        "weights",
        f"weights: NURBS weights: weight 2 is 0; weights must be positive; {WEIGHTS_FORM}",
    ),
    (
        "one weight too few",
        lambda: cagd.NurbsCurve(2, [0, 0, 0, 1, 1, 1], three, [1, 1]),
        "ShapeMismatch",
        "weights",
        "weights: NURBS weights: expected 3 weights (one per control point), found 2; "
        f"{WEIGHTS_FORM}",
    ),
    (
        "a NaN weight",
        lambda: cagd.NurbsCurve(2, [0, 0, 0, 1, 1, 1], three, [1, nan, 1]),
        "NonFinite",
        "weights",
        f"weights: value 2 is not finite (NaN); {FINITE}",
    ),
    # --- non-finite values (counted point by point, as Octave counts down the columns)
    (
        "a NaN control point of a B-spline",
        lambda: cagd.BSplineCurve(2, [0, 0, 0, 0.5, 1, 1, 1], [[0, 0], [nan, 1], [2, 0], [3, 1]]),
        "NonFinite",
        "points",
        f"points: value 3 is not finite (NaN); {FINITE}",
    ),
    (
        "an infinite Bézier control point",
        lambda: cagd.BezierCurve([[0, 0], [1, inf]]),
        "NonFinite",
        "points",
        f"points: value 4 is not finite (inf); {FINITE}",
    ),
    (
        "a NaN among exact control points",
        lambda: cagd.BezierCurve([[F(1, 2), 0], [1, nan]]),
        "NonFinite",
        "points",
        f"points: value 4 is not finite (NaN); {FINITE}",
    ),
    (
        "a NaN parameter",
        lambda: line(np.array([0.5, nan])),
        "NonFinite",
        "t",
        f"t: value 2 is not finite (NaN); {FINITE}",
    ),
    (
        "a NaN in a thesis function's control points",
        lambda: cagd.octave.deCasteljau(np.array([[0.0, 1.0], [0.0, nan]]), 3),
        "NonFinite",
        "kontrolneT",
        f"kontrolneT: value 4 is not finite (NaN); {FINITE}",
    ),
    # --- the degree limit
    (
        "a Bézier curve of degree 1001",
        lambda: cagd.BezierCurve(np.zeros((1002, 1))),
        "TooLarge",
        "points",
        f"points: degree: 1001 {DEGREE_LIMIT}; {LOWER_DEGREE}",
    ),
    (
        "a B-spline of degree 1001",
        lambda: cagd.BSplineCurve.clamped(1001, np.zeros((4, 2))),
        "TooLarge",
        "degree",
        f"degree: degree: 1001 {DEGREE_LIMIT}; {LOWER_DEGREE}",
    ),
    (
        "Bernstein polynomials of degree 5000",
        lambda: cagd.bernstein(0, 5000, 0.5),
        "TooLarge",
        "n",
        f"n: degree: 5000 {DEGREE_LIMIT}; {LOWER_DEGREE}",
    ),
    (
        "a Bernstein index above the degree",
        lambda: cagd.bernstein(5, 3, 0.5),
        "Shape",
        "i",
        "i: i = 5 exceeds the degree 3; expected an index 0 ≤ i ≤ n",
    ),
]


@pytest.mark.parametrize("row", ROWS, ids=[r[0] for r in ROWS])
def test_the_operation_layers_words(row):
    _, call, kind, argument, message = row
    with pytest.raises(cagd.CagdError) as info:
        call()
    assert str(info.value) == message
    assert info.value.kind == kind
    assert info.value.argument == argument


def test_the_largest_allowed_degree_is_accepted():
    """The limit is the same on both sides of it: degree 1000 is built, 1001 is refused."""
    assert cagd.BezierCurve(np.zeros((1001, 1))).degree == 1000
    assert cagd.BSplineCurve.clamped(1000, np.zeros((1001, 1))).degree == 1000
