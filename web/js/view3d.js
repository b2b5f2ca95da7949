// A rotatable 3-D view on a canvas: surfaces (filled like Octave's surf, or as wire nets),
// curves and draggable points, seen orthographically from an azimuth and an elevation (Octave's
// default view, az = −37.5°, el = 30°, to start with). Drag the background (or use the arrow
// keys) to rotate; drag a point to move it parallel to the screen.

const VIRIDIS = [
  [68, 1, 84],
  [59, 82, 139],
  [33, 145, 140],
  [94, 201, 98],
  [253, 231, 37],
];

/** The viridis colour map (Octave's default) at s in [0, 1], as the pictures of the program. */
export function viridis(s) {
  const t = Number.isFinite(s) ? Math.min(1, Math.max(0, s)) : 0.5;
  const x = t * (VIRIDIS.length - 1);
  const k = Math.min(Math.floor(x), VIRIDIS.length - 2);
  const f = x - k;
  const [a, b] = [VIRIDIS[k], VIRIDIS[k + 1]];
  const mix = (i) => Math.round(a[i] + (b[i] - a[i]) * f);
  return `rgb(${mix(0)},${mix(1)},${mix(2)})`;
}

export class View3D {
  /**
   * @param {HTMLCanvasElement} canvas
   * @param {{onDrag?: (id: string, p: number[]) => void, onSelect?: (id: string) => void}} hooks
   */
  constructor(canvas, hooks = {}) {
    this.canvas = canvas;
    this.hooks = hooks;
    this.az = (-37.5 * Math.PI) / 180;
    this.el = (30 * Math.PI) / 180;
    this.scene = { surfaces: [], curves: [], points: [] };
    this.bounds = null;
    this.drag = null;
    canvas.addEventListener("pointerdown", (e) => this.pointerDown(e));
    canvas.addEventListener("pointermove", (e) => this.pointerMove(e));
    canvas.addEventListener("pointerup", (e) => this.pointerUp(e));
    canvas.addEventListener("pointercancel", (e) => this.pointerUp(e));
    canvas.addEventListener("keydown", (e) => this.key(e));
  }

  /** Sets what is drawn; `fit` recomputes the bounds (else they only grow). */
  setScene(scene, fit = false) {
    this.scene = scene;
    const b = this.sceneBounds();
    if (fit || !this.bounds) this.bounds = b;
    else
      for (let k = 0; k < 3; k++) {
        this.bounds[k][0] = Math.min(this.bounds[k][0], b[k][0]);
        this.bounds[k][1] = Math.max(this.bounds[k][1], b[k][1]);
      }
    this.draw();
  }

  sceneBounds() {
    const b = [
      [Infinity, -Infinity],
      [Infinity, -Infinity],
      [Infinity, -Infinity],
    ];
    const add = (x, y, z) => {
      for (const [k, c] of [x, y, z].entries()) {
        if (!Number.isFinite(c)) continue;
        if (c < b[k][0]) b[k][0] = c;
        if (c > b[k][1]) b[k][1] = c;
      }
    };
    for (const s of this.scene.surfaces) for (let i = 0; i < s.grid.length; i += 3) add(s.grid[i], s.grid[i + 1], s.grid[i + 2]);
    for (const c of this.scene.curves) for (const p of c.points) add(p[0], p[1], p[2] ?? 0);
    for (const p of this.scene.points) add(p.p[0], p.p[1], p.p[2]);
    return b.map(([lo, hi]) => {
      if (!(hi >= lo)) return [-1, 1];
      if (hi - lo < 1e-9) return [lo - 0.5, hi + 0.5];
      return [lo, hi];
    });
  }

  basis() {
    const { az, el } = this;
    const r = [Math.cos(az), Math.sin(az), 0];
    const u = [-Math.sin(el) * Math.sin(az), Math.sin(el) * Math.cos(az), Math.cos(el)];
    const v = [Math.cos(el) * Math.sin(az), -Math.cos(el) * Math.cos(az), Math.sin(el)];
    return { r, u, v };
  }

