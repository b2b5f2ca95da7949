// The subdivision view: a Bézier curve split at t into two Bézier curves, whose control points
// are the diagonal and the last row of the de Casteljau scheme at t (cagd subdivide --steps,
// the L and R marks in the scheme).

import { BezierFamily } from "./bezier.js";

export default class SubdivideView extends BezierFamily {
  constructor(app) {
    super(app, "subdivide", "subdivide");
  }
}
