// The B-spline view: drag the control points and the interior knots; the basis functions
// N_i,p are drawn underneath, over the knots, from the library (bspline_view), and the point
// and basis at t are printed by `cagd bspline --steps`.

import { literal } from "./bezier.js";
import { num, Plane } from "./plane.js";
import { join, split } from "./shell.js";

const $ = (id) => document.getElementById(id);
const BASIS_SCALE = 0.3; // the basis plot's height per unit of N
const COLOURS = ["#0072bd", "#d95319", "#2a9d3a", "#7e2f8e", "#e08a00", "#00838f", "#c2185b", "#6d4c41", "#1f6fd1", "#9e9d24"];

const START = [
  [0, 0],
  [1, 2],
  [3, 3],
  [5, 1],
  [7, 3],
  [8, 0],
];

/** The clamped uniform knot vector: p+1 zeros, equally spaced interior knots, p+1 ones. */
export function clampedUniform(p, count) {
  const inner = count - p - 1;
  const knots = [];
  for (let k = 0; k <= p; k++) knots.push(0);
  for (let k = 1; k <= inner; k++) knots.push(Number((k / (inner + 1)).toFixed(4)));
  for (let k = 0; k <= p; k++) knots.push(1);
  return knots;
}

export default class BSplineView {
  constructor(app) {
    this.app = app;
    this.points = START.map((p) => [...p]);
    this.p = 3;
    this.knots = clampedUniform(this.p, this.points.length);
    this.plane = new Plane($("bspline-plane"), [-1, 9, -1, 4], { onDragEnd: () => this.commit() });
    this.basisPlane = new Plane($("bspline-basis"), [-0.05, 1.05, -0.08, 0.36], { onDragEnd: () => this.commit() });
    this.basisPlane.snap = 0.05;
    $("bspline-degree").addEventListener("change", () => {
      this.p = Number($("bspline-degree").value);
      while (this.points.length < this.p + 1) this.addPoint();
      this.knots = clampedUniform(this.p, this.points.length);
      this.rebuild();
    });
    for (const id of ["bspline-t", "bspline-exact"]) $(id).addEventListener("input", () => this.update(true));
    $("bspline-add").addEventListener("click", () => {
      this.addPoint();
      this.knots = clampedUniform(this.p, this.points.length);
      this.rebuild();
    });
    $("bspline-remove").addEventListener("click", () => {
      if (this.points.length > this.p + 1) this.points.pop();
      this.knots = clampedUniform(this.p, this.points.length);
      this.rebuild();
    });
    $("bspline-uniform").addEventListener("click", () => {
      this.knots = clampedUniform(this.p, this.points.length);
      this.rebuild();
    });
    this.rebuild();
  }

  addPoint() {
    const last = this.points[this.points.length - 1];
    this.points.push([Math.min(last[0] + 1, 8.5), (last[1] + 2) % 4]);
  }

  interior() {
    return this.knots.map((_, j) => j).filter((j) => j > this.p && j < this.knots.length - this.p - 1);
  }

  rebuild() {
    $("bspline-degree").value = String(this.p);
    this.plane.setBox(this.plane.box);
    for (const name of ["curve", "polygon", "marker", "handles"]) this.plane.layer(name);
    this.plane.handles(
      "handles",
      this.points,
      this.points.map((_, i) => `P${i}`),
      (i, q) => {
        this.points[i] = q;
        this.plane.moveHandle("handles", i, q, `P${i}`);
        this.update(false);
      },
    );
    this.basisPlane.setBox(this.basisPlane.box);
    for (const name of ["basis", "marker", "knots"]) this.basisPlane.layer(name);
    const inner = this.interior();
    this.basisPlane.handles(
      "knots",
      inner.map((j) => [this.knots[j], -0.04]),
      inner.map((j) => `knot u${j}`),
      (k, [x]) => {
        const j = inner[k];
        const clamped = Math.min(Math.max(x, this.knots[j - 1]), this.knots[j + 1]);
        this.knots[j] = Number(clamped.toFixed(6));
        this.basisPlane.moveHandle("knots", k, [this.knots[j], -0.04], `knot u${j}`);
        this.update(false);
      },
    );
    this.update(true);
  }

  get t() {
    return Number($("bspline-t").value);
  }

  update(full) {
    $("bspline-t-value").textContent = num(this.t);
    const v = JSON.parse(this.app.wasm.bspline_view(Float64Array.from(this.points.flat()), 2, this.p, Float64Array.from(this.knots), 201));
    const err = $("bspline-error");
    err.hidden = !v.error;
    err.textContent = v.error ?? "";
    if (v.error) return;
    const plane = this.plane;
    plane.clear("curve");
    plane.clear("polygon");
    plane.clear("marker");
    plane.polyline("curve", v.curve, 2, { class: "curve", stroke: "#0072bd", "stroke-width": 3 });
    plane.polyline("polygon", this.points.flat(), 2, { class: "polygon", stroke: "#dc1414", "stroke-width": 1.5 });
    const k = Math.round(this.t * (v.t.length - 1));
    plane.dot("marker", v.curve[2 * k], v.curve[2 * k + 1], 0.9, { fill: "#000" });
    const bp = this.basisPlane;
    bp.clear("basis");
    bp.clear("marker");
    v.basis.forEach((row, i) => {
      const flat = row.flatMap((y, m) => [v.t[m], BASIS_SCALE * y]);
      bp.polyline("basis", flat, 2, { stroke: COLOURS[i % COLOURS.length], "stroke-width": 2, "data-basis": i });
    });
    bp.polyline("marker", [this.t, 0, this.t, BASIS_SCALE], 2, { stroke: "#000", "stroke-dasharray": "3 3", "stroke-width": 1 });
    for (const u of v.knots) bp.dot("marker", u, -0.04, 0.4, { fill: "#888" });
    const argv = this.argv();
    const answer = this.app.runHere(argv);
    $("bspline-steps").textContent = answer.ok ? answer.stdout : answer.error;
    $("bspline-cmd").textContent = join(argv);
    if (full) this.commit();
  }

  argv() {
    const argv = ["cagd", "bspline", literal(this.points), "--degree", String(this.p), "--knots", `[${this.knots.map(num).join(" ")}]`, "--t", num(this.t), "--steps"];
    if ($("bspline-exact").checked) argv.push("--exact");
    return argv;
  }

  commit() {
    this.app.setHash(this.state());
  }

  state() {
    return { view: "bspline", cmd: join(this.argv()) };
  }

  load(cmd) {
    let args = [];
    try {
      args = split(cmd);
    } catch {
      /* keep the curve */
    }
    if (args[0] === "cagd") args.shift();
    const value = (flag) => (args.includes(flag) ? args[args.indexOf(flag) + 1] : undefined);
    const rows = args[1] === undefined ? null : this.app.matrix(args[1]);
    if (rows && rows.length === 2) this.points = this.app.columns(rows);
    const p = Number(value("--degree") ?? 3);
    if (Number.isInteger(p) && p >= 1 && p <= 5 && this.points.length > p) this.p = p;
    const knots = value("--knots") ? this.app.matrix(value("--knots")) : null;
    this.knots = knots && knots.flat().length === this.points.length + this.p + 1 ? knots.flat() : clampedUniform(this.p, this.points.length);
    const t = Number(value("--t"));
    if (Number.isFinite(t) && t >= 0 && t <= 1) $("bspline-t").value = String(t);
    $("bspline-exact").checked = args.includes("--exact");
    this.rebuild();
  }

  activate() {
    this.update(true);
  }
}
