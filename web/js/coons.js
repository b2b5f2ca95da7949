// The Coons view: four Bézier boundary curves meeting at the corners P1..P4; drag their control
// points in 3-D and see the bilinearly blended patch x = r_c + r_d − r_cd, or each of its parts,
// on an N × N grid (coons_view), with the numbers at (u, v) from `cagd coons --steps`.

import { explainInto } from "./explain.js";
import { num, toNumber } from "./numbers.js";
import { join, split } from "./shell.js";
import { View3D } from "./view3d.js";

const $ = (id) => document.getElementById(id);

// Primer 4.3's boundaries as quadratic Bézier curves: c1 = [u;0;u-u^2], c2 = [u;1;u],
// d1 = [0;v^2;v-v^2], d2 = [1;v;v].
const PRIMER = {
  corners: [
    [0, 0, 0],
    [1, 0, 0],
    [0, 1, 0],
    [1, 1, 1],
  ],
  inner: {
    c1: [[0.5, 0, 0.5]],
    c2: [[0.5, 1, 0.5]],
    d1: [[0, 0, 0.5]],
    d2: [[1, 0.5, 0.5]],
  },
};

// Which corners each boundary runs between: c1 = x(·,0) from P1 to P2, c2 = x(·,1) from P3 to
// P4, d1 = x(0,·) from P1 to P3, d2 = x(1,·) from P2 to P4.
const ENDS = { c1: [0, 1], c2: [2, 3], d1: [0, 2], d2: [1, 3] };
const COLOURS = { c1: "#dc1414", c2: "#dc1414", d1: "#009600", d2: "#009600" };

const literal = (pts) => `[${pts.map((p) => p.map(num).join(" ")).join("; ")}]'`;

export default class CoonsView {
  constructor(app) {
    this.app = app;
    this.reset(PRIMER);
    this.selected = "P4";
    this.frameTimes = [];
    this.view = new View3D($("coons-canvas"), {
      onDrag: (id, p) => this.drag(id, p),
      onSelect: (id) => this.select(id),
      onDragEnd: () => this.numbers(true),
    });
    for (const id of ["coons-x", "coons-rc", "coons-rd", "coons-rcd", "coons-n"]) $(id).addEventListener("input", () => this.update(true));
    for (const id of ["coons-u", "coons-v"]) $(id).addEventListener("input", () => this.update(true));
    $("coons-point").addEventListener("change", () => this.select($("coons-point").value));
    ["x", "y", "z"].forEach((axis, k) =>
      $(`coons-p${axis}`).addEventListener("change", () => {
        const p = [...this.point(this.selected)];
        const value = Number($(`coons-p${axis}`).value);
        if (!Number.isFinite(value)) return;
        p[k] = value;
        this.setPoint(this.selected, p);
        this.update(true);
      }),
    );
    this.options();
    this.relabel();
    this.update(true, true);
  }

  relabel() {
    explainInto(document.getElementById("coons-explain"), "coons");
  }

  reset(data) {
    this.corners = data.corners.map((p) => [...p]);
    this.inner = Object.fromEntries(Object.entries(data.inner).map(([k, v]) => [k, v.map((p) => [...p])]));
  }

  /** Control points of boundary `name`, corners included. */
  curve(name) {
    const [a, b] = ENDS[name];
    return [this.corners[a], ...this.inner[name], this.corners[b]];
  }

  ids() {
    const ids = ["P1", "P2", "P3", "P4"];
    for (const name of Object.keys(ENDS)) this.inner[name].forEach((_, k) => ids.push(`${name}:${k + 1}`));
    return ids;
  }

  point(id) {
    if (id.startsWith("P")) return this.corners[Number(id.slice(1)) - 1];
    const [name, k] = id.split(":");
    return this.inner[name][Number(k) - 1];
  }

  setPoint(id, p) {
    if (id.startsWith("P")) this.corners[Number(id.slice(1)) - 1] = p;
    else {
      const [name, k] = id.split(":");
      this.inner[name][Number(k) - 1] = p;
    }
  }

  label(id) {
    if (id.startsWith("P")) return `corner ${id}`;
    const [name, k] = id.split(":");
    return `${name}, control point ${k}`;
  }

  options() {
    const sel = $("coons-point");
    sel.replaceChildren(...this.ids().map((id) => new Option(this.label(id), id, false, id === this.selected)));
    this.fields();
  }

  fields() {
    const p = this.point(this.selected);
    ["x", "y", "z"].forEach((axis, k) => ($(`coons-p${axis}`).value = num(p[k])));
  }

  select(id) {
    this.selected = id;
    $("coons-point").value = id;
    this.fields();
    this.draw();
  }

