//! Thesis Primer 2.4 in exact rationals: the de Casteljau scheme of the cubic with control
//! points `b0 = (0,0,0)`, `b1 = (0,2,2)`, `b2 = (8,2,0)`, `b3 = (4,0,0)` at `t = 1/2`, every
//! intermediate point a fraction; the point on the curve is `(7/2, 3/2, 3/4)`, the thesis's
//! `(3.5, 1.5, 0.75)`.
//!
//! ```text
//! cargo run --example primer_2_4_exact
//! ```

use cagd::BezierCurve;
use nalgebra::DMatrix;
use num_rational::BigRational;

fn main() -> Result<(), cagd::Error> {
    let int = |n: i64| BigRational::from_integer(n.into());
    let control = DMatrix::from_row_slice(3, 4, &[0, 0, 8, 4, 0, 2, 2, 0, 0, 2, 0, 0]).map(int);
    let curve = BezierCurve::new(control)?;
    let scheme = curve.scheme(BigRational::new(1.into(), 2.into()));
    print!("{scheme}");
    let b = scheme.point_on_curve();
    println!("b(1/2) = ({}, {}, {})", b[0], b[1], b[2]);
    Ok(())
}
