// The form of every subcommand, generated from the command line's own definitions
// (cagd_cli::schema: the clap arguments with their help, defaults and choices, read through
// the WebAssembly). No subcommand has page code of its own: a new subcommand gets its form
// from its clap struct. The form's values map to arguments and back (argvOf, valuesOf) the way
// the command line parses them.

import { lang, t } from "./i18n.js";
import { join, split } from "./shell.js";

/** The file name under which a script typed into the page is passed to the command line. */
export const SCRIPT_FILE = "data.m";

/** Arguments the page decides itself (its language switch). */
const PAGE_OWNED = new Set(["lang"]);
/** Arguments shown together under "Output". */
const OUTPUT = ["exact", "steps", "rows", "plot", "mesh", "format", "digits", "output"];
const MESHES = ["stl", "obj", "ply"];

/** The first sentence of a help text (without its final period), and the rest. */
export function sentences(help) {
  const text = (help ?? "").trim();
  // A period ends the sentence when a space (or the end) follows, but not in "e.g." or "i.e.".
  const end = /(?<!\be\.g|\bi\.e)\.(\s|$)/.exec(text);
  if (!end) return [text, ""];
  return [text.slice(0, end.index), text.slice(end.index + 1).trim()];
}

/** How an argument is filled in: "flag", "choice", "lines", "plot", "mesh", "script" or "text". */
export function kindOf(cmd, a) {
  if (a.id === "plot") return "plot";
  if (a.id === "mesh") return "mesh";
  if (a.id === "script" || (cmd.name === "script" && a.positional)) return "script";
  if (!a.takes_value) return "flag";
  if (a.choices?.length) return "choice";
  if (a.repeated) return "lines";
  return "text";
}

/** The arguments of `cmd` the form shows, positional ones first. */
export function formArgs(cmd) {
  const args = cmd.args.filter((a) => !PAGE_OWNED.has(a.id));
  return [...args.filter((a) => a.positional), ...args.filter((a) => !a.positional)];
}

/** The examples of a subcommand, from its help ("Examples:" lines starting with cagd NAME). */
export function examples(cmd) {
  return (cmd.help ?? "")
    .split("\n")
    .map((line) => line.trim())
    .filter((line) => line.startsWith(`cagd ${cmd.name} `) || line === `cagd ${cmd.name}`);
}

const flagOf = (a) => (a.long ? `--${a.long}` : a.short ? `-${a.short}` : a.id);

/**
 * The arguments (after `cagd`) for the form values `v` of `cmd`: positional arguments in
 * order, then the options in the order of their definitions, then "other arguments".
 */
export function argvOf(cmd, v) {
  const args = [cmd.name];
  const opt = (flag, value) => {
    const s = String(value);
    args.push(...(s.startsWith("-") && s !== "-" ? [`${flag}=${s}`] : [flag, s]));
  };
  for (const a of formArgs(cmd)) {
    const kind = kindOf(cmd, a);
    const value = v[a.id];
    if (a.positional) {
      if (kind === "script") args.push(SCRIPT_FILE);
      else if (value !== undefined && value !== "") args.push(String(value));
      else if (a.required) args.push("");
      continue;
    }
    if (kind === "flag") {
      if (value === true) args.push(flagOf(a));
    } else if (kind === "plot") {
      if (value === true) opt(flagOf(a), v.plotFile || `${cmd.name}.svg`);
    } else if (kind === "mesh") {
      if (MESHES.includes(value)) opt(flagOf(a), `${cmd.name}.${value}`);
    } else if (kind === "script") {
      if (typeof value === "string" && value.trim()) opt(flagOf(a), SCRIPT_FILE);
    } else if (kind === "lines") {
      for (const line of String(value ?? "")
        .split("\n")
        .map((s) => s.trim())
        .filter(Boolean))
        opt(flagOf(a), line);
    } else if (value !== undefined && value !== "" && value !== false) {
      opt(flagOf(a), value);
    }
  }
  if (v.extra?.length) args.push(...v.extra);
  return args;
}

/**
 * The form values of `cmd` read back from its arguments (after `cagd NAME`), as the command
 * line would read them; what the form has no field for is kept in `extra`, in order.
 */
