// The Bézier views: the curve with de Casteljau's construction at t (this module), its
// subdivision at t (subdivide.js) and its degree elevation (elevate.js). Points in the plane
// or in space (rotate the 3-D view, drag a point along the plane of the screen), typed in the
// table or dragged; every number as typed, exact when "exact fractions" is on. The numbers and
// steps are the command line's own (cagd decasteljau / subdivide / elevate, in the page's
// language); the picture's curve is sampled by the library (bezier_view), its construction
// drawn from the command's answer.

import { viewMessage } from "./fields.js";
import { t } from "./i18n.js";
import { dragText, num, pointsLiteral, toNumber, valueOf } from "./numbers.js";
import { Plane } from "./plane.js";
import { PointsTable, typedPoints } from "./points-table.js";
import { join, split } from "./shell.js";
import { check, explainInto, frame, h, labelled, parameter, showError } from "./ui.js";
import { View3D } from "./view3d.js";

const PRIMER = [
  ["0", "0", "0"],
  ["0", "2", "2"],
  ["8", "2", "0"],
  ["4", "0", "0"],
];
const LEVEL_COLOURS = ["#dc1414", "#e08a00", "#2a9d3a", "#1f6fd1", "#7b3fa0", "#c2185b", "#00838f", "#6d4c41"];
const AXES = ["x", "y", "z"];

/** Points of a JSON matrix (rows of printed numbers, points as columns) as doubles. */
function pointsOf(rows) {
  if (!Array.isArray(rows)) return [];
  const m = rows.map((r) => (Array.isArray(r) ? r : [r]));
  return m[0].map((_, j) => m.map((r) => valueOf(r[j])));
}

/** A point's printed coordinates, "(7/2, 3/2)". */
const printed = (rows, j = 0) => `(${rows.map((r) => (Array.isArray(r) ? r[j] : r)).join(", ")})`;

export class BezierFamily {
  /** @param {"decasteljau" | "subdivide" | "elevate"} mode */
  constructor(app, mode, name) {
    this.app = app;
    this.mode = mode;
    this.name = name;
    this.points = PRIMER.map((p) => p.slice(0, 2));
    this.frameTimes = [];
    this.by = 1;
    const section = document.getElementById(`view-${name}`);
    this.parts = frame(section, { name, picture: "both", label: t("planeHint", { what: t(`tab.${name}`) }) });
    this.controls();
    this.plane = new Plane(this.parts.svg, [-1, 9, -1.5, 4.5], { onDragEnd: () => this.commit() });
    this.plane.label = (n, x, y) => t("pointAt", { name: n, coords: `${num(x)}, ${num(y)}` });
    this.space = new View3D(this.parts.canvas, {
      onDrag: (id, p) => this.dragTo(Number(id), p),
      onSelect: () => {},
      onDragEnd: () => this.commit(),
    });
    this.relabel();
    this.rebuild(true);
  }

