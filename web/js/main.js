// The page: views in tabs, links that keep the state (#view=…&cmd=<a cagd command line>) with
// history entries (Back works), the page's language, the WebAssembly compiled once and shared
// by the main thread (the interactive views) and the command-line workers, and the service
// worker that keeps everything for offline use.

import init, * as wasm from "../pkg/cagd_web.js";
import { CommandLine } from "./cli.js";
import { CommandView } from "./command-view.js";
import { applyStatic, chooseLang, lang, LANG_NAMES, LANGS, setLang, setMessageTranslator, t } from "./i18n.js";

const $ = (id) => document.getElementById(id);
const started = performance.now();
/**
 * The estimated operations (`--max-work`) a command may take on the main thread before the
 * workers are ready: tens of milliseconds at most (the default limit, 2·10⁹, is seconds), so
 * a page load never freezes noticeably.
 */
const QUICK_WORK = 10_000_000;

const viewModules = {
  bezier: () => import("./bezier.js"),
  subdivide: () => import("./subdivide.js"),
  elevate: () => import("./elevate.js"),
  coons: () => import("./coons.js"),
  gordon: () => import("./gordon.js"),
  bspline: () => import("./bspline.js"),
  insert: () => import("./insert.js"),
  basis: () => import("./basis.js"),
  nurbs: () => import("./nurbs.js"),
  spline: () => import("./spline.js"),
};

