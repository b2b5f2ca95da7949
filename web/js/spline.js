// The interpolating-spline view: the C² cubic spline through typed or dragged points, with its
// end condition (clamped with typed tangents, natural, closed) and its steps — the tridiagonal
// system of the tangents and its solution — from the command line's own cagd spline --steps.
// The lecture notes' clamped example gives the y-tangents (15, 48, −27, 15)/15.

import { viewMessage } from "./fields.js";
import { t } from "./i18n.js";
import { dragText, num, pointsLiteral, toNumber } from "./numbers.js";
import { Plane } from "./plane.js";
import { PointsTable, typedPoints } from "./points-table.js";
import { join, split } from "./shell.js";
import { check, explainInto, frame, h, labelled, parameter, showError } from "./ui.js";
import { pointsOf, printed } from "./bspline.js";

const NOTES = [
  ["0", "0"],
  ["2", "1"],
  ["4", "4"],
  ["6", "0"],
];

export default class SplineView {
  constructor(app) {
    this.app = app;
    this.points = NOTES.map((p) => [...p]);
    this.parts = frame(document.getElementById("view-spline"), { name: "spline", picture: "svg", label: t("planeHint", { what: t("tab.spline") }) });
    const c = this.parts.controls;
    this.end = h("select", { onchange: () => (this.placeSlider(), this.update(true)) }, ...["clamped", "natural", "closed"].map((e) => new Option(e, e)));
    this.start = h("input", { type: "text", spellcheck: "false", autocomplete: "off", value: "[1;1]", oninput: () => this.update(true) });
    this.finish = h("input", { type: "text", spellcheck: "false", autocomplete: "off", value: "[-1;1]", oninput: () => this.update(true) });
    this.table = new PointsTable(h("div", { class: "table-wrap" }), {
      columns: ["x", "y"],
      name: (i) => `x${i}`,
      onInput: (i, k, text) => {
        this.points[i][k] = text;
        this.rebuild(false);
      },
    });
    const param = parameter("spline-t", t("parameterT"), t("typedT"), "1.5");
    [this.slider, this.typed] = param.querySelectorAll("input");
    this.typed.value = "3/2";
    this.slider.addEventListener("input", () => {
      this.typed.value = num(Number(this.slider.value));
      this.update(true);
    });
    this.typed.addEventListener("input", () => {
      this.placeSlider();
      this.update(true);
    });
    c.append(
      labelled("spline-end", t("endCondition"), this.end),
      param,
      labelled("spline-start", t("startTangent"), this.start),
      labelled("spline-finish", t("endTangent"), this.finish),
      h("p", { class: "checks" }, check("spline-exact", t("exact"), true), check("spline-snap", t("snap"), true)),
      this.table.container,
      h(
        "p",
        { class: "buttons" },
        h("button", { type: "button", id: "spline-add", onclick: () => this.resize(1) }, t("addPoint")),
        h("button", { type: "button", id: "spline-remove", onclick: () => this.resize(-1) }, t("removePoint")),
      ),
    );
    document.getElementById("spline-exact").addEventListener("change", () => this.update(true));
    this.plane = new Plane(this.parts.svg, [-1, 7, -1, 5], { onDragEnd: () => this.commit() });
    this.plane.label = (n, x, y) => t("pointAt", { name: n, coords: `${num(x)}, ${num(y)}` });
    this.relabel();
    this.rebuild(true);
  }

  resize(by) {
    if (by > 0) {
      const last = this.points[this.points.length - 1].map(toNumber);
      this.points.push([num(last[0] + 2), num(last[1] + 1)]);
    } else if (this.points.length > 2) this.points.pop();
    this.rebuild(true);
  }

  doubles() {
    return this.points.map((p) => p.map(toNumber));
  }

  /** The parameter runs over [0, m − 1] (segment k on [k, k + 1]), [0, m] when closed. */
  placeSlider() {
    this.slider.min = "0";
    this.slider.max = String(this.end.value === "closed" ? this.points.length : this.points.length - 1);
    const x = toNumber(this.typed.value);
    if (Number.isFinite(x)) this.slider.value = String(x);
  }

