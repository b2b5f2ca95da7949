"""Bézier patches raised in degree, split and integrated; the conversions of Coons and Gordon
surfaces; the steps that objects made by a construction keep.

Oracles: the patch's own definition evaluated here, independently of cagd — the tensor
Bernstein sum ``Σ b_ij C(m,i) u^i (1-u)^(m-i) C(n,j) v^j (1-v)^(n-j)`` in Fractions (exact) and
in numpy (floats) — at the parameters each construction maps to; integrals by the exact
term-by-term integration of that sum in the power basis; steps against values worked by hand
from the sources' formulas."""

from fractions import Fraction as F
from math import comb

import numpy as np
import pytest

import cagd

RNG = np.random.default_rng(27)


def bernstein_sum(net, u, v):
    """The patch of ``net`` (``(m+1, n+1, d)``) at ``(u, v)`` by its definition (Fractions or
    floats, as the inputs are)."""
    m, n = len(net) - 1, len(net[0]) - 1
    d = len(net[0][0])
    bu = [comb(m, i) * u**i * (1 - u) ** (m - i) for i in range(m + 1)]
    bv = [comb(n, j) * v**j * (1 - v) ** (n - j) for j in range(n + 1)]
    return [sum(net[i][j][k] * bu[i] * bv[j] for i in range(m + 1) for j in range(n + 1)) for k in range(d)]


def random_net(m, n, d=3):
    return [[[F(int(x), 7) for x in RNG.integers(-40, 40, d)] for _ in range(n + 1)] for _ in range(m + 1)]


GRID = [F(0), F(1, 3), F(2, 5), F(1)]


@pytest.mark.parametrize("m, n, r, s", [(2, 3, 1, 0), (1, 1, 2, 3), (3, 0, 0, 2), (0, 2, 1, 1)])
def test_elevation_keeps_the_patch_exactly(m, n, r, s):
    net = random_net(m, n)
    p = cagd.BezierPatch(net, exact=True)
    e = p.elevate(r, s)
    assert e.degree == (m + r, n + s)
    raised = e.control_points.tolist()
    for u in GRID:
        for v in GRID:
            assert bernstein_sum(raised, u, v) == bernstein_sum(net, u, v)
    # The steps: the net of every degree, u first.
    names = [name for name, _ in e.steps.items]
    assert names[0] == f"degree_{m}_{n}" and names[-1] == f"degree_{m + r}_{n + s}"
    assert len(names) == r + s + 1
    assert e.steps[names[-1]].tolist() == raised


@pytest.mark.parametrize("direction", ["u", "v"])
@pytest.mark.parametrize("t", [F(1, 2), F(1, 3), F(5, 7)])
def test_subdivision_parts_are_the_patch_at_the_mapped_parameters(direction, t):
    net = random_net(3, 2)
    p = cagd.BezierPatch(net, exact=True)
    first, second = p.subdivide(t, direction)
    a, b = first.control_points.tolist(), second.control_points.tolist()
    for s in GRID:
        for w in GRID:
            if direction == "u":
                at_first, at_second = (t * s, w), (t + (1 - t) * s, w)
            else:
                at_first, at_second = (s, t * w), (s, t + (1 - t) * w)
            assert bernstein_sum(a, s, w) == bernstein_sum(net, *at_first)
            assert bernstein_sum(b, s, w) == bernstein_sum(net, *at_second)
    # Both parts keep the steps: a de Casteljau scheme per control curve, then the two nets.
    steps = first.steps
    assert second.steps["first"].tolist() == a and steps["second"].tolist() == b
    curves = 3 if direction == "u" else 4  # n + 1 columns, or m + 1 rows
    assert str(steps).count("de Casteljau scheme, degree") == curves
    assert "L(" in str(steps) and "R(" in str(steps)


def test_subdivision_in_doubles_agrees_with_numpy():
    net = RNG.uniform(-5, 5, (4, 3, 3))
    p = cagd.BezierPatch(net)
    first, second = p.subdivide(0.3, "v")
    s = np.linspace(0, 1, 7)
    for x in s:
        for y in s:
            np.testing.assert_allclose(first(x, y), bernstein_sum(net, x, 0.3 * y), atol=1e-13)
            np.testing.assert_allclose(second(x, y), bernstein_sum(net, x, 0.3 + 0.7 * y), atol=1e-13)


def power_integral(net, u, v):
    """``∫_0^u ∫_0^v`` of the patch (``None`` for a bound: no integral in that direction, the
    value at the other bound's parameter instead) by expanding each Bernstein polynomial in
    powers and integrating term by term."""

    def powers(deg, i):  # B_i^deg(t) = Σ_k (-1)^(k-i) C(deg,k) C(k,i) t^k
        return [0 if k < i else (-1) ** (k - i) * comb(deg, k) * comb(k, i) for k in range(deg + 1)]

    def term(coeffs, x, integrate):
        if integrate:
            return sum(F(c) * x ** (k + 1) / (k + 1) for k, c in enumerate(coeffs))
        return sum(F(c) * x**k for k, c in enumerate(coeffs))

    m, n = len(net) - 1, len(net[0]) - 1
    iu, iv = u, v
    return [
        sum(
            net[i][j][k] * term(powers(m, i), iu[0], iu[1]) * term(powers(n, j), iv[0], iv[1])
            for i in range(m + 1)
            for j in range(n + 1)
        )
        for k in range(len(net[0][0]))
    ]


