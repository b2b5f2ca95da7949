// The Coons view: four boundary curves meeting at the corners P1..P4, each a Bézier curve or a
// B-spline curve on its own knot vector (its domain mapped onto [0, 1]); drag their control
// points in 3-D or type them, and see the bilinearly blended patch x = r_c + r_d − r_cd, or
// each of its parts, on an N × N grid (coons_view: the operation layer's coons request), with
// the numbers at (u, v) from `cagd coons --steps --exact` (boundaries written as the command
// line writes them, bspline(P, U) for a B-spline). Coordinates and knots are kept as typed
// ("1/3" stays 1/3): the numbers at (u, v) are exact.

import { explainInto } from "./explain.js";
import { viewMessage } from "./fields.js";
import { t } from "./i18n.js";
import { dragText, num, pointsLiteral, rowLiteral, splitRow, toNumber, uniformKnots } from "./numbers.js";
import { join, split } from "./shell.js";
import { View3D } from "./view3d.js";

const $ = (id) => document.getElementById(id);

// Primer 4.3's boundaries as quadratic Bézier curves: c1 = [u;0;u-u^2], c2 = [u;1;u],
// d1 = [0;v^2;v-v^2], d2 = [1;v;v].
const PRIMER = {
  corners: [
    ["0", "0", "0"],
    ["1", "0", "0"],
    ["0", "1", "0"],
    ["1", "1", "1"],
  ],
  inner: {
    c1: [["0.5", "0", "0.5"]],
    c2: [["0.5", "1", "0.5"]],
    d1: [["0", "0", "0.5"]],
    d2: [["1", "0.5", "0.5"]],
  },
  knots: {},
};

// Which corners each boundary runs between: c1 = x(·,0) from P1 to P2, c2 = x(·,1) from P3 to
// P4, d1 = x(0,·) from P1 to P3, d2 = x(1,·) from P2 to P4.
const ENDS = { c1: [0, 1], c2: [2, 3], d1: [0, 2], d2: [1, 3] };
const NAMES = Object.keys(ENDS);
const COLOURS = { c1: "#dc1414", c2: "#dc1414", d1: "#009600", d2: "#009600" };

/** A call `name(a, b, …)` split at its top-level commas, as the command line reads it. */
function splitCall(text) {
  const s = String(text ?? "").trim();
  const m = /^(bezier|bspline)\s*\((.*)\)$/s.exec(s);
  if (!m) return null;
  const args = [];
  let depth = 0;
  let start = 0;
  for (let i = 0; i < m[2].length; i++) {
    const c = m[2][i];
    if ("[({".includes(c)) depth++;
    else if ("])}".includes(c)) depth--;
    else if (c === "," && depth === 0) {
      args.push(m[2].slice(start, i).trim());
      start = i + 1;
    }
  }
  args.push(m[2].slice(start).trim());
  return { name: m[1], args };
}

export default class CoonsView {
  constructor(app) {
    this.app = app;
    this.reset(PRIMER);
    this.selected = "P4";
    this.boundary = "c1";
    this.frameTimes = [];
    this.view = new View3D($("coons-canvas"), {
      onDrag: (id, p) => this.drag(id, p),
      onSelect: (id) => this.select(id),
      onDragEnd: () => this.numbers(true),
    });
    for (const id of ["coons-x", "coons-rc", "coons-rd", "coons-rcd", "coons-n", "coons-u", "coons-v"]) $(id).addEventListener("input", () => this.update(true));
    $("coons-point").addEventListener("change", () => this.select($("coons-point").value));
    ["x", "y", "z"].forEach((axis, k) =>
      $(`coons-p${axis}`).addEventListener("input", () => {
        const p = [...this.text(this.selected)];
        p[k] = $(`coons-p${axis}`).value.trim();
        this.setPoint(this.selected, p);
        this.update(true);
      }),
    );
    $("coons-curve").addEventListener("change", () => this.chooseBoundary($("coons-curve").value));
    $("coons-kind").addEventListener("change", () => this.setKind($("coons-kind").value));
    $("coons-degree").addEventListener("change", () => this.setDegree(Number($("coons-degree").value)));
    $("coons-knots").addEventListener("input", () => {
      this.knots[this.boundary] = splitRow($("coons-knots").value);
      this.boundaryFields(true);
      this.update(true);
    });
    $("coons-add").addEventListener("click", () => this.resize(+1));
    $("coons-remove").addEventListener("click", () => this.resize(-1));
    $("coons-uniform").addEventListener("click", () => this.uniform());
    this.relabel();
    this.options();
    this.update(true, true);
  }

