// Random command lines for every construction of the command line, from a seeded generator:
// the same seed gives the same inputs. Numbers are short decimals so that --exact applies.

export function rng(seed) {
  let a = seed >>> 0;
  const next = () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  const int = (lo, hi) => lo + Math.floor(next() * (hi - lo + 1));
  const pick = (xs) => xs[int(0, xs.length - 1)];
  const chance = (p) => next() < p;
  // A short decimal in [lo, hi]: an integer or one or two decimals.
  const dec = (lo = -5, hi = 5) => {
    const places = pick([0, 1, 1, 2]);
    const f = 10 ** places;
    return String(Number((int(Math.ceil(lo * f), Math.floor(hi * f)) / f).toFixed(places)));
  };
  return { next, int, pick, chance, dec };
}

function gen(r) {
  const pointsRows = (d, k, lo = -5, hi = 5) => Array.from({ length: k }, () => Array.from({ length: d }, () => r.dec(lo, hi)));
  // Points as the columns of a literal (transposed rows), or as rows with --rows.
  const pointArg = (rows) => {
    const asRows = r.chance(0.25);
    const text = `[${rows.map((p) => p.join(" ")).join("; ")}]`;
    return asRows ? { arg: text, extra: ["--rows"] } : { arg: `${text}'`, extra: [] };
  };
  const param = () => r.dec(0, 1);
  const params = (flag = "--t") =>
    r.pick([
      () => [flag, param()],
      () => [flag, `[${Array.from({ length: r.int(2, 4) }, param).join(" ")}]`],
      () => [flag, r.pick(["0:0.25:1", "0:0.5:1", "0.1:0.2:0.9"])],
      () => ["--n", String(r.int(2, 7))],
    ])();
  const surfaceParams = () =>
    r.chance(0.5) ? ["--u", param(), "--v", param()] : r.chance(0.5) ? ["--n", String(r.int(2, 5))] : ["--u", `[${param()} ${param()}]`, "--v", "0:0.5:1"];
  const common = (opts = {}) => {
    const out = [];
    if (opts.steps !== false && r.chance(0.5)) out.push("--steps");
    if (r.chance(0.5)) out.push("--exact");
    if (r.chance(0.2)) out.push("--format", r.pick(["json", "csv", "octave"]));
    return out;
  };
  // A network g(u, v) = [u; v; a*u*v + b*u^2 + c*v] and its curves.
  const surfaceCoeffs = () => [r.dec(-2, 2), r.dec(-2, 2), r.dec(-2, 2)];

  return {
    thesis: () => ["thesis"],
    decasteljau: () => {
      const p = pointArg(pointsRows(r.int(2, 3), r.int(2, 6)));
      return ["decasteljau", p.arg, ...p.extra, ...params(), ...common()];
    },
    "bezier-patch": () => {
      const m = r.int(1, 3);
      const n = r.int(1, 3);
      const net = Array.from({ length: m + 1 }, () => Array.from({ length: 3 * (n + 1) }, () => r.dec(-3, 3)));
      return ["bezier-patch", `[${net.map((row) => row.join(" ")).join("; ")}]`, ...surfaceParams(), ...common()];
    },
    coons: () => {
      if (r.chance(0.5)) {
        const [a, b, c] = surfaceCoeffs();
        const e = r.dec(-2, 2);
        const f = r.dec(-2, 2);
        return ["coons", "--c1", `[u;0;${a}*(u-u^2)]`, "--c2", `[u;1;${b}*u+${c}*(u-u^2)]`, "--d1", `[0;v;${e}*(v-v^2)]`, "--d2", `[1;v;${b}*v+${f}*(v-v^2)]`, ...surfaceParams(), ...common()];
      }
      const P = Array.from({ length: 4 }, () => [r.dec(-2, 2), r.dec(-2, 2), r.dec(-2, 2)]);
      const mid = () => [r.dec(-2, 2), r.dec(-2, 2), r.dec(-2, 2)];
      const bez = (a, b) => `[${[a, mid(), b].map((p) => p.join(" ")).join("; ")}]'`;
      return ["coons", "--c1", bez(P[0], P[1]), "--c2", bez(P[2], P[3]), "--d1", bez(P[0], P[2]), "--d2", bez(P[1], P[3]), ...surfaceParams(), ...common()];
    },
    "coons-bicubic": () => {
      const [a, b] = [r.dec(-2, 2), r.dec(-2, 2)];
      const vec = () => `[${r.dec(-1, 1)};${r.dec(-1, 1)};${r.dec(-1, 1)}]`;
      const twist = r.pick([[], ["--twist", "zero"], ["--twist", "given", "--twists", `[${[0, 1, 2].map(() => [0, 1, 2, 3].map(() => r.dec(-1, 1)).join(" ")).join("; ")}]`]]);
      return [
        "coons-bicubic",
        "--c1", `[u;0;${a}*u]`,
        "--c2", `[u;1;${a}*u+${b}]`,
        "--d1", `[0;v;${b}*v]`,
        "--d2", `[1;v;${a}+${b}*v]`,
        "--c1v", vec(), "--c2v", vec(), "--d1u", vec(), "--d2u", vec(),
        ...twist,
        ...surfaceParams(),
        ...common({ steps: false }),
      ];
    },
    "discrete-coons": () => {
      const m = r.int(2, 3);
      const n = r.int(2, 3);
      const net = Array.from({ length: m + 1 }, () => Array.from({ length: 3 * (n + 1) }, () => r.dec(-3, 3)));
      const mask = r.chance(0.3) ? [r.pick(["--mask=-0.25,0.5", "--mask=0,0.25", "--mask=0.05,0.2"])] : [];
      return ["discrete-coons", `[${net.map((row) => row.join(" ")).join("; ")}]`, ...mask, ...common({ steps: false })];
    },
    gordon: () => {
      const [a, b, c] = surfaceCoeffs();
      const k = r.pick([2, 3, 5]);
      const l = r.pick([2, 3, 5]);
      const nodes = (count) => Array.from({ length: count }, (_, i) => String(Number((i / (count - 1)).toFixed(4))));
      const us = nodes(k);
      const vs = nodes(l);
      const args = ["gordon"];
      for (const ui of us) args.push("--u-curve", `[${ui}; v; ${a}*${ui}*v + ${b}*${ui}^2 + ${c}*v]`);
      for (const vj of vs) args.push("--v-curve", `[u; ${vj}; ${a}*u*${vj} + ${b}*u^2 + ${c}*${vj}]`);
      if (r.chance(0.3)) args.push("--u-nodes", `[${us.join(" ")}]`);
      return [...args, ...surfaceParams(), ...common()];
    },
    lagrange: () => {
      const m = r.int(1, 4);
      const step = r.pick([0.25, 0.5, 1]);
      const start = Number(r.dec(-1, 1));
      const uniq = Array.from({ length: m + 1 }, (_, i) => String(Number((start + i * step).toFixed(4))));
      const args = ["lagrange", "--nodes", `[${uniq.join(" ")}]`];
      if (r.chance(0.5)) args.push("--points", `[${uniq.map(() => r.dec(-3, 3)).join(" ")}]`);
      return [...args, ...params(), ...common({ steps: false })];
    },
    bernstein: () => {
      const n = r.int(0, 8);
      const args = ["bernstein", "--degree", String(n)];
      if (r.chance(0.3)) args.push("--i", String(r.int(0, n)));
      return [...args, ...params(), ...common({ steps: false })];
    },
    derivative: () => {
      const k = r.int(2, 6);
      const p = pointArg(pointsRows(r.int(2, 3), k));
      const args = ["derivative", p.arg, ...p.extra, "--order", String(r.int(1, k - 1))];
      if (r.chance(0.6)) args.push("--t", param());
      return [...args, ...common({ steps: false })];
    },
    spline: () => {
      const k = r.int(3, 6);
      const rows = pointsRows(2, k);
      const end = r.pick(["natural", "clamped", "closed"]);
      if (end === "closed") rows.push([...rows[0]]);
      const p = pointArg(rows);
      const args = ["spline", p.arg, ...p.extra, "--end", end];
      if (end === "clamped") args.push("--start-tangent", `[${r.dec(-2, 2)};${r.dec(-2, 2)}]`, "--end-tangent", `[${r.dec(-2, 2)};${r.dec(-2, 2)}]`);
      if (r.chance(0.5)) args.push("--t", `[${Array.from({ length: 3 }, () => r.dec(0, rows.length - 1)).join(" ")}]`);
      return [...args, ...common({ steps: false })];
    },
    hermite: () => {
      const d = r.int(2, 3);
      const vec = () => `[${Array.from({ length: d }, () => r.dec(-3, 3)).join(";")}]`;
      return ["hermite", "--p0", vec(), "--p1", vec(), "--t0", vec(), "--t1", vec(), ...params(), ...common()];
    },
    bspline: () => {
      const k = r.int(3, 6);
      const p = r.int(1, Math.min(3, k - 1));
      const pts = pointArg(pointsRows(2, k));
      const args = ["bspline", pts.arg, ...pts.extra, "--degree", String(p)];
      if (r.chance(0.6)) {
        const inner = Array.from({ length: k - p - 1 }, () => r.dec(0.05, 0.95)).map(Number).sort((x, y) => x - y);
        args.push("--knots", `[${[...Array(p + 1).fill(0), ...inner, ...Array(p + 1).fill(1)].join(" ")}]`);
      }
      return [...args, ...params(), ...common()];
    },
    nurbs: () => {
      const k = r.int(3, 5);
      const p = r.int(1, Math.min(3, k - 1));
      const pts = pointArg(pointsRows(2, k));
      const w = Array.from({ length: k }, () => r.dec(0.5, 2));
      return ["nurbs", pts.arg, ...pts.extra, "--weights", `[${w.join(" ")}]`, "--degree", String(p), ...params(), ...common()];
    },
    curve: () => {
      const [a, b] = [r.dec(-2, 2), r.dec(-2, 2)];
      const expr = r.pick([`[u; ${a}*u^2; ${b}-u]`, `[t; ${a}*t^3 + ${b}*t]`, `[v; v^2; ${a}*v]`, `[cos(${a}*t); sin(${a}*t)]`, `[exp(${a}*u); u]`]);
      return ["curve", expr, ...params(), ...common({ steps: false })];
    },
    surface: () => {
      const [a, b] = [r.dec(-2, 2), r.dec(-2, 2)];
      const expr = r.pick([`[u; v; ${a}*u.*v + ${b}*u.^2]`, `[u; v; ${a}*u-u^2+${b}*v]`, `[u+v; u-v; ${a}]`]);
      return ["surface", expr, ...surfaceParams(), ...common({ steps: false })];
    },
    script: () => {
      const [a, b] = [r.dec(-2, 2), r.dec(-2, 2)];
      return {
        args: ["script", "data.m", "--n", String(r.int(2, 6)), ...common({ steps: false })],
        file: `x = linspace(0,1,N);\ny = ${a}*x.^2 + ${b};\nB = [1 2; 3 4] * ${b};\nfor i = 1:N\n  z(i) = x(i) * ${a};\nend\nc = [u; 0; u-u^2];\n`,
      };
    },
  };
}

/** `count` random inputs for each construction: {name: [{args, file?}]}. */
export function randomInputs(seed, count) {
  const r = rng(seed);
  const g = gen(r);
  const out = {};
  for (const [name, make] of Object.entries(g)) {
    out[name] = Array.from({ length: name === "thesis" ? 1 : count }, () => {
      const x = make();
      return Array.isArray(x) ? { args: x } : x;
    });
  }
  return out;
}