  /** A projector for the current view: world point to [sx, sy, depth]. */
  projector() {
    const { r, u, v } = this.basis();
    const c = this.bounds.map(([lo, hi]) => (lo + hi) / 2);
    const radius = Math.hypot(...this.bounds.map(([lo, hi]) => hi - lo)) / 2 || 1;
    const { width, height } = this.canvas;
    const scale = (0.44 * Math.min(width, height)) / radius;
    const cx = width / 2;
    const cy = height / 2;
    const project = (x, y, z) => {
      const d = [x - c[0], y - c[1], z - c[2]];
      return [
        cx + scale * (d[0] * r[0] + d[1] * r[1] + d[2] * r[2]),
        cy - scale * (d[0] * u[0] + d[1] * u[1] + d[2] * u[2]),
        d[0] * v[0] + d[1] * v[1] + d[2] * v[2],
      ];
    };
    return { project, scale, r, u };
  }

  draw() {
    const ctx = this.canvas.getContext("2d");
    const { width, height } = this.canvas;
    ctx.clearRect(0, 0, width, height);
    ctx.fillStyle = "#fff";
    ctx.fillRect(0, 0, width, height);
    if (!this.bounds) return;
    const { project } = this.projector();
    this.drawAxes(ctx, project);
    const [zlo, zhi] = this.bounds[2];
    for (const s of this.scene.surfaces) {
      const { grid, nu, nv } = s;
      const P = new Float64Array(nu * nv * 3);
      for (let k = 0; k < nu * nv; k++) {
        const q = project(grid[3 * k], grid[3 * k + 1], grid[3 * k + 2]);
        P[3 * k] = q[0];
        P[3 * k + 1] = q[1];
        P[3 * k + 2] = q[2];
      }
      if (s.style === "wire") {
        ctx.strokeStyle = s.colour;
        ctx.lineWidth = 1;
        ctx.beginPath();
        for (let i = 0; i < nu; i++)
          for (let j = 0; j < nv; j++) {
            const k = 3 * (i * nv + j);
            if (j === 0) ctx.moveTo(P[k], P[k + 1]);
            else ctx.lineTo(P[k], P[k + 1]);
          }
        for (let j = 0; j < nv; j++)
          for (let i = 0; i < nu; i++) {
            const k = 3 * (i * nv + j);
            if (i === 0) ctx.moveTo(P[k], P[k + 1]);
            else ctx.lineTo(P[k], P[k + 1]);
          }
        ctx.stroke();
        continue;
      }
      // Filled cells, far ones first (painter's algorithm), coloured by height.
      const cells = [];
      for (let i = 0; i + 1 < nu; i++)
        for (let j = 0; j + 1 < nv; j++) {
          const ks = [i * nv + j, (i + 1) * nv + j, (i + 1) * nv + j + 1, i * nv + j + 1];
          let depth = 0;
          let z = 0;
          for (const k of ks) {
            depth += P[3 * k + 2];
            z += grid[3 * k + 2];
          }
          cells.push([depth, z / 4, ks]);
        }
      cells.sort((a, b) => a[0] - b[0]);
      ctx.lineWidth = 0.6;
      ctx.strokeStyle = "rgba(0,0,0,0.45)";
      for (const [, z, ks] of cells) {
        ctx.beginPath();
        ctx.moveTo(P[3 * ks[0]], P[3 * ks[0] + 1]);
        for (let m = 1; m < 4; m++) ctx.lineTo(P[3 * ks[m]], P[3 * ks[m] + 1]);
        ctx.closePath();
        ctx.fillStyle = viridis((z - zlo) / (zhi - zlo || 1));
        ctx.fill();
        // Cell edges double the drawing work; fine grids read well without them.
        if (nu * nv <= 900) ctx.stroke();
      }
    }
    for (const c of this.scene.curves) {
      ctx.strokeStyle = c.colour;
      ctx.lineWidth = c.width ?? 2;
      ctx.setLineDash(c.dash ?? []);
      ctx.beginPath();
      c.points.forEach((p, k) => {
        const q = project(p[0], p[1], p[2] ?? 0);
        if (k === 0) ctx.moveTo(q[0], q[1]);
        else ctx.lineTo(q[0], q[1]);
      });
      ctx.stroke();
      ctx.setLineDash([]);
    }
    for (const p of this.scene.points) {
      const q = project(...p.p);
      ctx.beginPath();
      ctx.arc(q[0], q[1], p.selected ? 7 : 5, 0, 2 * Math.PI);
      ctx.fillStyle = p.fill ?? "#fff";
      ctx.fill();
      ctx.lineWidth = p.selected ? 3 : 2;
      ctx.strokeStyle = p.colour ?? "#dc1414";
      ctx.stroke();
    }
  }