  controls() {
    const c = this.parts.controls;
    this.table = new PointsTable(h("div", { class: "table-wrap" }), {
      columns: AXES.slice(0, 2),
      name: (i) => `b${i}`,
      onInput: (i, k, text) => {
        this.points[i][k] = text;
        this.redraw(true);
      },
    });
    const dim = h("select", { onchange: () => this.setDim(Number(dim.value)) }, new Option("2-D", "2"), new Option("3-D", "3"));
    this.dimSelect = dim;
    this.tParam = parameter(`${this.name}-t`, t("parameterT"), t("typedT"));
    const [slider, typed] = this.tParam.querySelectorAll("input");
    this.slider = slider;
    this.typed = typed;
    slider.addEventListener("input", () => {
      typed.value = num(Number(slider.value));
      this.update(true);
    });
    typed.addEventListener("input", () => {
      const x = toNumber(typed.value);
      if (Number.isFinite(x)) slider.value = String(Math.min(1, Math.max(0, x)));
      this.update(true);
    });
    const checks = h("p", { class: "checks" });
    if (this.mode === "decasteljau") checks.append(check(`${this.name}-construction`, t("construction3"), true));
    checks.append(check(`${this.name}-exact`, t("exact"), true), check(`${this.name}-snap`, t("snap"), true));
    const by = h("select", { onchange: () => ((this.by = Number(by.value)), this.update(true)) }, ...[1, 2, 3, 4, 5].map((r) => new Option(String(r), String(r))));
    this.bySelect = by;
    c.append(
      labelled(`${this.name}-dim`, t("dimension"), dim),
      this.mode === "elevate" ? labelled(`${this.name}-by`, t("elevateBy"), by) : this.tParam,
      checks,
      this.table.container,
      h(
        "p",
        { class: "buttons" },
        h("button", { type: "button", id: `${this.name}-add`, onclick: () => this.addPoint() }, t("addPoint")),
        h("button", { type: "button", id: `${this.name}-remove`, onclick: () => this.removePoint() }, t("removePoint")),
        h("button", { type: "button", id: `${this.name}-primer`, onclick: () => this.primer(2) }, t("primer24xy")),
        h("button", { type: "button", id: `${this.name}-primer3`, onclick: () => this.primer(3) }, t("primer24")),
        h("button", { type: "button", id: `${this.name}-degree10`, onclick: () => this.degree10() }, t("degree10")),
      ),
    );
    for (const id of [`${this.name}-construction`, `${this.name}-exact`]) document.getElementById(id)?.addEventListener("change", () => this.update(true));
    document.getElementById(`${this.name}-snap`).addEventListener("change", (e) => (this.plane.snap = e.target.checked ? 0.1 : 0));
  }

  get dim() {
    return this.points[0]?.length ?? 2;
  }

  get exact() {
    return document.getElementById(`${this.name}-exact`).checked;
  }

  setDim(d) {
    this.points = this.points.map((p) => (d === 3 ? [...p.slice(0, 2), p[2] ?? "0"] : p.slice(0, 2)));
    this.rebuild(true);
  }

  primer(d) {
    this.points = PRIMER.map((p) => p.slice(0, d));
    this.slider.value = "0.5";
    this.typed.value = "0.5";
    this.rebuild(true);
  }

  degree10() {
    this.points = Array.from({ length: 11 }, (_, i) => [num(0.8 * i), num(i % 2 ? 3.5 : 0.5 + (i % 4) / 2), "0"].slice(0, this.dim));
    this.rebuild(true);
  }

  addPoint() {
    const last = this.points[this.points.length - 1].map(toNumber);
    const p = [num(Math.min(last[0] + 1, 8.5)), num(last[1] + (this.points.length % 2 ? 1 : -1)), "0"];
    this.points.push(p.slice(0, this.dim));
    this.rebuild(false);
  }

  removePoint() {
    if (this.points.length > 2) this.points.pop();
    this.rebuild(false);
  }

  /** Doubles of the points, for drawing (NaN where a text is not a number yet). */
  doubles() {
    return this.points.map((p) => p.map(toNumber));
  }

  rebuild(fit) {
    const three = this.dim === 3;
    this.dimSelect.value = String(this.dim);
    this.parts.svg.toggleAttribute("hidden", three); // an SVG element has no `hidden` property
    this.parts.canvas.hidden = !three;
    this.table.set(this.points, AXES.slice(0, this.dim));
    if (!three) {
      if (fit) this.plane.setBox(Plane.fit(this.doubles(), 4));
      else this.plane.setBox(this.plane.box);
      for (const layer of ["curve", "polygon", "construction", "halves", "elevated", "marker", "handles"]) this.plane.layer(layer);
      this.plane.handles(
        "handles",
        this.doubles(),
        this.points.map((_, i) => `b${i}`),
        (i, p) => this.dragTo(i, p),
      );
    }
    this.update(true, fit);
  }

