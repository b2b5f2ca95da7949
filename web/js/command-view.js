// The command view: every construction of the command line, as a form and as the command line
// itself. Both run the same arguments through cagd_cli::run in the worker.

import { argvOf, byName, constructions, SCRIPT_FILE, valuesOf } from "./constructions.js";
import { join, split } from "./shell.js";

const $ = (id) => document.getElementById(id);

function field(id, labelText, control, hint) {
  const p = document.createElement("p");
  const label = document.createElement("label");
  label.htmlFor = id;
  label.textContent = labelText;
  control.id = id;
  p.append(label, control);
  if (hint) {
    const small = document.createElement("small");
    small.id = `${id}-hint`;
    small.textContent = hint;
    control.setAttribute("aria-describedby", small.id);
    p.append(small);
  }
  return p;
}

function input(value = "") {
  const i = document.createElement("input");
  i.type = "text";
  i.spellcheck = false;
  i.autocomplete = "off";
  i.value = value;
  return i;
}

function checkbox(id, text, checked) {
  const label = document.createElement("label");
  const box = document.createElement("input");
  box.type = "checkbox";
  box.id = id;
  box.checked = !!checked;
  label.append(box, ` ${text}`);
  return label;
}

function select(choices, value) {
  const s = document.createElement("select");
  for (const [v, text] of choices) s.add(new Option(text, v, false, v === value));
  return s;
}

export class CommandView {
  constructor(app) {
    this.app = app;
    this.urls = [];
    this.timer = null;
    this.runs = 0;
    const sel = $("construction");
    for (const c of constructions) sel.add(new Option(`${c.name} — ${c.title}`, c.name));
    sel.addEventListener("change", () => this.choose(sel.value, byName[sel.value].example, true));
    $("example").addEventListener("click", () => this.choose(this.c.name, this.c.example, true));
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
    $("stop").addEventListener("click", () => app.cli.stop());
    this.choose("decasteljau", byName.decasteljau.example, false);
  }

  /** Shows the form of construction `name` filled with `values`; runs it if `run`. */
  choose(name, values, run) {
    this.c = byName[name];
    $("construction").value = name;
    $("construction-about").textContent = this.c.about;
    this.fill({ plot: true, ...values });
    this.formChanged(run ? 0 : null);
  }

  fill(v) {
    const c = this.c;
    const box = $("fields");
    box.replaceChildren();
    for (const f of c.fields) {
      let control;
      if (f.type === "lines") {
        control = document.createElement("textarea");
        control.rows = 3;
        control.spellcheck = false;
        control.value = v[f.key] ?? "";
      } else if (f.type === "select") {
        control = select([["", "(default)"], ...f.choices.map((x) => [x, x])], v[f.key] ?? "");
      } else {
        control = input(v[f.key] ?? "");
        if (f.type === "number") control.inputMode = "numeric";
      }
      control.dataset.key = f.key;
      const flag = f.positional ? "" : ` (${f.flag})`;
      box.append(field(`f-${f.key}`, `${f.label}${flag}`, control, f.hint));
    }
    if (c.options.script || c.options.scriptFile) {
      const area = document.createElement("textarea");
      area.rows = 5;
      area.spellcheck = false;
      area.value = v.script ?? "";
      area.dataset.key = "script";
      const what = c.options.scriptFile ? "The data script" : "Data script run first (--script), optional";
      box.append(field("f-script", `${what} — file ${SCRIPT_FILE}`, area, "assignments and for loops, as in the thesis's appendices"));
    }
    const extra = input(v.extra?.length ? join(v.extra) : "");
    extra.dataset.key = "extra";
    box.append(field("f-extra", "Other arguments", extra, "anything else the command line takes, e.g. --max-work 1000000 or -o result.txt"));

    const sw = $("switches");
    sw.replaceChildren();
    const legend = document.createElement("legend");
    legend.textContent = "Output";
    sw.append(legend);
    if (c.options.exact !== false) sw.append(checkbox("s-exact", "Exact fractions (--exact)", v.exact));
    if (c.options.steps) sw.append(checkbox("s-steps", "Steps (--steps)", v.steps));
    if (c.options.rows) sw.append(checkbox("s-rows", "Points are rows (--rows)", v.rows));
    if (c.options.plot) sw.append(checkbox("s-plot", "Picture (--plot, SVG)", v.plot));
    if (c.options.mesh) {
      const m = select(
        [
          ["", "none"],
          ["stl", "STL"],
          ["obj", "OBJ"],
          ["ply", "PLY"],
        ],
        v.mesh ?? "",
      );
      m.dataset.key = "mesh";
      sw.append(field("s-mesh", "Mesh file (--mesh)", m));
    }
    if (c.options.format !== false) {
      const f = select(
        [
          ["text", "text"],
          ["json", "JSON"],
          ["csv", "CSV"],
          ["octave", "Octave save -text"],
        ],
        v.format ?? "text",
      );
      f.dataset.key = "format";
      sw.append(field("s-format", "Format (--format)", f));
    }
  }

