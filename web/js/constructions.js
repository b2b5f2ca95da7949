// Every construction of the cagd command line: its form fields (the same options, spelled as
// the command line spells them), an example, and the Octave code that computes the same
// numbers. The numbers on the page never come from here: the arguments are handed to the
// command line's own code (cagd_cli::run, compiled to WebAssembly).

const curveParams = [
  {
    key: "t",
    flag: "--t",
    label: "Parameters t",
    hint: "a number, a list such as [0 0.25 0.5] or a range such as 0:0.1:1",
  },
  { key: "n", flag: "--n", label: "or N samples, linspace(0,1,N)", type: "number" },
];

const surfaceParams = [
  { key: "u", flag: "--u", label: "Parameters u", hint: "a number, a list or a range" },
  { key: "v", flag: "--v", label: "Parameters v", hint: "a number, a list or a range" },
  { key: "n", flag: "--n", label: "or N samples per direction", type: "number" },
];

const boundary = [
  { key: "c1", flag: "--c1", label: "c1 = x(u,0)", hint: "an expression in u such as [u;0;u-u^2], or Bézier control points (columns)" },
  { key: "c2", flag: "--c2", label: "c2 = x(u,1)", hint: "an expression in u, or Bézier control points" },
  { key: "d1", flag: "--d1", label: "d1 = x(0,v)", hint: "an expression in v, or Bézier control points" },
  { key: "d2", flag: "--d2", label: "d2 = x(1,v)", hint: "an expression in v, or Bézier control points" },
];

const EXACT_NOTE = "% Octave computes in doubles; cagd --exact prints the same numbers as exact fractions.\n";

// Octave helpers written into the generated code when used.
const BERN =
  "bern = @(n, t) arrayfun(@(k) nchoosek(n, k), 0:n) .* t(:).^(0:n) .* (1 - t(:)).^(n - (0:n));  % B_k^n(t), one row per t\n";
const LAGR =
  "lagr = @(x, t) cell2mat(arrayfun(@(i) prod((t(:) - x(setdiff(1:numel(x), i))) ./ (x(i) - x(setdiff(1:numel(x), i))), 2), 1:numel(x), 'UniformOutput', false));  % L_i(t), one row per t\n";

const or = (x, d) => (x === undefined || x === "" ? d : x);
const mat = (text, rows) => (rows ? `(${text})'` : text);
const tOf = (v, d = "linspace(0, 1, 11)") => (v.t ? v.t : v.n ? `linspace(0, 1, ${v.n})` : d);
const uOf = (v, k) => (v[k] ? v[k] : v.n ? `linspace(0, 1, ${v.n})` : "linspace(0, 1, 11)");
const exact = (v) => (v.exact ? EXACT_NOTE : "");

/** Whether `text` is an expression in the parameter `p` (else: control points). */
const usesParam = (text, p) => new RegExp(`(^|[^A-Za-z0-9_])${p}([^A-Za-z0-9_]|$)`).test(text ?? "");

/** An Octave function handle for a curve argument: an expression in `p`, or Bézier points. */
function curveHandle(name, text, p, rows) {
  if (usesParam(text, p)) return `${name} = @(${p}) ${text};\n`;
  return `B_${name} = ${mat(text, rows)};  % Bézier control points\n${name} = @(${p}) B_${name} * bern(columns(B_${name}) - 1, ${p})';\n`;
}

function sampleCurve(expr, p, t) {
  return `f = @(${p}) ${expr};\n${p} = ${t};\nresult = cell2mat(arrayfun(f, ${p}, 'UniformOutput', false))`;
}

