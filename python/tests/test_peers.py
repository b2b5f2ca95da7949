"""Random cases against the peers: scipy.interpolate (B-splines), geomdl (B-spline and NURBS
curves and surfaces) and dhermes/bezier (Bézier curves)."""

import numpy as np
import pytest

import cagd
from conftest import peer

scipy_interpolate = peer("scipy.interpolate")
bezier = peer("bezier")
geomdl_bspline = peer("geomdl.BSpline")
geomdl_nurbs = peer("geomdl.NURBS")

RNG = np.random.default_rng(2014)


def close(ours, theirs, rel=1e-12):
    ours, theirs = np.asarray(ours, float), np.asarray(theirs, float)
    assert ours.shape == theirs.shape
    scale = max(1.0, np.nanmax(np.abs(theirs)) if theirs.size else 1.0)
    np.testing.assert_array_equal(np.isnan(ours), np.isnan(theirs))
    assert np.nanmax(np.abs(ours - theirs), initial=0.0) <= rel * scale


def random_knots(k, n, clamped):
    inner = np.sort(RNG.random(n - k - 1))
    if RNG.random() < 0.3 and inner.size > 1:
        inner[1] = inner[0]  # a double knot
    if clamped:
        return np.r_[np.zeros(k + 1), inner, np.ones(k + 1)]
    lo, hi = np.sort(RNG.uniform(-0.5, 0.0, k + 1)), np.sort(RNG.uniform(1.0, 1.5, k + 1))
    return np.r_[lo, inner, hi]


@pytest.mark.parametrize("case", range(40))
def test_bezier_curves_against_dhermes_bezier(case):
    n, d = int(RNG.integers(1, 11)), int(RNG.integers(2, 4))
    points = RNG.uniform(-10, 10, (n + 1, d))
    s = np.linspace(0, 1, 37)
    ours = cagd.BezierCurve(points)
    theirs = bezier.Curve(np.asfortranarray(points.T), degree=n)
    close(ours(s), theirs.evaluate_multi(s).T)
    close(ours.derivative()(s), np.column_stack([theirs.evaluate_hodograph(x)[:, 0] for x in s]).T)
    left, right = ours.subdivide(0.5)
    t_left, t_right = theirs.subdivide()
    close(left.control_points, t_left.nodes.T)
    close(right.control_points, t_right.nodes.T)
    close(ours.elevate().control_points, theirs.elevate().nodes.T)


@pytest.mark.parametrize("case", range(30))
def test_bspline_curves_against_scipy_and_geomdl(case):
    k = int(RNG.integers(1, 6))
    n = int(RNG.integers(k + 1, k + 12))
    t = random_knots(k, n, clamped=True)
    c = RNG.uniform(-5, 5, (n, 3))
    x = np.r_[np.linspace(0, 1, 51), t]
    ours = cagd.BSplineCurve(k, t, c)
    close(ours(x), scipy_interpolate.BSpline(t, c, k)(x))
    g = geomdl_bspline.Curve()
    g.degree, g.ctrlpts, g.knotvector = k, c.tolist(), t.tolist()
    close(ours(x[:51]), np.array(g.evaluate_list(x[:51].tolist())))
    if k > 1:
        close(ours.derivative()(x), scipy_interpolate.BSpline(t, c, k)(x, nu=1), rel=1e-10)


@pytest.mark.parametrize("case", range(20))
def test_nurbs_curves_against_geomdl(case):
    k = int(RNG.integers(1, 5))
    n = int(RNG.integers(k + 1, k + 10))
    t = random_knots(k, n, clamped=True)
    p = RNG.uniform(-5, 5, (n, 2))
    w = RNG.uniform(0.2, 3.0, n)
    x = np.linspace(0, 1, 41)
    ours = cagd.NurbsCurve(k, t, p, w)
    g = geomdl_nurbs.Curve()
    g.degree = k
    g.ctrlptsw = np.column_stack([p * w[:, None], w]).tolist()
    g.knotvector = t.tolist()
    close(ours(x), np.array(g.evaluate_list(x.tolist())))


@pytest.mark.parametrize("case", range(15))
def test_bspline_surfaces_against_geomdl(case):
    p, q = int(RNG.integers(1, 4)), int(RNG.integers(1, 4))
    nu, nv = int(RNG.integers(p + 1, p + 6)), int(RNG.integers(q + 1, q + 6))
    tu, tv = random_knots(p, nu, True), random_knots(q, nv, True)
    net = RNG.uniform(-3, 3, (nu, nv, 3))
    u, v = np.linspace(0, 1, 9), np.linspace(0, 1, 7)
    ours = cagd.BSplineSurface((p, q), tu, tv, net)(u, v)
    g = geomdl_bspline.Surface()
    g.degree_u, g.degree_v = p, q
    g.ctrlpts_size_u, g.ctrlpts_size_v = nu, nv
    g.ctrlpts = net.reshape(-1, 3).tolist()
    g.knotvector_u, g.knotvector_v = tu.tolist(), tv.tolist()
    theirs = np.array(g.evaluate_list([(a, b) for a in u for b in v])).reshape(len(u), len(v), 3)
    close(ours, theirs)


@pytest.mark.parametrize("case", range(60))
def test_scipy_bspline_drop_in_random(case):
    k = int(RNG.integers(0, 6))
    n = int(RNG.integers(k + 1, k + 15))
    t = random_knots(k, n, clamped=bool(RNG.integers(0, 2)))
    shape = [(n,), (n, 2), (n, 2, 3)][case % 3]
    c = RNG.uniform(-5, 5, shape)
    ours, theirs = cagd.BSpline(t, c, k), scipy_interpolate.BSpline(t, c, k)
    x = np.r_[RNG.uniform(t[0] - 0.5, t[-1] + 0.5, 40), t[k:n + 1]]
    for extrapolate in [True, False, "periodic"]:
        for nu in range(0, k + 2):
            if extrapolate is True and nu == 0 and k > 0 and (t[k] == t[k + 1] or t[n - 1] == t[n]):
                continue  # scipy continues an empty end span there (see python/SCIPY_SUITE.md)
            close(ours(x, nu=nu, extrapolate=extrapolate), theirs(x, nu=nu, extrapolate=extrapolate), rel=1e-9)
    a, b = sorted(RNG.uniform(t[0] - 0.3, t[-1] + 0.3, 2))
    for extrapolate in [False, "periodic"]:
        mine, theirs_i = ours.integrate(a, b, extrapolate=extrapolate), theirs.integrate(a, b, extrapolate=extrapolate)
        if np.isnan(theirs_i).any():
            # [a, b] misses the base interval: scipy (c of more than one dimension) evaluates
            # its antiderivative outside it and answers NaN; the integral is 0.
            assert extrapolate is False and (b < t[k] or a > t[n]) and np.all(mine == 0)
            continue
        close(mine, theirs_i, rel=1e-9)
    inside = np.linspace(t[k], t[n], 17)
    close(ours.antiderivative()(inside), theirs.antiderivative()(inside), rel=1e-9)
    try:
        their_derivative = theirs.derivative() if k > 0 else None
    except ValueError:  # scipy refuses a knot of multiplicity k + 1 inside
        their_derivative = None
    if their_derivative is not None:
        close(ours.derivative()(inside), their_derivative(inside), rel=1e-9)
    close(
        cagd.BSpline.design_matrix(inside, t, k).toarray(),
        scipy_interpolate.BSpline.design_matrix(inside, t, k).toarray(),
    )