  values() {
    const v = {};
    for (const control of $("fields").querySelectorAll("[data-key]")) v[control.dataset.key] = control.value.trim() === "" ? "" : control.value.replace(/\s+$/, "");
    for (const [id, key] of [
      ["s-exact", "exact"],
      ["s-steps", "steps"],
      ["s-rows", "rows"],
      ["s-plot", "plot"],
    ])
      if ($(id)) v[key] = $(id).checked;
    for (const control of $("switches").querySelectorAll("select[data-key]")) v[control.dataset.key] = control.value;
    try {
      v.extra = v.extra ? split(v.extra) : [];
    } catch {
      v.extra = [];
    }
    return v;
  }

  files(v) {
    return v.script && v.script.trim() ? [{ name: SCRIPT_FILE, text: v.script }] : [];
  }

  /** The form changed: new command line and Octave code; run after `delay` ms (null: not). */
  formChanged(delay = 500) {
    const v = this.values();
    this.args = argvOf(this.c, v);
    this.scriptFiles = this.files(v);
    $("cmdline").value = join(["cagd", ...this.args]);
    this.showOctave(v);
    clearTimeout(this.timer);
    if (delay !== null) this.timer = setTimeout(() => this.execute(), delay);
  }

  showOctave(v) {
    let code;
    try {
      code = this.c.octave(v);
    } catch {
      code = "% No Octave code for these inputs.";
    }
    $("octave").textContent = code;
  }

  runForm() {
    clearTimeout(this.timer);
    this.formChanged(null);
    return this.execute();
  }

  /** Runs a command line typed (or linked) as text; fills the form from it. */
  runTyped(text, files = null) {
    clearTimeout(this.timer);
    let args;
    try {
      args = split(text.trim());
    } catch (e) {
      return this.show({ ok: false, error: `cagd: error: cagd: ${e.message}; expected a command line as a shell reads it` }, text);
    }
    if (args[0] === "cagd") args.shift();
    const c = byName[args[0]];
    if (c) {
      const v = valuesOf(c, args.slice(1));
      if (files?.length) v.script = files[0].text;
      this.c = c;
      $("construction").value = c.name;
      $("construction-about").textContent = c.about;
      this.fill(v);
      this.showOctave(this.values());
    }
    this.args = args;
    this.scriptFiles = files ?? (c ? this.files(this.values()) : []);
    $("cmdline").value = join(["cagd", ...args]);
    return this.execute();
  }

  async execute() {
    const argv = ["cagd", ...this.args];
    const line = join(argv);
    const files = this.scriptFiles ?? [];
    this.app.setHash({ cmd: line, file: files[0]?.text });
    $("permalink").href = this.app.link({ cmd: line, file: files[0]?.text });
    $("busy").textContent = "Running…";
    $("stop").disabled = false;
    const answer = await this.app.cli.run(argv, files);
    if (answer.stopped && this.app.cli.busy) return; // superseded by a newer run
    $("stop").disabled = true;
    this.show(answer, line);
  }

  show(answer, line) {
    for (const url of this.urls) URL.revokeObjectURL(url);
    this.urls = [];
    $("busy").textContent = answer.ok ? "Done." : "";
    const error = $("error");
    error.hidden = answer.ok;
    error.textContent = answer.ok ? "" : answer.error;
    $("stdout").textContent = answer.ok ? answer.stdout : "";
    $("warnings").replaceChildren(
      ...(answer.warnings ?? []).map((w) => {
        const li = document.createElement("li");
        li.textContent = w;
        return li;
      }),
    );
    const pictures = $("pictures");
    const list = $("files");
    pictures.replaceChildren();
    list.replaceChildren();
    for (const f of answer.files ?? []) {
      const svg = f.path.toLowerCase().endsWith(".svg");
      const blob = new Blob([f.bytes], { type: svg ? "image/svg+xml" : "application/octet-stream" });
      const url = URL.createObjectURL(blob);
      this.urls.push(url);
      const name = f.path.split("/").pop();
      if (svg) {
        const fig = document.createElement("figure");
        const img = document.createElement("img");
        img.src = url;
        img.alt = `Picture ${name} drawn by the command (the same plotting code as the cagd program)`;
        const cap = document.createElement("figcaption");
        cap.textContent = name;
        fig.append(img, cap);
        pictures.append(fig);
      }
      const li = document.createElement("li");
      const a = document.createElement("a");
      a.href = url;
      a.download = name;
      a.textContent = `Download ${f.path} (${f.size} bytes)`;
      li.append(a);
      list.append(li);
    }
    const result = $("result");
    result.dataset.run = String(++this.runs);
    result.dataset.ok = String(!!answer.ok);
    result.dataset.line = line;
    this.app.answered();
  }
}
