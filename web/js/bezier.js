// The Bézier view: drag the control points and watch de Casteljau's construction at t, the
// subdivision at t and the degree elevation, drawn from the library's own scheme
// (bezier_view) and printed by the command line's own code (cagd decasteljau --steps).

import { num, Plane } from "./plane.js";
import { join, split } from "./shell.js";

const $ = (id) => document.getElementById(id);

const PRIMER = [
  [0, 0],
  [0, 2],
  [8, 2],
  [4, 0],
];

const LEVEL_COLOURS = ["#dc1414", "#e08a00", "#2a9d3a", "#1f6fd1", "#7b3fa0", "#c2185b", "#00838f", "#6d4c41"];

/** A matrix literal with one point per row, transposed: points as columns. */
export function literal(points) {
  return `[${points.map((p) => p.map(num).join(" ")).join("; ")}]'`;
}

/** Points from flat coordinates (`dim` numbers per point). */
export function pointsOf(flat, dim) {
  const out = [];
  for (let i = 0; i + dim <= flat.length; i += dim) out.push(Array.from(flat.slice(i, i + dim)));
  return out;
}

export default class BezierView {
  constructor(app) {
    this.app = app;
    this.points = PRIMER.map((p) => [...p]);
    this.plane = new Plane($("bezier-plane"), [-1, 9, -1.5, 4.5], { onDragEnd: () => this.commit() });
    this.frameTimes = [];
    for (const id of ["bezier-t", "bezier-construction", "bezier-subdivide", "bezier-elevate", "bezier-exact"])
      $(id).addEventListener("input", () => this.update(true));
    $("bezier-snap").addEventListener("change", () => (this.plane.snap = $("bezier-snap").checked ? 0.1 : 0));
    $("bezier-add").addEventListener("click", () => {
      const last = this.points[this.points.length - 1];
      this.points.push([Math.min(last[0] + 1, 8.5), last[1] + (this.points.length % 2 ? 1 : -1)]);
      this.rebuild();
    });
    $("bezier-remove").addEventListener("click", () => {
      if (this.points.length > 2) this.points.pop();
      this.rebuild();
    });
    $("bezier-primer").addEventListener("click", () => {
      this.points = PRIMER.map((p) => [...p]);
      $("bezier-t").value = "0.5";
      this.rebuild();
    });
    $("bezier-degree10").addEventListener("click", () => {
      this.points = Array.from({ length: 11 }, (_, i) => [0.8 * i, i % 2 ? 3.5 : 0.5 + (i % 4) / 2]);
      this.rebuild();
    });
    this.rebuild();
  }

  get t() {
    return Number($("bezier-t").value);
  }

  names() {
    return this.points.map((_, i) => `b${i}`);
  }

  rebuild() {
    this.plane.setBox(this.plane.box);
    this.layers();
    this.plane.handles("handles", this.points, this.names(), (i, p) => this.move(i, p));
    this.update(true);
  }

  layers() {
    for (const name of ["curve", "polygon", "construction", "halves", "elevated", "handles"]) this.plane.layer(name);
  }

  move(i, p) {
    const t0 = performance.now();
    this.points[i] = p;
    this.plane.moveHandle("handles", i, p, this.names()[i]);
    this.update(false);
    this.frameTimes.push(performance.now() - t0);
  }

  /** Redraws from the library; `full` also refreshes the link (not on every drag frame). */
  update(full) {
    const t = this.t;
    $("bezier-t-value").textContent = num(t);
    const flat = this.points.flat();
    const v = JSON.parse(this.app.wasm.bezier_view(Float64Array.from(flat), 2, t, 101));
    const err = $("bezier-error");
    err.hidden = !v.error;
    err.textContent = v.error ?? "";
    if (v.error) return;
    const plane = this.plane;
    plane.clear("curve");
    plane.clear("polygon");
    plane.clear("construction");
    plane.clear("halves");
    plane.clear("elevated");
    plane.polyline("curve", v.curve, 2, { class: "curve", stroke: "#0072bd", "stroke-width": 3 });
    plane.polyline("polygon", flat, 2, { class: "polygon", stroke: "#dc1414", "stroke-width": 1.5 });
    if ($("bezier-construction").checked) {
      v.levels.slice(1).forEach((level, r) => {
        const colour = LEVEL_COLOURS[(r + 1) % LEVEL_COLOURS.length];
        if (level.length > 2) plane.polyline("construction", level, 2, { stroke: colour, "stroke-width": 1.5, "stroke-dasharray": "4 3" });
        for (let i = 0; i < level.length; i += 2) plane.dot("construction", level[i], level[i + 1], 0.55, { fill: colour });
      });
      plane.dot("construction", v.point[0], v.point[1], 0.9, { class: "point-at-t", fill: "#000" });
    }
    if ($("bezier-subdivide").checked && v.left) {
      plane.polyline("halves", v.left, 2, { stroke: "#2a9d3a", "stroke-width": 3, opacity: 0.7 });
      plane.polyline("halves", v.right, 2, { stroke: "#7b3fa0", "stroke-width": 3, opacity: 0.7 });
    }
    if ($("bezier-elevate").checked) {
      plane.polyline("elevated", v.elevated, 2, { stroke: "#e08a00", "stroke-width": 1.5, "stroke-dasharray": "6 3" });
      for (let i = 0; i < v.elevated.length; i += 2) plane.dot("elevated", v.elevated[i], v.elevated[i + 1], 0.6, { fill: "#e08a00" });
    }
    // The numbers: the command line's own scheme.
    const argv = this.argv();
    const answer = this.app.runHere(argv);
    $("bezier-scheme").textContent = answer.ok ? answer.stdout : answer.error;
    const pts = (flatPts) => pointsOf(flatPts, 2).map((p) => `(${p.map(num).join(", ")})`).join("  ");
    // At the ends of [0, 1] one half would be empty: the subdivision says so instead.
    const halves = v.left
      ? [`left half [0, t]:  ${pts(v.left)}`, `right half [t, 1]: ${pts(v.right)}`]
      : [`no halves: ${v.halves_error}`];
    $("bezier-parts").textContent = [
      ...halves,
      `elevated to degree ${this.points.length}: ${pts(v.elevated)}`,
    ].join("\n");
    $("bezier-cmd").textContent = join(argv);
    if (full) this.commit();
  }

  argv() {
    const argv = ["cagd", "decasteljau", literal(this.points), "--t", num(this.t), "--steps"];
    if ($("bezier-exact").checked) argv.push("--exact");
    return argv;
  }

  commit() {
    this.app.setHash(this.state());
  }

  state() {
    return { view: "bezier", cmd: join(this.argv()) };
  }

  /** Opens the view on a `cagd decasteljau` command line (2-D points). */
  load(cmd) {
    let args;
    try {
      args = split(cmd);
    } catch {
      return this.rebuild();
    }
    if (args[0] === "cagd") args.shift();
    const tAt = args.indexOf("--t");
    if (tAt > 0 && Number.isFinite(Number(args[tAt + 1]))) $("bezier-t").value = args[tAt + 1];
    $("bezier-exact").checked = args.includes("--exact");
    const rows = args[1] === undefined ? null : this.app.matrix(args[1]);
    if (rows && rows.length >= 2 && rows[0].length >= 2) {
      const pts = args.includes("--rows") ? rows : this.app.columns(rows);
      if (pts[0].length === 2) this.points = pts;
    }
    this.rebuild();
  }

  activate() {
    this.update(true);
  }
}
