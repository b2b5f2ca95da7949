//! The package prices its work with the core's estimates, as the operation layer (the command
//! line, the page) prices the same construction: for each function below, the largest number
//! of points that `max_work` allows is the same as for the operation layer's request of the
//! same points, and one more is refused by both.

use cagd::grid::PointGrid;
use cagd_octave_pkg::{call, Kind, Value, VecSink};
use cagd_ops::knots::Degree;
use cagd_ops::ops::surface::SurfaceParams;
use cagd_ops::ops::{BSpline, BSplineSurface, BezierPatchPoints, DeCasteljau, Nurbs, NurbsSurface};
use cagd_ops::{execute, Context, Operation, Params};
use nalgebra::DMatrix;

use crate::values::{nrbmak, real};

/// A `max_work` small enough that the largest requests stay cheap in a test build.
const WORK: u64 = 3_000_000;

fn limits() -> cagd::Limits {
    cagd::Limits {
        max_work: WORK,
        ..cagd::Limits::default()
    }
}

/// The largest `n` in `1..` for which `accepts(n)` (which is monotone: true, then false).
fn largest(accepts: impl Fn(usize) -> bool) -> usize {
    let (mut lo, mut hi) = (1, 2);
    while accepts(hi) {
        (lo, hi) = (hi, 2 * hi);
    }
    assert!(accepts(lo), "not even {lo}");
    while hi - lo > 1 {
        let mid = (lo + hi) / 2;
        if accepts(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    lo
}

/// Whether the operation runs within the limits (any other error is a failure of the test).
fn op_accepts<O: Operation<f64>>(op: &O) -> bool {
    match execute(op, &mut Context::new(limits())) {
        Ok(_) => true,
        Err(e) if e.kind == cagd_ops::Kind::Limit => false,
        Err(e) => panic!("{e}"),
    }
}

/// Whether the package function runs within the limits.
fn pkg_accepts(name: &str, args: &[Value<'_>]) -> bool {
    match call(name, args, 1, &mut limits(), &mut VecSink::default()) {
        Ok(()) => true,
        Err(e) if e.kind == Kind::Limit => {
            assert!(e.message.contains("estimated operations"), "{e}");
            false
        }
        Err(e) => panic!("{e}"),
    }
}

/// Control points `d × n`, column-major.
fn points(d: usize, n: usize) -> Vec<f64> {
    (0..d * n).map(|k| ((k * 37) % 11) as f64 / 7.0).collect()
}

fn clamped(p: usize, n: usize) -> Vec<f64> {
    let mut u = vec![0.0; p + 1];
    u.extend((1..n - p).map(|i| i as f64 / (n - p) as f64));
    u.extend(vec![1.0; p + 1]);
    u
}

#[test]
fn de_casteljau_as_the_decasteljau_request() {
    let c = points(3, 12);
    let op_n = largest(|n| {
        op_accepts(&DeCasteljau {
            t: Params::Samples(n),
            ..DeCasteljau::new(DMatrix::from_column_slice(3, 12, &c))
        })
    });
    let pkg_n = largest(|n| {
        pkg_accepts(
            "deCasteljau",
            &[real(&[3, 12], &c), real(&[1, 1], &[n as f64])],
        )
    });
    // 3 · 12² operations a point.
    assert_eq!((op_n, pkg_n), (WORK as usize / 432, WORK as usize / 432));
}

#[test]
fn ploskev_b_as_the_bezier_patch_request() {
    // A packed net of degrees (3, 4): rows i, columns 3j+c.
    let (m1, n1) = (4, 5);
    let b = points(m1, 3 * n1);
    let net = PointGrid::from_shape_fn((m1, n1, 3), |(i, j, c)| b[i + m1 * (3 * j + c)]);
    let op_n = largest(|n| {
        op_accepts(&BezierPatchPoints {
            at: SurfaceParams {
                u: Params::Samples(n),
                v: Params::Samples(n),
                list: false,
            },
            ..BezierPatchPoints::new(net.clone())
        })
    });
    let pkg_n = largest(|n| {
        pkg_accepts(
            "ploskevB",
            &[real(&[m1, 3 * n1], &b), real(&[1, 1], &[n as f64])],
        )
    });
    assert_eq!(op_n, pkg_n);
    assert!(op_n > 10, "{op_n}");
}

#[test]
fn bspeval_as_the_bspline_request() {
    let (p, n, d) = (3, 20, 2);
    let (c, k) = (points(d, n), clamped(p, n));
    let t = |k: usize| cagd::linspace(0.0, 1.0, k);
    let op_n = largest(|m| {
        op_accepts(&BSpline {
            degree: Degree::Degree(p),
            knots: Some(k.clone()),
            t: Params::Given(t(m)),
            ..BSpline::new(DMatrix::from_column_slice(d, n, &c))
        })
    });
    let pkg_n = largest(|m| {
        let ts = t(m);
        pkg_accepts(
            "cagd_bspeval",
            &[
                real(&[1, 1], &[p as f64]),
                real(&[d, n], &c),
                real(&[1, k.len()], &k),
                real(&[1, m], &ts),
            ],
        )
    });
    assert_eq!(op_n, pkg_n);
}

/// `nrbmak (coefs, knots)`'s storage: coefficients (`4 × …`), one knot vector per direction.
struct Nrb {
    coefs: Vec<f64>,
    dims: Vec<usize>,
    knots: Vec<Vec<f64>>,
    knot_dims: Vec<[usize; 2]>,
    order: Vec<f64>,
    number: Vec<f64>,
    row_dims: [usize; 2],
}

impl Nrb {
    fn new(coefs: Vec<f64>, dims: &[usize], knots: Vec<Vec<f64>>, order: Vec<f64>) -> Self {
        Nrb {
            knot_dims: knots.iter().map(|k| [1, k.len()]).collect(),
            number: dims[1..].iter().map(|&x| x as f64).collect(),
            row_dims: [1, order.len()],
            dims: dims.to_vec(),
            coefs,
            knots,
            order,
        }
    }

    /// The structure as the package receives it.
    fn value(&self) -> Value<'_> {
        let mut knots: Vec<Value<'_>> = self
            .knots
            .iter()
            .zip(&self.knot_dims)
            .map(|(k, d)| real(d, k))
            .collect();
        let knots = if knots.len() == 1 {
            knots.remove(0)
        } else {
            Value::Cell {
                dims: &[1, 2],
                items: knots,
            }
        };
        nrbmak([
            ("coefs", real(&self.dims, &self.coefs)),
            ("knots", knots),
            ("order", real(&self.row_dims, &self.order)),
            ("number", real(&self.row_dims, &self.number)),
        ])
    }
}

#[test]
fn nrbeval_as_the_nurbs_requests() {
    // A cubic NURBS curve in 3-D (weights 1 to 2) and a bicubic surface.
    let (p, n) = (3, 15);
    let pts = points(3, n);
    let w: Vec<f64> = (0..n).map(|i| 1.0 + (i % 3) as f64 / 2.0).collect();
    let mut coefs = Vec::new();
    for i in 0..n {
        coefs.extend(pts[3 * i..3 * i + 3].iter().map(|x| x * w[i]));
        coefs.push(w[i]);
    }
    let knots = clamped(p, n);
    let t = |k: usize| cagd::linspace(0.0, 1.0, k);
    let op_n = largest(|m| {
        op_accepts(&Nurbs {
            degree: Degree::Degree(p),
            knots: Some(knots.clone()),
            t: Params::Given(t(m)),
            ..Nurbs::new(DMatrix::from_column_slice(3, n, &pts), w.clone())
        })
    });
    let curve = Nrb::new(coefs, &[4, n], vec![knots], vec![4.0]);
    let pkg_n = largest(|m| pkg_accepts("cagd_nrbeval", &[curve.value(), real(&[1, m], &t(m))]));
    assert_eq!(op_n, pkg_n);
    // The surface: coefs 4 × 6 × 7, weights 1.
    let (nu, nv) = (6, 7);
    let net = points(3, nu * nv);
    let mut sc = Vec::new();
    for k in 0..nu * nv {
        sc.extend_from_slice(&net[3 * k..3 * k + 3]);
        sc.push(1.0);
    }
    let sk = [clamped(3, nu), clamped(3, nv)];
    let grid = PointGrid::from_shape_fn((nu, nv, 3), |(i, j, c)| net[3 * (i + nu * j) + c]);
    let op_n = largest(|m| {
        op_accepts(&NurbsSurface {
            spline: BSplineSurface {
                degrees: [Degree::Degree(3), Degree::Degree(3)],
                knots: [Some(sk[0].clone()), Some(sk[1].clone())],
                at: SurfaceParams {
                    u: Params::Given(t(m)),
                    v: Params::Given(t(m)),
                    list: false,
                },
                ..BSplineSurface::new(grid.clone())
            },
            weights: DMatrix::from_element(nu, nv, 1.0),
        })
    });
    let surface = Nrb::new(sc, &[4, nu, nv], sk.to_vec(), vec![4.0, 4.0]);
    let pkg_n = largest(|m| {
        let (g, dims) = (t(m), [1, m]);
        let tt = Value::Cell {
            dims: &[1, 2],
            items: vec![real(&dims, &g), real(&dims, &g)],
        };
        pkg_accepts("cagd_nrbeval", &[surface.value(), tt])
    });
    assert_eq!(op_n, pkg_n);
}
