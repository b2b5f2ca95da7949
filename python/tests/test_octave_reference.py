"""cagd.octave against the fixed thesis code: every number here was written by GNU Octave
(octave_ref/cases/*.m through octave_ref/fixed/*.m, saved in octave_ref/expected/)."""

import re

import numpy as np
import pytest

from cagd import octave
from conftest import assert_close


def names(ws, pattern):
    return sorted(n for n in ws if re.fullmatch(pattern, n))


def test_decasteljau_curves(expected):
    for case in ["curves", "primer_2_4"]:
        ws = expected(case)
        outputs = names(ws, r"T_(.+)_N(\d+)")
        assert outputs, case
        for out in outputs:
            key, n = re.fullmatch(r"T_(.+)_N(\d+)", out).groups()
            assert_close(out, octave.deCasteljau(ws[f"P_{key}"], int(n)), ws[out])


def test_tenzor_and_ploskevb(expected):
    ws = expected("patches")
    for a in names(ws, r"A_deg\d+x\d+"):
        key = a[2:]
        assert_close(a, octave.tenzor(ws[f"B_{key}"]), ws[a])
    outputs = names(ws, r"P_deg\d+x\d+_N\d+")
    assert len(outputs) >= 20
    for out in outputs:
        key, n = re.fullmatch(r"P_(deg\d+x\d+)_N(\d+)", out).groups()
        assert_close(out, octave.ploskevB(ws[f"B_{key}"], int(n)), ws[out])


def test_snapshots(expected):
    ws = expected("compat_snapshots")
    assert_close("T", octave.deCasteljau(ws["snap_P_primer_2_4"], 5), ws["snap_T_primer_2_4_N5"])
    assert_close("A", octave.tenzor(ws["snap_B"]), ws["snap_A"])
    assert_close("P", octave.ploskevB(ws["snap_B"], 5), ws["snap_P_B_N5"])
    assert_close("L", octave.bilinearna(ws["snap_B"], 0.5, 0.25, 5), ws["snap_L_B"])
    args = [ws[f"snap_coons_{k}"] for k in ["c1", "c2", "d1", "d2", "P1", "P2", "P3", "P4"]]
    r, p = octave.krpaCoons(*args)
    assert_close("coons R", r, ws["snap_coons_R"])
    assert_close("coons P", p, ws["snap_coons_P"])
    g = [ws[f"snap_gordon_{k}"] for k in ["g_u", "g_v", "g_uv"]]
    x = ws["snap_gordon_x"]
    r, p = octave.krpaGordon(*g, x, x, 5)
    assert_close("gordon R", r, ws["snap_gordon_R"])
    assert_close("gordon P", p, ws["snap_gordon_P"])


def test_coons_thesis(expected):
    ws = expected("coons_thesis")
    corners = [ws[k] for k in ["P1", "P2", "P3", "P4"]]
    ex = [ws[f"ex_{k}"] for k in ["c1", "c2", "d1", "d2"]]
    t, rc, rd, rcd = octave.vrednostCoons(float(ws["ex_u"][0, 0]), float(ws["ex_v"][0, 0]), *ex, *corners)
    for name, ours in [("T", t), ("rc", rc), ("rd", rd), ("rcd", rcd)]:
        assert_close(name, ours, ws[f"ex_{name}"])
    for n in [2, 3, 10, 101]:
        curves = [ws[f"{k}_N{n}"] for k in ["c1", "c2", "d1", "d2"]]
        r, p = octave.krpaCoons(*curves, *corners)
        assert_close(f"P_N{n}", p, ws[f"P_N{n}"])
        if f"R_N{n}" in ws:
            assert_close(f"R_N{n}", r, ws[f"R_N{n}"])


