//! Live differential test: random cases of every appendix function, run through the fixed
//! Octave code in ONE live GNU Octave process and through the Rust twins of
//! `cagd_octave::compat`, compared value by value.
//!
//! ```sh
//! cargo test -p cagd-octave --test it differential -- --nocapture                       # default: 1200 cases
//! CAGD_DIFF_CASES=5000 CAGD_DIFF_SEED=7 cargo test -p cagd-octave --test it differential -- --nocapture
//! CAGD_DIFF_SEED=random cargo test -p cagd-octave --test it differential -- --nocapture  # a fresh seed (printed)
//! ```
//!
//! The cases (random degrees, dimensions, sample counts, parameters, coordinate scales from
//! 1e-3 to 1e3, Coons boundaries with compatible corners, Gordon networks cut from random
//! polynomial surfaces with separate node vectors) are written with the crate's text-format
//! writer into one input file; `octave_ref/differential.m` loads it, runs every case through
//! `octave_ref/fixed/`, and saves every output with `save -text`, which the crate's reader
//! reads back. Every output must agree within 4 ULPs or 1e-14 relative to the array's scale
//! (`tests/common`); `linspace` and `tenzor` must agree bit for bit. The report gives the number
//! of cases per function, the worst error, and the time. A failure names the case, its
//! function and the seed, so it can be replayed.
//!
//! Without Octave the test prints `skipped: octave not found` and passes, unless `CI` is set.

use cagd_test_support as common;

use std::collections::BTreeMap;
use std::time::Instant;

use cagd_octave::compat;
use cagd_octave::text_format::{read_text_file, write_text_file, Value, Workspace};
use common::{assert_close, assert_identical, octave_available, ErrorStats, TempDir};
use ndarray::{Array2, ArrayD};

/// Default number of cases (at least 1000 per run).
const DEFAULT_CASES: usize = 1200;
/// Default seed: runs are reproducible unless `CAGD_DIFF_SEED` says otherwise.
const DEFAULT_SEED: u64 = 2014;

/// SplitMix64: a small, well-mixed generator, so the test needs no extra dependency.
struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }

    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }

    /// Uniform integer in `lo..=hi`.
    fn int(&mut self, lo: usize, hi: usize) -> usize {
        lo + (self.next_u64() % (hi - lo + 1) as u64) as usize
    }

    fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }

    /// A coordinate scale between 1e-3 and 1e3.
    fn scale(&mut self) -> f64 {
        10f64.powf(self.range(-3.0, 3.0))
    }

    /// A `rows × cols` matrix uniform in `[-s, s]`.
    fn matrix(&mut self, rows: usize, cols: usize, s: f64) -> Array2<f64> {
        Array2::from_shape_simple_fn((rows, cols), || self.range(-s, s))
    }

    /// A parameter: mostly in [0, 1], sometimes outside (extrapolation), sometimes an end.
    fn param(&mut self) -> f64 {
        match self.int(0, 9) {
            0 => 0.0,
            1 => 1.0,
            2 => self.range(-0.5, 1.5),
            _ => self.unit(),
        }
    }
}