  relabel() {
    explainInto(document.getElementById("coons-explain"), "coons");
    $("coons-canvas").setAttribute("aria-label", `${t("tab.coons")}. ${t("rotateHint")}`);
    $("coons-curve").replaceChildren(...NAMES.map((n) => new Option(t(`field.${n}`), n, false, n === this.boundary)));
    if (this.grids !== undefined) {
      this.options();
      this.numbers(false);
    }
  }

  reset(data) {
    this.corners = data.corners.map((p) => [...p]);
    this.inner = Object.fromEntries(NAMES.map((k) => [k, data.inner[k].map((p) => [...p])]));
    // A boundary with knots is a B-spline curve of degree (knots − points − 1), else Bézier.
    this.knots = Object.fromEntries(NAMES.map((k) => [k, data.knots[k] ? [...data.knots[k]] : null]));
  }

  /** Typed control points of boundary `name`, corners included. */
  curveText(name) {
    const [a, b] = ENDS[name];
    return [this.corners[a], ...this.inner[name], this.corners[b]];
  }

  /** Control points of boundary `name` as doubles (NaN where a text is not a number yet). */
  curve(name) {
    return this.curveText(name).map((p) => p.map(toNumber));
  }

  ids() {
    const ids = ["P1", "P2", "P3", "P4"];
    for (const name of NAMES) this.inner[name].forEach((_, k) => ids.push(`${name}:${k + 1}`));
    return ids;
  }

  /** The typed coordinates of point `id`. */
  text(id) {
    if (id.startsWith("P")) return this.corners[Number(id.slice(1)) - 1];
    const [name, k] = id.split(":");
    return this.inner[name][Number(k) - 1];
  }

  /** Point `id` as doubles. */
  point(id) {
    return this.text(id).map(toNumber);
  }

  setPoint(id, p) {
    if (id.startsWith("P")) this.corners[Number(id.slice(1)) - 1] = p;
    else {
      const [name, k] = id.split(":");
      this.inner[name][Number(k) - 1] = p;
    }
  }

  label(id) {
    if (id.startsWith("P")) return t("corner", { name: id });
    const [name, k] = id.split(":");
    return t("curvePoint", { curve: name, k });
  }

  options() {
    const sel = $("coons-point");
    if (!this.ids().includes(this.selected)) this.selected = "P4";
    sel.replaceChildren(...this.ids().map((id) => new Option(this.label(id), id, false, id === this.selected)));
    this.fields();
    this.boundaryFields();
  }

  fields() {
    const p = this.text(this.selected);
    ["x", "y", "z"].forEach((axis, k) => {
      const input = $(`coons-p${axis}`);
      if (document.activeElement !== input) input.value = p[k];
    });
  }

  /** The chosen boundary's kind, degree and knots in their fields (`typing`: keep the knots field). */
  boundaryFields(typing = false) {
    const name = this.boundary;
    const knots = this.knots[name];
    const count = this.curveText(name).length;
    $("coons-curve").value = name;
    $("coons-kind").value = knots ? "bspline" : "bezier";
    const degree = knots ? knots.length - count - 1 : count - 1;
    const sel = $("coons-degree");
    if (![...sel.options].some((o) => o.value === String(degree))) sel.add(new Option(String(degree), String(degree)));
    sel.value = String(degree);
    sel.disabled = !knots;
    for (const e of document.querySelectorAll("#view-coons .bspline-only")) e.hidden = !knots;
    if (!typing || document.activeElement !== $("coons-knots")) $("coons-knots").value = knots ? rowLiteral(knots) : "";
  }

  chooseBoundary(name) {
    this.boundary = name;
    this.boundaryFields();
  }

  /** The domain [a, b] of a B-spline boundary as typed (the knots u_(p+1) and u_(n+1), counted from 1). */
  domain(name) {
    const knots = this.knots[name];
    const count = this.curveText(name).length;
    if (!knots) return { a: "0", b: "1" };
    const p = knots.length - count - 1;
    return { a: knots[p] ?? "0", b: knots[count] ?? "1" };
  }

  setKind(kind) {
    const name = this.boundary;
    if (kind === "bspline" && !this.knots[name]) {
      // The same curve: a Bézier curve is the B-spline of its degree on [0 … 0 1 … 1].
      const count = this.curveText(name).length;
      this.knots[name] = uniformKnots(count - 1, count);
    } else if (kind === "bezier") this.knots[name] = null;
    this.boundaryFields();
    this.update(true);
  }

  setDegree(p) {
    const name = this.boundary;
    if (!this.knots[name] || !(p >= 1)) return;
    const { a, b } = this.domain(name);
    while (this.curveText(name).length < p + 1) this.addPoint(name);
    this.knots[name] = uniformKnots(p, this.curveText(name).length, a, b);
    this.options();
    this.update(true);
  }