/** Reads `#key=value&…` (values URL-encoded; `+` is a plus, not a space). */
function readHash(hash = location.hash) {
  const out = {};
  for (const part of hash.replace(/^#/, "").split("&")) {
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

let routed = null;

const app = {
  wasm,
  cli: null,
  schema: [],
  steps: { labels: {}, phrases: [] },
  views: {},
  current: null,
  firstAnswer: null,
  link,
  t,
  /**
   * Keeps the page's state in its address without a new history entry (drags, edits). Only
   * the view shown writes it: a view built or updated while another is shown leaves it alone.
   */
  setHash(state) {
    if (state.view && state.view !== app.current) return;
    const h = link({ ...state, view: state.view ?? app.current });
    if (h !== location.hash) history.replaceState(null, "", h);
    routed = location.hash;
  },
  /** A new history entry for the state (a view opened, a command run): Back returns. */
  pushHash(state) {
    if (state.view && state.view !== app.current) return;
    const h = link({ ...state, view: state.view ?? app.current });
    if (h !== location.hash) history.pushState(null, "", h);
    routed = location.hash;
  },
  /** `argv` with the page's language for the readable steps (`--lang`), unless English. */
  localized(argv) {
    return lang() === "en" || argv.includes("--lang") ? argv : [...argv, "--lang", lang()];
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
  /**
   * A command line on the main thread under the work limit QUICK_WORK, with the files it
   * writes: its answer, or null when it is above the limit (or sets its own) and belongs in a
   * worker.
   */
  runQuick(argv, files = []) {
    // A limit of its own, or arguments after `--` (where an option reads as a value): the worker.
    if (argv.some((a) => a === "--" || a === "--max-work" || a.startsWith("--max-work="))) return null;
    const answer = app.runHere([...argv, "--max-work", String(QUICK_WORK)], files);
    if (!answer.ok) return answer.limit === "max_work" || answer.code !== 2 ? null : { ...answer, thread: "main" };
    answer.files = answer.files.map((f, i) => ({ ...f, bytes: wasm.file_bytes(i) }));
    answer.thread = "main";
    return answer;
  },
  /** The items of a command's answer as data (`--format json`): {ok, data} or {ok: false, error}. */
  data(argv) {
    const answer = app.runHere([...argv, "--format", "json"]);
    if (!answer.ok) return answer;
    return { ok: true, data: JSON.parse(answer.stdout), warnings: answer.warnings };
  },
  /**
   * Called when a result is shown: the first one gives the page's answer time, counted from
   * the start of the navigation (performance.now()'s origin, the navigation entry's
   * startTime 0), and, for the breakdown, from the start of this module.
   */
  answered() {
    if (app.firstAnswer === null) {
      app.firstAnswer = performance.now();
      document.documentElement.dataset.firstAnswerMs = app.firstAnswer.toFixed(1);
      document.documentElement.dataset.scriptAnswerMs = (app.firstAnswer - started).toFixed(1);
      // The command view's worker, the service worker and the views' modules start once the
      // first answer is on the screen: before, they would compete with it for the processor.
      app.cli.warm();
      registerServiceWorker();
      warmViews();
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
  show: (name, state) => show(name, state),
};
globalThis.cagdApp = app;

/** Views being built: one construction per view, however often it is asked for meanwhile. */
const building = {};

/**
 * The view `name`, built when first asked for: its module is imported (the service worker has
 * it offline) and constructed once. Meanwhile its panel says so; a module that cannot be loaded
 * leaves a message in the panel (asked again the next time the view is opened).
 */
function viewOf(name) {
  if (app.views[name]) return Promise.resolve(app.views[name]);
  if (building[name]) return building[name];
  const panel = $(`view-${name}`);
  // Panels built by their module are empty until then; the Coons and Gordon panels have markup.
  const empty = !panel.querySelector(":scope > :not(.view-message)");
  placeholder(panel, empty ? { role: "status", class: "loading" } : null, t("viewLoading"));
  building[name] = Promise.all([viewModules[name](), app.wasmReady])
    .then(([module]) => {
      placeholder(panel, null);
      app.views[name] = new module.default(app);
      return app.views[name];
    })
    .catch((e) => {
      placeholder(panel, { role: "alert", class: "error view-failed" }, t("viewFailed", { reason: e?.message ?? String(e) }));
      return null;
    })
    .finally(() => delete building[name]);
  return building[name];
}

/** The page's message at the top of a view's panel (`attrs` null: none), replacing the last. */
function placeholder(panel, attrs, text = "") {
  panel.querySelector(":scope > .view-message")?.remove();
  if (!attrs) return;
  const e = document.createElement("p");
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  e.classList.add("view-message");
  e.textContent = text;
  panel.prepend(e);
}

/**
 * Shows view `name` (its tab selected, its panel visible) and answers the view once it is
 * built, or null when the user has moved on meanwhile (a newer show) or the view could not be
 * loaded: a view no longer shown is neither activated nor loaded, and writes no link.
 */
async function show(name, state = {}) {
  if (!(name in viewModules) && name !== "command") name = "command";
  app.current = name;
  for (const tab of document.querySelectorAll('[role="tab"]')) {
    const on = tab.dataset.view === name;
    tab.setAttribute("aria-selected", String(on));
    tab.tabIndex = on ? 0 : -1;
    $(tab.getAttribute("aria-controls")).hidden = !on;
    // In the next frame, when the page is laid out anyway: asked now, the position of the tab
    // would force a layout of the whole page before the view's first answer.
    if (on) requestAnimationFrame(() => tab.scrollIntoView?.({ block: "nearest", inline: "nearest" }));
  }
  const view = name === "command" ? app.views.command : await viewOf(name);
  if (!view || app.current !== name) return null;
  if (state.cmd && view.load) view.load(state.cmd);
  else if (view.activate && !state.routed) view.activate();
  return view;
}

async function route() {
  if (location.hash === routed) return;
  routed = location.hash;
  const h = readHash();
  const name = h.view ?? "command";
  if (name === "command") {
    // The link says what runs here (its command, or the form's example): not the view's own.
    await show("command", { routed: true });
    if (h.cmd) app.views.command.runTyped(h.cmd, h.file ? [{ name: "data.m", text: h.file }] : null, false);
    else app.views.command.runForm(false);
  } else {
    const view = await show(name, { cmd: h.cmd });
    if (view && !h.cmd && view.state) app.setHash(view.state());
  }
}

/** A tab chosen by the user: a new history entry, then the view's own state in it. */
async function openTab(name) {
  if (name !== app.current) {
    history.pushState(null, "", link({ view: name }));
    routed = location.hash;
  }
  const view = await show(name);
  // Another tab chosen meanwhile (fast arrow keys): that one writes the link.
  if (!view) return;
  if (name === "command") app.setHash({ view: "command", ...app.views.command.linkState() });
  else app.setHash(view.state ? view.state() : { view: name });
}

function tabs() {
  const list = [...document.querySelectorAll('[role="tab"]')];
  for (const tab of list) {
    tab.addEventListener("click", () => openTab(tab.dataset.view));
    tab.addEventListener("keydown", (e) => {
      const i = list.indexOf(tab);
      const j = { ArrowRight: i + 1, ArrowLeft: i - 1, Home: 0, End: list.length - 1 }[e.key];
      if (j === undefined) return;
      e.preventDefault();
      const next = list[(j + list.length) % list.length];
      next.focus();
      openTab(next.dataset.view);
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
      const label = b.textContent;
      try {
        await navigator.clipboard.writeText(text);
        b.textContent = t("copied");
      } catch {
        b.textContent = t("selectCopy");
      }
      setTimeout(() => (b.textContent = label), 1500);
    } else if (b.classList.contains("open-command")) {
      app.openCommand($(b.dataset.from).textContent);
    }
  });
}

function languageSwitch() {
  const sel = $("lang");
  sel.replaceChildren(...LANGS.map((l) => new Option(LANG_NAMES[l], l)));
  sel.value = lang();
  sel.addEventListener("change", () => {
    setLang(sel.value, true);
    applyStatic();
    for (const view of Object.values(app.views)) view.relabel?.();
  });
}

/**
 * The forms' schema and the steps' labels ({schema, steps}; pkg/tables.json, read from the
 * WebAssembly by web/build.sh) and the page's WebAssembly module
 * (compiled once for the main thread and the workers): both asked for by index.html's first
 * script as the page began to load, while these modules were still on their way.
 */
const tables = () => window.cagdEarly.tables;
const compile = () => window.cagdEarly.wasm;

/**
 * The views' modules, fetched and evaluated once the first answer is on the screen (when the
 * browser is idle), so that a tab opens at once without slowing the first answer (preloaded
 * with the page, they compete with the page's own modules and the .wasm for the network and
 * the parser). A module that fails here is asked for again when its tab is opened.
 */
function warmViews() {
  const idle = globalThis.requestIdleCallback ?? ((f) => setTimeout(f, 200));
  idle(() => {
    for (const load of Object.values(viewModules)) load().catch(() => {});
  });
}

function registerServiceWorker() {
  if (!("serviceWorker" in navigator) || !/^https?:$/.test(location.protocol)) return;
  navigator.serviceWorker.register("sw.js").catch(() => {
    /* the page works without it, online */
  });
}

async function main() {
  setLang(chooseLang());
  applyStatic();
  languageSwitch();
  tabs();
  copyButtons();
  // The .wasm compiles in the background while the page builds the linked command's form from
  // the tables; a command waits for it (app.wasmReady), a view is built once it is there.
  app.wasmReady = compile().then(async (module) => {
    await init({ module_or_path: module });
    performance.mark("cagd:wasm-ready");
    setMessageTranslator((message, code) => wasm.message_in(message, code));
    return module;
  });
  const failed = (e) => {
    $("loading").textContent = t("wasmFailed", { reason: e?.message ?? e });
  };
  try {
    ({ schema: app.schema, steps: app.steps } = await tables());
  } catch (e) {
    failed(e);
    return;
  }
  app.cli = new CommandLine(app.wasmReady, app.runQuick);
  app.wasmReady.then(() => {
    $("loading").hidden = true;
  }, failed);
  app.views.command = new CommandView(app);
  window.addEventListener("popstate", route);
  window.addEventListener("hashchange", route);
  performance.mark("cagd:form-ready");
  await route();
}

main();
