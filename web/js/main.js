// The page: views in tabs, links that keep the state (#cmd=<a cagd command line>), the
// command-line worker and the WebAssembly on the main thread for the interactive views.

import init, * as wasm from "../pkg/cagd_web.js";
import { CommandLine } from "./cli.js";
import { CommandView } from "./command-view.js";

const $ = (id) => document.getElementById(id);
const started = performance.now();

const viewModules = {
  bezier: () => import("./bezier.js"),
  coons: () => import("./coons.js"),
  gordon: () => import("./gordon.js"),
  bspline: () => import("./bspline.js"),
  nurbs: () => import("./nurbs.js"),
};

/** Reads `#key=value&…` (values URL-encoded; `+` is a plus, not a space). */
function readHash() {
  const out = {};
  for (const part of location.hash.replace(/^#/, "").split("&")) {
    if (!part) continue;
    const eq = part.indexOf("=");
    const key = eq < 0 ? part : part.slice(0, eq);
    try {
      out[key] = eq < 0 ? "" : decodeURIComponent(part.slice(eq + 1));
    } catch {
      out[key] = part.slice(eq + 1);
    }
  }
  return out;
}

function link({ view, cmd, file }) {
  const parts = [];
  if (view && view !== "command") parts.push(`view=${view}`);
  if (cmd) parts.push(`cmd=${encodeURIComponent(cmd)}`);
  if (file) parts.push(`file=${encodeURIComponent(file)}`);
  return `#${parts.join("&")}`;
}

let panicMessage = null;
globalThis.cagdPanic = (message) => {
  panicMessage = message;
};

const app = {
  wasm,
  cli: new CommandLine(),
  views: {},
  current: null,
  firstAnswer: null,
  link,
  /** Keeps the page's state in its address (no new history entry). */
  setHash(state) {
    const view = state.view ?? app.current;
    history.replaceState(null, "", link({ ...state, view }));
  },
  /** A command line on the main thread, for the interactive views' small inputs. */
  runHere(argv, files = []) {
    panicMessage = null;
    try {
      return JSON.parse(
        wasm.run(
          argv,
          files.map((f) => f.name),
          files.map((f) => f.text),
        ),
      );
    } catch (e) {
      return { ok: false, code: 1, error: panicMessage ?? `cagd: internal error: ${e}; this is a bug in cagd` };
    }
  },
  /** Called when a result is shown: the first one gives the page's answer time. */
  answered() {
    if (app.firstAnswer === null) {
      app.firstAnswer = performance.now() - started;
      document.documentElement.dataset.firstAnswerMs = app.firstAnswer.toFixed(1);
    }
  },
  /** The value of an Octave matrix literal, read by the library: rows of numbers, or null. */
  matrix(text) {
    const answer = app.runHere(["cagd", "script", "value.m", "--format", "json"], [{ name: "value.m", text: `M = ${text};` }]);
    if (!answer.ok) return null;
    const m = JSON.parse(answer.stdout).M;
    if (!Array.isArray(m)) return [[m]];
    return m.map((row) => (Array.isArray(row) ? row : [row]));
  },
  /** The columns of a matrix (rows of numbers) as points. */
  columns(rows) {
    return rows[0].map((_, j) => rows.map((r) => r[j]));
  },
  /** Opens the command view with a command line. */
  openCommand(cmd) {
    show("command");
    app.views.command.runTyped(cmd);
  },
};
globalThis.cagdApp = app;

async function viewOf(name) {
  if (!app.views[name]) {
    const module = await viewModules[name]();
    app.views[name] = new module.default(app);
  }
  return app.views[name];
}

async function show(name, state = {}) {
  if (!(name in viewModules) && name !== "command") name = "command";
  app.current = name;
  for (const tab of document.querySelectorAll('[role="tab"]')) {
    const on = tab.dataset.view === name;
    tab.setAttribute("aria-selected", String(on));
    tab.tabIndex = on ? 0 : -1;
    $(tab.getAttribute("aria-controls")).hidden = !on;
  }
  const view = name === "command" ? app.views.command : await viewOf(name);
  if (state.cmd && view.load) view.load(state.cmd);
  else if (view.activate) view.activate();
  if (name !== "command" && view.state) app.setHash(view.state());
  else if (name !== "command") app.setHash({ view: name });
  return view;
}

async function route() {
  const h = readHash();
  const name = h.view ?? "command";
  if (name === "command") {
    await show("command");
    if (h.cmd) app.views.command.runTyped(h.cmd, h.file ? [{ name: "data.m", text: h.file }] : null);
    else app.views.command.runForm();
  } else {
    await show(name, { cmd: h.cmd });
  }
}

function tabs() {
  const list = [...document.querySelectorAll('[role="tab"]')];
  for (const tab of list) {
    tab.addEventListener("click", () => show(tab.dataset.view));
    tab.addEventListener("keydown", (e) => {
      const i = list.indexOf(tab);
      const j = { ArrowRight: i + 1, ArrowLeft: i - 1, Home: 0, End: list.length - 1 }[e.key];
      if (j === undefined) return;
      e.preventDefault();
      const next = list[(j + list.length) % list.length];
      next.focus();
      show(next.dataset.view);
    });
  }
}

function copyButtons() {
  document.addEventListener("click", async (e) => {
    const b = e.target.closest("button");
    if (!b) return;
    if (b.dataset.copy || b.dataset.copyLink) {
      const target = $(b.dataset.copy || b.dataset.copyLink);
      const text = b.dataset.copyLink ? new URL(target.getAttribute("href"), location.href).href : (target.value ?? target.textContent);
      try {
        await navigator.clipboard.writeText(text);
        b.textContent = "Copied";
      } catch {
        b.textContent = "Select and copy";
      }
      setTimeout(() => (b.textContent = b.dataset.copyLink ? "Copy link" : b.dataset.copy === "octave" ? "Copy Octave code" : "Copy"), 1500);
    } else if (b.classList.contains("open-command")) {
      app.openCommand($(b.dataset.from).textContent);
    }
  });
}

async function main() {
  tabs();
  copyButtons();
  try {
    await init();
  } catch (e) {
    $("loading").textContent = `cagd: internal error: the WebAssembly did not load (${e}); serve the page over http (cagd serve) and reload`;
    return;
  }
  $("loading").hidden = true;
  app.views.command = new CommandView(app);
  window.addEventListener("hashchange", route);
  await route();
}

main();
