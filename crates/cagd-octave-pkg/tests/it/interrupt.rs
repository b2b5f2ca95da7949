//! Every function that does long work asks its interrupt between chunks and stops when it says
//! so (Octave's Ctrl-C through the oct-file): each call below succeeds when never interrupted
//! and, with an interrupt that answers "stop" from its second question on, fails with
//! `cagd:interrupted` after asking exactly twice — so it was asked during the work (the work
//! of each call spans several chunks), not only once before it. The live test with SIGINT in
//! Octave is `octave_pkg/tests/interrupt.sh`.

use std::sync::atomic::{AtomicUsize, Ordering};

use cagd_octave_pkg::{call_interruptible, Kind, Real, Value, VecSink};

use crate::values::nrbmak;

/// An argument's storage: Octave's size and the values, column-major.
struct Arg {
    dims: Vec<usize>,
    data: Vec<f64>,
}

fn arg(dims: &[usize], data: Vec<f64>) -> Arg {
    assert_eq!(dims.iter().product::<usize>(), data.len());
    Arg {
        dims: dims.to_vec(),
        data,
    }
}

fn scalar(x: f64) -> Arg {
    arg(&[1, 1], vec![x])
}

fn row(data: Vec<f64>) -> Arg {
    arg(&[1, data.len()], data)
}

fn value(a: &Arg) -> Value<'_> {
    Value::Real(Real {
        dims: &a.dims,
        data: &a.data,
    })
}

/// `k` parameters spread over `[0, 1]`, in a scrambled order.
fn params(k: usize) -> Vec<f64> {
    (0..k).map(|i| ((i * 7919) % k) as f64 / k as f64).collect()
}

/// Clamped uniform knots of degree `p` for `n` control points.
fn clamped(p: usize, n: usize) -> Vec<f64> {
    let mut u = vec![0.0; p + 1];
    u.extend((1..n - p).map(|i| i as f64 / (n - p) as f64));
    u.extend(vec![1.0; p + 1]);
    u
}

/// Pseudo-random numbers in `[0, 1)` (a fixed linear congruential sequence).
fn numbers(n: usize, seed: u64) -> Vec<f64> {
    let mut x = seed;
    (0..n)
        .map(|_| {
            x = x
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            (x >> 11) as f64 / (1u64 << 53) as f64
        })
        .collect()
}

/// An octave-nurbs structure's storage: `coefs`, one knot vector per direction, `order`,
/// `number` (the sizes of `coefs` after the first).
struct Nrb {
    coefs: Arg,
    knots: Vec<Arg>,
    order: Arg,
    number: Arg,
}

fn nrb(coefs: Arg, degrees: &[usize]) -> Nrb {
    let sizes = coefs.dims[1..].to_vec();
    let knots = degrees
        .iter()
        .zip(&sizes)
        .map(|(&p, &n)| row(clamped(p, n)))
        .collect();
    Nrb {
        order: row(degrees.iter().map(|&p| (p + 1) as f64).collect()),
        number: row(sizes.iter().map(|&n| n as f64).collect()),
        knots,
        coefs,
    }
}

impl Nrb {
    /// `nrbmak (coefs, knots)` as the package receives it.
    fn value(&self) -> Value<'_> {
        let knots = if self.knots.len() == 1 {
            value(&self.knots[0])
        } else {
            Value::Cell {
                dims: if self.knots.len() == 2 {
                    &[1, 2]
                } else {
                    &[1, 3]
                },
                items: self.knots.iter().map(value).collect(),
            }
        };
        nrbmak([
            ("number", value(&self.number)),
            ("coefs", value(&self.coefs)),
            ("knots", knots),
            ("order", value(&self.order)),
        ])
    }
}