def test_coons_random(expected):
    ws = expected("coons_random")
    for r in [1, 2, 3]:
        key = lambda k: ws[f"r{r}_{k}"]
        q, a, b = key("Q"), key("A"), key("B")
        corners = [q[:, [i]] for i in range(4)]
        _, p = octave.krpaCoons(key("c1"), key("c2"), key("d1"), key("d2"), *corners)
        assert_close(f"r{r}_P", p, key("P"))
        ends = [(0, 1, 0), (2, 3, 1), (0, 2, 2), (1, 3, 3)]  # (start corner, end corner, column)

        def f(k, s):
            i, j, c = ends[k]
            # The case script's order of operations, element by element.
            return (1 - s) * q[:, [i]] + s * q[:, [j]] + (s * (1 - s)) * (a[:, [c]] + b[:, [c]] * s)

        uv = key("uv")
        for k in range(5):
            u, v = uv[0, k], uv[1, k]
            out = octave.vrednostCoons(u, v, f(0, u), f(1, u), f(2, v), f(3, v), *corners)
            for name, ours in zip(["T", "rc", "rd", "rcd"], out):
                assert_close(f"r{r}_{name}[{k}]", ours[:, 0], key(name)[:, k])


def test_gordon(expected):
    ws = expected("gordon_thesis")
    x = ws["x"]
    for n in [3, 10, 101]:
        _, p = octave.krpaGordon(ws[f"g_u_N{n}"], ws[f"g_v_N{n}"], ws["g_uv"], x, x, n)
        assert_close(f"P_N{n}", p, ws[f"P_N{n}"])
    ws = expected("gordon_random")
    for r in [1, 2, 3]:
        key = lambda k: ws[f"r{r}_{k}"]
        n = key("t").shape[1]
        _, p = octave.krpaGordon(key("g_u"), key("g_v"), key("g_uv"), key("xu"), key("xv"), n)
        # Ill-conditioned node sets amplify rounding by κ = Λ_u + Λ_v + Λ_u Λ_v (Lebesgue
        # constants): two correct operation orders (barycentric weights here, Octave's
        # products there) may differ by κ·ε of the scale, as crates/cagd-octave's test allows.
        kappa = max(10.0, conditioning(key("xu").ravel(), key("xv").ravel()))
        scale = np.abs(key("P")).max()
        err = np.abs(p - key("P")).max()
        assert err <= kappa * np.finfo(float).eps * scale, (r, err, kappa)


def lebesgue(x):
    """max over [0, 1] of Σ_i |L_i(t)|, sampled at 4001 points (products, numpy)."""
    t = np.linspace(0, 1, 4001)
    total = np.zeros_like(t)
    for i, xi in enumerate(x):
        li = np.ones_like(t)
        for j, xj in enumerate(x):
            if j != i:
                li *= (t - xj) / (xi - xj)
        total += np.abs(li)
    return total.max()


def conditioning(xu, xv):
    lu, lv = lebesgue(xu), lebesgue(xv)
    return lu + lv + lu * lv


def test_lagrange(expected):
    ws = expected("lagrange_basis")
    for k in [1, 2, 3]:
        x, t, l = ws[f"x{k}"], ws[f"t{k}"], ws[f"L{k}"]
        for i in range(x.size):
            assert_close(f"L{k}[{i}]", octave.Lagrange(x, i + 1, t), l[[i], :])


def test_exact_agrees_with_octave(expected):
    """The same functions on Fractions: exact, and the doubles round to Octave's numbers."""
    from fractions import Fraction

    ws = expected("compat_snapshots")
    b = np.array(ws["snap_B"].astype(int), dtype=object)
    p = octave.ploskevB(b, 5)
    assert isinstance(p[1, 2, 2], Fraction)
    assert_close("exact P", p.astype(float), ws["snap_P_B_N5"])
    l = octave.bilinearna(b, Fraction(1, 2), Fraction(1, 4), 5)
    assert_close("exact L", l.astype(float), ws["snap_L_B"])


def test_save_and_load_keep_every_bit(tmp_path):
    t = octave.deCasteljau(np.random.default_rng(7).random((3, 5)), 11)
    octave.save(tmp_path / "out.txt", T=t, N=11.0, row=np.array([0.1, 0.2]))
    back = octave.load(tmp_path / "out.txt")
    assert np.array_equal(back["T"], t)
    assert back["N"].tolist() == [[11.0]] and back["row"].tolist() == [[0.1, 0.2]]