  /** A drag (or arrow key) moved point i to the doubles `p`: its texts as the drag writes them. */
  dragTo(i, p) {
    const t0 = performance.now();
    const snap = document.getElementById(`${this.name}-snap`).checked ? 0.1 : 0;
    this.points[i] = p.map((x) => dragText(x, snap, 10));
    if (this.dim === 2) this.plane.moveHandle("handles", i, this.points[i].map(toNumber), `b${i}`);
    this.table.set(this.points, AXES.slice(0, this.dim));
    this.update(false);
    this.frameTimes.push(performance.now() - t0);
  }

  /** The command line of the view (without --format). */
  argv() {
    const control = pointsLiteral(this.points);
    let argv;
    if (this.mode === "elevate") argv = ["cagd", "elevate", control, "--by", String(this.by), "--steps"];
    else argv = ["cagd", this.mode, control, "--t", this.typed.value.trim() || "0", "--steps"];
    if (this.exact) argv.push("--exact");
    return argv;
  }

  /** Redraws after a typed edit (the table keeps its shape). */
  redraw() {
    if (this.dim === 2) this.plane.handles("handles", this.doubles(), this.points.map((_, i) => `b${i}`), (i, p) => this.dragTo(i, p));
    this.update(true);
  }

  /** Runs the command for the numbers and draws; `full` also refreshes the link. */
  update(full, fit = false) {
    const argv = this.argv();
    const text = this.app.runHere(this.app.localized(argv));
    this.parts.steps.textContent = text.ok ? text.stdout : "";
    this.parts.cmd.textContent = join(this.app.localized(argv));
    showError(this.parts.error, text.ok ? null : viewMessage(this.name, text.error));
    const answer = text.ok ? this.app.data(argv) : null;
    this.data = answer?.ok ? answer.data : null;
    this.parts.answer.textContent = this.data ? this.summary(this.data) : "";
    this.draw(fit);
    if (full) this.commit();
  }

  summary(d) {
    if (this.mode === "elevate") {
      const c = d.control ?? d.result;
      return `${t("elevated")}: ${c[0].map((_, j) => printed(c, j)).join("  ")}`;
    }
    if (this.mode === "subdivide") {
      const left = d.left ?? d.result?.left;
      const right = d.right ?? d.result?.right;
      if (!left || !right) return "";
      return `${t("halves")}: ${left[0].map((_, j) => printed(left, j)).join(" ")} | ${right[0].map((_, j) => printed(right, j)).join(" ")}`;
    }
    return `b(${this.typed.value.trim()}) = ${printed(d.result)}`;
  }

  /** The picture: the curve (library samples), the polygon and the view's construction. */
  draw(fit = false) {
    const pts = this.doubles();
    if (pts.flat().some((x) => !Number.isFinite(x))) return;
    const flat = Float64Array.from(pts.flat());
    const tt = Math.min(1, Math.max(0, toNumber(this.typed.value) || 0));
    const v = JSON.parse(this.app.wasm.bezier_view(flat, this.dim, tt, 101));
    if (v.error) return;
    const overlays = this.overlays();
    if (this.dim === 3) return this.draw3(v.curve, pts, overlays, fit);
    const plane = this.plane;
    for (const layer of ["curve", "polygon", "construction", "halves", "elevated", "marker"]) plane.clear(layer);
    plane.polyline("curve", v.curve, 2, { class: "curve", stroke: "#0072bd", "stroke-width": 3 });
    plane.polyline("polygon", flat, 2, { class: "polygon", stroke: "#dc1414", "stroke-width": 1.5 });
    for (const o of overlays) {
      plane.polyline(o.layer, o.points.flat(), 2, { stroke: o.colour, "stroke-width": o.width ?? 1.5, "stroke-dasharray": o.dash ?? "", opacity: o.opacity ?? 1, class: o.class ?? "" });
      if (o.dots) for (const p of o.points) plane.dot(o.layer, p[0], p[1], 0.55, { fill: o.colour });
    }
    if (this.marker) plane.marker("marker", this.marker[0], this.marker[1], `${t("pointOnCurve")}: ${this.markerText}`);
  }

