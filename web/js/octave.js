// The Octave code that computes the same numbers as a subcommand, written from the form's
// values (keyed by the command line's argument ids, as forms.js reads them): plain Octave for
// the thesis's constructions, octave-nurbs and octave-splines where the course uses them. The
// numbers on the page never come from here; this is for a student who wants to check them in
// Octave. A subcommand without code here gets none (never another subcommand's).

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

const CODE = {
  "thesis": () =>
      "% The thesis's own Octave code reproduces these examples; the cagd repository keeps it,\n% fixed, in octave_ref/fixed/ and runs it in octave_ref/cases/ (primer_2_4.m,\n% coons_thesis.m, gordon_thesis.m).\naddpath('octave_ref/fixed');\nT = deCasteljau([0 0 8 4; 0 2 2 0; 0 2 0 0], 3);  % T(:,2) is the point at t = 1/2\nT(:, 2)",
  "decasteljau": (v) =>
      exact(v) +
      `B = ${mat(v.control, v.rows)};  % control points, one per column\nt = ${tOf(v)};\nn = columns(B) - 1;\nresult = zeros(rows(B), numel(t));\nfor k = 1:numel(t)\n  b = B;                                            % b_i^0 = b_i\n  for r = 1:n\n    b = (1 - t(k)) * b(:, 1:end-1) + t(k) * b(:, 2:end);   % b_i^r(t)\n  end\n  result(:, k) = b;\nend\nresult`,
  "bezier-patch": (v) =>
      exact(v) +
      BERN +
      `B = ${v.net};  % packed net\nu = ${uOf(v, "u")}; v = ${uOf(v, "v")};\nm = rows(B) - 1; n = columns(B) / 3 - 1;\nresult = zeros(numel(u), numel(v), 3);\nfor c = 1:3\n  result(:, :, c) = bern(m, u) * B(:, c:3:end) * bern(n, v)';\nend\nresult`,
  "coons": (v) =>
      exact(v) +
      BERN +
      curveHandle("c1", v.c1, "u", v.rows) +
      curveHandle("c2", v.c2, "u", v.rows) +
      curveHandle("d1", v.d1, "v", v.rows) +
      curveHandle("d2", v.d2, "v", v.rows) +
      `P1 = c1(0); P2 = c1(1); P3 = c2(0); P4 = c2(1);  % the corners\nu = ${uOf(v, "u")}; v = ${uOf(v, "v")};\nfor i = 1:numel(u)\n  for j = 1:numel(v)\n    rc  = (1 - v(j)) * c1(u(i)) + v(j) * c2(u(i));                       % (4.1)\n    rd  = (1 - u(i)) * d1(v(j)) + u(i) * d2(v(j));                       % (4.2)\n    rcd = (1-u(i))*(1-v(j))*P1 + u(i)*(1-v(j))*P2 + (1-u(i))*v(j)*P3 + u(i)*v(j)*P4;  % (4.3)\n    result(i, j, :) = rc + rd - rcd;\n  end\nend\nresult = squeeze(result)`,
  "coons-bicubic": (v) => {
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
  "discrete-coons": (v) =>
      exact(v) +
      `B = ${v.net};  % packed net; b(i,j,:) = B(i, 3*j-2:3*j)\nm = rows(B) - 1; n = columns(B) / 3 - 1;\nb = permute(reshape(B', 3, n+1, m+1), [3 2 1]);\nresult = b;\nfor i = 2:m\n  for j = 2:n\n    s = (i-1)/m; t = (j-1)/n;\n    result(i, j, :) = (1-s)*b(1,j,:) + s*b(m+1,j,:) + (1-t)*b(i,1,:) + t*b(i,n+1,:) ...\n      - ((1-s)*(1-t)*b(1,1,:) + s*(1-t)*b(m+1,1,:) + (1-s)*t*b(1,n+1,:) + s*t*b(m+1,n+1,:));\n  end\nend\nresult${v.mask ? "\n% (--mask solves the affine mask instead; not written out here)" : ""}`,
  "gordon": (v) => {
      const uc = (v.u_curves ?? "").split("\n").map((s) => s.trim()).filter(Boolean);
      const vc = (v.v_curves ?? "").split("\n").map((s) => s.trim()).filter(Boolean);
      const lines = [exact(v), BERN, LAGR];
      uc.forEach((c, i) => lines.push(curveHandle(`gu${i + 1}`, c, "v", v.rows)));
      vc.forEach((c, j) => lines.push(curveHandle(`gv${j + 1}`, c, "u", v.rows)));
      lines.push(`gu = {${uc.map((_, i) => `gu${i + 1}`).join(", ")}};  % g(u_i, v)\n`);
      lines.push(`gv = {${vc.map((_, j) => `gv${j + 1}`).join(", ")}};  % g(u, v_j)\n`);
      lines.push(`xu = ${v.u_nodes || `linspace(0, 1, ${uc.length})`}; xv = ${v.v_nodes || `linspace(0, 1, ${vc.length})`};\n`);
      lines.push(
        `u = ${uOf(v, "u")}; v = ${uOf(v, "v")};\nfor i = 1:numel(u)\n  for j = 1:numel(v)\n    Lu = lagr(xu, u(i)); Lv = lagr(xv, v(j));\n    g1 = 0; g2 = 0; g12 = 0;\n    for a = 1:numel(xu), g1 = g1 + Lu(a) * gu{a}(v(j)); end\n    for b = 1:numel(xv), g2 = g2 + Lv(b) * gv{b}(u(i)); end\n    for a = 1:numel(xu), for b = 1:numel(xv), g12 = g12 + Lu(a) * Lv(b) * gu{a}(xv(b)); end, end\n    result(i, j, :) = g1 + g2 - g12;\n  end\nend\nresult = squeeze(result)`,
      );
      return lines.join("");
    },
  "lagrange": (v) =>
      exact(v) +
      LAGR +
      `x = ${v.nodes};\nt = ${tOf(v)};\nL = lagr(x, t)  % row = parameter, column = L_0..L_m` +
      (v.points ? `\nP = ${mat(v.points, v.rows)};\nresult = P * L'` : ""),
  "bernstein": (v) =>
      exact(v) +
      BERN +
      `n = ${or(v.degree, 3)};\nt = ${tOf(v)};\nB = bern(n, t)${v.i !== undefined && v.i !== "" ? `;\nresult = B(:, ${Number(v.i) + 1})` : "  % row = parameter, column = B_0^n..B_n^n"}`,
  "derivative": (v) =>
      exact(v) +
      BERN +
      `B = ${mat(v.control, v.rows)};\nr = ${or(v.order, 1)}; n = columns(B) - 1;\ncontrol = B;\nfor k = 1:r\n  control = (n - k + 1) * diff(control, 1, 2);  % n!/(n-r)! Δ^r b_i\nend\ncontrol` +
      (v.t ? `\nt = ${v.t};\nresult = control * bern(n - r, t)'` : ""),
  "spline": (v) => {
      const P = mat(v.points, v.rows);
      const t = v.t || "0:0.1:(columns(P) - 1)";
      const fit =
        v.end === "clamped"
          ? `pp = spline(x, [${v.start_tangent} P ${v.end_tangent}]);  % clamped: the end tangents`
          : v.end === "closed"
            ? "pkg load splines\npp = csape(x, P, 'periodic');  % closed (the first point repeated last)"
            : "pkg load splines\npp = csape(x, P, 'variational');  % natural";
      return exact(v) + `P = ${P};\nx = 0:columns(P) - 1;\n${fit}\nt = ${t};\nresult = ppval(pp, t)`;
    },
  "hermite": (v) =>
      exact(v) +
      `p0 = ${v.p0}; p1 = ${v.p1}; t0 = ${v.t0}; t1 = ${v.t1};\nt = ${tOf(v)};\nH = [2*t.^3 - 3*t.^2 + 1; -2*t.^3 + 3*t.^2; t.^3 - 2*t.^2 + t; t.^3 - t.^2];  % Hermite basis\nresult = [p0 p1 t0 t1] * H`,
  "bspline": (v) => {
      const p = or(v.degree, 3);
      const knots = v.knots || `[zeros(1, ${p}) linspace(0, 1, columns(C) - ${p} + 1) ones(1, ${p})]`;
      return exact(v) + `pkg load nurbs\nC = ${mat(v.control, v.rows)};\np = ${p};\nknots = ${knots};\nt = ${tOf(v, "linspace(knots(p+1), knots(end-p), 11)").replace("linspace(0, 1,", "linspace(knots(p+1), knots(end-p),")};\nresult = bspeval(p, C, knots, t)`;
    },
  "nurbs": (v) => {
      const p = or(v.degree, 2);
      const knots = v.knots || `[zeros(1, ${p}) linspace(0, 1, columns(P) - ${p} + 1) ones(1, ${p})]`;
      return (
        exact(v) +
        `pkg load nurbs\nP = ${mat(v.control, v.rows)};\nw = ${v.weights};\np = ${p};\nknots = ${knots};\ncoefs = [P .* w; zeros(3 - rows(P), columns(P)); w];  % weighted, homogeneous\nt = ${tOf(v, "linspace(knots(p+1), knots(end-p), 11)").replace("linspace(0, 1,", "linspace(knots(p+1), knots(end-p),")};\nresult = nrbeval(nrbmak(coefs, knots), t);\nresult = result(1:rows(P), :)`
      );
    },
  "elevate": (v) =>
    exact(v) +
    (v.knots
      ? `pkg load nurbs\nC = ${mat(v.control, v.rows)};\np = ${or(v.degree, 3)};\nknots = ${v.knots};\n[result, knots_new] = bspdegelev(p, C, knots, ${or(v.by, 1)})`
      : `B = ${mat(v.control, v.rows)};  % control points, one per column\nfor r = 1:${or(v.by, 1)}\n  n = columns(B) - 1;\n  a = (1:n) / (n + 1);                             % i/(n+1), i = 1..n\n  B = [B(:, 1), a .* B(:, 1:n) + (1 - a) .* B(:, 2:n+1), B(:, end)];  % b_i^(1)\nend\nresult = B`),
  "subdivide": (v) =>
    exact(v) +
    `B = ${mat(v.control, v.rows)};  % control points, one per column\nt = ${or(v.t, "0.5")};\nn = columns(B) - 1;\nleft = B(:, 1); right = B(:, end);\nb = B;\nfor r = 1:n\n  b = (1 - t) * b(:, 1:end-1) + t * b(:, 2:end);   % level r of the scheme\n  left(:, end+1) = b(:, 1);                         % the diagonal b_0^r\n  right = [b(:, end), right];                        % the last row b_(n-r)^r\nend\nleft\nright`,
  "insert-knot": (v) =>
    exact(v) +
    `pkg load nurbs\nC = ${mat(v.control, v.rows)};\np = ${or(v.degree, 3)};\nknots = ${v.knots || `[zeros(1, p) linspace(0, 1, columns(C) - p + 1) ones(1, p)]`};\n[control, knots] = bspkntins(p, C, knots, ${v.insert})  % Boehm's algorithm`,
  "bspline-basis": (v) =>
    exact(v) +
    `pkg load nurbs\nknots = ${v.knots};\np = ${or(v.degree, 3)};\nn = numel(knots) - p - 2;                        % n + 1 basis functions\nt = ${v.t || "linspace(knots(1), knots(end), 11)"};\nresult = zeros(numel(t), n + 1);\nfor k = 1:numel(t)\n  s = findspan(n, p, t(k), knots);\n  result(k, s-p+1:s+1) = basisfun(s, t(k), p, knots);  % N_(s-p),p .. N_s,p\nend\nresult`,
  "curve": (v) => {
      const p = ["u", "v", "t"].find((q) => usesParam(v.expr, q)) ?? "t";
      return exact(v) + sampleCurve(v.expr, p, tOf(v));
    },
  "surface": (v) =>
      exact(v) +
      `f = @(u, v) ${v.expr};\nu = ${uOf(v, "u")}; v = ${uOf(v, "v")};\nfor i = 1:numel(u)\n  for j = 1:numel(v)\n    result(i, j, :) = f(u(i), v(j));\n  end\nend\nresult`,
  "script": (v) => `${v.n ? `N = ${v.n};\n` : ""}${v.script ?? ""}`,
};

/** The Octave code of subcommand `name` for the form values `v`, or null. */
export function octaveCode(name, v) {
  const code = CODE[name];
  if (!code) return null;
  try {
    return code(v);
  } catch {
    return null;
  }
}
