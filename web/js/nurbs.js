// The NURBS view: drag the control points and change a point's weight with the slider; the
// curve and the rational basis R_i,p come from the library (nurbs_view), the point and basis
// at t from `cagd nurbs --steps`.

import { literal } from "./bezier.js";
import { num, Plane } from "./plane.js";
import { join, split } from "./shell.js";

const $ = (id) => document.getElementById(id);
const BASIS_SCALE = 0.3;
const COLOURS = ["#0072bd", "#d95319", "#2a9d3a", "#7e2f8e", "#e08a00", "#00838f", "#c2185b", "#6d4c41"];

const CIRCLE = {
  points: [
    [1, 0],
    [1, 1],
    [0, 1],
  ],
  weights: [1, 0.7071067811865476, 1],
};

export default class NurbsView {
  constructor(app) {
    this.app = app;
    this.setCurve(CIRCLE.points, CIRCLE.weights, 2);
    this.selected = 1;
    this.plane = new Plane($("nurbs-plane"), [-0.5, 2, -0.5, 1.5], { onDragEnd: () => this.commit() });
    this.plane.snap = 0.05;
    this.basisPlane = new Plane($("nurbs-basis"), [-0.05, 1.05, -0.05, 0.36]);
    $("nurbs-point").addEventListener("change", () => this.select(Number($("nurbs-point").value)));
    $("nurbs-weight").addEventListener("input", () => {
      this.weights[this.selected] = Number($("nurbs-weight").value);
      this.update(false);
    });
    $("nurbs-weight").addEventListener("change", () => this.commit());
    $("nurbs-degree").addEventListener("change", () => {
      const p = Number($("nurbs-degree").value);
      while (this.points.length < p + 1) this.addPoint();
      this.p = p;
      this.rebuild();
    });
    $("nurbs-t").addEventListener("input", () => this.update(true));
    $("nurbs-circle").addEventListener("click", () => {
      this.setCurve(CIRCLE.points, CIRCLE.weights, 2);
      this.rebuild();
    });
    $("nurbs-add").addEventListener("click", () => {
      this.addPoint();
      this.rebuild();
    });
    this.rebuild();
  }

  setCurve(points, weights, p) {
    this.points = points.map((q) => [...q]);
    this.weights = [...weights];
    this.p = p;
  }

  addPoint() {
    const last = this.points[this.points.length - 1];
    this.points.push([last[0] + 0.5, last[1] - 0.25]);
    this.weights.push(1);
  }

  select(i) {
    this.selected = i;
    $("nurbs-point").value = String(i);
    $("nurbs-weight").value = String(this.weights[i]);
    $("nurbs-weight-value").textContent = num(this.weights[i]);
  }

  rebuild() {
    $("nurbs-degree").value = String(this.p);
    const sel = $("nurbs-point");
    sel.replaceChildren(...this.points.map((_, i) => new Option(`P${i}`, String(i))));
    this.select(Math.min(this.selected, this.points.length - 1));
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
      (i) => this.select(i),
    );
    this.basisPlane.setBox(this.basisPlane.box);
    this.update(true);
  }

  get t() {
    return Number($("nurbs-t").value);
  }

  update(full) {
    $("nurbs-t-value").textContent = num(this.t);
    $("nurbs-weight-value").textContent = num(this.weights[this.selected]);
    // No knots: the library's clamped uniform vector, as the command line's default.
    const v = JSON.parse(this.app.wasm.nurbs_view(Float64Array.from(this.points.flat()), 2, Float64Array.from(this.weights), this.p, new Float64Array(0), 201));
    const err = $("nurbs-error");
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
    v.basis.forEach((row, i) => {
      bp.polyline("basis", row.flatMap((y, m) => [v.t[m], BASIS_SCALE * y]), 2, { stroke: COLOURS[i % COLOURS.length], "stroke-width": 2 });
    });
    const argv = this.argv();
    const answer = this.app.runHere(argv);
    $("nurbs-steps").textContent = answer.ok ? answer.stdout : answer.error;
    $("nurbs-cmd").textContent = join(argv);
    if (full) this.commit();
  }

  argv() {
    return ["cagd", "nurbs", literal(this.points), "--weights", `[${this.weights.map(num).join(" ")}]`, "--degree", String(this.p), "--t", num(this.t), "--steps"];
  }

  commit() {
    this.app.setHash(this.state());
  }

  state() {
    return { view: "nurbs", cmd: join(this.argv()) };
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
    const weights = value("--weights") ? this.app.matrix(value("--weights")) : null;
    if (rows && rows.length === 2 && weights && weights.flat().length === rows[0].length) {
      const p = Number(value("--degree") ?? 2);
      this.setCurve(this.app.columns(rows), weights.flat(), Number.isInteger(p) && p >= 1 && p <= 3 && rows[0].length > p ? p : 2);
    }
    const t = Number(value("--t"));
    if (Number.isFinite(t) && t >= 0 && t <= 1) $("nurbs-t").value = String(t);
    this.rebuild();
  }

  activate() {
    this.update(true);
  }
}