  draw3(curve, pts, overlays, fit) {
    const line = [];
    for (let i = 0; i + 3 <= curve.length; i += 3) line.push([curve[i], curve[i + 1], curve[i + 2]]);
    const curves = [
      { points: line, colour: "#0072bd", width: 3 },
      { points: pts, colour: "#dc1414", width: 1.5 },
      ...overlays.map((o) => ({ points: o.points, colour: o.colour, width: o.width ?? 1.5, dash: o.dash ? [4, 3] : [] })),
    ];
    const points = pts.map((p, i) => ({ id: String(i), p, colour: "#dc1414" }));
    if (this.marker) points.push({ p: this.marker, fill: "#000", colour: "#fff" });
    this.space.setScene({ surfaces: [], curves, points }, fit);
  }

  /** The view's own lines over the curve, from the command's answer (exact → doubles). */
  overlays() {
    this.marker = null;
    const d = this.data;
    if (!d) return [];
    if (this.mode === "elevate") return [{ layer: "elevated", points: pointsOf(d.control ?? d.result), colour: "#e08a00", dash: "6 3", dots: true, class: "elevated" }];
    if (this.mode === "subdivide") {
      const left = d.left ?? d.result?.left;
      const right = d.right ?? d.result?.right;
      if (!left || !right) return [];
      return [
        { layer: "halves", points: pointsOf(left), colour: "#2a9d3a", width: 3, opacity: 0.8, dots: true, class: "left" },
        { layer: "halves", points: pointsOf(right), colour: "#7b3fa0", width: 3, opacity: 0.8, dots: true, class: "right" },
      ];
    }
    this.marker = pointsOf(d.result)[0];
    this.markerText = printed(d.result);
    if (!document.getElementById(`${this.name}-construction`)?.checked || !d.scheme) return [];
    const levels = Object.keys(d.scheme)
      .filter((k) => /^r\d+$/.test(k))
      .sort((a, b) => Number(a.slice(1)) - Number(b.slice(1)))
      .slice(1);
    return levels.map((k, r) => ({ layer: "construction", points: pointsOf(d.scheme[k]), colour: LEVEL_COLOURS[(r + 1) % LEVEL_COLOURS.length], dash: "4 3", dots: true }));
  }

  commit() {
    this.app.setHash(this.state());
  }

  state() {
    return { view: this.name, cmd: join(this.app.localized(this.argv())) };
  }

  /** Opens the view on a command line of its subcommand: points of any dimension, t, exact. */
  load(cmd) {
    let args = [];
    try {
      args = split(cmd);
    } catch {
      return this.rebuild(true);
    }
    if (args[0] === "cagd") args.shift();
    const value = (flag) => (args.includes(flag) ? args[args.indexOf(flag) + 1] : undefined);
    const tText = value("--t");
    if (tText !== undefined) {
      this.typed.value = tText;
      const x = toNumber(tText);
      if (Number.isFinite(x)) this.slider.value = String(Math.min(1, Math.max(0, x)));
    }
    const by = Number(value("--by") ?? value("-r"));
    if (Number.isInteger(by) && by >= 1 && by <= 5) {
      this.by = by;
      this.bySelect.value = String(by);
    }
    document.getElementById(`${this.name}-exact`).checked = args.includes("--exact");
    const points = typedPoints(this.app, args[1], args.includes("--rows"), [2, 3]);
    if (points) this.points = points;
    this.rebuild(true);
  }

  activate() {
    this.update(true);
  }

  relabel() {
    explainInto(this.parts.explain, this.mode);
    this.parts.stepsTitle.textContent = t("steps");
    this.parts.open.textContent = t("openCommand");
    if (this.data !== undefined) this.update(false);
  }
}

export default class BezierView extends BezierFamily {
  constructor(app) {
    super(app, "decasteljau", "bezier");
  }
}
