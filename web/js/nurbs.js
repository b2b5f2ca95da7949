// The NURBS view: a B-spline curve with a weight per control point (typed in the table, exact
// with "exact fractions"), its rational basis R_i,p, and the point at t as the command line
// computes it (cagd nurbs --steps). The quarter circle with weights 1, 1, 2 passes through
// (3/5, 4/5) at t = 1/2.

import { SplineFamily } from "./bspline.js";

export default class NurbsView extends SplineFamily {
  constructor(app) {
    super(app, "nurbs");
  }
}
