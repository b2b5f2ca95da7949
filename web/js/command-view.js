// The command view: every subcommand of the command line, as a form generated from the
// program's own argument definitions (forms.js) and as the command line itself. Both run the
// same arguments through cagd_cli::run in the command view's worker. A typed command always
// shows its own form and Octave code; the form's Run runs what the form shows.

import { explainInto } from "./explain.js";
import { argvOf, buildForm, examples, readForm, SCRIPT_FILE, summaryOf, valuesOf } from "./forms.js";
import { localMessage, t } from "./i18n.js";
import { octaveCode } from "./octave.js";
import { join, split } from "./shell.js";

const $ = (id) => document.getElementById(id);

export class CommandView {
  constructor(app) {
    this.app = app;
    this.urls = [];
    this.timer = null;
    this.runs = 0;
    this.byName = Object.fromEntries(app.schema.map((c) => [c.name, c]));
    this.plotFile = null;
    const sel = $("construction");
    for (const c of app.schema) sel.add(new Option(c.name, c.name));
    this.nameConstructions();
    sel.addEventListener("change", () => this.choose(sel.value, this.example(sel.value), true));
    $("example").addEventListener("click", () => this.choose(this.c.name, this.example(this.c.name), true));
    $("command-form").addEventListener("submit", (e) => {
      e.preventDefault();
      this.runForm();
    });
    $("command-form").addEventListener("input", () => this.formChanged());
    $("command-form").addEventListener("change", () => this.formChanged());
    $("cmdline-form").addEventListener("submit", (e) => {
      e.preventDefault();
      this.runTyped($("cmdline").value);
    });
    $("stop").addEventListener("click", () => app.cli.stop("command"));
    this.show({ name: "decasteljau", values: this.example("decasteljau") });
  }

  /** The construction list's entries, `name — summary` in the page's language. */
  nameConstructions() {
    for (const option of $("construction").options) {
      const c = this.byName[option.value];
      const about = c ? summaryOf(c).replace(/\.$/, "") : "";
      option.textContent = about ? `${c.name} — ${about}` : option.value;
    }
  }

  /** The form values of the first example of subcommand `name` (from its help). */
  example(name) {
    const c = this.byName[name];
    const line = examples(c)[0];
    let v = { extra: [] };
    if (line) {
      try {
        v = valuesOf(c, split(line).slice(2));
      } catch {
        /* an example the page cannot read: an empty form */
      }
    }
    if (v.plot === undefined && c.args.some((a) => a.id === "plot")) v.plot = true;
    return v;
  }

  /** Shows the form of subcommand `name` filled with `values` (nothing runs). */
  show({ name, values }) {
    this.c = this.byName[name];
    $("construction").value = name;
    $("construction-about").textContent = summaryOf(this.c);
    explainInto($("command-explain"), name);
    this.plotFile = values.plotFile ?? null;
    buildForm(this.c, values, $("fields"), $("switches"));
  }

  /** Shows subcommand `name`'s form with `values` and runs it if `run`. */
  choose(name, values, run) {
    this.show({ name, values });
    this.formChanged(run ? 0 : null);
  }

  values() {
    const v = readForm($("fields"), $("switches"));
    if (this.plotFile) v.plotFile = this.plotFile;
    return v;
  }

  files(v) {
    return typeof v.script === "string" && v.script.trim() ? [{ name: SCRIPT_FILE, text: v.script }] : [];
  }

  /** The form changed: new command line and Octave code; run after `delay` ms (null: not). */
  formChanged(delay = 500) {
    const v = this.values();
    this.args = argvOf(this.c, v);
    this.scriptFiles = this.files(v);
    $("cmdline").value = join(["cagd", ...this.args]);
    this.showOctave(this.c.name, v);
    clearTimeout(this.timer);
    if (delay !== null) this.timer = setTimeout(() => this.execute(false), delay);
  }

  showOctave(name, v) {
    $("octave").textContent = octaveCode(name, v) ?? t("noOctave", { name });
  }

  runForm(push = true) {
    clearTimeout(this.timer);
    this.formChanged(null);
    return this.execute(push);
  }