/// One random case: the Octave function, its named arguments, and the twin's outputs.
struct Case {
    function: &'static str,
    args: Vec<(&'static str, Value)>,
    /// Outputs compared bit for bit (linspace, tenzor) rather than within the tolerance.
    exact: bool,
    ours: Vec<(&'static str, ArrayD<f64>)>,
}

fn scalar(x: f64) -> Value {
    Value::Scalar(x)
}

fn de_casteljau_case(rng: &mut Rng) -> Case {
    let d = rng.int(1, 4);
    let n = rng.int(0, 12);
    let samples = if rng.chance(0.05) { 0 } else { rng.int(1, 25) };
    let s = rng.scale();
    let p = rng.matrix(d, n + 1, s);
    let t = compat::de_casteljau(p.view(), samples).expect("de_casteljau");
    Case {
        function: "deCasteljau",
        args: vec![("P", p.into()), ("N", scalar(samples as f64))],
        exact: false,
        ours: vec![("T", t.into_dyn())],
    }
}

/// A packed `(m+1) × 3(n+1)` net.
fn packed_net(rng: &mut Rng, max_degree: usize) -> Array2<f64> {
    let m = rng.int(0, max_degree);
    let n = rng.int(0, max_degree);
    let s = rng.scale();
    rng.matrix(m + 1, 3 * (n + 1), s)
}

fn ploskev_b_case(rng: &mut Rng) -> Case {
    let b = packed_net(rng, 4);
    let samples = rng.int(1, 6);
    let p = compat::ploskev_b(b.view(), samples).expect("ploskev_b");
    Case {
        function: "ploskevB",
        args: vec![("B", b.into()), ("N", scalar(samples as f64))],
        exact: false,
        ours: vec![("P", p.into_dyn())],
    }
}

fn bilinearna_case(rng: &mut Rng) -> Case {
    let b = packed_net(rng, 6);
    let (u, v) = (rng.param(), rng.param());
    let samples = rng.int(1, 10);
    let l = compat::bilinearna(b.view(), u, v, samples).expect("bilinearna");
    Case {
        function: "bilinearna",
        args: vec![
            ("B", b.into()),
            ("u", scalar(u)),
            ("v", scalar(v)),
            ("N", scalar(samples as f64)),
        ],
        exact: false,
        ours: vec![("L", l.into_dyn())],
    }
}

fn tenzor_case(rng: &mut Rng) -> Case {
    let b = packed_net(rng, 7);
    let a = compat::tenzor(b.view()).expect("tenzor");
    Case {
        function: "tenzor",
        args: vec![("B", b.into())],
        exact: true,
        ours: vec![("A", a.into_dyn())],
    }
}

fn linspace_case(rng: &mut Rng) -> Case {
    let s = rng.scale();
    let a = rng.range(-s, s);
    let b = if rng.chance(0.1) {
        -a
    } else {
        rng.range(-s, s)
    };
    let n = rng.int(0, 120);
    let y = compat::linspace(a, b, n).expect("linspace");
    Case {
        function: "linspace",
        args: vec![("a", scalar(a)), ("b", scalar(b)), ("N", scalar(n as f64))],
        exact: true,
        ours: vec![("y", y.into_dyn())],
    }
}

fn lagrange_case(rng: &mut Rng) -> Case {
    let k = rng.int(1, 8);
    // Distinct nodes in any order, as a row or a column.
    let mut nodes: Vec<f64> = Vec::new();
    while nodes.len() < k {
        let x = rng.range(-1.0, 2.0);
        if nodes.iter().all(|y| (x - y).abs() > 0.05) {
            nodes.push(x);
        }
    }
    let x = if rng.chance(0.5) {
        Array2::from_shape_vec((1, k), nodes.clone()).unwrap()
    } else {
        Array2::from_shape_vec((k, 1), nodes.clone()).unwrap()
    };
    let m = rng.int(1, k);
    let (r, c) = (rng.int(1, 4), rng.int(1, 6));
    let u = Array2::from_shape_simple_fn((r, c), || {
        if rng.chance(0.1) {
            nodes[rng.int(0, k - 1)]
        } else {
            rng.range(-0.5, 1.5)
        }
    });
    let v = compat::lagrange(x.view(), m, u.view()).expect("lagrange");
    Case {
        function: "Lagrange",
        args: vec![("x", x.into()), ("m", scalar(m as f64)), ("u", u.into())],
        exact: false,
        ours: vec![("v", v.into_dyn())],
    }
}

/// Random Coons boundary data with compatible corners, as in `octave_ref/cases/coons_random.m`:
/// corners `P1..P4` and, per curve, coefficients `A`, `B` of
/// `c(s) = (1−s) Pa + s Pb + s(1−s)(A + B s)`, which is exactly `Pa` at 0 and `Pb` at 1.
struct CoonsData {
    corners: [Vec<f64>; 4],
    a: [Vec<f64>; 4],
    b: [Vec<f64>; 4],
}

/// Curve `k` (c1, c2, d1, d2) runs from corner `ENDS[k].0` to corner `ENDS[k].1`.
const ENDS: [(usize, usize); 4] = [(0, 1), (2, 3), (0, 2), (1, 3)];

impl CoonsData {
    fn random(rng: &mut Rng, d: usize) -> Self {
        let s = rng.scale();
        let mut vecs = |scale: f64| -> [Vec<f64>; 4] {
            std::array::from_fn(|_| (0..d).map(|_| rng.range(-scale, scale)).collect())
        };
        CoonsData {
            corners: vecs(s),
            a: vecs(s),
            b: vecs(s),
        }
    }

    fn curve(&self, k: usize, t: f64) -> Array2<f64> {
        let (pa, pb) = (&self.corners[ENDS[k].0], &self.corners[ENDS[k].1]);
        Array2::from_shape_fn((pa.len(), 1), |(c, _)| {
            (1.0 - t) * pa[c] + t * pb[c] + (t * (1.0 - t)) * (self.a[k][c] + self.b[k][c] * t)
        })
    }

    fn sampled(&self, k: usize, t: &[f64]) -> Array2<f64> {
        let d = self.corners[0].len();
        Array2::from_shape_fn((d, t.len()), |(c, j)| self.curve(k, t[j])[[c, 0]])
    }

    fn corner(&self, k: usize) -> Array2<f64> {
        Array2::from_shape_vec((self.corners[k].len(), 1), self.corners[k].clone()).unwrap()
    }
}

fn vrednost_coons_case(rng: &mut Rng) -> Case {
    let d = rng.int(1, 4);
    let data = CoonsData::random(rng, d);
    let (u, v) = (rng.param(), rng.param());
    let vals = [
        data.curve(0, u),
        data.curve(1, u),
        data.curve(2, v),
        data.curve(3, v),
    ];
    let p = [0, 1, 2, 3].map(|k| data.corner(k));
    let r = compat::vrednost_coons(
        u,
        v,
        vals[0].view(),
        vals[1].view(),
        vals[2].view(),
        vals[3].view(),
        p[0].view(),
        p[1].view(),
        p[2].view(),
        p[3].view(),
    )
    .expect("vrednost_coons");
    let [c1, c2, d1, d2] = vals;
    let [p1, p2, p3, p4] = p;
    Case {
        function: "vrednostCoons",
        args: vec![
            ("u", scalar(u)),
            ("v", scalar(v)),
            ("c1", c1.into()),
            ("c2", c2.into()),
            ("d1", d1.into()),
            ("d2", d2.into()),
            ("P1", p1.into()),
            ("P2", p2.into()),
            ("P3", p3.into()),
            ("P4", p4.into()),
        ],
        exact: false,
        ours: vec![
            ("T", r.t.into_dyn()),
            ("rc", r.rc.into_dyn()),
            ("rd", r.rd.into_dyn()),
            ("rcd", r.rcd.into_dyn()),
        ],
    }
}

fn krpa_coons_case(rng: &mut Rng) -> Case {
    let data = CoonsData::random(rng, 3);
    let n = rng.int(2, 15);
    let t = cagd::linspace(0.0, 1.0, n);
    let c = [0, 1, 2, 3].map(|k| data.sampled(k, &t));
    let p = [0, 1, 2, 3].map(|k| data.corner(k));
    let s = compat::krpa_coons(
        c[0].view(),
        c[1].view(),
        c[2].view(),
        c[3].view(),
        p[0].view(),
        p[1].view(),
        p[2].view(),
        p[3].view(),
    )
    .expect("krpa_coons");
    let [c1, c2, d1, d2] = c;
    let [p1, p2, p3, p4] = p;
    Case {
        function: "krpaCoons",
        args: vec![
            ("c1", c1.into()),
            ("c2", c2.into()),
            ("d1", d1.into()),
            ("d2", d2.into()),
            ("P1", p1.into()),
            ("P2", p2.into()),
            ("P3", p3.into()),
            ("P4", p4.into()),
        ],
        exact: false,
        ours: vec![("R", s.r.into_dyn()), ("P", s.p.into_dyn())],
    }
}

/// `count` increasing nodes in about [0, 1], well apart (each within a quarter of the spacing
/// of the equispaced position; the ends kept at 0 and 1 half of the time), so that the Lagrange
/// blending stays well conditioned.
fn spread_nodes(rng: &mut Rng, count: usize) -> Vec<f64> {
    let h = 1.0 / (count - 1) as f64;
    let keep_ends = rng.chance(0.5);
    (0..count)
        .map(|i| {
            let x = i as f64 * h;
            if keep_ends && (i == 0 || i == count - 1) {
                x
            } else {
                x + rng.range(-0.25, 0.25) * h
            }
        })
        .collect()
}

fn krpa_gordon_case(rng: &mut Rng) -> Case {
    let (mu, nv) = (rng.int(2, 5), rng.int(2, 5));
    let n = rng.int(2, 10);
    let (xu, xv) = (spread_nodes(rng, mu), spread_nodes(rng, nv));
    // A random polynomial surface S(u, v) = Σ C_ab u^a v^b of degree ≤ (4, 3); the network is
    // cut from it (so it is compatible by construction).
    let (da, db) = (rng.int(0, 4), rng.int(0, 3));
    let s = rng.scale();
    let coef: Vec<[f64; 3]> = (0..(da + 1) * (db + 1))
        .map(|_| [rng.range(-s, s), rng.range(-s, s), rng.range(-s, s)])
        .collect();
    let surface = |u: f64, v: f64| -> [f64; 3] {
        let mut out = [0.0; 3];
        for a in 0..=da {
            for b in 0..=db {
                let w = u.powi(a as i32) * v.powi(b as i32);
                for (o, c) in out.iter_mut().zip(coef[a * (db + 1) + b]) {
                    *o += c * w;
                }
            }
        }
        out
    };
    let t = cagd::linspace(0.0, 1.0, n);
    let g_u = Array2::from_shape_fn((3, nv * n), |(c, k)| surface(t[k % n], xv[k / n])[c]);
    let g_v = Array2::from_shape_fn((3, mu * n), |(c, k)| surface(xu[k / n], t[k % n])[c]);
    let g_uv = Array2::from_shape_fn((mu, 3 * nv), |(i, k)| surface(xu[i], xv[k / 3])[k % 3]);
    let x_u = Array2::from_shape_vec((1, mu), xu).unwrap();
    let x_v = Array2::from_shape_vec((1, nv), xv).unwrap();
    let g = compat::krpa_gordon(
        g_u.view(),
        g_v.view(),
        g_uv.view(),
        x_u.view(),
        x_v.view(),
        n,
    )
    .expect("krpa_gordon");
    Case {
        function: "krpaGordon",
        args: vec![
            ("g_u", g_u.into()),
            ("g_v", g_v.into()),
            ("g_uv", g_uv.into()),
            ("x_u", x_u.into()),
            ("x_v", x_v.into()),
            ("N", scalar(n as f64)),
        ],
        exact: false,
        ours: vec![("R", g.r.into_dyn()), ("P", g.p.into_dyn())],
    }
}

/// Case generators with their relative weights (cheap Octave calls more often).
type Generator = fn(&mut Rng) -> Case;
const GENERATORS: &[(Generator, usize)] = &[
    (de_casteljau_case, 20),
    (ploskev_b_case, 8),
    (bilinearna_case, 15),
    (tenzor_case, 10),
    (linspace_case, 10),
    (lagrange_case, 15),
    (vrednost_coons_case, 10),
    (krpa_coons_case, 7),
    (krpa_gordon_case, 5),
];

fn generate(count: usize, seed: u64) -> Vec<Case> {
    let mut rng = Rng(seed);
    let total: usize = GENERATORS.iter().map(|(_, w)| w).sum();
    // Every function at least once, then by weight.
    let mut cases: Vec<Case> = GENERATORS.iter().map(|(g, _)| g(&mut rng)).collect();
    while cases.len() < count {
        let mut pick = rng.int(0, total - 1);
        for (g, w) in GENERATORS {
            if pick < *w {
                cases.push(g(&mut rng));
                break;
            }
            pick -= w;
        }
    }
    cases
}

fn settings() -> (usize, u64) {
    let count = match std::env::var("CAGD_DIFF_CASES") {
        Ok(s) => s
            .parse()
            .unwrap_or_else(|_| panic!("CAGD_DIFF_CASES={s:?}: expected a number of cases")),
        Err(_) => DEFAULT_CASES,
    };
    let seed = match std::env::var("CAGD_DIFF_SEED") {
        Ok(s) if s == "random" => std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map(|d| d.as_nanos() as u64)
            .unwrap_or(DEFAULT_SEED),
        Ok(s) => s
            .parse()
            .unwrap_or_else(|_| panic!("CAGD_DIFF_SEED={s:?}: expected a number or `random`")),
        Err(_) => DEFAULT_SEED,
    };
    (count, seed)
}

#[test]
fn twins_agree_with_live_octave_on_random_cases() {
    if !octave_available("twins_agree_with_live_octave_on_random_cases") {
        return;
    }
    let (count, seed) = settings();
    let start = Instant::now();
    let cases = generate(count, seed);

    let mut input = Workspace::new();
    input.insert("count", cases.len() as f64);
    for (k, case) in cases.iter().enumerate() {
        let p = format!("c{}_", k + 1);
        input.insert(format!("{p}fn"), case.function);
        for (name, value) in &case.args {
            input.insert(format!("{p}{name}"), value.clone());
        }
    }
    let dir = TempDir::new("differential");
    write_text_file(dir.path().join("in.txt"), &input).expect("write the input file");
    let generated = start.elapsed();

    let fixed = common::octave_ref_dir().join("fixed");
    let script = format!(
        "addpath('{}'); addpath('{}');\ndifferential('in.txt', 'out.txt');\ndisp('DONE');\n",
        fixed.display(),
        common::octave_ref_dir().display()
    );
    let octave_start = Instant::now();
    let stdout = common::run_octave(dir.path(), "run_differential", &script);
    assert!(
        stdout.contains(&format!("differential: OK, {} case(s)", cases.len())),
        "Octave did not run every case (seed {seed}):\n{stdout}"
    );
    let octave_time = octave_start.elapsed();
    let output = read_text_file(dir.path().join("out.txt")).expect("read Octave's output");

    let mut stats = ErrorStats::default();
    let mut per_function: BTreeMap<&str, (usize, ErrorStats)> = BTreeMap::new();
    for (k, case) in cases.iter().enumerate() {
        let entry = per_function.entry(case.function).or_default();
        entry.0 += 1;
        for (name, ours) in &case.ours {
            let var = format!("c{}_{name}", k + 1);
            let label = format!(
                "case {} ({}, output {name}; replay with CAGD_DIFF_SEED={seed} \
                 CAGD_DIFF_CASES={count})",
                k + 1,
                case.function
            );
            let octave = output
                .array(&var)
                .unwrap_or_else(|e| panic!("{label}: {e}"));
            // Octave drops trailing singleton dimensions: compare as the twin's shape.
            let octave = if octave.shape() != ours.shape() && octave.len() == ours.len() {
                let shape = ours.shape().to_vec();
                octave
                    .into_shape_with_order(shape)
                    .unwrap_or_else(|e| panic!("{label}: {e}"))
            } else {
                octave
            };
            if case.exact {
                assert_identical(&label, ours, &octave);
                entry.1.compared += ours.len();
                stats.compared += ours.len();
            } else {
                let s = assert_close(&label, ours, &octave);
                entry.1.merge(&s);
                stats.merge(&s);
            }
        }
    }
    let total = start.elapsed();
    eprintln!(
        "[differential] {} random case(s), seed {seed}: generated in {:.2?}, Octave {:.2?}, \
         total {:.2?}",
        cases.len(),
        generated,
        octave_time,
        total
    );
    for (f, (n, s)) in &per_function {
        eprintln!("[differential]   {f:<14} {n:>5} case(s); {s}");
    }
    eprintln!("[differential] worst over all: {stats}");
    assert!(cases.len() >= count);
}

/// The generator is deterministic for a seed, and covers every function.
#[test]
fn generator_is_reproducible_and_complete() {
    let a = generate(200, 99);
    let b = generate(200, 99);
    assert_eq!(a.len(), 200);
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(x.function, y.function);
        assert_eq!(x.args, y.args);
    }
    for (g, _) in GENERATORS {
        let f = g(&mut Rng(1)).function;
        assert!(a.iter().any(|c| c.function == f), "{f} never generated");
    }
}
