"""Bad input raises cagd.CagdError (a ValueError) naming its kind and argument — never a crash,
a hang or a silent wrong answer."""

import math
import signal
from fractions import Fraction as F

import numpy as np
import pytest

import cagd
from cagd import octave

nan = float("nan")
line = cagd.BezierCurve([[0, 0], [1, 0]])
P = np.array([[0, 0, 8, 4], [0, 2, 2, 0], [0, 2, 0, 0]], dtype=float)
col = lambda *xs: np.array([[x] for x in xs], dtype=float)
square = lambda n: [
    np.array([np.linspace(0, 1, n), np.zeros(n), np.zeros(n)]),
    np.array([np.linspace(0, 1, n), np.ones(n), np.zeros(n)]),
    np.array([np.zeros(n), np.linspace(0, 1, n), np.zeros(n)]),
    np.array([np.ones(n), np.linspace(0, 1, n), np.zeros(n)]),
]
corners = [col(0, 0, 0), col(1, 0, 0), col(0, 1, 0), col(1, 1, 0)]

CASES = {
    # cagd.octave
    "deCasteljau no points": (lambda: octave.deCasteljau(np.zeros((3, 0)), 3), "TooFewPoints"),
    "deCasteljau NaN": (lambda: octave.deCasteljau([[0.0, nan]], 3), "NonFinite"),
    "deCasteljau N over the limit": (lambda: octave.deCasteljau(P, 10**7), "TooLarge"),
    "deCasteljau work over the limit": (lambda: octave.deCasteljau(np.zeros((3, 1000)), 10**6), "TooLarge"),
    "ploskevB work over the limit": (lambda: octave.ploskevB(np.zeros((200, 600)), 3000), "TooLarge"),
    "krpaGordon work over the limit": (lambda: octave.krpaGordon(np.zeros((3, 1000 * 10)), np.zeros((3, 1000 * 10)), np.zeros((1000, 3000)), np.linspace(0, 1, 1000), np.linspace(0, 1, 1000), 3000), "TooLarge"),
    "Lagrange work over the limit": (lambda: octave.Lagrange(np.linspace(0, 1, 1000), 1, np.zeros(10**6)), "TooLarge"),
    "deCasteljau complex": (lambda: octave.deCasteljau(P + 1j, 3), "Conversion"),
    "deCasteljau text": (lambda: octave.deCasteljau([["a", "b"]], 3), "Conversion"),
    "deCasteljau 3-D": (lambda: octave.deCasteljau(np.zeros((2, 2, 2)), 3), "ShapeMismatch"),
    "ploskevB columns": (lambda: octave.ploskevB(np.zeros((2, 4)), 3), "ShapeMismatch"),
    "ploskevB grid over the limit": (lambda: octave.ploskevB(np.zeros((2, 6)), 10**4), "TooLarge"),
    "bilinearna NaN u": (lambda: octave.bilinearna(np.zeros((2, 6)), nan, 0.5, 3), "NonFinite"),
    "tenzor columns": (lambda: octave.tenzor(np.zeros((2, 5))), "ShapeMismatch"),
    "krpaCoons short curve": (lambda: octave.krpaCoons(*square(4)[:3], square(3)[3], *corners), "ShapeMismatch"),
    "krpaCoons corner": (lambda: octave.krpaCoons(*square(4), *corners[:3], col(1, 1, 1)), "CornerMismatch"),
    "vrednostCoons NaN": (lambda: octave.vrednostCoons(nan, 0.5, *[col(0, 0, 0)] * 8), "NonFinite"),
    "krpaGordon nodes": (lambda: octave.krpaGordon(np.zeros((3, 6)), np.zeros((3, 6)), np.zeros((2, 6)), [[0, 0]], [[0, 1]], 3), "DuplicateNodes"),
    "Lagrange m = 0": (lambda: octave.Lagrange([0, 0.5, 1], 0, 0.5), "InvalidArgument"),
    "Lagrange duplicate": (lambda: octave.Lagrange([0, 0.5, 0], 1, 0.5), "DuplicateNodes"),
    # classes
    "BezierCurve empty": (lambda: cagd.BezierCurve(np.zeros((0, 2))), "Shape"),
    "BezierCurve degree over the limit": (lambda: cagd.BezierCurve(np.zeros((2000, 2))), "TooLarge"),
    "BezierCurve Inf": (lambda: cagd.BezierCurve([[0, math.inf]]), "NonFinite"),
    "BezierCurve exact NaN": (lambda: cagd.BezierCurve([[F(1, 2), nan]]), "NonFinite"),
    "BezierCurve derivative order": (lambda: line.derivative(3), "DerivativeOrder"),
    "BezierPatch rank": (lambda: cagd.BezierPatch(np.zeros((2, 2))), "ShapeMismatch"),
    "BezierPatch grid over the limit": (lambda: cagd.BezierPatch(np.zeros((2, 2, 3)))(np.zeros(10**4), np.zeros(10**4)), "TooLarge"),
    "BSplineCurve decreasing knots": (lambda: cagd.BSplineCurve(1, [0, 1, 0.5, 2], [[0], [1]]), "DecreasingKnots"),
    "BSplineCurve knot count": (lambda: cagd.BSplineCurve(2, [0, 0, 1, 1], [[0], [1], [2]]), "KnotCount"),
    "BSplineCurve insert outside": (lambda: cagd.BSplineCurve.clamped(2, [[0], [1], [2]]).insert_knots(5), "ParameterOutOfRange"),
    "NurbsCurve weight": (lambda: cagd.NurbsCurve(1, [0, 0, 1, 1], [[0, 0], [1, 0]], [1, -1]), "NonPositiveWeight"),
    "CoonsPatch corners": (lambda: cagd.CoonsPatch(line, line, line, line), "CornerMismatch"),
    "CoonsPatch blend": (lambda: cagd.CoonsPatch(line, line, line, line, blend="cubic"), "Conversion"),
    "CoonsPatch not a curve": (lambda: cagd.CoonsPatch(line, line, line, [[0, 0]]), "Conversion"),
    "CoonsPatch mixed": (lambda: cagd.CoonsPatch(line, cagd.BezierCurve([[0, 1], [1, 1]], exact=True), line, line), "Conversion"),
    "GordonSurface too few": (lambda: cagd.GordonSurface([0], [0, 1], [line], [line, line]), "TooFewCurves"),
    "CubicSpline too few": (lambda: cagd.CubicSpline([[0, 0]]), "TooFewPoints"),
    "CubicSpline end": (lambda: cagd.CubicSpline([[0, 0], [1, 1]], end="cubic"), "Conversion"),
    "CubicSpline clamped without tangents": (lambda: cagd.CubicSpline([[0, 0], [1, 1]], end="clamped"), "Usage"),
    "CubicSpline natural with a tangent": (lambda: cagd.CubicSpline([[0, 0], [1, 1]], start=[1, 0]), "Usage"),
    "HermiteCubic dimensions": (lambda: cagd.HermiteCubic([0, 0], [1, 1, 1], [0, 0], [0, 0]), "ShapeMismatch"),
    "Lagrange unsorted or equal nodes": (lambda: cagd.Lagrange([0, 0], [[0], [1]]), "DuplicateNodes"),
    "bernstein degree over the limit": (lambda: cagd.bernstein(0, 5000, 0.5), "TooLarge"),
    "convert_cubic columns": (lambda: cagd.convert_cubic(np.zeros((3, 2)), "bezier", "hermite"), "ShapeMismatch"),
    "set_limit unknown": (lambda: cagd.set_limit("max_speed", 3), "Conversion"),
    # cagd.BSpline (scipy's drop-in)
    "BSpline decreasing knots": (lambda: cagd.BSpline([0, 1, 0.5, 2, 3], [1, 2], 2), "DecreasingKnots"),
    "BSpline too few coefficients": (lambda: cagd.BSpline([0, 0, 0, 1, 2, 2, 2], [1, 2], 2), "TooFewControlPoints"),
    "BSpline NaN knot": (lambda: cagd.BSpline([0, 0, nan, 1, 1], [1, 2], 1), "NonFinite"),
    "BSpline negative degree": (lambda: cagd.BSpline([0, 1], [1], -1), "Conversion"),
    "BSpline complex knots": (lambda: cagd.BSpline([0, 0, 1j, 1], [1, 2], 1), "Conversion"),
    "BSpline derivative order": (lambda: cagd.BSpline([0, 0, 1, 1], [1, 2], 1).derivative(2), "DerivativeOrder"),
    "BSpline integrate NaN": (lambda: cagd.BSpline([0, 0, 1, 1], [1, 2], 1).integrate(0, nan), "NonFinite"),
    "BSpline design matrix out of bounds": (lambda: cagd.BSpline.design_matrix([2.0], [0, 0, 1, 1], 1), "ParameterOutOfRange"),
}


