"""Rich display in Jupyter: SVG pictures of curves and surfaces, HTML tables of control points
and of the steps of a construction (exact values written as fractions). Display only: every
number shown is computed by the core."""

import html
import math
from fractions import Fraction

import numpy as np

_W, _H, _PAD = 360, 260, 16


def _text(x):
    if isinstance(x, Fraction):
        return str(x)
    if isinstance(x, float):
        return f"{x:.6g}"
    return str(x)


def _array_html(a):
    a = np.asarray(a, dtype=object)
    if a.ndim == 0:
        return html.escape(_text(a.item()))
    if a.ndim == 1:
        return "(" + ", ".join(html.escape(_text(x)) for x in a) + ")"
    rows = "".join(f"<tr><td>{_array_html(r)}</td></tr>" for r in a)
    return f"<table>{rows}</table>"


def steps_html(title, text, items):
    """The steps as a table of their named values (and the core's own text, when it has one)."""
    body = "".join(
        f"<tr><th style='text-align:left'>{html.escape(str(n))}</th><td>{_array_html(v)}</td></tr>"
        for n, v in items
    )
    pre = f"<pre>{html.escape(text)}</pre>" if text else ""
    return f"<div><b>{html.escape(title)}</b>{pre}<table>{body}</table></div>"


def _project(p):
    p = np.asarray(p, dtype=float)
    if p.shape[-1] == 1:
        return p[..., 0], np.zeros(p.shape[:-1])
    if p.shape[-1] == 2:
        return p[..., 0], p[..., 1]
    c, s = math.cos(math.pi / 6), math.sin(math.pi / 6)
    x, y, z = p[..., 0], p[..., 1], p[..., 2]
    return (x - y) * c, z + (x + y) * s


def _svg(polylines, points=()):
    xs = np.concatenate([np.ravel(x) for x, _, _ in polylines] + [np.ravel(p[0]) for p in points] or [np.zeros(1)])
    ys = np.concatenate([np.ravel(y) for _, y, _ in polylines] + [np.ravel(p[1]) for p in points] or [np.zeros(1)])
    finite = np.isfinite(xs) & np.isfinite(ys)
    xs, ys = xs[finite], ys[finite]
    x0, x1 = (xs.min(), xs.max()) if xs.size else (0, 1)
    y0, y1 = (ys.min(), ys.max()) if ys.size else (0, 1)
    scale = min((_W - 2 * _PAD) / max(x1 - x0, 1e-12), (_H - 2 * _PAD) / max(y1 - y0, 1e-12))

    def to_px(x, y):
        return _PAD + (np.asarray(x) - x0) * scale, _H - _PAD - (np.asarray(y) - y0) * scale

    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{_W}" height="{_H}" viewBox="0 0 {_W} {_H}">']
    for x, y, style in polylines:
        px, py = to_px(x, y)
        pts = " ".join(f"{a:.2f},{b:.2f}" for a, b in zip(px, py) if math.isfinite(a) and math.isfinite(b))
        parts.append(f'<polyline fill="none" points="{pts}" {style}/>')
    for x, y in points:
        for a, b in zip(*to_px(np.ravel(x), np.ravel(y))):
            parts.append(f'<circle cx="{a:.2f}" cy="{b:.2f}" r="3" fill="#c33"/>')
    parts.append("</svg>")
    return "".join(parts)


def _interval(obj):
    lo, hi = getattr(obj, "domain", (0.0, 1.0))
    return float(lo), float(hi)


def curve_svg(obj):
    """The curve sampled at 201 parameters over its domain, with its control polygon."""
    lo, hi = _interval(obj)
    t = np.linspace(lo, hi, 201)
    if getattr(obj, "exact", False):
        t = [Fraction(x) for x in t]
        t = np.array(t, dtype=object)
    px, py = _project(np.asarray(obj(t), dtype=float))
    lines = [(px, py, 'stroke="#236" stroke-width="2"')]
    points = []
    control = getattr(obj, "control_points", None)
    if control is not None:
        cx, cy = _project(np.asarray(control, dtype=float))
        lines.append((cx, cy, 'stroke="#c33" stroke-dasharray="4 3"'))
        points.append((cx, cy))
    return _svg(lines, points)


def surface_svg(obj):
    """Eleven lines of the surface in each direction over its domain, with its control net."""
    dom = getattr(obj, "domain", ((0.0, 1.0), (0.0, 1.0)))
    (u0, u1), (v0, v1) = [(float(a), float(b)) for a, b in dom]
    u, v = np.linspace(u0, u1, 11), np.linspace(v0, v1, 11)
    if getattr(obj, "exact", False):
        u = np.array([Fraction(x) for x in u], dtype=object)
        v = np.array([Fraction(x) for x in v], dtype=object)
    grid = np.asarray(obj(u, v), dtype=float)
    px, py = _project(grid)
    style = 'stroke="#236" stroke-width="1.2"'
    lines = [(px[i], py[i], style) for i in range(px.shape[0])]
    lines += [(px[:, j], py[:, j], style) for j in range(px.shape[1])]
    points = []
    control = getattr(obj, "control_points", None)
    if control is not None:
        cx, cy = _project(np.asarray(control, dtype=float))
        net = 'stroke="#c33" stroke-dasharray="4 3"'
        lines += [(cx[i], cy[i], net) for i in range(cx.shape[0])]
        lines += [(cx[:, j], cy[:, j], net) for j in range(cx.shape[1])]
        points.append((cx, cy))
    return _svg(lines, points)


def _steps_html(obj):
    """The steps of the construction that made ``obj`` (none for an object given directly)."""
    try:
        steps = getattr(obj, "steps", None)
    except ValueError as e:  # a limit the steps exceed: say so instead of failing the display
        return f"<p>steps: {html.escape(str(e))}</p>"
    return steps._repr_html_() if steps is not None else ""


def object_html(obj):
    """The object's description, its control points (fractions as written), its picture and
    the steps of the construction that made it."""
    control = getattr(obj, "control_points", None)
    table = _array_html(control) if control is not None else ""
    svg = obj._repr_svg_()
    steps = _steps_html(obj)
    return (
        f"<div><b>{html.escape(repr(obj))}</b><div style='display:flex;gap:1em'>{svg}"
        f"<div>{table}</div></div>{steps}</div>"
    )
