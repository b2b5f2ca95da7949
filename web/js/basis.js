// The basis-function view: the B-spline basis functions N_i,p of a knot vector (typed, any
// interval; interior knots draggable) and the Cox–de Boor triangle at t, every N_i,j for
// j = 0 … p, exact with "exact fractions" — from the command line's own cagd bspline-basis
// --steps. The cubic basis of [0 0 0 0 1 2 3 3 3 3] at t = 3/2 is 1/32, 15/32, 15/32, 1/32.

import { viewMessage } from "./fields.js";
import { t } from "./i18n.js";
import { dragText, num, rowLiteral, splitRow, toNumber, valueOf } from "./numbers.js";
import { Plane } from "./plane.js";
import { join, split } from "./shell.js";
import { check, explainInto, frame, h, labelled, parameter, showError } from "./ui.js";

const COLOURS = ["#0072bd", "#d95319", "#2a9d3a", "#7e2f8e", "#e08a00", "#00838f", "#c2185b", "#6d4c41", "#1f6fd1", "#9e9d24"];

export default class BasisView {
  constructor(app) {
    this.app = app;
    this.p = 3;
    this.knots = ["0", "0", "0", "0", "1", "2", "3", "3", "3", "3"];
    this.parts = frame(document.getElementById("view-basis"), { name: "basis", picture: "svg", label: t("basisPlot") });
    const c = this.parts.controls;
    const degree = h("select", { onchange: () => ((this.p = Number(degree.value)), this.rebuild()) }, ...[0, 1, 2, 3, 4, 5].map((p) => new Option(String(p), String(p))));
    this.degreeSelect = degree;
    const param = parameter("basis-t", t("parameterT"), t("typedT"), "1.5");
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
    this.knotsInput = h("input", { type: "text", class: "wide", spellcheck: "false", autocomplete: "off", "aria-describedby": "basis-knots-hint" });
    this.knotsInput.addEventListener("input", () => {
      this.knots = splitRow(this.knotsInput.value);
      this.rebuild(true);
    });
    c.append(
      labelled("basis-degree", t("degree"), degree),
      param,
      labelled("basis-knots", t("knots"), this.knotsInput, h("small", { id: "basis-knots-hint" }, t("knotsHint"))),
      h("p", { class: "checks" }, check("basis-exact", t("exact"), true), check("basis-snap", t("snap"), true)),
    );
    document.getElementById("basis-exact").addEventListener("change", () => this.update(true));
    this.triangle = h("table", { class: "triangle", id: "basis-triangle" });
    this.parts.extra.append(h("h2", { id: "basis-triangle-title" }, t("triangle")), h("div", { class: "table-wrap" }, this.triangle));
    this.plane = new Plane(this.parts.svg, [-0.2, 3.2, -0.12, 1.1], { onDragEnd: () => this.commit() });
    this.plane.label = (n, x) => t("pointAt", { name: n, coords: num(x) });
    this.plane.snap = 0;
    this.relabel();
    this.rebuild();
  }

  placeSlider() {
    const k = this.knots.map(toNumber);
    if (k.length && k.every(Number.isFinite) && k[k.length - 1] > k[0]) {
      this.slider.min = String(k[0]);
      this.slider.max = String(k[k.length - 1]);
    }
    const x = toNumber(this.typed.value);
    if (Number.isFinite(x)) this.slider.value = String(x);
  }

  rebuild(typing = false) {
    this.degreeSelect.value = String(this.p);
    if (!typing || document.activeElement !== this.knotsInput) this.knotsInput.value = rowLiteral(this.knots);
    this.placeSlider();
    const k = this.knots.map(toNumber);
    if (k.length >= 2 && k.every(Number.isFinite) && k[k.length - 1] > k[0]) {
      const w = k[k.length - 1] - k[0];
      this.plane.setBox([k[0] - 0.06 * w, k[k.length - 1] + 0.06 * w, -0.12, 1.1]);
    } else this.plane.setBox(this.plane.box);
    for (const layer of ["basis", "marker", "knots"]) this.plane.layer(layer);
    const inner = this.knots.map((_, j) => j).filter((j) => j > 0 && j < this.knots.length - 1);
    this.inner = inner;
    this.plane.handles(
      "knots",
      inner.map((j) => [k[j], -0.06]),
      inner.map((j) => `u${j}`),
      (i, [x]) => this.dragKnot(inner[i], x),
    );
    this.update(true);
  }

  dragKnot(j, x) {
    const k = this.knots.map(toNumber);
    const width = k[k.length - 1] - k[0] || 1;
    let text = dragText(x, document.getElementById("basis-snap").checked ? width / 20 : 0, width);
    if (toNumber(text) <= k[j - 1]) text = this.knots[j - 1];
    else if (toNumber(text) >= k[j + 1]) text = this.knots[j + 1];
    this.knots[j] = text;
    this.knotsInput.value = rowLiteral(this.knots);
    this.plane.moveHandle("knots", this.inner.indexOf(j), [toNumber(text), -0.06], `u${j}`);
    this.update(false);
  }