def test_antiderivatives_and_integral_are_the_term_by_term_integrals():
    net = random_net(2, 3)
    p = cagd.BezierPatch(net, exact=True)
    fu, fv = p.antiderivative("u"), p.antiderivative("v")
    fuv = fu.antiderivative("v")
    assert (fu.degree, fv.degree, fuv.degree) == ((3, 3), (2, 4), (3, 4))
    for u in GRID:
        for v in GRID:
            assert fu(u, v).tolist() == power_integral(net, (u, True), (v, False))
            assert fv(u, v).tolist() == power_integral(net, (u, False), (v, True))
            assert fuv(u, v).tolist() == power_integral(net, (u, True), (v, True))
    one = F(1)
    assert p.integral().tolist() == power_integral(net, (one, True), (one, True))
    # In doubles, the same within rounding.
    q = cagd.BezierPatch(np.array(net, dtype=float))
    np.testing.assert_allclose(q.integral(), [float(x) for x in p.integral()], rtol=1e-14)


def test_patch_construction_errors_name_their_argument():
    p = cagd.BezierPatch([[[0, 0], [0, 1]], [[1, 0], [1, 1]]])
    with pytest.raises(cagd.CagdError) as e:
        p.subdivide(1.0)
    assert (e.value.kind, e.value.argument) == ("EmptyInterval", "t")
    with pytest.raises(cagd.CagdError) as e:
        p.subdivide(float("nan"), "v")
    assert (e.value.kind, e.value.argument) == ("NonFinite", "t")
    with pytest.raises(cagd.CagdError) as e:
        p.subdivide(0.5, "w")
    assert (e.value.kind, e.value.argument) == ("Conversion", "direction")
    with pytest.raises(cagd.CagdError) as e:
        p.elevate(5000, 0)
    assert (e.value.kind, e.value.argument) == ("TooLarge", "r, s")


def line(a, b):
    return cagd.BezierCurve([a, b], exact=True)


def test_coons_and_gordon_of_bezier_curves_convert_to_one_bezier_patch():
    c1 = cagd.BezierCurve([[0, 0, 0], [F(1, 3), 0, 1], [F(2, 3), 0, -1], [1, 0, 0]], exact=True)
    c2 = cagd.BezierCurve([[0, 1, 0], [F(1, 2), 1, 2], [1, 1, 0]], exact=True)
    d1, d2 = line([0, 0, 0], [0, 1, 0]), line([1, 0, 0], [1, 1, 0])
    coons = cagd.CoonsPatch(c1, c2, d1, d2)
    b = coons.to_bezier()
    assert b.degree == (3, 1)
    for u in GRID:
        for v in GRID:
            assert b(u, v).tolist() == coons(u, v).tolist()
    g = cagd.GordonSurface([0, 1], [0, 1], [d1, d2], [c1, c2])
    gb = g.to_bezier()
    for u in GRID:
        for v in GRID:
            assert gb(u, v).tolist() == g(u, v).tolist() == coons(u, v).tolist()
    with pytest.raises(cagd.CagdError) as e:
        cagd.CoonsPatch(c1, c2, d1, d2, blend="hermite").to_bezier()
    assert e.value.kind == "Conversion"
    with pytest.raises(cagd.CagdError):
        coons.to_bspline()


def test_coons_of_bspline_curves_converts_to_one_bspline_surface():
    k2 = [0, 0, 0, F(1, 2), 1, 1, 1]
    c1 = cagd.BSplineCurve(2, k2, [[0, 0, 0], [F(3, 10), F(-1, 5), 1], [F(7, 10), F(1, 5), 0], [1, 0, 0]])
    lin = lambda a, b: cagd.BSplineCurve(1, [0, 0, 1, 1], [a, b], exact=True)
    c2, d1, d2 = lin([0, 1, 0], [1, 1, 0]), lin([0, 0, 0], [0, 1, 0]), lin([1, 0, 0], [1, 1, 0])
    coons = cagd.CoonsPatch(c1, c2, d1, d2)
    s = coons.to_bspline()
    assert s.degree == (2, 1)
    for u in GRID:
        for v in GRID:
            assert s(u, v).tolist() == coons(u, v).tolist()


