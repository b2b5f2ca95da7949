// The Gordon view: a curve network (expressions, as the command line takes them), the surface
// g = g1 + g2 − g12 and its parts on a grid, and the network curves, rotatable in 3-D. All the
// numbers come from `cagd gordon --steps --format json` and `cagd curve --format json`, run in
// the worker (a network may be large).

import { explainInto } from "./explain.js";
import { viewMessage } from "./fields.js";
import { t } from "./i18n.js";
import { join, split } from "./shell.js";
import { View3D } from "./view3d.js";

const $ = (id) => document.getElementById(id);

const EXAMPLE = {
  u: ["[0;v;v]", "[0.5;v;0.25+v]", "[1;v;v]"],
  v: ["[u;0;u-u^2]", "[u;0.5;0.5+u-u^2]", "[u;1;1+u-u^2]"],
};

const lines = (id) =>
  $(id)
    .value.split("\n")
    .map((s) => s.trim())
    .filter(Boolean);

export default class GordonView {
  constructor(app) {
    this.app = app;
    this.view = new View3D($("gordon-canvas"));
    $("gordon-ucurves").value = EXAMPLE.u.join("\n");
    $("gordon-vcurves").value = EXAMPLE.v.join("\n");
    $("gordon-form").addEventListener("submit", (e) => {
      e.preventDefault();
      this.update(true);
    });
    $("gordon-n").addEventListener("change", () => this.update(false));
    $("gordon-n").addEventListener("input", () => ($("gordon-n-value").textContent = $("gordon-n").value));
    for (const id of ["gordon-g", "gordon-g1", "gordon-g2", "gordon-g12"]) $(id).addEventListener("input", () => this.draw());
    this.relabel();
    this.update(true);
  }

  relabel() {
    explainInto(document.getElementById("gordon-explain"), "gordon");
  }

  /** Runs a command in this view's own worker lane (never the command view's). */
  run(argv) {
    return this.app.cli.run(this.app.localized(argv), [], "gordon");
  }

  /** An error or a failed run: no stale numbers or picture stay beside the message. */
  fail(answer) {
    const err = $("gordon-error");
    err.hidden = false;
    err.textContent = viewMessage("gordon", answer.error);
    this.grids = null;
    this.network = [];
    $("gordon-steps").textContent = "";
    this.view.setScene({ surfaces: [], curves: [], points: [] }, true);
  }

  argv(extra = []) {
    const argv = ["cagd", "gordon"];
    for (const c of lines("gordon-ucurves")) argv.push("--u-curve", c);
    for (const c of lines("gordon-vcurves")) argv.push("--v-curve", c);
    return [...argv, ...extra];
  }

  async update(fit) {
    const n = $("gordon-n").value;
    const err = $("gordon-error");
    const shown = this.argv(["--n", n, "--steps"]);
    $("gordon-cmd").textContent = join(shown);
    this.app.setHash(this.state());
    $("gordon-busy").textContent = t("running");
    const answer = await this.app.cli.run(this.argv(["--n", n, "--steps", "--format", "json"]), [], "gordon");
    if (answer.superseded) return;
    $("gordon-busy").textContent = "";
    if (!answer.ok) return this.fail(answer);
    err.hidden = true;
    const data = JSON.parse(answer.stdout);
    const flat = (g) => Float64Array.from(g.flat(2));
    this.grids = { g: flat(data.result), g1: flat(data.g1), g2: flat(data.g2), g12: flat(data.g12), nu: data.result.length, nv: data.result[0].length };
    // The network curves, sampled by the command line.
    this.network = [];
    for (const c of [...lines("gordon-ucurves"), ...lines("gordon-vcurves")]) {
      const r = await this.app.cli.run(["cagd", "curve", c, "--n", "41", "--format", "json"], [], "gordon");
      if (r.superseded) return;
      if (r.ok) {
        const m = JSON.parse(r.stdout).result;
        this.network.push(m[0].map((_, j) => m.map((row) => row[j])));
      }
    }
    // The readable steps at the network's first interior node, as text.
    const text = await this.run(this.argv(["--u", "0.25", "--v", "0.75", "--steps", "--exact"]));
    if (text.superseded) return;
    if (!text.ok) return this.fail(text);
    $("gordon-steps").textContent = text.stdout;
    this.draw(fit);
  }

  draw(fit = false) {
    if (!this.grids) return;
    const { nu, nv } = this.grids;
    const surfaces = [];
    if ($("gordon-g").checked) surfaces.push({ grid: this.grids.g, nu, nv, style: "filled" });
    for (const [key, colour] of [
      ["g1", "#ed9121"],
      ["g2", "#7e2f8e"],
      ["g12", "#555"],
    ])
      if ($(`gordon-${key}`).checked) surfaces.push({ grid: this.grids[key], nu, nv, style: "wire", colour });
    const curves = this.network.map((points) => ({ points, colour: "#dc1414", width: 3 }));
    this.view.setScene({ surfaces, curves, points: [] }, fit);
  }

  state() {
    return { view: "gordon", cmd: join(this.argv(["--n", $("gordon-n").value, "--steps"])) };
  }

  load(cmd) {
    let args = [];
    try {
      args = split(cmd);
    } catch {
      /* keep the network */
    }
    const all = (flag) => args.flatMap((a, i) => (a === flag && i + 1 < args.length ? [args[i + 1]] : []));
    if (all("--u-curve").length) $("gordon-ucurves").value = all("--u-curve").join("\n");
    if (all("--v-curve").length) $("gordon-vcurves").value = all("--v-curve").join("\n");
    const n = Number(args[args.indexOf("--n") + 1]);
    if (Number.isInteger(n) && n >= 2 && n <= 40) $("gordon-n").value = String(n);
    $("gordon-n-value").textContent = $("gordon-n").value;
    this.update(true);
  }

  activate() {
    this.draw();
  }
}
