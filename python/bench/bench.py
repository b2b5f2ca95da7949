"""Speed of the Python package, one thread against one (RAYON_NUM_THREADS=1 for cagd; scipy
and geomdl evaluate on one thread), printed as the tables of docs/PERFORMANCE.md ("In Python").

1. curve evaluation on 10⁶ points: cagd.BSpline and cagd.BSplineCurve against
   scipy.interpolate.BSpline and geomdl (cubic, 3-D, 10 control points);
2. surface evaluation on 10⁶ points (1000 × 1000 grid): cagd.BSplineSurface against scipy's
   NdBSpline (at the 10⁶ grid points) and geomdl;
3. the thesis functions (all eight): cagd.octave against the fixed Octave code
   (octave_ref/fixed, timed by python/bench/thesis_timings.m in GNU Octave on the same inputs);
4. one call's overhead: a single point.

geomdl evaluates point by point in Python (about 45 µs a point): by default it runs on all 10⁶
points (a few minutes); --geomdl-points K times it on K points and scales the time to 10⁶.

Usage (from the repository root, with the package, scipy and geomdl installed):
    RAYON_NUM_THREADS=1 python python/bench/bench.py [--no-octave] [--geomdl-points K]
"""

import argparse
import os
import platform
import subprocess
import sys
import tempfile
import time

import numpy as np

import cagd


def best(f, reps=5):
    t = float("inf")
    for _ in range(reps):
        s = time.perf_counter()
        f()
        t = min(t, time.perf_counter() - s)
    return t


def row(name, times):
    base = times.get("cagd.BSpline") or times.get("cagd") or next(iter(times.values()))
    cells = "  ".join(f"{k}: {v:.4g} s ({v / base:.1f}x)" for k, v in times.items())
    print(f"| {name} | " + " | ".join(f"{v:.4g}" for v in times.values()) + " |   " + cells)


def geomdl_label(points):
    """geomdl's column: on all 10⁶ points, or scaled from fewer."""
    return "geomdl (10^6 points)" if points >= 1_000_000 else f"geomdl (scaled from {points} points)"