  drawAxes(ctx, project) {
    const [[x0, x1], [y0, y1], [z0, z1]] = this.bounds;
    const o = project(x0, y0, z0);
    ctx.lineWidth = 1;
    ctx.font = "14px sans-serif";
    for (const [name, end] of [
      ["x", [x1, y0, z0]],
      ["y", [x0, y1, z0]],
      ["z", [x0, y0, z1]],
    ]) {
      const e = project(...end);
      ctx.strokeStyle = "rgba(0,0,0,0.35)";
      ctx.beginPath();
      ctx.moveTo(o[0], o[1]);
      ctx.lineTo(e[0], e[1]);
      ctx.stroke();
      ctx.fillStyle = "#333";
      ctx.fillText(name, e[0] + 4, e[1] - 4);
    }
  }

  pick(e) {
    const rect = this.canvas.getBoundingClientRect();
    const sx = ((e.clientX - rect.left) * this.canvas.width) / rect.width;
    const sy = ((e.clientY - rect.top) * this.canvas.height) / rect.height;
    if (!this.bounds) return { sx, sy, hit: null };
    const { project } = this.projector();
    let best = null;
    let bestDist = 12;
    for (const p of this.scene.points) {
      if (!p.id) continue;
      const q = project(...p.p);
      const d = Math.hypot(q[0] - sx, q[1] - sy);
      if (d < bestDist) {
        best = p;
        bestDist = d;
      }
    }
    return { sx, sy, hit: best };
  }

  pointerDown(e) {
    const { sx, sy, hit } = this.pick(e);
    this.canvas.setPointerCapture(e.pointerId);
    this.drag = { sx, sy, id: hit?.id ?? null, p: hit ? [...hit.p] : null };
    if (hit && this.hooks.onSelect) this.hooks.onSelect(hit.id);
  }

  pointerMove(e) {
    if (!this.drag) return;
    const { sx, sy } = this.pick(e);
    const dx = sx - this.drag.sx;
    const dy = sy - this.drag.sy;
    if (this.drag.id && this.hooks.onDrag) {
      const { scale, r, u } = this.projector();
      const p = this.drag.p.map((c, k) => c + (dx * r[k] - dy * u[k]) / scale);
      this.hooks.onDrag(this.drag.id, p);
    } else if (!this.drag.id) {
      this.az -= dx * 0.01;
      this.el = Math.max(-Math.PI / 2, Math.min(Math.PI / 2, this.el + dy * 0.01));
      this.drag.sx = sx;
      this.drag.sy = sy;
      this.draw();
    }
  }

  pointerUp(e) {
    if (this.drag && this.canvas.hasPointerCapture(e.pointerId)) this.canvas.releasePointerCapture(e.pointerId);
    const id = this.drag?.id;
    this.drag = null;
    if (id && this.hooks.onDragEnd) this.hooks.onDragEnd(id);
  }

  key(e) {
    const step = (5 * Math.PI) / 180;
    const moves = {
      ArrowLeft: () => (this.az += step),
      ArrowRight: () => (this.az -= step),
      ArrowUp: () => (this.el = Math.min(Math.PI / 2, this.el + step)),
      ArrowDown: () => (this.el = Math.max(-Math.PI / 2, this.el - step)),
    };
    if (moves[e.key]) {
      moves[e.key]();
      e.preventDefault();
      this.draw();
    }
  }
}
