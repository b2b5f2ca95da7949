// The spline views over a knot vector: the B-spline curve with its basis functions (this
// module), the NURBS curve with its weights and rational basis (nurbs.js) and knot insertion
// by Boehm's algorithm (insert.js). Points, weights, knots and the parameter are kept as typed
// ("1/3" stays 1/3, exact with "exact fractions"), on any knot interval: the slider covers the
// curve's domain [u_(p+1), u_(n+1)], the basis plot the whole knot vector. Interior knots can be
// dragged (snapping is optional). The numbers and steps are the command line's own (cagd
// bspline / nurbs / insert-knot, in the page's language); the picture's curve and basis are
// sampled by the library (bspline_view, nurbs_view) and the point at t is the command's answer.

import { viewMessage } from "./fields.js";
import { t } from "./i18n.js";
import { dragText, num, pointsLiteral, rowLiteral, splitRow, toNumber, uniformKnots, valueOf } from "./numbers.js";
import { Plane } from "./plane.js";
import { PointsTable, typedPoints } from "./points-table.js";
import { join, split } from "./shell.js";
import { check, explainInto, frame, h, labelled, parameter, showError } from "./ui.js";

const BASIS_SCALE = 0.3; // the basis plot's height per unit of N
const COLOURS = ["#0072bd", "#d95319", "#2a9d3a", "#7e2f8e", "#e08a00", "#00838f", "#c2185b", "#6d4c41", "#1f6fd1", "#9e9d24"];

/** Points of a JSON matrix (rows of printed numbers, points as columns) as doubles. */
export function pointsOf(rows) {
  if (!Array.isArray(rows)) return [];
  const m = rows.map((r) => (Array.isArray(r) ? r : [r]));
  return m[0].map((_, j) => m.map((r) => valueOf(r[j])));
}

/** Point j of a JSON matrix as printed, "(15/32, 29/32)". */
export const printed = (rows, j = 0) => `(${rows.map((r) => (Array.isArray(r) ? r[j] : r)).join(", ")})`;

const DEFAULTS = {
  bspline: {
    points: [
      ["0", "0"],
      ["1", "2"],
      ["3", "3"],
      ["5", "1"],
      ["7", "3"],
      ["8", "0"],
    ],
    p: 3,
    knots: null,
    t: "1/2",
  },
  nurbs: {
    points: [
      ["1", "0"],
      ["1", "1"],
      ["0", "1"],
    ],
    weights: ["1", "1", "2"],
    p: 2,
    knots: ["0", "0", "0", "1", "1", "1"],
    t: "1/2",
  },
  insert: {
    points: [
      ["0", "0"],
      ["1", "2"],
      ["2", "3"],
      ["3", "1"],
      ["4", "2"],
      ["5", "0"],
    ],
    p: 2,
    knots: ["0", "0", "0", "1", "2", "2", "3", "3", "3"],
    t: "3/2",
  },
};

export class SplineFamily {
  /** @param {"bspline" | "nurbs" | "insert"} mode */
  constructor(app, mode) {
    this.app = app;
    this.mode = mode;
    this.name = mode;
    const d = DEFAULTS[mode];
    this.points = d.points.map((p) => [...p]);
    this.weights = d.weights ? [...d.weights] : null;
    this.p = d.p;
    this.knots = d.knots ? [...d.knots] : uniformKnots(this.p, this.points.length);
    this.frameTimes = [];
    const what = t(`tab.${mode}`);
    this.parts = frame(document.getElementById(`view-${mode}`), { name: mode, picture: "svg", basis: mode !== "insert", label: t("planeHint", { what }) });
    this.controls(d.t);
    this.plane = new Plane(this.parts.svg, [-1, 9, -1, 4], { onDragEnd: () => this.commit() });
    this.plane.label = (n, x, y) => t("pointAt", { name: n, coords: `${num(x)}, ${num(y)}` });
    if (this.parts.basis) {
      this.basisPlane = new Plane(this.parts.basis, [-0.05, 1.05, -0.08, 0.36], { onDragEnd: () => this.commit() });
      this.basisPlane.label = (n, x) => t("pointAt", { name: n, coords: num(x) });
    }
    this.relabel();
    this.rebuild(true);
  }

