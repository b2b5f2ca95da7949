//! Reading an Octave `save -text` file and evaluating what it holds: the cubic B-spline
//! `p3_uniform` of the Octave reference file `octave_ref/expected/bspline_curves.txt` (degree,
//! knots and control points as octave-nurbs saved them, with the values of its `bspeval`),
//! rebuilt as a `BSplineCurve` and evaluated at Octave's parameters.
//!
//! ```text
//! cargo run --example octave_text_file
//! ```

use cagd::bspline::BSplineCurve;
use cagd_octave::text_format::read_text_file;
use nalgebra::DMatrix;

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/octave_ref/expected/bspline_curves.txt"
    );
    let file = read_text_file(path)?;
    let matrix = |name: &str| -> Result<DMatrix<f64>, cagd_octave::TextFormatError> {
        let a = file.matrix(name)?;
        Ok(DMatrix::from_fn(a.nrows(), a.ncols(), |i, j| a[[i, j]]))
    };
    let degree = file.scalar("deg_p3_uniform")? as usize;
    let knots: Vec<f64> = matrix("knots_p3_uniform")?.iter().copied().collect();
    let curve = BSplineCurve::new(degree, knots.clone(), matrix("C_p3_uniform")?)?;
    let (a, b) = curve.domain();
    println!(
        "p3_uniform: degree {degree}, {} control points, knots {knots:?}, domain [{a}, {b}]",
        curve.control().ncols()
    );
    // Octave's parameters (linspace over the domain) and its bspeval values there.
    let us = matrix("u_p3_uniform")?;
    let octave = matrix("P_p3_uniform")?;
    let mut worst: f64 = 0.0;
    for (k, u) in us.iter().enumerate() {
        let x = curve.try_eval(*u)?;
        worst = worst.max((x - octave.column(k)).amax());
    }
    let x = curve.try_eval(1.0)?;
    println!("C(1) = ({}, {})", x[0], x[1]);
    println!(
        "largest difference from Octave at {} parameters: {worst:e}",
        us.len()
    );
    Ok(())
}
