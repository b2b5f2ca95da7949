"""Exact answers of the sources' worked examples (docs/SOURCES.md), in Fractions."""

from fractions import Fraction as F

import numpy as np

import cagd
from cagd import octave


def fr(*xs):
    return [F(x) for x in xs]


def test_primer_2_4_thesis_function():
    # Thesis Primer 2.4: b0 = (0,0,0), b1 = (0,2,2), b2 = (8,2,0), b3 = (4,0,0); b(1/2) = (7/2, 3/2, 3/4).
    b = np.array([[0, 0, 8, 4], [0, 2, 2, 0], [0, 2, 0, 0]], dtype=object)
    t = octave.deCasteljau(b, 3)
    assert t[:, 1].tolist() == fr("7/2", "3/2", "3/4")
    assert t[:, 2].tolist() == fr(4, 0, 0)


def test_primer_2_4_scheme():
    c = cagd.BezierCurve([[0, 0, 0], [0, 2, 2], [8, 2, 0], [4, 0, 0]], exact=True)
    s = c.scheme(F(1, 2))
    assert s["r = 1"].tolist() == [fr(0, 1, 1), fr(4, 2, 1), fr(6, 1, 0)]
    assert s["r = 2"].tolist() == [fr(2, "3/2", 1), fr(5, "3/2", "1/2")]
    assert s["point"].tolist() == fr("7/2", "3/2", "3/4")
    assert "(7/2, 3/2, 3/4)" in str(s)
    left, right = c.subdivide(F(1, 2))
    assert left.control_points[-1].tolist() == right.control_points[0].tolist() == fr("7/2", "3/2", "3/4")


def primer_4_3_curves():
    # Thesis Primer 4.3: c1 = (u, 0, u − u²), c2 = (u, 1, u), d1 = (0, v², v − v²), d2 = (1, v, v)
    # in Bernstein form.
    c1 = cagd.BezierCurve([[0, 0, 0], [F(1, 2), 0, F(1, 2)], [1, 0, 0]])
    c2 = cagd.BezierCurve([[0, 1, 0], [1, 1, 1]], exact=True)
    d1 = cagd.BezierCurve([[0, 0, 0], [0, 0, F(1, 2)], [0, 1, 0]])
    d2 = cagd.BezierCurve([[1, 0, 0], [1, 1, 1]], exact=True)
    return c1, c2, d1, d2


def test_primer_4_3_coons_parts():
    p = cagd.CoonsPatch(*primer_4_3_curves())
    parts = p.parts(F(1, 5), F(1, 2))
    assert parts["rc"].tolist() == fr("1/5", "1/2", "9/50")
    assert parts["rd"].tolist() == fr("1/5", "3/10", "3/10")
    assert parts["rcd"].tolist() == fr("1/5", "1/2", "1/10")
    assert parts["x"].tolist() == fr("1/5", "3/10", "19/50")


def test_primer_4_3_vrednost_coons():
    u, v = F(1, 5), F(1, 2)
    col = lambda *xs: np.array([[F(x)] for x in xs], dtype=object)
    t, rc, rd, rcd = octave.vrednostCoons(
        u, v,
        col(u, 0, u - u * u), col(u, 1, u), col(0, v * v, v - v * v), col(1, v, v),
        col(0, 0, 0), col(1, 0, 0), col(0, 1, 0), col(1, 1, 1),
    )
    assert t[:, 0].tolist() == fr("1/5", "3/10", "19/50")
    assert rc[:, 0].tolist() == fr("1/5", "1/2", "9/50")


def test_gordon_reproduces_a_bilinear_network_exactly():
    # A Gordon surface of straight lines g(u, v) = (u, v, uv) on nodes 0, 1/2, 1 reproduces
    # the hyperbolic paraboloid exactly (thesis §5: it interpolates every network curve).
    nodes = [F(0), F(1, 2), F(1)]
    at_u = [cagd.BezierCurve([[u, 0, 0], [u, 1, u]], exact=True) for u in nodes]
    at_v = [cagd.BezierCurve([[0, v, 0], [1, v, v]], exact=True) for v in nodes]
    g = cagd.GordonSurface(nodes, nodes, at_u, at_v)
    parts = g.parts(F(1, 3), F(3, 4))
    assert parts["g"].tolist() == fr("1/3", "3/4", "1/4")
    assert g(F(1, 5), F(2, 7)).tolist() == fr("1/5", "2/7", "2/35")