def test_de_boor_steps_count_the_span_from_one_as_the_command_line():
    # Knots u_1..u_7 = 0, 0, 0, 1, 2, 2, 2 (the CAD notes count from 1): 1/2 lies in
    # [u_3, u_4) = [0, 1), so the span is 3; alpha1 = (u - u_i)/(u_(i+2) - u_i) for i = 2, 3
    # (from 1): 1/2 and 1/4.
    c = cagd.BSplineCurve(2, [0, 0, 0, 1, 2, 2, 2], [[0, 0], [1, 2], [3, 2], [4, 0]], exact=True)
    s = c.de_boor(F(1, 2))
    assert s["span"] == 3 and isinstance(s["span"], int)
    assert s["alpha1"].tolist() == [F(1, 2), F(1, 4)]
    assert s["alpha2"].tolist() == [F(1, 2)]
    assert s["d2"].tolist() == [c(F(1, 2)).tolist()]
    assert s["result"].tolist() == [c(F(1, 2)).tolist()]
    assert [n for n, _ in s.items][:3] == ["t", "span", "d0"]


def test_knot_insertion_keeps_boehms_steps():
    c = cagd.BSplineCurve(2, [0, 0, 0, 1, 2, 2, 2], [[0, 0], [1, 2], [3, 2], [4, 0]], exact=True)
    r = c.insert_knots([F(1, 2), F(3, 2)])
    # 1/2 in [u_3, u_4) = [0, 1) of 0, 0, 0, 1, 2, 2, 2; then 3/2 in [u_5, u_6) = [1, 2) of
    # 0, 0, 0, 1/2, 1, 2, 2, 2 (knots counted from 1).
    assert r.steps["insert_1.span"] == 3 and r.steps["insert_2.span"] == 5
    # α_i = (u - u_i)/(u_(i+p) - u_i): for u = 1/2, i = 2, 3 (from 1): 1/2, 1/4.
    assert r.steps["insert_1.alpha"].tolist() == [F(1, 2), F(1, 4)]
    assert r.steps["insert_2.control"].tolist() == r.control_points.tolist()
    assert c.steps is None


def test_curve_elevation_and_subdivision_keep_their_steps():
    c = cagd.BezierCurve([[0, 0], [1, 2], [3, 1]], exact=True)
    e = c.elevate(2)
    assert [n for n, _ in e.steps.items] == ["degree_3", "degree_4", "control"]
    assert e.steps["degree_3"].tolist() == c.elevate().control_points.tolist()
    left, right = c.subdivide(F(1, 4))
    scheme = left.steps
    assert scheme["left"].tolist() == left.control_points.tolist()
    assert scheme["right"].tolist() == right.control_points.tolist()
    assert "LR(" in str(scheme)
    b = cagd.BSplineCurve(2, [0, 0, 0, 1, 1, 1], [[0, 0], [1, 2], [3, 1]], exact=True).elevate()
    assert b.steps["knots_before"].tolist() == [0, 0, 0, 1, 1, 1] and b.steps["degree"] == 3


def test_interpolation_steps():
    s = cagd.CubicSpline([[0, 0], [1, 1], [2, 0]], exact=True)
    # The natural spline's system for the tangents, uniform parameters (the lecture notes).
    assert s.steps["system"].tolist() == [[2, 1, 0], [1, 4, 1], [0, 1, 2]]
    assert s.steps["rhs"].tolist() == [[3, 3], [6, 0], [3, -3]]
    assert s.steps["tangents"].tolist() == s.tangents.tolist()
    assert s.steps["segment_1.bezier"].tolist() == [[0, 0], [F(1, 3), F(1, 2)], [F(2, 3), 1], [1, 1]]
    # Lagrange's blending matrix G for the nodes 0, 1, 2 (rows L_i, highest power first).
    g = cagd.Lagrange([0, 1, 2], [[0], [1], [4]], exact=True).steps
    assert g["coefficients"].tolist() == [[F(1, 2), F(-3, 2), 1], [-1, 2, 0], [F(1, 2), F(-1, 2), 0]]
    # The Hermite basis at 0, 1/2, 1 in the order of the geometry [x1 x2 t1 t2] (H0, H3, H1,
    # H2) and the Bézier points x1, x1 + t1/3, x2 - t2/3, x2.
    h = cagd.HermiteCubic([0, 0], [3, 0], [3, 3], [3, -3], exact=True).steps
    assert h["hermite_basis"].tolist() == [
        [1, 0, 0, 0],
        [F(1, 2), F(1, 2), F(1, 8), F(-1, 8)],
        [0, 1, 0, 0],
    ]
    assert h["bezier_control"].tolist() == [[0, 0], [1, 1], [2, 1], [3, 0]]


def test_objects_show_their_steps_in_jupyter():
    c = cagd.BezierCurve([[0, 0], [1, 2], [3, 1]], exact=True)
    left, _ = c.subdivide(F(1, 2))
    html = left._repr_html_()
    assert "subdivision by de Casteljau" in html and "scheme.r2" in html
    assert "<b>" in c._repr_html_() and "subdivision" not in c._repr_html_()
    patch = cagd.BezierPatch([[[0, 0, 0], [0, 1, 0]], [[1, 0, 0], [1, 1, 1]]]).elevate(1, 1)
    assert "degree_2_2" in patch._repr_html_()
