//! Points and derivatives of a Bézier patch, exact, with a warning for a parameter outside it.

use cagd::grid::PointGrid;
use cagd_ops::ops::surface::SurfaceParams;
use cagd_ops::ops::BezierPatchPoints;
use cagd_ops::{execute, Context, Params, Role};
use num_rational::BigRational;

#[test]
fn the_twist_of_the_hyperbolic_paraboloid_is_constant() {
    // x(u, v) = (u, v, uv): x_uv = (0, 0, 1) everywhere (thesis Trditev 3.3).
    let q = |x: i64| BigRational::from_integer(x.into());
    let net = PointGrid::from_vec(
        (2, 2, 3),
        [0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 1].map(q).to_vec(),
    )
    .unwrap();
    let op = BezierPatchPoints {
        du: 1,
        dv: 1,
        at: SurfaceParams {
            u: Params::Given(vec![BigRational::new(1.into(), 3.into())]),
            v: Params::Given(vec![q(2)]),
            list: false,
        },
        ..BezierPatchPoints::new(net)
    };
    let mut cx = Context::new(cagd::Limits::default());
    let answer = execute(&op, &mut cx).unwrap();
    assert_eq!(
        answer.report.matrix("result").unwrap().as_slice(),
        &[q(0), q(0), q(1)]
    );
    // v = 2 lies outside the patch's square.
    assert_eq!(cx.take_warnings()[0].role, Role::V);
}