  controls(tText) {
    const c = this.parts.controls;
    const name = this.name;
    const degree = h("select", { onchange: () => this.setDegree(Number(degree.value)) }, ...[1, 2, 3, 4, 5].map((p) => new Option(String(p), String(p))));
    this.degreeSelect = degree;
    const param = parameter(`${name}-t`, this.mode === "insert" ? t("parameterU") : t("parameterT"), this.mode === "insert" ? t("typedU") : t("typedT"), "0.5");
    [this.slider, this.typed] = param.querySelectorAll("input");
    this.typed.value = tText;
    this.slider.addEventListener("input", () => {
      this.typed.value = num(Number(this.slider.value));
      this.update(true);
    });
    this.typed.addEventListener("input", () => {
      this.placeSlider();
      this.update(true);
    });
    this.knotsInput = h("input", { type: "text", class: "wide", spellcheck: "false", autocomplete: "off", "aria-describedby": `${name}-knots-hint` });
    this.knotsInput.addEventListener("input", () => {
      this.knots = splitRow(this.knotsInput.value);
      this.rebuild(false, true);
    });
    const columns = this.mode === "nurbs" ? ["x", "y", t("weight")] : ["x", "y"];
    this.columns = columns;
    this.table = new PointsTable(h("div", { class: "table-wrap" }), {
      columns,
      name: (i) => `P${i}`,
      caption: this.mode === "nurbs" ? `${t("points")}, ${t("weights")}` : t("points"),
      onInput: (i, k, text) => {
        if (k === 2) this.weights[i] = text;
        else this.points[i][k] = text;
        this.rebuild(false, true);
      },
    });
    const buttons = h(
      "p",
      { class: "buttons" },
      h("button", { type: "button", id: `${name}-add`, onclick: () => this.resize(+1) }, t("addPoint")),
      h("button", { type: "button", id: `${name}-remove`, onclick: () => this.resize(-1) }, t("removePoint")),
      h("button", { type: "button", id: `${name}-uniform`, onclick: () => this.uniform() }, t("uniform")),
    );
    if (this.mode === "nurbs") buttons.append(h("button", { type: "button", id: "nurbs-circle", onclick: () => this.circle() }, t("circle")));
    c.append(
      labelled(`${name}-degree`, t("degree"), degree),
      param,
      labelled(`${name}-knots`, t("knots"), this.knotsInput, h("small", { id: `${name}-knots-hint` }, t("knotsHint"))),
      h("p", { class: "checks" }, check(`${name}-exact`, t("exact"), true), check(`${name}-snap`, t("snap"), true)),
      this.table.container,
      buttons,
    );
    document.getElementById(`${name}-exact`).addEventListener("change", () => this.update(true));
  }

  get exact() {
    return document.getElementById(`${this.name}-exact`).checked;
  }

  get snap() {
    return document.getElementById(`${this.name}-snap`).checked;
  }

  /** The curve's domain [u_(p+1), u_(n+1)] as typed texts and as doubles. */
  domain() {
    const a = this.knots[this.p];
    const b = this.knots[this.points.length];
    return { a, b, lo: toNumber(a), hi: toNumber(b) };
  }

  placeSlider() {
    const { lo, hi } = this.domain();
    if (Number.isFinite(lo) && Number.isFinite(hi) && hi > lo) {
      this.slider.min = String(lo);
      this.slider.max = String(hi);
    }
    const x = toNumber(this.typed.value);
    if (Number.isFinite(x)) this.slider.value = String(x);
  }

  setDegree(p) {
    const { a, b } = this.domain();
    this.p = p;
    while (this.points.length < p + 1) this.addPoint();
    this.knots = uniformKnots(p, this.points.length, a ?? "0", b ?? "1");
    this.rebuild(true);
  }

  addPoint() {
    const last = this.points[this.points.length - 1].map(toNumber);
    this.points.push([num(last[0] + 1), num(last[1] + (this.points.length % 2 ? 1 : -1))]);
    this.weights?.push("1");
  }

  resize(by) {
    const { a, b } = this.domain();
    if (by > 0) this.addPoint();
    else if (this.points.length > this.p + 1) {
      this.points.pop();
      this.weights?.pop();
    }
    this.knots = uniformKnots(this.p, this.points.length, a ?? "0", b ?? "1");
    this.rebuild(true);
  }

  uniform() {
    const { a, b } = this.domain();
    this.knots = uniformKnots(this.p, this.points.length, a ?? "0", b ?? "1");
    this.rebuild(false);
  }

  circle() {
    const d = DEFAULTS.nurbs;
    this.points = d.points.map((p) => [...p]);
    this.weights = [...d.weights];
    this.p = d.p;
    this.knots = [...d.knots];
    this.typed.value = d.t;
    this.rebuild(true);
  }

  doubles() {
    return this.points.map((p) => p.map(toNumber));
  }

  rows() {
    return this.points.map((p, i) => (this.weights ? [...p, this.weights[i]] : p));
  }