  uniform() {
    const name = this.boundary;
    const knots = this.knots[name];
    if (!knots) return;
    const count = this.curveText(name).length;
    const { a, b } = this.domain(name);
    this.knots[name] = uniformKnots(Math.max(1, knots.length - count - 1), count, a, b);
    this.boundaryFields();
    this.update(true);
  }

  /** A new inner point of boundary `name`, between its last inner point and its end. */
  addPoint(name) {
    const pts = this.curve(name);
    const [p, q] = [pts[pts.length - 2], pts[pts.length - 1]];
    this.inner[name].push(p.map((x, k) => num((x + q[k]) / 2)));
  }

  /** One control point more or less on the chosen boundary; a B-spline keeps its degree. */
  resize(by) {
    const name = this.boundary;
    const knots = this.knots[name];
    const count = this.curveText(name).length;
    const p = knots ? knots.length - count - 1 : null;
    const { a, b } = this.domain(name);
    if (by > 0) this.addPoint(name);
    else if (this.inner[name].length > 0 && (p === null || count - 1 >= p + 1)) this.inner[name].pop();
    else return;
    if (knots) this.knots[name] = uniformKnots(p, this.curveText(name).length, a, b);
    this.options();
    this.update(true, true);
  }

  select(id) {
    this.selected = id;
    $("coons-point").value = id;
    if (!id.startsWith("P")) this.chooseBoundary(id.split(":")[0]);
    this.fields();
    this.draw();
  }

  drag(id, p) {
    const t0 = performance.now();
    this.setPoint(
      id,
      p.map((c) => dragText(c, 0.01)),
    );
    this.fields();
    this.update(false);
    this.frameTimes.push(performance.now() - t0);
  }

  get n() {
    return Number($("coons-n").value);
  }

  /** The boundaries as coons_view takes them (null when a coordinate or knot is not a number). */
  boundaries() {
    const list = NAMES.map((name) => ({ points: this.curve(name).flat(), knots: this.knots[name]?.map(toNumber) ?? null }));
    const numbers = list.every((c) => c.points.every(Number.isFinite) && (c.knots ?? []).every(Number.isFinite));
    return numbers ? JSON.stringify(list) : null;
  }

  update(full, fit = false) {
    $("coons-n-value").textContent = String(this.n);
    $("coons-u-value").textContent = $("coons-u").value;
    $("coons-v-value").textContent = $("coons-v").value;
    const parts = ["coons-rc", "coons-rd", "coons-rcd"].some((id) => $(id).checked);
    const err = $("coons-error");
    const boundaries = this.boundaries();
    try {
      // (Not numbers yet: the command line below names what it cannot read.)
      this.grids = boundaries ? this.app.wasm.coons_view(boundaries, this.n, parts) : null;
      err.hidden = true;
    } catch (e) {
      this.grids = null;
      err.hidden = false;
      err.textContent = viewMessage("coons", String(e));
    }
    this.draw(fit);
    if (full || !this.grids) this.numbers(full);
  }

  draw(fit = false) {
    const curves = [];
    const surfaces = [];
    const n = this.n;
    const len = n * n * 3;
    if (this.grids && this.grids.length >= len) {
      const grid = (k) => this.grids.subarray(k * len, (k + 1) * len);
      if ($("coons-x").checked) surfaces.push({ grid: grid(0), nu: n, nv: n, style: "filled" });
      const wires = [
        ["coons-rc", 1, "#ed9121"],
        ["coons-rd", 2, "#7e2f8e"],
        ["coons-rcd", 3, "#555"],
      ];
      for (const [id, k, colour] of wires) if ($(id).checked && this.grids.length >= (k + 1) * len) surfaces.push({ grid: grid(k), nu: n, nv: n, style: "wire", colour });
      const x = grid(0);
      const at = (a, b) => [x[(a * n + b) * 3], x[(a * n + b) * 3 + 1], x[(a * n + b) * 3 + 2]];
      const edge = (f) => Array.from({ length: n }, (_, k) => f(k));
      curves.push(
        { points: edge((k) => at(k, 0)), colour: COLOURS.c1, width: 3 },
        { points: edge((k) => at(k, n - 1)), colour: COLOURS.c2, width: 3 },
        { points: edge((k) => at(0, k)), colour: COLOURS.d1, width: 3 },
        { points: edge((k) => at(n - 1, k)), colour: COLOURS.d2, width: 3 },
      );
    }
    for (const name of NAMES) curves.push({ points: this.curve(name), colour: COLOURS[name], width: name === this.boundary ? 2 : 1, dash: [4, 3] });
    const points = this.ids().map((id) => ({ id, p: this.point(id), selected: id === this.selected, colour: id.startsWith("P") ? "#000" : COLOURS[id.split(":")[0]] }));
    if (this.marker && this.grids) points.push({ p: this.marker, fill: "#000", colour: "#fff" });
    this.view.setScene({ surfaces, curves, points: points.filter((q) => q.p.every(Number.isFinite)) }, fit);
  }