def curves(geomdl_points):
    from scipy.interpolate import BSpline
    from geomdl import BSpline as GB

    k, n = 3, 10
    t = np.r_[np.zeros(k), np.linspace(0, 1, n - k + 1), np.ones(k)]
    c = np.random.default_rng(1).uniform(-1, 1, (n, 3))
    x = np.random.default_rng(2).random(1_000_000)
    xs = np.sort(x)
    ours, theirs = cagd.BSpline(t, c, k), BSpline(t, c, k)
    curve = cagd.BSplineCurve(k, t, c)
    assert np.allclose(ours(x), theirs(x), atol=1e-13)
    g = GB.Curve()
    g.degree, g.ctrlpts, g.knotvector = k, c.tolist(), t.tolist()
    sub = xs[:: max(1, len(xs) // geomdl_points)].tolist()
    tg = best(lambda: g.evaluate_list(sub), 1) * len(xs) / len(sub)
    print("\n## curve: cubic B-spline, 3-D, 10 control points, 10^6 parameters (random; sorted)")
    print("| case | cagd.BSpline | cagd.BSplineCurve | scipy BSpline | %s |" % geomdl_label(len(sub)))
    for label, xx in [("random", x), ("sorted", xs)]:
        times = {
            "cagd.BSpline": best(lambda: ours(xx)),
            "cagd.BSplineCurve": best(lambda: curve(xx)),
            "scipy": best(lambda: theirs(xx)),
            "geomdl": tg,
        }
        row(label, times)


def surfaces(geomdl_points):
    from scipy.interpolate import NdBSpline
    from geomdl import BSpline as GB

    p, n = 3, 10
    kn = np.r_[np.zeros(p), np.linspace(0, 1, n - p + 1), np.ones(p)]
    i, j = np.meshgrid(np.arange(n), np.arange(n), indexing="ij")
    net = np.stack([i / 9, j / 9, (7 * i + 3 * j) % 5 / 4 - 0.5], axis=-1)
    u = np.linspace(0, 1, 1000)
    ours = cagd.BSplineSurface((p, p), kn, kn, net)
    nd = NdBSpline((kn, kn), net, (p, p))
    grid = np.stack(np.meshgrid(u, u, indexing="ij"), axis=-1).reshape(-1, 2)
    assert np.allclose(ours(u, u).reshape(-1, 3), nd(grid), atol=1e-13)
    g = GB.Surface()
    g.degree_u = g.degree_v = p
    g.ctrlpts_size_u = g.ctrlpts_size_v = n
    g.ctrlpts = net.reshape(-1, 3).tolist()
    g.knotvector_u = g.knotvector_v = kn.tolist()
    m = int(round(np.sqrt(geomdl_points)))
    pts = [(a, b) for a in np.linspace(0, 1, m) for b in np.linspace(0, 1, m)]
    tg = best(lambda: g.evaluate_list(pts), 1) * 1e6 / len(pts)
    print("\n## surface: bicubic B-spline, 10 × 10 net, 1000 × 1000 grid (10^6 points)")
    print("| case | cagd.BSplineSurface | scipy NdBSpline | %s |" % geomdl_label(len(pts)))
    row("grid", {"cagd": best(lambda: ours(u, u), 3), "scipy NdBSpline": best(lambda: nd(grid), 3), "geomdl": tg})


def thesis(root):
    with tempfile.TemporaryDirectory() as tmp:
        inputs = os.path.join(tmp, "inputs.txt")
        out = subprocess.run(
            ["octave", "--no-gui", "--quiet", "python/bench/thesis_timings.m", inputs],
            cwd=root, capture_output=True, text=True, check=True,
        ).stdout
        ws = cagd.octave.load(inputs)
    octave = {line.split("\t")[0]: float(line.split("\t")[2]) for line in out.splitlines() if "\t" in line}
    o = cagd.octave
    corners = [ws[k] for k in ["P1", "P2", "P3", "P4"]]
    ours = {
        "deCasteljau_N1000": lambda: o.deCasteljau(ws["curve"], 1000),
        "deCasteljau_N10000": lambda: o.deCasteljau(ws["curve"], 10000),
        "ploskevB_N30": lambda: o.ploskevB(ws["kontrolneT"], 30),
        "ploskevB_N100": lambda: o.ploskevB(ws["kontrolneT"], 100),
        "bilinearna": lambda: o.bilinearna(ws["kontrolneT"], 0.3, 0.7, 10),
        "tenzor_4x4": lambda: o.tenzor(ws["kontrolneT"]),
        "tenzor_200x200": lambda: o.tenzor(ws["bigT"]),
        "vrednostCoons": lambda: o.vrednostCoons(0.3, 0.7, *[ws[f"vc_{k}"] for k in ["c1", "c2", "d1", "d2"]], *corners),
        "krpaCoons_N100": lambda: o.krpaCoons(*[ws[f"coons_{k}_N100"] for k in ["c1", "c2", "d1", "d2"]], *corners),
        "krpaCoons_N300": lambda: o.krpaCoons(*[ws[f"coons_{k}_N300"] for k in ["c1", "c2", "d1", "d2"]], *corners),
        "krpaGordon_N20": lambda: o.krpaGordon(ws["gordon_g_u_N20"], ws["gordon_g_v_N20"], ws["gordon_g_uv_N20"], ws["nodes"], ws["nodes"], 20),
        "krpaGordon_N50": lambda: o.krpaGordon(ws["gordon_g_u_N50"], ws["gordon_g_v_N50"], ws["gordon_g_uv_N50"], ws["nodes"], ws["nodes"], 50),
        "Lagrange_K100000": lambda: o.Lagrange(ws["nodes"], 3, np.linspace(-0.1, 1.1, 100000)),
    }
    print("\n## the thesis functions: fixed Octave code (GNU Octave, interpreted) against cagd.octave")
    print("| case | Octave (s) | cagd.octave (s) | ratio |")
    print("|---|---|---|---|")
    for name, f in ours.items():
        t = best(f, 5)
        ratio = octave[name] / t
        print(f"| {name} | {octave[name]:.4g} | {t:.4g} | {ratio:.0f}x |" if ratio >= 10 else f"| {name} | {octave[name]:.4g} | {t:.4g} | {ratio:.2g}x |")


def overhead():
    from scipy.interpolate import BSpline

    t = np.r_[0, 0, 0, 0, 0.5, 1, 1, 1, 1.0]
    c = np.arange(5.0)
    ours, theirs = cagd.BSpline(t, c, 3), BSpline(t, c, 3)
    bez = cagd.BezierCurve([[0, 0, 0], [1, 2, 1], [3, -1, 2], [4, 1, 0]])
    reps = 20000
    per = lambda f: best(lambda: [f() for _ in range(reps)], 3) / reps
    print("\n## one call's overhead (one point, best of 3 × 20000 calls)")
    print("| call | time per call |")
    print("|---|---|")
    for name, f in [
        ("cagd.BSpline(t, c, 3)(0.3)", lambda: ours(0.3)),
        ("scipy BSpline(t, c, 3)(0.3)", lambda: theirs(0.3)),
        ("cagd.BezierCurve(...)(0.3)", lambda: bez(0.3)),
        ("cagd.octave.deCasteljau(B, 1)", lambda: cagd.octave.deCasteljau(np.array([[0.0, 1, 3, 4]]), 1)),
        ("numpy: np.asarray(0.3) + 1", lambda: np.asarray(0.3) + 1),
    ]:
        print(f"| `{name}` | {per(f) * 1e6:.2f} µs |")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--no-octave", action="store_true")
    ap.add_argument("--geomdl-points", type=int, default=1_000_000)
    args = ap.parse_args()
    root = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    import scipy

    print(f"# machine: {os.cpu_count()} cores, {platform.processor() or platform.machine()}, {platform.system()} {platform.release()}")
    print(f"# python {platform.python_version()}, numpy {np.__version__}, scipy {scipy.__version__}, cagd {cagd.__version__}")
    print(f"# RAYON_NUM_THREADS={os.environ.get('RAYON_NUM_THREADS', 'unset')}; load before: {open('/proc/loadavg').read().split()[:3]}")
    curves(args.geomdl_points)
    surfaces(args.geomdl_points)
    if not args.no_octave:
        thesis(root)
    overhead()
    print(f"\n# load after: {open('/proc/loadavg').read().split()[:3]}")


if __name__ == "__main__":
    sys.exit(main())
