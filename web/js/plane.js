// A 2-D view in SVG: world coordinates with y up, a light grid, polylines, and control points
// that can be dragged with a pointer or moved with the arrow keys (each point is focusable and
// labelled for screen readers).

const NS = "http://www.w3.org/2000/svg";

export function el(name, attrs = {}, parent = null) {
  const e = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (parent) parent.appendChild(e);
  return e;
}

/** Shortest text of a number, without binary noise such as 0.30000000000000004. */
export function num(x) {
  if (Object.is(x, -0) || Math.abs(x) < 1e-12) return "0";
  const short = Number(x.toPrecision(12));
  return Math.abs(short - x) <= 1e-15 * Math.abs(x) ? String(short) : String(x);
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
    this.setBox(box);
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
    for (let x = Math.ceil(x0); x <= x1; x++)
      el("line", { x1: x, x2: x, y1: -y1, y2: -y0, "stroke-width": x === 0 ? 2 * unit : unit }, grid);
    for (let y = Math.ceil(y0); y <= y1; y++)
      el("line", { x1: x0, x2: x1, y1: -y, y2: -y, "stroke-width": y === 0 ? 2 * unit : unit }, grid);
    this.layers = {};
  }

  layer(name) {
    if (!this.layers[name]) this.layers[name] = el("g", { class: name }, this.svg);
    return this.layers[name];
  }

  /** A polyline through flat points (x0, y0, x1, y1, … with `dim` numbers per point). */
  polyline(layerName, flat, dim, attrs = {}) {
    const pts = [];
    for (let i = 0; i + dim <= flat.length; i += dim) pts.push(`${flat[i]},${-flat[i + 1]}`);
    return el("polyline", { points: pts.join(" "), fill: "none", "vector-effect": "non-scaling-stroke", ...attrs }, this.layer(layerName));
  }

  dot(layerName, x, y, r, attrs = {}) {
    return el("circle", { cx: x, cy: -y, r: r * this.unit * 900 * 0.012, "vector-effect": "non-scaling-stroke", ...attrs }, this.layer(layerName));
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

  /**
   * Draws draggable handles for `points` ([[x, y], …]); `onMove(i, [x, y])` is called while a
   * handle is dragged or moved with the keyboard, `onSelect(i)` when one is picked.
   */
  handles(layerName, points, names, onMove, onSelect = () => {}, selected = -1) {
    const g = this.layer(layerName);
    g.replaceChildren();
    points.forEach(([x, y], i) => {
      const c = this.dot(layerName, x, y, 1, {
        class: i === selected ? "handle selected" : "handle",
        tabindex: "0",
        role: "button",
        "aria-roledescription": "draggable point",
        "aria-label": `${names[i]} at (${num(x)}, ${num(y)}); arrow keys move it`,
        "data-index": i,
      });
      c.addEventListener("pointerdown", (e) => {
        e.preventDefault();
        c.setPointerCapture(e.pointerId);
        onSelect(i);
        const move = (ev) => {
          const [wx, wy] = this.world(ev);
          onMove(i, [this.snapped(wx), this.snapped(wy)]);
        };
        const up = () => {
          c.removeEventListener("pointermove", move);
          c.removeEventListener("pointerup", up);
          c.removeEventListener("pointercancel", up);
          if (this.hooks.onDragEnd) this.hooks.onDragEnd();
        };
        c.addEventListener("pointermove", move);
        c.addEventListener("pointerup", up);
        c.addEventListener("pointercancel", up);
      });
      c.addEventListener("focus", () => onSelect(i));
      c.addEventListener("keydown", (e) => {
        const step = e.shiftKey ? 0.01 : this.snap || 0.1;
        const d = { ArrowLeft: [-step, 0], ArrowRight: [step, 0], ArrowUp: [0, step], ArrowDown: [0, -step] }[e.key];
        if (!d) return;
        e.preventDefault();
        const [px, py] = [Number(c.getAttribute("cx")), -Number(c.getAttribute("cy"))];
        const q = [px + d[0], py + d[1]].map((x) => (e.shiftKey ? x : this.snapped(x)));
        onMove(i, q.map((x) => Number(x.toFixed(6))));
        if (this.hooks.onDragEnd) this.hooks.onDragEnd();
      });
    });
  }

  /** Moves handle i (and its label) without rebuilding the handles, keeping focus. */
  moveHandle(layerName, i, [x, y], name) {
    const c = this.layer(layerName).querySelector(`[data-index="${i}"]`);
    if (!c) return;
    c.setAttribute("cx", x);
    c.setAttribute("cy", -y);
    c.setAttribute("aria-label", `${name} at (${num(x)}, ${num(y)}); arrow keys move it`);
  }
}