  argv() {
    const argv = ["cagd", "bspline-basis", "--knots", rowLiteral(this.knots), "--degree", String(this.p), "--t", this.typed.value.trim() || "0", "--steps"];
    if (document.getElementById("basis-exact").checked) argv.push("--exact");
    return argv;
  }

  update(full) {
    const argv = this.argv();
    const text = this.app.runHere(this.app.localized(argv));
    this.parts.steps.textContent = text.ok ? text.stdout : "";
    this.parts.cmd.textContent = join(this.app.localized(argv));
    showError(this.parts.error, text.ok ? null : viewMessage("basis", text.error));
    const answer = text.ok ? this.app.data(argv) : null;
    this.data = answer?.ok ? answer.data : null;
    const values = this.data ? [this.data.result].flat(2) : [];
    this.parts.answer.textContent = this.data ? `N_i,${this.p}(${this.typed.value.trim()}) = ${values.join(", ")}` : "";
    this.fillTriangle();
    this.draw();
    if (full) this.commit();
  }

  /** The triangle N_i,j(t): one row per degree j, the command's numbers as printed. */
  fillTriangle() {
    this.triangle.replaceChildren();
    const tri = this.data?.triangle;
    if (!tri) return;
    const levels = Object.keys(tri)
      .filter((k) => /^p\d+$/.test(k))
      .sort((a, b) => Number(a.slice(1)) - Number(b.slice(1)));
    const head = this.triangle.createTHead().insertRow();
    head.append(h("th", { scope: "col" }, "j \\ i"));
    const width = [tri[levels[0]]].flat(2).length;
    for (let i = 0; i < width; i++) head.append(h("th", { scope: "col" }, String(i)));
    const body = this.triangle.createTBody();
    for (const key of levels) {
      const row = body.insertRow();
      row.append(h("th", { scope: "row" }, key.slice(1)));
      for (const x of [tri[key]].flat(2)) row.insertCell().textContent = String(x);
    }
  }

  draw() {
    this.plane.clear("basis");
    this.plane.clear("marker");
    const k = this.knots.map(toNumber);
    if (!k.every(Number.isFinite) || !(k[k.length - 1] > k[0])) return;
    const sampled = this.app.data(["cagd", "bspline-basis", "--knots", rowLiteral(this.knots), "--degree", String(this.p), "--n", "241"]);
    if (!sampled.ok) return;
    const ts = [sampled.data.t].flat(2).map(valueOf);
    const rows = sampled.data.result.map((r) => [r].flat().map(valueOf));
    const count = rows[0]?.length ?? 0;
    for (let i = 0; i < count; i++)
      this.plane.polyline(
        "basis",
        ts.flatMap((x, m) => [x, rows[m][i]]),
        2,
        { stroke: COLOURS[i % COLOURS.length], "stroke-width": 2, "data-basis": i },
      );
    const at = toNumber(this.typed.value);
    if (Number.isFinite(at)) {
      this.plane.polyline("marker", [at, 0, at, 1], 2, { class: "t-line", stroke: "#000", "stroke-dasharray": "3 3", "stroke-width": 1 });
      const values = this.data ? [this.data.result].flat(2).map(valueOf) : [];
      values.forEach((y, i) => {
        if (y > 0) this.plane.marker("marker", at, y, `N_${i},${this.p}(${this.typed.value.trim()}) = ${[this.data.result].flat(2)[i]}`);
      });
    }
    for (const u of k) this.plane.dot("marker", u, -0.06, 0.4, { fill: "#888" });
  }

  commit() {
    this.app.setHash(this.state());
  }

  state() {
    return { view: "basis", cmd: join(this.app.localized(this.argv())) };
  }

  load(cmd) {
    let args = [];
    try {
      args = split(cmd);
    } catch {
      return this.rebuild();
    }
    const value = (flag) => (args.includes(flag) ? args[args.indexOf(flag) + 1] : undefined);
    if (value("--knots")) this.knots = splitRow(value("--knots"));
    const p = Number(value("--degree") ?? (value("--order") ? Number(value("--order")) - 1 : 3));
    if (Number.isInteger(p) && p >= 0 && p <= 5) this.p = p;
    if (value("--t") !== undefined) this.typed.value = value("--t");
    document.getElementById("basis-exact").checked = args.includes("--exact");
    this.rebuild();
  }

  activate() {
    this.update(true);
  }

  relabel() {
    explainInto(this.parts.explain, "bspline-basis");
    this.parts.stepsTitle.textContent = t("steps");
    this.parts.open.textContent = t("openCommand");
    document.getElementById("basis-triangle-title").textContent = t("triangle");
    if (this.data !== undefined) this.update(false);
  }
}