export function valuesOf(cmd, args) {
  const v = { extra: [] };
  const fields = formArgs(cmd);
  const positional = fields.filter((a) => a.positional);
  const byFlag = new Map();
  for (const a of cmd.args) {
    if (a.long) byFlag.set(`--${a.long}`, a);
    if (a.short) byFlag.set(`-${a.short}`, a);
  }
  let k = 0;
  for (let i = 0; i < args.length; i++) {
    const token = args[i];
    const eq = token.startsWith("--") ? token.indexOf("=") : -1;
    const flag = eq > 0 ? token.slice(0, eq) : token;
    const inline = eq > 0 ? token.slice(eq + 1) : undefined;
    const a = byFlag.get(flag);
    const take = () => (inline !== undefined ? inline : args[++i]);
    if (a && !PAGE_OWNED.has(a.id)) {
      const kind = kindOf(cmd, a);
      if (kind === "flag") v[a.id] = true;
      else if (kind === "plot") {
        v.plot = true;
        v.plotFile = take();
      } else if (kind === "mesh") {
        const file = take() ?? "";
        const ext = file.split(".").pop();
        if (file === `${cmd.name}.${ext}` && MESHES.includes(ext)) v.mesh = ext;
        else v.extra.push(flag, file);
      } else if (kind === "script") v.scriptName = take();
      else if (kind === "lines") v[a.id] = v[a.id] ? `${v[a.id]}\n${take()}` : take();
      else v[a.id] = take();
    } else if (a) {
      if (a.takes_value) take();
    } else if (token.startsWith("--max-") || token.startsWith("--")) {
      v.extra.push(token);
      if (inline === undefined && token.startsWith("--max-") && i + 1 < args.length) v.extra.push(args[++i]);
    } else if (!token.startsWith("-") || token === "-" || /^-[0-9.]/.test(token)) {
      if (k < positional.length) {
        const p = positional[k++];
        if (kindOf(cmd, p) === "script") v.scriptName = token;
        else v[p.id] = token;
      } else v.extra.push(token);
    } else {
      v.extra.push(token);
    }
  }
  return v;
}

// --- The form's controls ---------------------------------------------------------------

function el(tag, attrs = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, value] of Object.entries(attrs)) {
    if (value === undefined || value === null || value === false) continue;
    if (k === "dataset") Object.assign(e.dataset, value);
    else if (k in e && typeof value !== "string") e[k] = value;
    else e.setAttribute(k, value === true ? "" : value);
  }
  e.append(...children);
  return e;
}

function labelled(id, text, control, hint) {
  control.id = id;
  const p = el("p", {}, el("label", { for: id }, ...[text].flat()), control);
  if (hint) {
    const small = el("small", { id: `${id}-hint` }, hint);
    control.setAttribute("aria-describedby", small.id);
    p.append(small);
  }
  return p;
}

function textInput(value) {
  return el("input", { type: "text", spellcheck: "false", autocomplete: "off", value: value ?? "" });
}

function hintOf(a, rest) {
  const parts = [];
  if (rest && rest.length < 400) parts.push(rest);
  if (a.default !== null && a.default !== undefined && a.default !== "") parts.push(t("defaultIs", { value: a.default }));
  return parts.join(" ");
}

/** The page's own short words for the output options every subcommand shares. */
const SHARED = { exact: "arg.exact", steps: "arg.steps", rows: "arg.rows", format: "arg.format", digits: "arg.digits", output: "arg.output" };

/** A subcommand's summary in the page's language (clap's `about` in English). */
export function summaryOf(cmd) {
  return cmd.i18n?.[lang()] ?? cmd.about ?? "";
}

/**
 * An argument's label and hint in the page's language: the command line's own translation
 * (cagd_cli::lang::forms, handed over by the schema), or in English clap's help, its first
 * sentence (up to a colon) the label and the rest the hint.
 */
export function wordsOf(a) {
  const own = a.i18n?.[lang()];
  const sentence = (s) => s.charAt(0).toUpperCase() + s.slice(1);
  if (own) return SHARED[a.id] ? [t(SHARED[a.id]), `${own.label}. ${sentence(own.hint)}`] : [own.label, own.hint];
  let [first, rest] = sentences(a.help);
  // "Control points b_0..b_n: a matrix literal, …": the name is the label, the form a hint.
  const colon = first.indexOf(": ");
  if (colon > 0 && colon < 60) [first, rest] = [first.slice(0, colon), `${first.slice(colon + 2)}. ${rest}`.trim()];
  if (SHARED[a.id]) [first, rest] = [t(SHARED[a.id]), a.help ?? ""];
  return [first, rest];
}

