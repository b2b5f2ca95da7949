// The knot-insertion view: Boehm's algorithm on a B-spline curve (cagd insert-knot --steps):
// the span of the new knot u, the factors α_i and the new control polygon drawn over the old
// one, the curve unchanged. The course's example inserts u = 3/2 into a degree-2 B-spline and
// gets (7/4, 11/4) and (5/2, 2) among the new points.

import { SplineFamily } from "./bspline.js";

export default class InsertView extends SplineFamily {
  constructor(app) {
    super(app, "insert");
  }
}