  /** Rebuilds the handles and the table; `fit` refits the picture, `typing` keeps the knot field. */
  rebuild(fit, typing = false) {
    this.degreeSelect.value = String(this.p);
    if (!typing || document.activeElement !== this.knotsInput) this.knotsInput.value = rowLiteral(this.knots);
    this.table.set(this.rows(), this.columns);
    this.placeSlider();
    const pts = this.doubles();
    if (fit && pts.flat().every(Number.isFinite)) this.plane.setBox(Plane.fit(pts, 2));
    else this.plane.setBox(this.plane.box);
    for (const layer of ["curve", "polygon", "inserted", "marker", "handles"]) this.plane.layer(layer);
    this.plane.handles(
      "handles",
      pts,
      this.points.map((_, i) => `P${i}`),
      (i, q) => this.dragPoint(i, q),
    );
    if (this.basisPlane) this.knotHandles();
    this.update(true);
  }

  knotHandles() {
    const k = this.knots.map(toNumber);
    const bp = this.basisPlane;
    if (k.length >= 2 && k.every(Number.isFinite) && k[k.length - 1] > k[0]) {
      const w = k[k.length - 1] - k[0];
      bp.setBox([k[0] - 0.05 * w, k[k.length - 1] + 0.05 * w, -0.08, 0.36]);
    } else bp.setBox(bp.box);
    for (const layer of ["basis", "marker", "knots"]) bp.layer(layer);
    bp.snap = 0;
    const m = this.knots.length - 1;
    const inner = [];
    for (let j = this.p + 1; j < m - this.p; j++) inner.push(j);
    this.inner = inner;
    bp.handles(
      "knots",
      inner.map((j) => [k[j], -0.04]),
      inner.map((j) => `u${j}`),
      (i, [x]) => this.dragKnot(inner[i], x),
    );
  }

  dragPoint(i, q) {
    const t0 = performance.now();
    const snap = this.snap ? 0.1 : 0;
    this.points[i] = q.map((x) => dragText(x, snap, 10));
    this.plane.moveHandle("handles", i, this.points[i].map(toNumber), `P${i}`);
    this.table.set(this.rows(), this.columns);
    this.update(false);
    this.frameTimes.push(performance.now() - t0);
  }

  /** Knot j dragged to x: kept between its neighbours, written as the drag writes it. */
  dragKnot(j, x) {
    const below = toNumber(this.knots[j - 1]);
    const above = toNumber(this.knots[j + 1]);
    const { lo, hi } = this.domain();
    const width = hi - lo || 1;
    let text = dragText(x, this.snap ? width / 20 : 0, width);
    if (toNumber(text) <= below) text = this.knots[j - 1];
    else if (toNumber(text) >= above) text = this.knots[j + 1];
    this.knots[j] = text;
    this.knotsInput.value = rowLiteral(this.knots);
    const k = this.inner.indexOf(j);
    this.basisPlane.moveHandle("knots", k, [toNumber(text), -0.04], `u${j}`);
    this.update(false);
  }

  argv() {
    const control = pointsLiteral(this.points);
    const knots = rowLiteral(this.knots);
    const at = this.typed.value.trim() || "0";
    let argv;
    if (this.mode === "insert") argv = ["cagd", "insert-knot", control, "--degree", String(this.p), "--knots", knots, "--insert", at];
    else if (this.mode === "nurbs") argv = ["cagd", "nurbs", control, "--weights", rowLiteral(this.weights), "--degree", String(this.p), "--knots", knots, "--t", at];
    else argv = ["cagd", "bspline", control, "--degree", String(this.p), "--knots", knots, "--t", at];
    argv.push("--steps");
    if (this.exact) argv.push("--exact");
    return argv;
  }

  update(full) {
    const argv = this.argv();
    const text = this.app.runHere(this.app.localized(argv));
    this.parts.steps.textContent = text.ok ? text.stdout : "";
    this.parts.cmd.textContent = join(this.app.localized(argv));
    showError(this.parts.error, text.ok ? null : viewMessage(this.name, text.error));
    const answer = text.ok ? this.app.data(argv) : null;
    this.data = answer?.ok ? answer.data : null;
    this.parts.answer.textContent = this.data ? this.summary(this.data) : "";
    this.draw();
    if (full) this.commit();
  }

  summary(d) {
    if (this.mode === "insert") {
      const c = d.control;
      return `${t("newPoints")}: ${c[0].map((_, j) => printed(c, j)).join(" ")}`;
    }
    const basis = d.basis ? `;  N = ${(Array.isArray(d.basis[0]) ? d.basis[0] : d.basis).join(", ")}` : "";
    return `x(${this.typed.value.trim()}) = ${printed(d.result)}${basis}`;
  }