  /** Runs a command line typed (or linked) as text; shows its subcommand's form filled from it. */
  runTyped(text, files = null, push = true) {
    clearTimeout(this.timer);
    let args;
    try {
      args = split(text.trim());
    } catch (e) {
      return this.answer({ ok: false, error: `cagd: error: cagd: ${e.message}; expected a command line as a shell reads it` }, text);
    }
    if (args[0] === "cagd") args.shift();
    const c = this.byName[args[0]];
    if (c) {
      const v = valuesOf(c, args.slice(1));
      if (files?.length) v.script = files[0].text;
      this.show({ name: c.name, values: v });
      this.showOctave(c.name, this.values());
    } else {
      // Not a subcommand: no form belongs to it, so none is shown as if it did.
      $("fields").replaceChildren();
      $("switches").hidden = true;
      $("construction").value = "";
      $("construction-about").textContent = "";
      $("command-explain").hidden = true;
      $("octave").textContent = "";
      this.c = null;
    }
    this.args = args;
    this.scriptFiles = files ?? (c ? this.files(this.values()) : []);
    $("cmdline").value = join(["cagd", ...args]);
    return this.execute(push);
  }

  /** Opened from another view before anything ran here: the form's example runs (no blank view). */
  activate() {
    if (this.args === undefined) this.runForm(false);
  }

  /** The state a link keeps. */
  linkState() {
    const line = join(this.app.localized(["cagd", ...(this.args ?? [])]));
    return { cmd: line, file: this.scriptFiles?.[0]?.text };
  }

  async execute(push) {
    // The page's language is part of the command (--lang): a copied line prints the same steps.
    const argv = this.app.localized(["cagd", ...this.args]);
    const line = join(argv);
    $("cmdline").value = line;
    const files = this.scriptFiles ?? [];
    const state = { view: "command", cmd: line, file: files[0]?.text };
    if (this.app.current === "command") {
      if (push) this.app.pushHash(state);
      else this.app.setHash(state);
    }
    $("permalink").href = this.app.link(state);
    // A new command: the old answer goes at once, so nothing stale stays beside "Running…".
    this.clear();
    $("busy").textContent = t("running");
    $("stop").disabled = false;
    const answer = await this.app.cli.run(argv, files, "command");
    if (answer.superseded) return; // a newer command of this view took over
    $("stop").disabled = true;
    this.answer(answer, line);
  }

  clear() {
    this.shown = null;
    for (const url of this.urls) URL.revokeObjectURL(url);
    this.urls = [];
    $("error").hidden = true;
    $("error").textContent = "";
    $("stdout").textContent = "";
    $("warnings").replaceChildren();
    $("pictures").replaceChildren();
    $("files").replaceChildren();
  }

  answer(answer, line) {
    this.clear();
    this.shown = answer;
    $("busy").textContent = answer.ok ? t("done") : "";
    $("error").hidden = answer.ok;
    $("stdout").textContent = answer.ok ? answer.stdout : "";
    this.showMessages();
    for (const f of answer.files ?? []) this.file(f);
    const result = $("result");
    result.dataset.run = String(++this.runs);
    result.dataset.ok = String(!!answer.ok);
    result.dataset.line = line;
    // Where it ran: "main" (a small command before the worker was ready) or "worker".
    result.dataset.thread = answer.thread ?? "worker";
    this.app.answered();
  }

  /** The answer's error and warnings, in the page's language. */
  showMessages() {
    const answer = this.shown ?? {};
    $("error").textContent = answer.ok === false ? localMessage(answer.error) : "";
    $("warnings").replaceChildren(
      ...(answer.warnings ?? []).map((w) => {
        const li = document.createElement("li");
        li.textContent = localMessage(w);
        return li;
      }),
    );
  }

  file(f) {
    const svg = f.path.toLowerCase().endsWith(".svg");
    const blob = new Blob([f.bytes], { type: svg ? "image/svg+xml" : "application/octet-stream" });
    const url = URL.createObjectURL(blob);
    this.urls.push(url);
    const name = f.path.split("/").pop();
    if (svg) {
      const fig = document.createElement("figure");
      const img = document.createElement("img");
      img.src = url;
      img.alt = t("picture", { name });
      const cap = document.createElement("figcaption");
      cap.textContent = name;
      fig.append(img, cap);
      $("pictures").append(fig);
    }
    const li = document.createElement("li");
    const a = document.createElement("a");
    a.href = url;
    a.download = name;
    a.textContent = t("download", { path: f.path, size: f.size });
    li.append(a);
    $("files").append(li);
  }

  relabel() {
    this.nameConstructions();
    this.showMessages();
    if (this.c) {
      $("construction-about").textContent = summaryOf(this.c);
      explainInto($("command-explain"), this.c.name);
      const v = this.values();
      buildForm(this.c, v, $("fields"), $("switches"));
      this.showOctave(this.c.name, v);
    }
  }
}
