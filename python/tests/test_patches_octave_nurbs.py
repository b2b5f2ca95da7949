"""Bézier patch elevation and subdivision against live GNU Octave's octave-nurbs: a Bézier patch
of degree ``(m, n)`` is the NURBS surface of its net with unit weights over the knots
``(0^(m+1), 1^(m+1))`` and ``(0^(n+1), 1^(n+1))``; ``nrbdegelev`` raises it, and ``nrbkntins``
inserting ``t`` ``m`` times in ``u`` splits it into the nets of the two parts (rows ``0..m`` and
``m..2m``). In CI Octave with octave-nurbs must be there; elsewhere the tests are skipped
without it."""

import shutil
import subprocess

import numpy as np
import pytest

import cagd
from conftest import in_ci

RNG = np.random.default_rng(800)


def octave_nurbs(script):
    """The numbers the Octave script prints, one line a result, after ``pkg load nurbs``."""
    if shutil.which("octave") is None:
        if in_ci():
            pytest.fail("GNU Octave is needed for the octave-nurbs cross-checks in CI")
        pytest.skip("no GNU Octave")
    run = subprocess.run(
        ["octave", "--no-gui", "--quiet", "--norc", "--eval", "pkg load nurbs\n" + script],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert run.returncode == 0, run.stderr
    return [np.array(line.split(), dtype=float) for line in run.stdout.splitlines() if line.strip()]


def nrb_surface(net):
    """Octave code making ``srf``, the NURBS surface of the Bézier net ``net`` (``(m+1, n+1, 3)``)."""
    m, n = net.shape[0] - 1, net.shape[1] - 1
    values = " ".join(f"{x:.17g}" for x in np.moveaxis(net, 2, 0).ravel(order="F"))
    return (
        f"c = ones(4, {m + 1}, {n + 1}); c(1:3, :, :) = reshape([{values}], 3, {m + 1}, {n + 1});\n"
        f"srf = nrbmak(c, {{[zeros(1, {m + 1}) ones(1, {m + 1})], [zeros(1, {n + 1}) ones(1, {n + 1})]}});\n"
    )


def printed_net(values, rows, cols):
    """A net printed column-major from Octave's ``coefs(1:3, :, :)`` as ``(rows, cols, 3)``."""
    return np.moveaxis(values.reshape((3, rows, cols), order="F"), 0, 2)


@pytest.mark.parametrize("m, n, r, s", [(2, 1, 1, 2), (3, 3, 2, 0), (1, 4, 0, 1)])
def test_elevation_is_octave_nurbs_nrbdegelev(m, n, r, s):
    net = RNG.uniform(-3, 3, (m + 1, n + 1, 3))
    (octave,) = octave_nurbs(
        nrb_surface(net) + f"e = nrbdegelev(srf, [{r} {s}]);\nprintf('%.17g ', e.coefs(1:3, :, :)); printf('\\n');\n"
    )
    ours = cagd.BezierPatch(net).elevate(r, s).control_points
    np.testing.assert_allclose(ours, printed_net(octave, m + r + 1, n + s + 1), rtol=0, atol=1e-13)


@pytest.mark.parametrize("direction", ["u", "v"])
@pytest.mark.parametrize("t", [0.5, 0.3])
def test_subdivision_is_octave_nurbs_knot_insertion(direction, t):
    m, n = 3, 2
    net = RNG.uniform(-3, 3, (m + 1, n + 1, 3))
    k = m if direction == "u" else n
    insert = f"{{{t} * ones(1, {k}), []}}" if direction == "u" else f"{{[], {t} * ones(1, {k})}}"
    (octave,) = octave_nurbs(
        nrb_surface(net) + f"r = nrbkntins(srf, {insert});\nprintf('%.17g ', r.coefs(1:3, :, :)); printf('\\n');\n"
    )
    rows, cols = (2 * m + 1, n + 1) if direction == "u" else (m + 1, 2 * n + 1)
    refined = printed_net(octave, rows, cols)
    first, second = cagd.BezierPatch(net).subdivide(t, direction)
    if direction == "u":
        want_first, want_second = refined[: m + 1], refined[m:]
    else:
        want_first, want_second = refined[:, : n + 1], refined[:, n:]
    np.testing.assert_allclose(first.control_points, want_first, rtol=0, atol=1e-13)
    np.testing.assert_allclose(second.control_points, want_second, rtol=0, atol=1e-13)