/// Calls `name` twice: never interrupted (it must succeed), then interrupted at the first
/// question, which comes after the first chunk of work (it must stop with `cagd:interrupted`
/// after exactly one question: the rest of the work is not done).
fn stops(name: &str, args: &[Value<'_>], nargout: usize) {
    let mut limits = cagd::Limits::default();
    call_interruptible(
        name,
        (args, nargout),
        &mut limits,
        &|| false,
        &mut VecSink::default(),
    )
    .unwrap_or_else(|e| panic!("{name}: {e}"));
    let asked = AtomicUsize::new(0);
    let second = || {
        asked.fetch_add(1, Ordering::SeqCst);
        true
    };
    let e = call_interruptible(
        name,
        (args, nargout),
        &mut limits,
        &second,
        &mut VecSink::default(),
    )
    .expect_err(&format!(
        "{name} ({} arguments) was not interrupted",
        args.len()
    ));
    assert_eq!(
        (e.kind, e.message.as_str()),
        (Kind::Interrupted, format!("{name}: interrupted").as_str()),
        "{name}"
    );
    assert_eq!(asked.load(Ordering::SeqCst), 1, "{name}");
}

#[test]
fn the_thesis_functions_stop_between_chunks() {
    let p = row(numbers(101, 1));
    stops("deCasteljau", &[value(&p), value(&scalar(1000.0))], 1);
    // A packed net of degrees 30 × 30 on a 200 × 200 grid.
    let b = arg(&[31, 93], numbers(31 * 93, 2));
    stops("ploskevB", &[value(&b), value(&scalar(200.0))], 1);
    let x = row((0..101).map(|i| i as f64 / 100.0).collect());
    let u = row(params(10_000));
    stops("Lagrange", &[value(&x), value(&scalar(3.0)), value(&u)], 1);
    // krpaCoons and krpaGordon of the plane (u, v, u + v), N = 300.
    let n = 300;
    let t: Vec<f64> = cagd::linspace(0.0, 1.0, n);
    let curve = |f: &dyn Fn(f64) -> [f64; 3]| arg(&[3, n], t.iter().flat_map(|&s| f(s)).collect());
    let coons = [
        curve(&|s| [s, 0.0, s]),
        curve(&|s| [s, 1.0, s + 1.0]),
        curve(&|s| [0.0, s, s]),
        curve(&|s| [1.0, s, 1.0 + s]),
        arg(&[3, 1], vec![0.0, 0.0, 0.0]),
        arg(&[3, 1], vec![1.0, 0.0, 1.0]),
        arg(&[3, 1], vec![0.0, 1.0, 1.0]),
        arg(&[3, 1], vec![1.0, 1.0, 2.0]),
    ];
    let args: Vec<Value<'_>> = coons.iter().map(value).collect();
    stops("krpaCoons", &args, 2);
    let g_u = arg(
        &[3, 2 * n],
        [0.0, 1.0]
            .iter()
            .flat_map(|&v| t.iter().flat_map(move |&s| [s, v, s + v]))
            .collect(),
    );
    let g_v = arg(
        &[3, 2 * n],
        [0.0, 1.0]
            .iter()
            .flat_map(|&u| t.iter().flat_map(move |&s| [u, s, u + s]))
            .collect(),
    );
    // Row i: g(u_i, v_0), g(u_i, v_1), column-major.
    let g_uv = arg(
        &[2, 6],
        vec![0.0, 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 1.0, 1.0, 1.0, 1.0, 2.0],
    );
    let nodes = row(vec![0.0, 1.0]);
    let count = scalar(n as f64);
    let args = [
        value(&g_u),
        value(&g_v),
        value(&g_uv),
        value(&nodes),
        value(&nodes),
        value(&count),
    ];
    stops("krpaGordon", &args, 2);
}

#[test]
fn the_twins_stop_between_chunks() {
    let (p, n) = (3, 40);
    let u = row(params(10_000));
    // A curve with unit weights (sorted parameters: the Bézier pieces; scrambled: the
    // B-spline batch), with other weights, and its homogeneous form [p, w].
    let mut c = numbers(4 * n, 3);
    c.iter_mut().skip(3).step_by(4).for_each(|w| *w = 1.0);
    let unit = nrb(arg(&[4, n], c.clone()), &[p]);
    let sorted = row(cagd::linspace(0.0, 1.0, 10_000));
    stops("cagd_nrbeval", &[unit.value(), value(&sorted)], 1);
    stops("cagd_nrbeval", &[unit.value(), value(&u)], 1);
    c.iter_mut().skip(3).step_by(4).for_each(|w| *w += 0.5);
    let weighted = nrb(arg(&[4, n], c), &[p]);
    stops("cagd_nrbeval", &[weighted.value(), value(&u)], 1);
    stops("cagd_nrbeval", &[weighted.value(), value(&u)], 2);
    // A surface on a grid (in bands of rows), at scattered points; a volume on a grid.
    let srf = nrb(arg(&[4, 12, 12], numbers(4 * 144, 4)), &[3, 3]);
    let g = row(params(700));
    let grid = Value::Cell {
        dims: &[1, 2],
        items: vec![value(&g), value(&g)],
    };
    stops("cagd_nrbeval", &[srf.value(), grid], 1);
    let pts = arg(&[2, 20_000], numbers(40_000, 5));
    stops("cagd_nrbeval", &[srf.value(), value(&pts)], 1);
    let vol = nrb(arg(&[4, 6, 6, 6], numbers(4 * 216, 6)), &[2, 2, 2]);
    let g3 = row(params(60));
    let grid3 = Value::Cell {
        dims: &[1, 3],
        items: vec![value(&g3), value(&g3), value(&g3)],
    };
    stops("cagd_nrbeval", &[vol.value(), grid3], 1);
    // The univariate functions at 10000 parameters.
    let knots = row(clamped(p, n));
    let cp = arg(&[2, n], numbers(2 * n, 7));
    let pp = scalar(p as f64);
    stops(
        "cagd_bspeval",
        &[value(&pp), value(&cp), value(&knots), value(&u)],
        1,
    );
    let spans = row(vec![10.0; 10_000]);
    let span_u = row((0..10_000)
        .map(|i| 0.2 + 0.02 * i as f64 / 10_000.0)
        .collect());
    stops(
        "cagd_basisfun",
        &[value(&spans), value(&span_u), value(&pp), value(&knots)],
        1,
    );
    let nd = scalar(2.0);
    stops(
        "cagd_basisfunder",
        &[
            value(&spans),
            value(&pp),
            value(&span_u),
            value(&knots),
            value(&nd),
        ],
        1,
    );
    let nn = scalar((n - 1) as f64);
    stops(
        "cagd_findspan",
        &[value(&nn), value(&pp), value(&u), value(&knots)],
        1,
    );
}

#[test]
fn nrbdeval_stops_between_chunks() {
    // A cubic and a derivative structure as nrbderiv builds one: degree 2, 39 coefficients.
    let n = 40;
    let mut c = numbers(4 * n, 8);
    c.iter_mut().skip(3).step_by(4).for_each(|w| *w = 1.0);
    let curve = nrb(arg(&[4, n], c), &[3]);
    let deriv = nrb(arg(&[4, n - 1], numbers(4 * (n - 1), 9)), &[2]);
    let u = row(params(10_000));
    let nout = scalar(2.0);
    let args = [curve.value(), deriv.value(), value(&u), value(&nout)];
    stops("cagd_nrbdeval", &args, 3);
}

#[test]
fn the_native_functions_stop_between_chunks() {
    let p = arg(&[2, 101], numbers(202, 10));
    let t = row(params(1000));
    stops("cagd_bezier", &[value(&p), value(&t)], 1);
    let (deg, n) = (3, 40);
    let cp = arg(&[2, n], numbers(2 * n, 11));
    let u = row(params(10_000));
    let knots = row(clamped(deg, n));
    let d = scalar(deg as f64);
    stops(
        "cagd_bspline",
        &[value(&d), value(&cp), value(&knots), value(&u)],
        1,
    );
    let w = row(numbers(n, 12).iter().map(|x| 0.5 + x).collect());
    stops(
        "cagd_nurbs",
        &[value(&d), value(&cp), value(&w), value(&knots), value(&u)],
        1,
    );
    let net = arg(&[3, 31, 31], numbers(3 * 31 * 31, 13));
    let g = row(params(200));
    stops("cagd_bezier_patch", &[value(&net), value(&g), value(&g)], 1);
    // A Coons patch of four lines, on a 400 × 400 grid.
    let line = |a: [f64; 3], b: [f64; 3]| arg(&[3, 2], vec![a[0], a[1], a[2], b[0], b[1], b[2]]);
    let (o, x, y, xy) = (
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 1.0, 1.0],
    );
    let lines = [line(o, x), line(y, xy), line(o, y), line(x, xy)];
    let g = row(params(400));
    let mut args: Vec<Value<'_>> = lines.iter().map(value).collect();
    args.extend([value(&g), value(&g)]);
    stops("cagd_coons", &args, 1);
    stops(
        "cagd_spline",
        &[value(&cp), value(&row(params(100_000)))],
        1,
    );
}
