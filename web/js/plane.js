// A 2-D view in SVG: world coordinates with y up, a light grid, polylines, markers, and control
// points that can be dragged with a pointer or a finger (each with a hit area of at least 44 px)
// or moved with the arrow keys (each point is focusable and labelled for screen readers).

import { num } from "./numbers.js";

export { num };

const NS = "http://www.w3.org/2000/svg";
/** The radius of a handle's hit area on the screen, in CSS pixels (a 46 px target: at least 44 after rounding). */
const HIT_PX = 23;

export function el(name, attrs = {}, parent = null) {
  const e = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (parent) parent.appendChild(e);
  return e;
}

/** The centre attributes of a circle at (x, y); a point not known yet (NaN) is not shown. */
function at(x, y) {
  const known = Number.isFinite(x) && Number.isFinite(y);
  return known ? { cx: x, cy: -y, display: "inline" } : { cx: 0, cy: 0, display: "none" };
}

export class Plane {
  /**
   * @param {SVGSVGElement} svg
   * @param {[number, number, number, number]} box world [xmin, xmax, ymin, ymax]
   */
  constructor(svg, box, hooks = {}) {
    this.svg = svg;
    this.hooks = hooks;
    this.box = box;
    this.snap = 0.1;
    this.layers = {};
    this.label = (name, x, y) => `${name} at (${num(x)}, ${num(y)}); arrow keys move it`;
    this.setBox(box);
    if (typeof ResizeObserver === "function") new ResizeObserver(() => this.resizeHits()).observe(svg);
  }

  setBox(box) {
    this.box = box;
    const [x0, x1, y0, y1] = box;
    this.svg.setAttribute("viewBox", `${x0} ${-y1} ${x1 - x0} ${y1 - y0}`);
    this.svg.setAttribute("preserveAspectRatio", "xMidYMid meet");
    this.svg.replaceChildren();
    const grid = el("g", { class: "grid", "aria-hidden": "true" }, this.svg);
    const unit = (x1 - x0) / 900;
    this.unit = unit;
    const step = 10 ** Math.floor(Math.log10(Math.max(x1 - x0, y1 - y0) / 4));
    for (let x = Math.ceil(x0 / step) * step; x <= x1; x += step)
      el("line", { x1: x, x2: x, y1: -y1, y2: -y0, "stroke-width": Math.abs(x) < step / 2 ? 2 * unit : unit }, grid);
    for (let y = Math.ceil(y0 / step) * step; y <= y1; y += step)
      el("line", { x1: x0, x2: x1, y1: -y, y2: -y, "stroke-width": Math.abs(y) < step / 2 ? 2 * unit : unit }, grid);
    this.layers = {};
  }

