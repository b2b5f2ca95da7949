//! A Gordon surface through a network of NURBS curves: three circular arcs (rational, exact)
//! at the heights `u = 0, 1/2, 1` with radii 1, 3/2, 1, and three quadratic profiles at the
//! angles 0°, 45°, 90° — the profiles given on the knot domain `[0, 2]`, which the surface
//! reparametrises onto `[0, 1]` as it does every curve. The network is cut from a surface of
//! revolution, which the Gordon surface reproduces: every point `g(u, v)` lies at the distance
//! `1 + 2u(1 − u)` from the z axis, on a network curve (`v = 1/2`) or between them.
//!
//! ```text
//! cargo run --example gordon_nurbs_network
//! ```

use cagd::gordon::GordonSurface;
use cagd::nurbs::NurbsCurve;
use cagd::Surface;
use nalgebra::DMatrix;

/// The quarter circle of radius `r` at height `z` from the x axis to the y axis:
/// a rational quadratic with weights 1, √½, 1 (its parameter 1/2 is the 45° point).
fn arc(r: f64, z: f64) -> Result<NurbsCurve, cagd::Error> {
    let points = DMatrix::from_column_slice(3, 3, &[r, 0.0, z, r, r, z, 0.0, r, z]);
    let knots = vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
    NurbsCurve::new(
        2,
        knots,
        points,
        vec![1.0, std::f64::consts::FRAC_1_SQRT_2, 1.0],
    )
}

/// The profile at the angle `phi`: radius `1 + 2t(1 − t)` (control radii 1, 2, 1), height `t`,
/// on the knots 0, 0, 0, 2, 2, 2.
fn profile(phi: f64) -> Result<NurbsCurve, cagd::Error> {
    let (c, s) = (phi.cos(), phi.sin());
    let points = DMatrix::from_fn(3, 3, |row, k| {
        let (r, z) = ([1.0, 2.0, 1.0][k], [0.0, 0.5, 1.0][k]);
        [r * c, r * s, z][row]
    });
    NurbsCurve::new(2, vec![0.0, 0.0, 0.0, 2.0, 2.0, 2.0], points, vec![1.0; 3])
}

fn main() -> Result<(), cagd::Error> {
    let nodes = vec![0.0, 0.5, 1.0];
    let arcs = vec![arc(1.0, 0.0)?, arc(1.5, 0.5)?, arc(1.0, 1.0)?];
    let quarter = std::f64::consts::FRAC_PI_2;
    let profiles = vec![profile(0.0)?, profile(0.5 * quarter)?, profile(quarter)?];
    let ((a, b), (c, d)) = (profiles[0].domain(), arcs[0].domain());
    println!("profiles on [{a}, {b}], arcs on [{c}, {d}]");
    let g = GordonSurface::new(nodes.clone(), nodes, arcs, profiles)?;
    for (u, v) in [(0.25, 0.5), (0.25, 0.25)] {
        let x = g.eval(u, v);
        println!(
            "g({u}, {v}) = ({:.12}, {:.12}, {:.12}), {:.12} from the z axis",
            x[0],
            x[1],
            x[2],
            x[0].hypot(x[1])
        );
    }
    Ok(())
}