def test_nurbs_circle_is_exact():
    # The CAD notes' NURBS circle with rational weights: quadratic, 7 control points on the
    # square, weights 1, 1/2, 1/2, 1, …: every point has x² + y² = 1 exactly.
    h = F(1, 2)
    c = cagd.NurbsCurve(
        2, [0, 0, 0, F(1, 4), h, h, F(3, 4), 1, 1, 1],
        [[1, 0], [1, 1], [-1, 1], [-1, 0], [-1, -1], [1, -1], [1, 0]],
        [1, h, h, 1, h, h, 1],
    )
    pts = c(np.array([F(k, 24) for k in range(25)], dtype=object))
    assert {x * x + y * y for x, y in pts} == {F(1)}
    assert c(F(1, 8)).tolist() == fr("4/5", "3/5")


def test_discrete_coons_centre():
    # The centre of a 3×3 height field from its boundary: (1 + 1)/2 + (1 + 3)/2 − (0 + 0 + 0 + 2)/4.
    z = [[0, 1, 0], [1, 9, 3], [0, 1, 2]]
    net = np.array([[[x] for x in row] for row in z], dtype=object)
    out = cagd.discrete_coons(net)
    assert out[1, 1, 0] == F(5, 2)


def test_hermite_to_bezier():
    # Lecture notes: b1 = x1 + t1/3, b2 = x2 − t2/3.
    h = cagd.HermiteCubic([0, 0], [3, 0], [3, 3], [3, -3], exact=True)
    assert h.to_bezier().control_points.tolist() == [fr(0, 0), fr(1, 1), fr(2, 1), fr(3, 0)]
    m = cagd.conversion_matrix("hermite", "bezier", exact=True)
    assert m[2, 1] == F(1, 3) and m[3, 2] == F(-1, 3)


def test_bernstein_and_lagrange():
    assert cagd.bernstein(1, 3, F(1, 2)) == F(3, 8)
    assert octave.Lagrange(np.array([0, F(1, 2), 1], dtype=object), 2, F(1, 4)) == F(3, 4)
    lag = cagd.Lagrange([0, 1, 2], [[0, 0], [1, 1], [2, 4]], exact=True)
    assert lag(F(3, 2)).tolist() == fr("3/2", "9/4")


def test_bspline_exact_integral_and_derivative():
    # ∫ of N_{i,2} over 0,0,0,1/2,1,1,1 are 1/6, 1/3, 1/3, 1/6.
    s = cagd.BSplineCurve(2, [0, 0, 0, F(1, 2), 1, 1, 1], [[6], [0], [0], [0]])
    assert s.integral().tolist() == [F(1)]
    assert s.derivative()(F(1, 4)).tolist() == [F(-12)]


def test_continuity_of_a_subdivision():
    c = cagd.BezierCurve([[0, 0], [1, 2], [3, 2], [4, 0]], exact=True)
    a, b = c.subdivide(F(1, 3))
    # The halves keep the parameter of the whole curve: [0, 1/3] and [1/3, 1], joined C1.
    assert a.domain == (0, F(1, 3)) and b.domain == (F(1, 3), 1)
    assert cagd.continuity(a, b) == {"c0": True, "c1": True, "g1": True}
    # Joined with the parameter restarting at 0, the speed jumps: G1 but not C1.
    b0 = cagd.BezierCurve(b.control_points)
    a0 = cagd.BezierCurve(a.control_points)
    assert cagd.continuity(a0, b0) == {"c0": True, "c1": False, "g1": True}


def test_the_halves_of_a_subdivision_differentiate_on_their_intervals():
    """The derivative, elevation and subdivision of a half keep its parameter interval: the
    half's derivative at t is the whole curve's (Primer 2.4's cubic), not the derivative of
    the half reparametrised over [0, 1]."""
    c = cagd.BezierCurve([[0, 0, 0], [0, 2, 2], [8, 2, 0], [4, 0, 0]], exact=True)
    a, b = c.subdivide(F(1, 3))
    t = F(1, 6)
    assert a.derivative()(t).tolist() == c.derivative()(t).tolist()
    assert a.derivative(2)(t).tolist() == c.derivative(2)(t).tolist()
    assert a.elevate(2).domain == (0, F(1, 3))
    assert a.elevate(2)(t).tolist() == c(t).tolist()
    left, right = b.subdivide(F(2, 3))
    assert left.domain == (F(1, 3), F(2, 3)) and right.domain == (F(2, 3), 1)
    assert right(F(5, 6)).tolist() == c(F(5, 6)).tolist()
