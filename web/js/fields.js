// The names in a view's messages: the one place where the page maps the program's name of an
// argument — the command line's (CONTROL, --knots), or the operation layer's role key that the
// views' own WebAssembly exports use (control, knots, c1, grid) — to the label of the view's
// field that holds it, in the page's language. A view shows every message through
// viewMessage, so its messages speak of its own fields and never of an option it lacks.

import { localMessage, t } from "./i18n.js";

const POINTS = { CONTROL: "points", control: "points", spline: "points" };
const T = { "--t": "parameterT", t: "parameterT" };
const SPLINE = { ...POINTS, ...T, "--degree": "degree", degree: "degree", "--knots": "knots", knots: "knots" };

/** By view: the program's names of an argument → the i18n key of the view's label for it. */
export const FIELDS = {
  bezier: { ...POINTS, ...T },
  subdivide: { ...POINTS, ...T },
  elevate: { ...POINTS, "--by": "elevateBy", "-r": "elevateBy", by: "elevateBy" },
  bspline: SPLINE,
  nurbs: { ...SPLINE, "--weights": "weights", weights: "weights" },
  insert: { ...SPLINE, "--insert": "parameterU", at: "parameterU", "--t": "parameterU", t: "parameterU" },
  basis: { ...T, "--degree": "degree", degree: "degree", "--knots": "knots", knots: "knots" },
  spline: {
    ...T,
    POINTS: "points",
    points: "points",
    "--end": "endCondition",
    ends: "endCondition",
    "--start-tangent": "startTangent",
    t0: "startTangent",
    "--end-tangent": "endTangent",
    t1: "endTangent",
  },
  coons: {
    "--c1": "field.c1",
    c1: "field.c1",
    "--c2": "field.c2",
    c2: "field.c2",
    "--d1": "field.d1",
    d1: "field.d1",
    "--d2": "field.d2",
    d2: "field.d2",
    boundary: "field.boundary",
    "--c1/--c2/--d1/--d2": "field.boundary",
    "--u": "parameterUCoons",
    u: "parameterUCoons",
    "--v": "parameterV",
    v: "parameterV",
    grid: "grid",
    "--n": "grid",
  },
  gordon: {
    "--u-curve": "ucurves",
    u_curves: "ucurves",
    "--v-curve": "vcurves",
    v_curves: "vcurves",
    network: "field.network",
    "--u-curve/--v-curve": "field.network",
    grid: "grid",
    "--n": "grid",
  },
};

/** How the command line tells the reading of a matrix and the flags that raise a limit: words
 * about options no view has (a view's table has one row per point; its limits are the page's). */
const COMMAND_LINE_ONLY = [/ \(read as [^()]*\)/g, / \(raise it with [^()]*\)/g];

/**
 * `message` (one line, `cagd: error: NAME: PROBLEM; expected FORM`, or a warning) as view
 * `view` shows it: NAME as the label of the view's field, without the command line's words
 * about options the view lacks, in the page's language (localMessage). A name the view has no
 * field for stays as it is.
 */
export function viewMessage(view, message) {
  if (!message) return message;
  const m = /^(cagd: [^:]+: )(.*?): (.*)$/s.exec(message);
  if (!m) return localMessage(message);
  const [, head, name, rest] = m;
  const key = FIELDS[view]?.[name];
  const tidy = COMMAND_LINE_ONLY.reduce((s, re) => s.replace(re, ""), rest);
  return localMessage(`${head}${key ? t(key) : name}: ${tidy}`);
}

/** Every name of an argument `view` maps (for the tests). */
export function fieldNames(view) {
  return Object.keys(FIELDS[view] ?? {});
}