  rebuild(fit) {
    this.table.set(this.points);
    const pts = this.doubles();
    if (fit && pts.flat().every(Number.isFinite)) this.plane.setBox(Plane.fit(pts, 2));
    else this.plane.setBox(this.plane.box);
    this.placeSlider();
    for (const layer of ["curve", "polygon", "tangents", "marker", "handles"]) this.plane.layer(layer);
    this.plane.handles(
      "handles",
      pts,
      this.points.map((_, i) => `x${i}`),
      (i, q) => {
        this.points[i] = q.map((x) => dragText(x, document.getElementById("spline-snap").checked ? 0.1 : 0, 10));
        this.plane.moveHandle("handles", i, this.points[i].map(toNumber), `x${i}`);
        this.table.set(this.points);
        this.update(false);
      },
    );
    this.update(true);
  }

  argv() {
    const end = this.end.value;
    const argv = ["cagd", "spline", pointsLiteral(this.points), "--end", end];
    if (end === "clamped") argv.push("--start-tangent", this.start.value.trim(), "--end-tangent", this.finish.value.trim());
    argv.push("--t", this.typed.value.trim() || "0", "--steps");
    if (document.getElementById("spline-exact").checked) argv.push("--exact");
    return argv;
  }

  update(full) {
    const clamped = this.end.value === "clamped";
    this.start.disabled = !clamped;
    this.finish.disabled = !clamped;
    const argv = this.argv();
    const text = this.app.runHere(this.app.localized(argv));
    this.parts.steps.textContent = text.ok ? text.stdout : "";
    this.parts.cmd.textContent = join(this.app.localized(argv));
    showError(this.parts.error, text.ok ? null : viewMessage("spline", text.error));
    const answer = text.ok ? this.app.data(argv) : null;
    this.data = answer?.ok ? answer.data : null;
    const tangents = this.data?.tangents;
    const at = this.data?.result ? `;  x(${this.typed.value.trim()}) = ${printed(this.data.result)}` : "";
    this.parts.answer.textContent = tangents ? `x′ = ${tangents[0].map((_, j) => printed(tangents, j)).join("  ")}${at}` : "";
    this.draw();
    if (full) this.commit();
  }

  draw() {
    for (const layer of ["curve", "polygon", "tangents", "marker"]) this.plane.clear(layer);
    const pts = this.doubles();
    if (!pts.flat().every(Number.isFinite)) return;
    const m = this.end.value === "closed" ? pts.length : pts.length - 1;
    const argv = this.argv().filter((a) => a !== "--steps" && a !== "--exact");
    argv.splice(argv.indexOf("--t"), 2);
    const sampled = this.app.data([...argv, "--t", `0:${num(m / 160)}:${m}`]);
    this.plane.polyline("polygon", pts.flat(), 2, { class: "polygon", stroke: "#dc1414", "stroke-width": 1, "stroke-dasharray": "4 3" });
    if (sampled.ok) this.plane.polyline("curve", pointsOf(sampled.data.result).flat(), 2, { class: "curve", stroke: "#0072bd", "stroke-width": 3 });
    const tangents = this.data?.tangents ? pointsOf(this.data.tangents) : [];
    tangents.forEach((d, i) => {
      const p = pts[i];
      if (!p) return;
      this.plane.polyline("tangents", [p[0], p[1], p[0] + d[0] / 3, p[1] + d[1] / 3], 2, { stroke: "#2a9d3a", "stroke-width": 2, class: "tangent" });
    });
    if (this.data?.result) {
      const [x, y] = pointsOf(this.data.result)[0];
      this.plane.marker("marker", x, y, `${t("pointOnCurve")}: ${printed(this.data.result)}`);
    }
  }

  commit() {
    this.app.setHash(this.state());
  }

  state() {
    return { view: "spline", cmd: join(this.app.localized(this.argv())) };
  }

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
    if (points) this.points = points;
    if (value("--start-tangent")) this.start.value = value("--start-tangent");
    if (value("--end-tangent")) this.finish.value = value("--end-tangent");
    const end = value("--end") ?? (value("--start-tangent") && value("--end-tangent") ? "clamped" : "natural");
    if (["clamped", "natural", "closed"].includes(end)) this.end.value = end;
    if (value("--t") !== undefined) this.typed.value = value("--t");
    document.getElementById("spline-exact").checked = args.includes("--exact");
    this.rebuild(true);
  }

  activate() {
    this.update(true);
  }

  relabel() {
    explainInto(this.parts.explain, "spline");
    this.parts.stepsTitle.textContent = t("steps");
    this.parts.open.textContent = t("openCommand");
    if (this.data !== undefined) this.update(false);
  }
}