export const constructions = [
  {
    name: "thesis",
    title: "The thesis's worked examples",
    about:
      "Primer 2.4 (de Casteljau at t = 1/2), a Bézier patch, Primer 4.3 (r_c, r_d, r_cd exactly), appendix C's Coons patch and appendix D's Gordon surface, with steps and pictures.",
    fields: [],
    options: { format: false, exact: false },
    example: {},
    octave: () =>
      "% The thesis's own Octave code reproduces these examples; the cagd repository keeps it,\n% fixed, in octave_ref/fixed/ and runs it in octave_ref/cases/ (primer_2_4.m,\n% coons_thesis.m, gordon_thesis.m).\naddpath('octave_ref/fixed');\nT = deCasteljau([0 0 8 4; 0 2 2 0; 0 2 0 0], 3);  % T(:,2) is the point at t = 1/2\nT(:, 2)",
  },
  {
    name: "decasteljau",
    title: "Bézier curve by de Casteljau's algorithm",
    about: "Points b(t) of a Bézier curve (thesis algorithm 1); with steps, the whole scheme b_i^r(t).",
    fields: [
      { key: "control", positional: true, label: "Control points b_0..b_n (one per column)", hint: "a matrix literal such as [0 0 0; 0 2 2; 8 2 0; 4 0 0]'" },
      ...curveParams,
    ],
    options: { rows: true, steps: true, script: true, plot: true },
    example: { control: "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'", t: "0.5", steps: true, exact: true },
    octave: (v) =>
      exact(v) +
      `B = ${mat(v.control, v.rows)};  % control points, one per column\nt = ${tOf(v)};\nn = columns(B) - 1;\nresult = zeros(rows(B), numel(t));\nfor k = 1:numel(t)\n  b = B;                                            % b_i^0 = b_i\n  for r = 1:n\n    b = (1 - t(k)) * b(:, 1:end-1) + t(k) * b(:, 2:end);   % b_i^r(t)\n  end\n  result(:, k) = b;\nend\nresult`,
  },
  {
    name: "bezier-patch",
    title: "Bézier patch",
    about: "Points of a tensor-product Bézier patch (thesis algorithms 2–4, ploskevB).",
    fields: [
      { key: "net", positional: true, label: "Control net, packed (m+1)×3(n+1) as ploskevB takes it", hint: "row i = [b_i0 b_i1 … b_in], x y z side by side" },
      ...surfaceParams,
    ],
    options: { steps: true, script: true, plot: true, mesh: true },
    example: { net: "[0 0 0 0 2 1 0 4 0; 2 0 1 2 2 4 2 4 1; 4 0 0 4 2 1 4 4 0]", u: "0.5", v: "0.5", steps: true },
    octave: (v) =>
      exact(v) +
      BERN +
      `B = ${v.net};  % packed net\nu = ${uOf(v, "u")}; v = ${uOf(v, "v")};\nm = rows(B) - 1; n = columns(B) / 3 - 1;\nresult = zeros(numel(u), numel(v), 3);\nfor c = 1:3\n  result(:, :, c) = bern(m, u) * B(:, c:3:end) * bern(n, v)';\nend\nresult`,
  },
  {
    name: "coons",
    title: "Coons patch, bilinearly blended",
    about: "x = r_c + r_d − r_cd from four boundary curves (thesis 4.1, algorithms 5, 6); with steps, r_c, r_d and r_cd.",
    fields: [...boundary, ...surfaceParams],
    options: { rows: true, steps: true, script: true, plot: true, mesh: true },
    example: { c1: "[u;0;u-u^2]", c2: "[u;1;u]", d1: "[0;v^2;v-v^2]", d2: "[1;v;v]", u: "0.2", v: "0.5", steps: true, exact: true },
    octave: (v) =>
      exact(v) +
      BERN +
      curveHandle("c1", v.c1, "u", v.rows) +
      curveHandle("c2", v.c2, "u", v.rows) +
      curveHandle("d1", v.d1, "v", v.rows) +
      curveHandle("d2", v.d2, "v", v.rows) +
      `P1 = c1(0); P2 = c1(1); P3 = c2(0); P4 = c2(1);  % the corners\nu = ${uOf(v, "u")}; v = ${uOf(v, "v")};\nfor i = 1:numel(u)\n  for j = 1:numel(v)\n    rc  = (1 - v(j)) * c1(u(i)) + v(j) * c2(u(i));                       % (4.1)\n    rd  = (1 - u(i)) * d1(v(j)) + u(i) * d2(v(j));                       % (4.2)\n    rcd = (1-u(i))*(1-v(j))*P1 + u(i)*(1-v(j))*P2 + (1-u(i))*v(j)*P3 + u(i)*v(j)*P4;  % (4.3)\n    result(i, j, :) = rc + rd - rcd;\n  end\nend\nresult = squeeze(result)`,
  },
  {
    name: "coons-bicubic",
    title: "Coons patch, bicubically blended",
    about: "A Coons patch that also matches cross-boundary derivatives (thesis 4.3), with a choice of corner twists.",
    fields: [
      ...boundary,
      { key: "c1v", flag: "--c1v", label: "x_v(u,0), across c1", hint: "an expression in u, or Bézier control points" },
      { key: "c2v", flag: "--c2v", label: "x_v(u,1), across c2" },
      { key: "d1u", flag: "--d1u", label: "x_u(0,v), across d1", hint: "an expression in v, or Bézier control points" },
      { key: "d2u", flag: "--d2u", label: "x_u(1,v), across d2" },
      { key: "twist", flag: "--twist", label: "Corner twists x_uv", type: "select", choices: ["zero", "gregory", "given"] },
      { key: "twists", flag: "--twists", label: "Given twists (d×4, at P1..P4)" },
      ...surfaceParams,
    ],
    options: { rows: true, script: true, plot: true, mesh: true },
    example: { c1: "[u;0;0]", c2: "[u;1;0]", d1: "[0;v;0]", d2: "[1;v;0]", c1v: "[0;1;0]", c2v: "[0;1;0]", d1u: "[1;0;0]", d2u: "[1;0;0]", n: "5" },
    octave: (v) => {
      const lines = [exact(v), BERN];
      for (const [k, p] of [["c1", "u"], ["c2", "u"], ["d1", "v"], ["d2", "v"], ["c1v", "u"], ["c2v", "u"], ["d1u", "v"], ["d2u", "v"]]) {
        lines.push(curveHandle(k, or(v[k], "[0;0;0]"), p, v.rows));
      }
      const tw = v.twist === "given" ? `TW = ${or(v.twists, "zeros(3, 4)")};` : "TW = zeros(rows(c1(0)), 4);";
      if (v.twist === "gregory") lines.push("% Gregory's twists vary with (u, v); this code uses zero twists instead.\n");
      lines.push(
        `H = @(t) [(1-t)^2*(1+2*t), t*(1-t)^2, -t^2*(1-t), t^2*(3-2*t)];  % Hermite basis H0..H3\n${tw}  % x_uv at P1..P4\nu = ${uOf(v, "u")}; v = ${uOf(v, "v")};\nfor i = 1:numel(u)\n  for j = 1:numel(v)\n    Hu = H(u(i)); Hv = H(v(j));\n    hc = Hu(1)*d1(v(j)) + Hu(2)*d1u(v(j)) + Hu(3)*d2u(v(j)) + Hu(4)*d2(v(j));\n    hd = Hv(1)*c1(u(i)) + Hv(2)*c1v(u(i)) + Hv(3)*c2v(u(i)) + Hv(4)*c2(u(i));\n    M = {c1(0), c1v(0), c2v(0), c2(0); d1u(0), TW(:,1), TW(:,3), d1u(1); d2u(0), TW(:,2), TW(:,4), d2u(1); c1(1), c1v(1), c2v(1), c2(1)};\n    hcd = 0;\n    for a = 1:4, for b = 1:4, hcd = hcd + Hu(a) * Hv(b) * M{a, b}; end, end\n    result(i, j, :) = hc + hd - hcd;\n  end\nend\nresult = squeeze(result)`,
      );
      return lines.join("");
    },
  },
  {
    name: "discrete-coons",
    title: "Discrete Coons patch",
    about: "The interior control points of a Bézier net from its boundary (or an affine mask).",
    fields: [
      { key: "net", positional: true, label: "Control net, packed (m+1)×3(n+1)", hint: "only the boundary rows and columns are used" },
      { key: "mask", flag: "--mask", label: "Mask α,β (α + β = 1/4; optional)", hint: "e.g. -0.25,0.5" },
    ],
    options: { script: true, plot: true },
    example: { net: "[0 0 0 0 1 0 0 2 0; 1 0 0 0 0 0 1 2 1; 2 0 0 2 1 1 2 2 0]" },
    octave: (v) =>
      exact(v) +
      `B = ${v.net};  % packed net; b(i,j,:) = B(i, 3*j-2:3*j)\nm = rows(B) - 1; n = columns(B) / 3 - 1;\nb = permute(reshape(B', 3, n+1, m+1), [3 2 1]);\nresult = b;\nfor i = 2:m\n  for j = 2:n\n    s = (i-1)/m; t = (j-1)/n;\n    result(i, j, :) = (1-s)*b(1,j,:) + s*b(m+1,j,:) + (1-t)*b(i,1,:) + t*b(i,n+1,:) ...\n      - ((1-s)*(1-t)*b(1,1,:) + s*(1-t)*b(m+1,1,:) + (1-s)*t*b(1,n+1,:) + s*t*b(m+1,n+1,:));\n  end\nend\nresult${v.mask ? "\n% (--mask solves the affine mask instead; not written out here)" : ""}`,
  },
  {
    name: "gordon",
    title: "Gordon surface",
    about: "g = g1 + g2 − g12 through a network of curves (thesis 4.4, algorithm 7); with steps, g1, g2, g12.",
    fields: [
      { key: "ucurves", flag: "--u-curve", type: "lines", label: "Curves g(u_i, v), in v — one per line, in node order" },
      { key: "vcurves", flag: "--v-curve", type: "lines", label: "Curves g(u, v_j), in u — one per line, in node order" },
      { key: "unodes", flag: "--u-nodes", label: "Nodes u_i (default equally spaced)" },
      { key: "vnodes", flag: "--v-nodes", label: "Nodes v_j (default equally spaced)" },
      ...surfaceParams,
    ],
    options: { rows: true, steps: true, script: true, plot: true, mesh: true },
    example: {
      vcurves: "[u;0;u-u^2]\n[u;0.5;0.5+u-u^2]\n[u;1;1+u-u^2]",
      ucurves: "[0;v;v]\n[0.5;v;0.25+v]\n[1;v;v]",
      u: "0.25",
      v: "0.75",
      steps: true,
      exact: true,
    },
    octave: (v) => {
      const uc = (v.ucurves ?? "").split("\n").map((s) => s.trim()).filter(Boolean);
      const vc = (v.vcurves ?? "").split("\n").map((s) => s.trim()).filter(Boolean);
      const lines = [exact(v), BERN, LAGR];
      uc.forEach((c, i) => lines.push(curveHandle(`gu${i + 1}`, c, "v", v.rows)));
      vc.forEach((c, j) => lines.push(curveHandle(`gv${j + 1}`, c, "u", v.rows)));
      lines.push(`gu = {${uc.map((_, i) => `gu${i + 1}`).join(", ")}};  % g(u_i, v)\n`);
      lines.push(`gv = {${vc.map((_, j) => `gv${j + 1}`).join(", ")}};  % g(u, v_j)\n`);
      lines.push(`xu = ${v.unodes || `linspace(0, 1, ${uc.length})`}; xv = ${v.vnodes || `linspace(0, 1, ${vc.length})`};\n`);
      lines.push(
        `u = ${uOf(v, "u")}; v = ${uOf(v, "v")};\nfor i = 1:numel(u)\n  for j = 1:numel(v)\n    Lu = lagr(xu, u(i)); Lv = lagr(xv, v(j));\n    g1 = 0; g2 = 0; g12 = 0;\n    for a = 1:numel(xu), g1 = g1 + Lu(a) * gu{a}(v(j)); end\n    for b = 1:numel(xv), g2 = g2 + Lv(b) * gv{b}(u(i)); end\n    for a = 1:numel(xu), for b = 1:numel(xv), g12 = g12 + Lu(a) * Lv(b) * gu{a}(xv(b)); end, end\n    result(i, j, :) = g1 + g2 - g12;\n  end\nend\nresult = squeeze(result)`,
      );
      return lines.join("");
    },
  },
  {
    name: "lagrange",
    title: "Lagrange interpolation",
    about: "The Lagrange basis polynomials L_i(t), or the polynomial through values at the nodes.",
    fields: [
      { key: "nodes", flag: "--nodes", label: "Nodes x_0..x_m", hint: "a list such as [0 0.5 1] or a range" },
      { key: "points", flag: "--points", label: "Values at the nodes (d×(m+1); optional)" },
      ...curveParams,
    ],
    options: { rows: true, plot: true },
    example: { nodes: "[0 0.5 1]", t: "0.25", exact: true },
    octave: (v) =>
      exact(v) +
      LAGR +
      `x = ${v.nodes};\nt = ${tOf(v, "linspace(min(x), max(x), 11)").replace("linspace(0, 1,", "linspace(min(x), max(x),")};\nL = lagr(x, t)  % row = parameter, column = L_0..L_m` +
      (v.points ? `\nP = ${mat(v.points, v.rows)};\nresult = P * L'` : ""),
  },
  {
    name: "bernstein",
    title: "Bernstein polynomials",
    about: "The values B_i^n(t) = C(n,i) t^i (1−t)^(n−i).",
    fields: [
      { key: "degree", flag: "--degree", label: "Degree n", type: "number" },
      { key: "i", flag: "--i", label: "Only B_i^n, i =", type: "number" },
      ...curveParams,
    ],
    options: {},
    example: { degree: "3", t: "0.5", exact: true },
    octave: (v) =>
      exact(v) +
      BERN +
      `n = ${or(v.degree, 3)};\nt = ${tOf(v)};\nB = bern(n, t)${v.i !== undefined && v.i !== "" ? `;\nresult = B(:, ${Number(v.i) + 1})` : "  % row = parameter, column = B_0^n..B_n^n"}`,
  },
  {
    name: "derivative",
    title: "Derivative of a Bézier curve",
    about: "The control points n!/(n−r)! Δ^r b_i of the r-th derivative, and its values.",
    fields: [
      { key: "control", positional: true, label: "Control points (one per column)" },
      { key: "order", flag: "--order", label: "Order r", type: "number" },
      { key: "t", flag: "--t", label: "Values at t (optional)" },
    ],
    options: { rows: true, script: true, plot: true },
    example: { control: "[0 0 0; 0 2 2; 8 2 0; 4 0 0]'", order: "1", t: "0.5", exact: true },
    octave: (v) =>
      exact(v) +
      BERN +
      `B = ${mat(v.control, v.rows)};\nr = ${or(v.order, 1)}; n = columns(B) - 1;\ncontrol = B;\nfor k = 1:r\n  control = (n - k + 1) * diff(control, 1, 2);  % n!/(n-r)! Δ^r b_i\nend\ncontrol` +
      (v.t ? `\nt = ${v.t};\nresult = control * bern(n - r, t)'` : ""),
  },
  {
    name: "spline",
    title: "Interpolating cubic spline",
    about: "The C² cubic spline through points (the lecture notes): its tangents and samples; segment k runs over [k, k+1].",
    fields: [
      { key: "points", positional: true, label: "Points (one per column)" },
      { key: "end", flag: "--end", label: "End condition", type: "select", choices: ["natural", "clamped", "closed"] },
      { key: "starttangent", flag: "--start-tangent", label: "Start tangent (clamped)" },
      { key: "endtangent", flag: "--end-tangent", label: "End tangent (clamped)" },
      { key: "t", flag: "--t", label: "Parameters t (segment k on [k, k+1])" },
    ],
    options: { rows: true, plot: true },
    example: { points: "[0 0; 2 1; 4 4; 6 0]'", end: "clamped", starttangent: "[1;1]", endtangent: "[-1;1]", exact: true },
    octave: (v) => {
      const P = mat(v.points, v.rows);
      const t = v.t || "0:0.1:(columns(P) - 1)";
      const fit =
        v.end === "clamped"
          ? `pp = spline(x, [${v.starttangent} P ${v.endtangent}]);  % clamped: the end tangents`
          : v.end === "closed"
            ? "pkg load splines\npp = csape(x, P, 'periodic');  % closed (the first point repeated last)"
            : "pkg load splines\npp = csape(x, P, 'variational');  % natural";
      return exact(v) + `P = ${P};\nx = 0:columns(P) - 1;\n${fit}\nt = ${t};\nresult = ppval(pp, t)`;
    },
  },
  {
    name: "hermite",
    title: "Hermite (Ferguson) cubic",
    about: "The cubic with given end points and end tangents (the lecture notes).",
    fields: [
      { key: "p0", flag: "--p0", label: "Start point x(0)" },
      { key: "p1", flag: "--p1", label: "End point x(1)" },
      { key: "t0", flag: "--t0", label: "Start tangent x'(0)" },
      { key: "t1", flag: "--t1", label: "End tangent x'(1)" },
      ...curveParams,
    ],
    options: { steps: true, plot: true },
    example: { p0: "[0;0]", p1: "[1;0]", t0: "[1;1]", t1: "[1;-1]", t: "0.5", exact: true },
    octave: (v) =>
      exact(v) +
      `p0 = ${v.p0}; p1 = ${v.p1}; t0 = ${v.t0}; t1 = ${v.t1};\nt = ${tOf(v)};\nH = [2*t.^3 - 3*t.^2 + 1; -2*t.^3 + 3*t.^2; t.^3 - 2*t.^2 + t; t.^3 - t.^2];  % Hermite basis\nresult = [p0 p1 t0 t1] * H`,
  },
  {
    name: "bspline",
    title: "B-spline curve",
    about: "A B-spline curve by de Boor's algorithm (the CAD notes); with steps, the basis functions N_i,p(t).",
    fields: [
      { key: "control", positional: true, label: "Control points (one per column)" },
      { key: "degree", flag: "--degree", label: "Degree p", type: "number" },
      { key: "knots", flag: "--knots", label: "Knots (n+p+1 for n points; default clamped uniform)" },
      ...curveParams,
    ],
    options: { rows: true, steps: true, plot: true },
    example: { control: "[0 0; 1 2; 3 2; 4 0]'", degree: "2", knots: "[0 0 0 0.5 1 1 1]", t: "0.25", steps: true, exact: true },
    octave: (v) => {
      const p = or(v.degree, 3);
      const knots = v.knots || `[zeros(1, ${p}) linspace(0, 1, columns(C) - ${p} + 1) ones(1, ${p})]`;
      return exact(v) + `pkg load nurbs\nC = ${mat(v.control, v.rows)};\np = ${p};\nknots = ${knots};\nt = ${tOf(v, "linspace(knots(p+1), knots(end-p), 11)").replace("linspace(0, 1,", "linspace(knots(p+1), knots(end-p),")};\nresult = bspeval(p, C, knots, t)`;
    },
  },
  {
    name: "nurbs",
    title: "NURBS curve",
    about: "A rational B-spline curve with weights (the CAD notes); with steps, the rational basis R_i,p(t).",
    fields: [
      { key: "control", positional: true, label: "Control points (one per column)" },
      { key: "weights", flag: "--weights", label: "Weights (one per point, positive)" },
      { key: "degree", flag: "--degree", label: "Degree p", type: "number" },
      { key: "knots", flag: "--knots", label: "Knots (n+p+1 for n points; default clamped uniform)" },
      ...curveParams,
    ],
    options: { rows: true, steps: true, plot: true },
    example: { control: "[1 0; 1 1; 0 1]'", weights: "[1 0.7071067811865476 1]", degree: "2", n: "5" },
    octave: (v) => {
      const p = or(v.degree, 3);
      const knots = v.knots || `[zeros(1, ${p}) linspace(0, 1, columns(P) - ${p} + 1) ones(1, ${p})]`;
      return (
        exact(v) +
        `pkg load nurbs\nP = ${mat(v.control, v.rows)};\nw = ${v.weights};\np = ${p};\nknots = ${knots};\ncoefs = [P .* w; zeros(3 - rows(P), columns(P)); w];  % weighted, homogeneous\nt = ${tOf(v, "linspace(knots(p+1), knots(end-p), 11)").replace("linspace(0, 1,", "linspace(knots(p+1), knots(end-p),")};\nresult = nrbeval(nrbmak(coefs, knots), t);\nresult = result(1:rows(P), :)`
      );
    },
  },
  {
    name: "curve",
    title: "Curve from an expression",
    about: "Samples of a curve written as the thesis writes curves, e.g. [u; 0; u-u^2].",
    fields: [{ key: "expr", positional: true, label: "The curve: an expression in t, u or v" }, ...curveParams],
    options: { script: true, plot: true },
    example: { expr: "[u; 0; u-u^2]", n: "5" },
    octave: (v) => {
      const p = ["u", "v", "t"].find((q) => usesParam(v.expr, q)) ?? "t";
      return exact(v) + sampleCurve(v.expr, p, tOf(v));
    },
  },
  {
    name: "surface",
    title: "Surface from an expression",
    about: "Samples of a surface written as an expression in u and v on a grid.",
    fields: [{ key: "expr", positional: true, label: "The surface: an expression in u and v" }, ...surfaceParams],
    options: { script: true, plot: true, mesh: true },
    example: { expr: "[u; v; u.*v]", n: "3" },
    octave: (v) =>
      exact(v) +
      `f = @(u, v) ${v.expr};\nu = ${uOf(v, "u")}; v = ${uOf(v, "v")};\nfor i = 1:numel(u)\n  for j = 1:numel(v)\n    result(i, j, :) = f(u(i), v(j));\n  end\nend\nresult`,
  },
  {
    name: "script",
    title: "Octave data script",
    about: "Runs a thesis-style data script (assignments, for loops) and prints its variables.",
    fields: [{ key: "n", flag: "--n", label: "Bind N", type: "number" }],
    options: { scriptFile: true },
    example: { script: "u = linspace(0,1,N);\nc1 = [u; zeros(1,N); u-u.^2];\nP1 = [0;0;0];", n: "5" },
    octave: (v) => `${v.n ? `N = ${v.n};\n` : ""}${v.script ?? ""}`,
  },
];