@pytest.mark.parametrize("name", sorted(CASES))
def test_bad_input_raises_cagd_error(name):
    call, kind = CASES[name]
    with pytest.raises(cagd.CagdError) as info:
        call()
    assert isinstance(info.value, ValueError)
    assert str(info.value)
    if kind is not None:
        assert info.value.kind == kind, (info.value.kind, str(info.value))


def test_error_names_its_argument():
    with pytest.raises(cagd.CagdError) as info:
        cagd.BSplineCurve(1, [0, 1, 0.5, 2], [[0], [1]])
    assert info.value.argument == "knots"
    assert str(info.value).startswith("knots: knot vector: knot 3 (0.5) is below")
    assert "non-decreasing" in str(info.value)


def test_limits_can_be_raised_and_restored():
    try:
        cagd.set_limit("max_degree", 3000)
        assert cagd.BezierCurve(np.zeros((2000, 1))).degree == 1999
    finally:
        cagd.set_limit()
    assert cagd.limits()["max_degree"] == 1000


def test_ctrl_c_stops_a_long_evaluation():
    """A long evaluation runs in chunks and checks for signals between them: an interrupt
    raised by a timer ends it with KeyboardInterrupt instead of waiting for it to finish."""
    k = 60
    t = np.r_[np.zeros(k), np.linspace(0, 1, 200), np.ones(k)]
    spline = cagd.BSpline(t, np.random.default_rng(0).random(len(t) - k - 1), k)
    x = np.random.default_rng(1).random(4_000_000)

    def interrupt(signum, frame):
        raise KeyboardInterrupt

    old = signal.signal(signal.SIGALRM, interrupt)
    signal.setitimer(signal.ITIMER_REAL, 0.2)
    try:
        with pytest.raises(KeyboardInterrupt):
            spline(x, nu=1)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, old)


