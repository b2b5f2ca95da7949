// Small helpers for the views' markup: elements, labelled controls, and the frame every view
// shares (picture, a one-line answer under it, controls, explanation, steps, command).

import { explainInto } from "./explain.js";
import { t } from "./i18n.js";

const SVG = "http://www.w3.org/2000/svg";

/** An element with attributes (booleans as presence, `dataset`, `on*` listeners). */
export function h(tag, attrs = {}, ...children) {
  const e = tag === "svg" ? document.createElementNS(SVG, "svg") : document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (v === undefined || v === null || v === false) continue;
    if (k === "dataset") Object.assign(e.dataset, v);
    else if (k.startsWith("on") && typeof v === "function") e.addEventListener(k.slice(2), v);
    else if (k === "value" && "value" in e) e.value = v;
    else if (k === "checked") e.checked = !!v;
    else e.setAttribute(k, v === true ? "" : v);
  }
  e.append(...children.filter((c) => c !== null && c !== undefined));
  return e;
}

/** `<p><label for=id>text</label> control</p>`. */
export function labelled(id, text, control, ...after) {
  control.id = id;
  return h("p", {}, h("label", { for: id }, text), " ", control, ...after);
}

/** A checkbox inside its label. */
export function check(id, text, checked = false) {
  return h("label", { class: "check" }, h("input", { type: "checkbox", id, checked }), ` ${text}`);
}

/** A parameter: a slider over [lo, hi] and a text field holding the value as typed. */
export function parameter(prefix, text, typedText, value = "0.5") {
  const slider = h("input", { type: "range", id: `${prefix}`, min: "0", max: "1", step: "any", value });
  const typed = h("input", { type: "text", id: `${prefix}-text`, class: "typed", inputmode: "decimal", spellcheck: "false", autocomplete: "off", value, "aria-label": typedText });
  return h("p", { class: "parameter" }, h("label", { for: prefix }, text), " ", slider, " ", typed);
}

/**
 * The frame of a view inside its section: returns its parts by name. `picture` is "svg",
 * "canvas" or "both" (a plane and a 3-D canvas, one shown at a time).
 */
export function frame(section, { name, picture = "svg", basis = false, label }) {
  const parts = {};
  const pic = h("div", { class: "picture" });
  if (picture === "svg" || picture === "both") {
    parts.svg = h("svg", { id: `${name}-plane`, class: "plane", role: "group", "aria-label": label });
    pic.append(parts.svg);
  }
  if (picture === "canvas" || picture === "both") {
    parts.canvas = h("canvas", { id: `${name}-canvas`, width: "640", height: "520", tabindex: "0", "aria-label": `${label}. ${t("rotateHint")}` });
    if (picture === "both") parts.canvas.hidden = true;
    pic.append(parts.canvas);
  }
  if (basis) {
    parts.basis = h("svg", { id: `${name}-basis`, class: "basis", role: "group", "aria-label": t("basisPlot") });
    pic.append(parts.basis);
  }
  parts.answer = h("p", { id: `${name}-answer`, class: "answer", role: "status", "aria-live": "polite" });
  parts.controls = h("form", { class: "controls", "aria-label": label, onsubmit: (e) => e.preventDefault() });
  parts.error = h("p", { id: `${name}-error`, role: "alert", class: "error", hidden: true });
  parts.explain = h("details", { class: "explain", open: true });
  parts.stepsTitle = h("h2", {}, t("steps"));
  parts.steps = h("pre", { id: `${name}-steps`, tabindex: "0", "aria-label": t("steps") });
  parts.extra = h("div", { class: "extra" });
  parts.cmd = h("code", { id: `${name}-cmd` });
  parts.open = h("button", { type: "button", class: "open-command", dataset: { from: `${name}-cmd` } }, t("openCommand"));
  section.replaceChildren(
    h(
      "div",
      { class: "columns" },
      h("div", { class: "panel" }, pic, parts.answer, parts.error, parts.controls),
      h("div", { class: "panel output" }, parts.explain, parts.extra, parts.stepsTitle, parts.steps, h("p", { class: "cmd" }, parts.cmd, " ", parts.open)),
    ),
  );
  return parts;
}

/** Shows `message` (a one-line error) in `p`, or hides it. */
export function showError(p, message) {
  p.hidden = !message;
  p.textContent = message ?? "";
}

export { explainInto };