export const byName = Object.fromEntries(constructions.map((c) => [c.name, c]));

/** The file name under which a script typed into the page is passed to the command line. */
export const SCRIPT_FILE = "data.m";

/**
 * The arguments (after `cagd`) for a construction and form values: positional fields first,
 * then options in field order, then the common switches.
 */
export function argvOf(c, v) {
  const args = [c.name];
  if (c.options.scriptFile) args.push(SCRIPT_FILE);
  for (const f of c.fields.filter((f) => f.positional)) args.push(v[f.key] ?? "");
  const opt = (flag, value) => {
    const s = String(value);
    args.push(...(s.startsWith("-") ? [`${flag}=${s}`] : [flag, s]));
  };
  for (const f of c.fields.filter((f) => !f.positional)) {
    const value = v[f.key];
    if (value === undefined || value === "" || value === false) continue;
    if (f.type === "lines") {
      for (const line of String(value).split("\n").map((s) => s.trim()).filter(Boolean)) opt(f.flag, line);
    } else {
      opt(f.flag, value);
    }
  }
  if (c.options.rows && v.rows) args.push("--rows");
  if (c.options.steps && v.steps) args.push("--steps");
  if (c.options.script && v.script && v.script.trim()) args.push("--script", SCRIPT_FILE);
  if (c.options.format !== false && v.format && v.format !== "text") args.push("--format", v.format);
  if (c.options.exact !== false && v.exact) args.push("--exact");
  if (c.options.plot && v.plot) args.push("--plot", `${c.name}.svg`);
  if (c.options.mesh && v.mesh) args.push("--mesh", `${c.name}.${v.mesh}`);
  if (v.extra) args.push(...v.extra);
  return args;
}

