// The elevation view: a Bézier curve written with r more control points (cagd elevate --by r
// --steps), the elevated control polygon drawn over the old one.

import { BezierFamily } from "./bezier.js";

export default class ElevateView extends BezierFamily {
  constructor(app) {
    super(app, "elevate", "elevate");
  }
}