  /** The library's samples of the curve and its basis over the domain, in doubles. */
  samples() {
    const pts = Float64Array.from(this.doubles().flat());
    const knots = Float64Array.from(this.knots.map(toNumber));
    if (pts.some((x) => !Number.isFinite(x)) || knots.some((x) => !Number.isFinite(x))) return null;
    const v =
      this.mode === "nurbs"
        ? JSON.parse(this.app.wasm.nurbs_view(pts, 2, Float64Array.from(this.weights.map(toNumber)), this.p, knots, 201))
        : JSON.parse(this.app.wasm.bspline_view(pts, 2, this.p, knots, 201));
    return v.error ? null : v;
  }

  draw() {
    const plane = this.plane;
    for (const layer of ["curve", "polygon", "inserted", "marker"]) plane.clear(layer);
    const v = this.samples();
    if (!v) return;
    plane.polyline("curve", v.curve, 2, { class: "curve", stroke: "#0072bd", "stroke-width": 3 });
    plane.polyline("polygon", this.doubles().flat(), 2, { class: "polygon", stroke: "#dc1414", "stroke-width": 1.5, "stroke-dasharray": this.mode === "insert" ? "5 4" : "" });
    const d = this.data;
    if (this.mode === "insert" && d?.control) {
      const q = pointsOf(d.control);
      plane.polyline("inserted", q.flat(), 2, { class: "inserted", stroke: "#2a9d3a", "stroke-width": 2.5 });
      for (const p of q) plane.dot("inserted", p[0], p[1], 0.7, { fill: "#2a9d3a" });
    } else if (d?.result) {
      const [x, y] = pointsOf(d.result)[0];
      plane.marker("marker", x, y, `${t("pointOnCurve")}: ${printed(d.result)}`);
    }
    if (!this.basisPlane) return;
    const bp = this.basisPlane;
    bp.clear("basis");
    bp.clear("marker");
    v.basis.forEach((row, i) => {
      bp.polyline(
        "basis",
        row.flatMap((y, m) => [v.t[m], BASIS_SCALE * y]),
        2,
        { stroke: COLOURS[i % COLOURS.length], "stroke-width": 2, "data-basis": i },
      );
    });
    const at = toNumber(this.typed.value);
    if (Number.isFinite(at)) bp.polyline("marker", [at, 0, at, BASIS_SCALE], 2, { class: "t-line", stroke: "#000", "stroke-dasharray": "3 3", "stroke-width": 1 });
    for (const u of this.knots.map(toNumber)) bp.dot("marker", u, -0.04, 0.4, { fill: "#888" });
  }

  commit() {
    this.app.setHash(this.state());
  }

  state() {
    return { view: this.name, cmd: join(this.app.localized(this.argv())) };
  }

  /** Opens the view on a command line of its subcommand, every value as typed. */
  load(cmd) {
    let args = [];
    try {
      args = split(cmd);
    } catch {
      return this.rebuild(true);
    }
    if (args[0] === "cagd") args.shift();
    const value = (flag) => (args.includes(flag) ? args[args.indexOf(flag) + 1] : undefined);
    const points = typedPoints(this.app, args[1], args.includes("--rows"), [2]);
    const weights = value("--weights") ? splitRow(value("--weights")) : null;
    if (points) {
      this.points = points;
      if (this.mode === "nurbs") this.weights = weights && weights.length === points.length ? weights : points.map(() => "1");
    }
    const p = Number(value("--degree") ?? (value("--order") ? Number(value("--order")) - 1 : 3));
    if (Number.isInteger(p) && p >= 1 && p <= 5) this.p = p;
    const knots = value("--knots");
    this.knots = knots ? splitRow(knots) : uniformKnots(this.p, this.points.length);
    const at = value(this.mode === "insert" ? "--insert" : "--t");
    if (at !== undefined) this.typed.value = at;
    document.getElementById(`${this.name}-exact`).checked = args.includes("--exact");
    this.rebuild(true);
  }

  activate() {
    this.update(true);
  }

  relabel() {
    explainInto(this.parts.explain, this.mode === "insert" ? "insert-knot" : this.mode);
    this.parts.stepsTitle.textContent = t("steps");
    this.parts.open.textContent = t("openCommand");
    if (this.data !== undefined) this.update(false);
  }
}

export default class BSplineView extends SplineFamily {
  constructor(app) {
    super(app, "bspline");
  }
}