  /** A box around `points` ([[x, y], …]) with a margin, at least `min` wide and high. */
  static fit(points, min = 1) {
    const xs = points.map((p) => p[0]).filter(Number.isFinite);
    const ys = points.map((p) => p[1]).filter(Number.isFinite);
    if (!xs.length) return [-1, 1, -1, 1];
    let [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
    const w = Math.max(x1 - x0, min);
    const h = Math.max(y1 - y0, min * 0.6);
    const cx = (x0 + x1) / 2;
    const cy = (y0 + y1) / 2;
    [x0, x1, y0, y1] = [cx - 0.6 * w, cx + 0.6 * w, cy - 0.65 * h, cy + 0.65 * h];
    return [x0, x1, y0, y1];
  }

  layer(name) {
    if (!this.layers[name]) this.layers[name] = el("g", { class: name }, this.svg);
    return this.layers[name];
  }

  /** A polyline through flat points (x0, y0, x1, y1, … with `dim` numbers per point). */
  polyline(layerName, flat, dim, attrs = {}) {
    const pts = [];
    // A point not known yet (a coordinate being typed) is left out, not drawn at NaN.
    for (let i = 0; i + dim <= flat.length; i += dim) if (Number.isFinite(flat[i]) && Number.isFinite(flat[i + 1])) pts.push(`${flat[i]},${-flat[i + 1]}`);
    return el("polyline", { points: pts.join(" "), fill: "none", "vector-effect": "non-scaling-stroke", ...attrs }, this.layer(layerName));
  }

  dot(layerName, x, y, r, attrs = {}) {
    return el("circle", { ...at(x, y), r: r * this.unit * 900 * 0.012, "vector-effect": "non-scaling-stroke", ...attrs }, this.layer(layerName));
  }

  /** The point at a parameter: a filled circle with a ring, labelled for screen readers. */
  marker(layerName, x, y, label) {
    const m = this.dot(layerName, x, y, 1.1, { class: "point-at-t", fill: "#000", stroke: "#fff", "stroke-width": 2, role: "img", "aria-label": label });
    const title = el("title", {}, m);
    title.textContent = label;
    return m;
  }

  clear(layerName) {
    this.layer(layerName).replaceChildren();
  }

  /** World coordinates of a pointer event. */
  world(e) {
    const pt = this.svg.createSVGPoint();
    pt.x = e.clientX;
    pt.y = e.clientY;
    const p = pt.matrixTransform(this.svg.getScreenCTM().inverse());
    return [p.x, -p.y];
  }

  snapped(x) {
    return this.snap ? Math.round(x / this.snap) * this.snap : x;
  }

  /** The world radius of a 44 px target at the current size of the picture. */
  hitRadius() {
    const rect = this.svg.getBoundingClientRect();
    const [x0, x1, y0, y1] = this.box;
    const scale = Math.min(rect.width / (x1 - x0), rect.height / (y1 - y0));
    return scale > 0 ? HIT_PX / scale : 4 * this.unit * 900 * 0.012;
  }

  resizeHits() {
    const r = this.hitRadius();
    for (const c of this.svg.querySelectorAll("circle.hit")) c.setAttribute("r", r);
  }

  /**
   * Draws draggable handles for `points` ([[x, y], …]); `onMove(i, [x, y])` is called while a
   * handle is dragged or moved with the keyboard, `onSelect(i)` when one is picked.
   */
  handles(layerName, points, names, onMove, onSelect = () => {}, selected = -1) {
    const g = this.layer(layerName);
    g.replaceChildren();
    const hit = this.hitRadius();
    // The hit areas first, under every visible point: a point stays on top of its neighbours'.
    const areas = points.map(([x, y], i) => el("circle", { class: "hit", ...at(x, y), r: hit, fill: "transparent", "data-index": i, "aria-hidden": "true" }, g));
    points.forEach(([x, y], i) => {
      const area = areas[i];
      const c = this.dot(layerName, x, y, 1, {
        class: i === selected ? "handle selected" : "handle",
        tabindex: "0",
        role: "button",
        "aria-roledescription": "draggable point",
        "aria-label": this.label(names[i], x, y),
        "data-index": i,
      });
      const down = (e) => {
        e.preventDefault();
        c.focus({ preventScroll: true });
        const target = e.currentTarget;
        target.setPointerCapture(e.pointerId);
        onSelect(i);
        const move = (ev) => {
          const [wx, wy] = this.world(ev);
          onMove(i, [this.snapped(wx), this.snapped(wy)]);
        };
        const up = () => {
          target.removeEventListener("pointermove", move);
          target.removeEventListener("pointerup", up);
          target.removeEventListener("pointercancel", up);
          if (this.hooks.onDragEnd) this.hooks.onDragEnd();
        };
        target.addEventListener("pointermove", move);
        target.addEventListener("pointerup", up);
        target.addEventListener("pointercancel", up);
      };
      c.addEventListener("pointerdown", down);
      area.addEventListener("pointerdown", down);
      c.addEventListener("focus", () => onSelect(i));
      c.addEventListener("keydown", (e) => {
        const step = e.shiftKey ? 0.01 : this.snap || 0.1;
        const d = { ArrowLeft: [-step, 0], ArrowRight: [step, 0], ArrowUp: [0, step], ArrowDown: [0, -step] }[e.key];
        if (!d) return;
        e.preventDefault();
        const [px, py] = [Number(c.getAttribute("cx")), -Number(c.getAttribute("cy"))];
        const q = [px + d[0], py + d[1]].map((x) => (e.shiftKey ? x : this.snapped(x)));
        onMove(
          i,
          q.map((x) => Number(x.toFixed(6))),
        );
        if (this.hooks.onDragEnd) this.hooks.onDragEnd();
      });
    });
  }

  /** Moves handle i (and its label) without rebuilding the handles, keeping focus. */
  moveHandle(layerName, i, [x, y], name) {
    for (const c of this.layer(layerName).querySelectorAll(`[data-index="${i}"]`)) {
      for (const [k, v] of Object.entries(at(x, y))) c.setAttribute(k, v);
      if (c.classList.contains("handle")) c.setAttribute("aria-label", this.label(name, x, y));
    }
  }
}