def test_ctrl_c_stops_a_long_request():
    """A request of the operation layer (here an exact degree elevation by 900, some seconds of
    work) asks Python for signals between its steps, the interpreter's lock released: Ctrl-C
    (a real SIGINT, sent by another process 0.3 s in, as a terminal sends it) ends it with
    KeyboardInterrupt within moments, and the next request runs as usual.

    The signal comes from outside the interpreter, and the test installs Python's own SIGINT
    handler for its duration: a process started in the background by a non-interactive shell
    (as CI starts its jobs) inherits SIGINT ignored, where Ctrl-C, interrupt_main and kill all
    do nothing (CI, 2026-12-06)."""
    import os
    import signal
    import subprocess
    import time

    curve = cagd.BezierCurve([[F(1, 3), F(2, 7)], [F(5, 11), F(3, 13)]], exact=True)
    cagd.set_limit("max_work", 10**16)
    sender = None
    handler = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        start = time.monotonic()
        sender = subprocess.Popen(["sh", "-c", f"sleep 0.3; kill -INT {os.getpid()}"])
        with pytest.raises(KeyboardInterrupt):
            curve.elevate(900)
        assert time.monotonic() - start < 3
    finally:
        if sender is not None:
            sender.wait()
        signal.signal(signal.SIGINT, handler)
        cagd.set_limit()
    assert curve.elevate(2).degree == 3