  drag(id, p) {
    const t0 = performance.now();
    this.setPoint(
      id,
      p.map((c) => Math.round(c * 100) / 100),
    );
    this.fields();
    this.update(false);
    this.frameTimes.push(performance.now() - t0);
  }

  get n() {
    return Number($("coons-n").value);
  }

  update(full, fit = false) {
    $("coons-n-value").textContent = String(this.n);
    $("coons-u-value").textContent = $("coons-u").value;
    $("coons-v-value").textContent = $("coons-v").value;
    const parts = ["coons-rc", "coons-rd", "coons-rcd"].some((id) => $(id).checked);
    const flat = (name) => Float64Array.from(this.curve(name).flat());
    const err = $("coons-error");
    try {
      this.grids = this.app.wasm.coons_view(flat("c1"), flat("c2"), flat("d1"), flat("d2"), this.n, parts);
      err.hidden = true;
    } catch (e) {
      err.hidden = false;
      err.textContent = String(e);
      return;
    }
    this.draw(fit);
    if (full) this.numbers(true);
  }

  draw(fit = false) {
    if (!this.grids) return;
    const n = this.n;
    const len = n * n * 3;
    const surfaces = [];
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
    const curves = [
      { points: edge((k) => at(k, 0)), colour: COLOURS.c1, width: 3 },
      { points: edge((k) => at(k, n - 1)), colour: COLOURS.c2, width: 3 },
      { points: edge((k) => at(0, k)), colour: COLOURS.d1, width: 3 },
      { points: edge((k) => at(n - 1, k)), colour: COLOURS.d2, width: 3 },
    ];
    for (const name of Object.keys(ENDS)) curves.push({ points: this.curve(name), colour: COLOURS[name], width: 1, dash: [4, 3] });
    const points = this.ids().map((id) => ({ id, p: this.point(id), selected: id === this.selected, colour: id.startsWith("P") ? "#000" : COLOURS[id.split(":")[0]] }));
    if (this.marker) points.push({ p: this.marker, fill: "#000", colour: "#fff" });
    this.view.setScene({ surfaces, curves, points }, fit);
  }

  argv(format) {
    const argv = ["cagd", "coons"];
    for (const name of ["c1", "c2", "d1", "d2"]) argv.push(`--${name}`, literal(this.curve(name)));
    argv.push("--u", $("coons-u").value, "--v", $("coons-v").value, "--steps", "--exact");
    if (format) argv.push("--format", format);
    return argv;
  }

  /** The numbers at (u, v), by the command line's own code. */
  numbers(commit) {
    const argv = this.argv();
    const answer = this.app.runHere(this.app.localized(argv));
    $("coons-steps").textContent = answer.ok ? answer.stdout : answer.error;
    $("coons-cmd").textContent = join(this.app.localized(argv));
    // The point x(u, v) as exact fractions (the answer line) and in doubles (the marker).
    const json = this.app.runHere(this.argv("json"));
    const point = json.ok ? JSON.parse(json.stdout).result.map((row) => String(Array.isArray(row) ? row[0] : row)) : null;
    $("coons-answer").textContent = point ? `x(${$("coons-u").value}, ${$("coons-v").value}) = (${point.join(", ")})` : "";
    if (point) {
      this.marker = point.map(toNumber);
      this.draw();
    }
    if (commit) this.app.setHash(this.state());
  }

  state() {
    return { view: "coons", cmd: join(this.argv()) };
  }

  /** Opens the view on a `cagd coons` command line whose boundaries are Bézier points. */
  load(cmd) {
    let args = [];
    try {
      args = split(cmd);
    } catch {
      /* keep the current patch */
    }
    const value = (flag) => args[args.indexOf(flag) + 1];
    const curves = {};
    for (const name of ["c1", "c2", "d1", "d2"]) {
      const text = value(`--${name}`);
      const rows = text === undefined ? null : this.app.matrix(text);
      if (!rows || rows.length !== 3) return this.update(true, true);
      curves[name] = this.app.columns(rows);
    }
    if (curves.c1.length < 2 || curves.c2.length < 2 || curves.d1.length < 2 || curves.d2.length < 2) return this.update(true, true);
    this.reset({
      corners: [curves.c1[0], curves.c1.at(-1), curves.c2[0], curves.c2.at(-1)],
      inner: Object.fromEntries(Object.entries(curves).map(([k, v]) => [k, v.slice(1, -1)])),
    });
    for (const [flag, id] of [
      ["--u", "coons-u"],
      ["--v", "coons-v"],
    ])
      if (Number.isFinite(Number(value(flag)))) $(id).value = value(flag);
    this.selected = "P4";
    this.options();
    this.update(true, true);
  }

  activate() {
    this.update(true);
  }
}
