//! A Coons patch from four B-spline boundaries, one of them a uniform cubic B-spline on
//! `[0, 4]`: the patch takes each boundary over its whole domain, reparametrised affinely onto
//! `[0, 1]` (`x(u, 0) = c1(4u)`), and prints one point: exactly `(37/64, 89/128, 31/64)`, from
//! the curves' closed forms.
//!
//! ```text
//! cargo run --example coons_bspline_boundaries
//! ```

use cagd::bspline::BSplineCurve;
use cagd::coons::CoonsPatch;
use cagd::Surface;
use nalgebra::DMatrix;

/// The points as the columns of a control matrix.
fn points(p: &[[f64; 3]]) -> DMatrix<f64> {
    DMatrix::from_fn(3, p.len(), |r, c| p[c][r])
}

fn main() -> Result<(), cagd::Error> {
    // x(u, 0): the uniform cubic B-spline over (0,0,0), (1,0,2), (2,0,0), ends replicated.
    let c1 = BSplineCurve::uniform_cubic(
        &points(&[[0.0, 0.0, 0.0], [1.0, 0.0, 2.0], [2.0, 0.0, 0.0]]),
        true,
    )?;
    // x(u, 1): a clamped quadratic.
    let c2 = BSplineCurve::clamped(
        2,
        points(&[[0.0, 2.0, 0.0], [1.0, 2.0, 1.0], [2.0, 2.0, 0.0]]),
    )?;
    // x(0, v): a quadratic on the knots 0, 0, 0, 1, 2, 2, 2.
    let d1 = BSplineCurve::new(
        2,
        vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0],
        points(&[
            [0.0, 0.0, 0.0],
            [0.0, 1.0, -1.0],
            [0.0, 1.5, 0.5],
            [0.0, 2.0, 0.0],
        ]),
    )?;
    // x(1, v): a line.
    let d2 = BSplineCurve::clamped(1, points(&[[2.0, 0.0, 0.0], [2.0, 2.0, 0.0]]))?;
    for (name, curve) in [("c1", &c1), ("c2", &c2), ("d1", &d1), ("d2", &d2)] {
        let (a, b) = curve.domain();
        println!("{name} on [{a}, {b}]");
    }
    let patch = CoonsPatch::new(c1, c2, d1, d2)?;
    let x = patch.eval(0.375, 0.25);
    println!("x(3/8, 1/4) = ({:.7}, {:.7}, {:.7})", x[0], x[1], x[2]);
    Ok(())
}