  /** Boundary `name` as the command line writes it: control points, or bspline(P, U). */
  literal(name) {
    const points = pointsLiteral(this.curveText(name));
    const knots = this.knots[name];
    return knots ? `bspline(${points}, ${rowLiteral(knots)})` : points;
  }

  argv(format) {
    const argv = ["cagd", "coons"];
    for (const name of NAMES) argv.push(`--${name}`, this.literal(name));
    argv.push("--u", $("coons-u").value, "--v", $("coons-v").value, "--steps", "--exact");
    if (format) argv.push("--format", format);
    return argv;
  }

  /** The numbers at (u, v), by the command line's own code. */
  numbers(commit) {
    const argv = this.argv();
    const answer = this.app.runHere(this.app.localized(argv));
    $("coons-steps").textContent = answer.ok ? answer.stdout : "";
    $("coons-cmd").textContent = join(this.app.localized(argv));
    const err = $("coons-error");
    if (!answer.ok) {
      err.hidden = false;
      err.textContent = viewMessage("coons", answer.error);
    }
    // The point x(u, v) as exact fractions (the answer line) and in doubles (the marker).
    const json = answer.ok ? this.app.runHere(this.argv("json")) : null;
    const point = json?.ok ? JSON.parse(json.stdout).result.map((row) => String(Array.isArray(row) ? row[0] : row)) : null;
    $("coons-answer").textContent = point ? `x(${$("coons-u").value}, ${$("coons-v").value}) = (${point.join(", ")})` : "";
    this.marker = point ? point.map(toNumber) : null;
    this.draw();
    if (commit) this.app.setHash(this.state());
  }

  state() {
    return { view: "coons", cmd: join(this.argv()) };
  }

  /** Control points (columns) and knots of a boundary written as the command line takes it. */
  readBoundary(text) {
    const call = splitCall(text);
    const pointsText = call ? call.args[0] : text;
    const rows = pointsText === undefined ? null : this.app.matrix(pointsText);
    if (!rows || rows.length !== 3) return null;
    const points = this.app.columns(rows).map((p) => p.map(num));
    // Entries typed as plain numbers or fractions keep their text (1/3 stays 1/3).
    const typed = /^\[(.*)\]'$/s.exec(pointsText.trim());
    if (typed) {
      const cells = typed[1].split(/;|\n/).map((r) => r.trim().split(/[\s,]+/).filter(Boolean)).filter((r) => r.length);
      if (cells.length === points.length && cells.every((r) => r.length === 3 && r.every((c) => Number.isFinite(toNumber(c))))) points.splice(0, points.length, ...cells);
    }
    if (call?.name === "bspline") {
      if (call.args.length !== 2) return null;
      return { points, knots: splitRow(call.args[1]) };
    }
    return { points, knots: null };
  }

  /** Opens the view on a `cagd coons` command line whose boundaries are control points or bspline(P, U). */
  load(cmd) {
    let args = [];
    try {
      args = split(cmd);
    } catch {
      /* keep the current patch */
    }
    const value = (flag) => (args.includes(flag) ? args[args.indexOf(flag) + 1] : undefined);
    const curves = {};
    for (const name of NAMES) {
      const c = this.readBoundary(value(`--${name}`));
      if (!c || c.points.length < 2) return this.update(true, true);
      curves[name] = c;
    }
    this.reset({
      corners: [curves.c1.points[0], curves.c1.points.at(-1), curves.c2.points[0], curves.c2.points.at(-1)],
      inner: Object.fromEntries(NAMES.map((k) => [k, curves[k].points.slice(1, -1)])),
      knots: Object.fromEntries(NAMES.map((k) => [k, curves[k].knots])),
    });
    for (const [flag, id] of [
      ["--u", "coons-u"],
      ["--v", "coons-v"],
    ])
      if (Number.isFinite(Number(value(flag)))) $(id).value = value(flag);
    this.selected = "P4";
    this.boundary = NAMES.find((k) => this.knots[k]) ?? "c1";
    this.options();
    this.update(true, true);
  }

  activate() {
    this.update(true);
  }
}