/**
 * The form values of a construction read back from command-line arguments (after `cagd` and
 * the subcommand); arguments the form has no field for are kept in `extra`, in order.
 */
export function valuesOf(c, args) {
  const v = { extra: [] };
  const positional = c.fields.filter((f) => f.positional);
  const byFlag = Object.fromEntries(c.fields.filter((f) => f.flag).map((f) => [f.flag, f]));
  const switches = { "--rows": "rows", "--steps": "steps", "--exact": "exact" };
  let k = 0;
  let sawScriptFile = !c.options.scriptFile;
  for (let i = 0; i < args.length; i++) {
    const a = args[i];
    const eq = a.startsWith("--") ? a.indexOf("=") : -1;
    const flag = eq > 0 ? a.slice(0, eq) : a;
    const inline = eq > 0 ? a.slice(eq + 1) : undefined;
    const take = () => (inline !== undefined ? inline : args[++i]);
    if (byFlag[flag]) {
      const f = byFlag[flag];
      const value = take();
      if (f.type === "lines") v[f.key] = v[f.key] ? `${v[f.key]}\n${value}` : value;
      else v[f.key] = value;
    } else if (switches[a]) {
      v[switches[a]] = true;
    } else if (flag === "--format") {
      v.format = take();
    } else if (flag === "--plot" && c.options.plot) {
      const value = take();
      if (value === `${c.name}.svg`) v.plot = true;
      else v.extra.push("--plot", value);
    } else if (flag === "--mesh" && c.options.mesh) {
      const value = take();
      const ext = value.split(".").pop();
      if (value === `${c.name}.${ext}` && ["stl", "obj", "ply"].includes(ext)) v.mesh = ext;
      else v.extra.push("--mesh", value);
    } else if (flag === "--script" && c.options.script) {
      v.scriptName = take();
    } else if (/^--max-/.test(flag) || ["-o", "--output", "--out", "--plot", "--mesh", "--script", "--format"].includes(flag)) {
      v.extra.push(a);
      if (inline === undefined && i + 1 < args.length) v.extra.push(args[++i]);
    } else if (!a.startsWith("-") || a === "-" || /^-[0-9.]/.test(a)) {
      if (!sawScriptFile) {
        v.scriptName = a;
        sawScriptFile = true;
      } else if (k < positional.length) {
        v[positional[k++].key] = a;
      } else {
        v.extra.push(a);
      }
    } else {
      v.extra.push(a);
    }
  }
  return v;
}