/** One argument's control (its paragraph), filled from the values `v`. */
function control(cmd, a, v) {
  const kind = kindOf(cmd, a);
  const [first, rest] = wordsOf(a);
  const flag = a.positional ? a.value_name ?? a.id.toUpperCase() : flagOf(a);
  const id = `f-${a.id}`;
  // The option's name is kept whole on one line: "(--interval)", never "(--" and "interval)".
  const name = () => [`${first || a.id} `, el("span", { class: "flag" }, `(${flag})`)];
  if (kind === "flag") {
    const box = el("input", { type: "checkbox", id, checked: v[a.id] === true, dataset: { arg: a.id } });
    return el("p", { class: "switch" }, el("label", {}, box, " ", ...name()));
  }
  if (kind === "plot") {
    const box = el("input", { type: "checkbox", id, checked: v.plot === true, dataset: { arg: "plot" } });
    return el("p", { class: "switch" }, el("label", {}, box, ` ${t("pictureSwitch")} (--plot ${v.plotFile || `${cmd.name}.svg`})`));
  }
  if (kind === "mesh") {
    const s = el("select", { dataset: { arg: "mesh" } }, new Option(t("meshNone"), ""), ...MESHES.map((m) => new Option(`${cmd.name}.${m}`, m)));
    s.value = v.mesh ?? "";
    return labelled(id, name(), s);
  }
  if (kind === "script") {
    const area = el("textarea", { rows: 5, spellcheck: "false", dataset: { arg: "script", of: a.id } });
    area.value = v.script ?? "";
    return labelled(id, t("script"), area, t("scriptHint"));
  }
  if (kind === "choice") {
    const def = a.default ? t("defaultChoice", { value: a.default }) : t("defaultNone");
    const s = el("select", { dataset: { arg: a.id } }, new Option(def, ""), ...a.choices.map((c) => new Option(c, c)));
    s.value = a.choices.includes(v[a.id]) ? v[a.id] : "";
    return labelled(id, name(), s, hintOf({ ...a, default: null }, ""));
  }
  if (kind === "lines") {
    const area = el("textarea", { rows: 3, spellcheck: "false", dataset: { arg: a.id } });
    area.value = v[a.id] ?? "";
    return labelled(id, [...name(), `, ${t("oneLine")}`], area, hintOf(a, rest));
  }
  const input = textInput(v[a.id]);
  input.dataset.arg = a.id;
  if (/^(N|P|K|Q|R)$/.test(a.value_name ?? "")) input.inputMode = "numeric";
  return labelled(id, name(), input, hintOf(a, rest));
}

/**
 * Builds the form of `cmd` into `fields` (its inputs) and `switches` (the output options),
 * filled from `v`.
 */
export function buildForm(cmd, v, fields, switches) {
  fields.replaceChildren();
  const legend = el("legend", {}, t("output"));
  switches.replaceChildren(legend);
  for (const a of formArgs(cmd)) {
    const p = control(cmd, a, v);
    (OUTPUT.includes(a.id) ? switches : fields).append(p);
  }
  const extra = textInput(v.extra?.length ? join(v.extra) : "");
  extra.dataset.arg = "extra";
  fields.append(labelled("f-extra", t("other"), extra, t("otherHint")));
  switches.hidden = switches.children.length <= 1;
}

/** The values of the form built by buildForm. */
export function readForm(fields, switches) {
  const v = {};
  for (const c of [...fields.querySelectorAll("[data-arg]"), ...switches.querySelectorAll("[data-arg]")]) {
    const key = c.dataset.arg;
    if (c.type === "checkbox") v[key] = c.checked;
    else v[key] = c.value.trim() === "" ? "" : c.value.replace(/\s+$/, "");
  }
  try {
    v.extra = v.extra ? split(v.extra) : [];
  } catch {
    v.extra = [];
  }
  return v;
}
