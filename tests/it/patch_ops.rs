//! Bézier patches raised in degree, split and integrated, against an oracle that shares no code
//! with them: the patch written in the monomial basis (each `B_i^m(u)` expanded as
//! `Σ_k (−1)^(k−i) C(m,k) C(k,i) u^k`, binomials from Pascal's triangle here), evaluated by
//! powers and integrated term by term (`∫₀ᵘ s^k ds = u^(k+1)/(k+1)`), all in exact rationals.
//! Two polynomials of degree at most `(m, n)` that agree on `(m+1) × (n+1)` distinct grid
//! points are the same polynomial, so the grids below prove identities, not samples.

use cagd::bezier::{BezierPatch, Direction, Edge};
use cagd::Scalar;
use nalgebra::DMatrix;
use proptest::prelude::*;

use crate::support::{q, Q};

/// Pascal's triangle up to row `n`.
fn pascal(n: usize) -> Vec<Vec<Q>> {
    let mut rows: Vec<Vec<Q>> = vec![vec![q(1, 1)]];
    for r in 1..=n {
        let prev = &rows[r - 1];
        let row = (0..=r)
            .map(|k| {
                let left = if k > 0 { prev[k - 1].clone() } else { q(0, 1) };
                let right = prev.get(k).cloned().unwrap_or_else(|| q(0, 1));
                left + right
            })
            .collect();
        rows.push(row);
    }
    rows
}

/// The monomial coefficients of `B_i^n`: `[k] ↦ (−1)^(k−i) C(n,k) C(k,i)` for `k ≥ i`.
fn bernstein_in_powers(n: usize, i: usize, c: &[Vec<Q>]) -> Vec<Q> {
    (0..=n)
        .map(|k| {
            if k < i {
                return q(0, 1);
            }
            let sign = if (k - i) % 2 == 0 { q(1, 1) } else { q(-1, 1) };
            sign * c[n][k].clone() * c[k][i].clone()
        })
        .collect()
}

/// The patch in powers: `a[c][(k, l)]` is the coefficient of `u^k v^l` in coordinate `c`.
fn in_powers(p: &BezierPatch<Q>) -> Vec<DMatrix<Q>> {
    let (m, n) = p.degree();
    let c = pascal(m.max(n));
    let bu: Vec<Vec<Q>> = (0..=m).map(|i| bernstein_in_powers(m, i, &c)).collect();
    let bv: Vec<Vec<Q>> = (0..=n).map(|j| bernstein_in_powers(n, j, &c)).collect();
    p.coordinates()
        .iter()
        .map(|x| {
            DMatrix::from_fn(m + 1, n + 1, |k, l| {
                let mut sum = q(0, 1);
                for i in 0..=m {
                    for j in 0..=n {
                        sum += x[(i, j)].clone() * bu[i][k].clone() * bv[j][l].clone();
                    }
                }
                sum
            })
        })
        .collect()
}

fn power(x: &Q, k: usize) -> Q {
    (0..k).fold(q(1, 1), |acc, _| acc * x.clone())
}

/// `Σ_k Σ_l a[(k,l)] u^k v^l` per coordinate.
fn eval_powers(a: &[DMatrix<Q>], u: &Q, v: &Q) -> Vec<Q> {
    a.iter()
        .map(|c| {
            let mut sum = q(0, 1);
            for k in 0..c.nrows() {
                for l in 0..c.ncols() {
                    sum += c[(k, l)].clone() * power(u, k) * power(v, l);
                }
            }
            sum
        })
        .collect()
}

/// `∫₀ᵘ ∫₀ᵛ` (or only one of them) of the power form, term by term.
fn integral_powers(a: &[DMatrix<Q>], u: Option<&Q>, v: Option<&Q>, at: (&Q, &Q)) -> Vec<Q> {
    a.iter()
        .map(|c| {
            let mut sum = q(0, 1);
            for k in 0..c.nrows() {
                for l in 0..c.ncols() {
                    let fu = match u {
                        Some(u) => power(u, k + 1) / q(k as i64 + 1, 1),
                        None => power(at.0, k),
                    };
                    let fv = match v {
                        Some(v) => power(v, l + 1) / q(l as i64 + 1, 1),
                        None => power(at.1, l),
                    };
                    sum += c[(k, l)].clone() * fu * fv;
                }
            }
            sum
        })
        .collect()
}

/// `count` distinct rationals in `[0, 1]`.
fn grid(count: usize) -> Vec<Q> {
    (0..count)
        .map(|k| q(2 * k as i64 + 1, 2 * count as i64 + 1))
        .collect()
}

fn point(p: &BezierPatch<Q>, u: &Q, v: &Q) -> Vec<Q> {
    p.eval(u.clone(), v.clone()).iter().cloned().collect()
}

fn rational() -> impl Strategy<Value = Q> {
    (-30i64..=30, 1i64..=7).prop_map(|(n, d)| q(n, d))
}

fn rational_patch(max: usize) -> impl Strategy<Value = BezierPatch<Q>> {
    (0..=max, 0..=max, 1usize..=3).prop_flat_map(|(m, n, d)| {
        prop::collection::vec(rational(), d * (m + 1) * (n + 1)).prop_map(move |v| {
            let coords = v
                .chunks((m + 1) * (n + 1))
                .map(|c| DMatrix::from_row_slice(m + 1, n + 1, c))
                .collect();
            BezierPatch::new(coords).unwrap()
        })
    })
}

/// A split parameter strictly inside `(0, 1)`.
fn inner() -> impl Strategy<Value = Q> {
    (2i64..=11).prop_flat_map(|d| (1..d).prop_map(move |k| q(k, d)))
}

fn to_f64(p: &BezierPatch<Q>) -> BezierPatch<f64> {
    BezierPatch::new(
        p.coordinates()
            .iter()
            .map(|x| x.map(|e| e.to_f64()))
            .collect(),
    )
    .unwrap()
}

/// The worst difference between an `f64` net and the exact one, relative to its size.
fn net_error(ours: &BezierPatch<f64>, exact: &BezierPatch<Q>) -> f64 {
    let scale = 1.0
        + exact
            .coordinates()
            .iter()
            .flat_map(|x| x.iter())
            .fold(0.0f64, |m, x| m.max(x.to_f64().abs()));
    ours.coordinates()
        .iter()
        .zip(exact.coordinates())
        .flat_map(|(a, b)| a.iter().zip(b.iter()))
        .fold(0.0f64, |m, (a, b)| m.max((a - b.to_f64()).abs()))
        / scale
}

#[test]
fn the_power_form_oracle_reproduces_the_hyperbolic_paraboloid() {
    // (u, v, uv): the oracle itself, checked on a patch known in closed form.
    let a = in_powers(&BezierPatch::<Q>::hyperbolic_paraboloid());
    let (u, v) = (q(2, 7), q(3, 5));
    assert_eq!(
        eval_powers(&a, &u, &v),
        vec![u.clone(), v.clone(), u.clone() * v.clone()]
    );
    assert_eq!(
        integral_powers(&a, Some(&q(1, 1)), Some(&q(1, 1)), (&u, &v)),
        vec![q(1, 2), q(1, 2), q(1, 4)]
    );
}

#[test]
fn a_worked_elevation_and_split_of_a_biquadratic_patch() {
    // z = u²(1 − v) = B_2^2(u) B_0^1(v): a patch of degree (2, 1) with b_{2,0} = 1.
    let z = DMatrix::from_row_slice(3, 2, &[0, 0, 0, 0, 1, 0].map(|k| q(k, 1)));
    let p = BezierPatch::new(vec![z]).unwrap();
    // Raised to (2, 2): the v-column 0 → (1, ½, 0) in the last row.
    let e = p.elevate(0, 1).unwrap();
    assert_eq!(
        e.coordinates()[0],
        DMatrix::from_row_slice(3, 3, &[0, 0, 0, 0, 0, 0, 2, 1, 0].map(|k| q(k, 2)))
    );
    // Split at u = 1/2: the first part is z = (s/2)²(1 − v), last row ¼, ¼·0.
    let (first, second) = p.subdivide(Direction::U, q(1, 2)).unwrap();
    assert_eq!(
        first.coordinates()[0],
        DMatrix::from_row_slice(3, 2, &[0, 0, 0, 0, 1, 0].map(|k| q(k, 4)))
    );
    // The second part's first row is the curve x(½, v): ¼(1 − v).
    assert_eq!(
        second.coordinates()[0]
            .row(0)
            .iter()
            .cloned()
            .collect::<Vec<_>>(),
        vec![q(1, 4), q(0, 1)]
    );
    // ∫∫ u²(1 − v) = 1/3 · 1/2.
    assert_eq!(p.integral().unwrap()[0], q(1, 6));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Elevation keeps the polynomial: the same power form (padded with zeros), exactly.
    #[test]
    fn elevation_keeps_the_polynomial(p in rational_patch(4), r in 0usize..=3, s in 0usize..=3) {
        let (m, n) = p.degree();
        let e = p.elevate(r, s).unwrap();
        prop_assert_eq!(e.degree(), (m + r, n + s));
        let (a, b) = (in_powers(&p), in_powers(&e));
        for (x, y) in a.iter().zip(&b) {
            for k in 0..=m + r {
                for l in 0..=n + s {
                    let want = if k <= m && l <= n { x[(k, l)].clone() } else { q(0, 1) };
                    prop_assert_eq!(&y[(k, l)], &want);
                }
            }
        }
        // The corners stay; the integral is the same.
        for (i, j, k, l) in [(0, 0, 0, 0), (m, 0, m + r, 0), (0, n, 0, n + s), (m, n, m + r, n + s)] {
            prop_assert_eq!(p.control_point(i, j), e.control_point(k, l));
        }
        prop_assert_eq!(p.integral().unwrap(), e.integral().unwrap());
    }

    /// The two parts of a split are the patch at the mapped parameters, exactly, and share the
    /// curve at the split.
    #[test]
    fn subdivision_reparametrises_the_two_parts(p in rational_patch(4), t in inner(), in_u in any::<bool>()) {
        let (m, n) = p.degree();
        let dir = if in_u { Direction::U } else { Direction::V };
        let (first, second) = p.subdivide(dir, t.clone()).unwrap();
        prop_assert_eq!(first.degree(), (m, n));
        prop_assert_eq!(second.degree(), (m, n));
        let a = in_powers(&p);
        let one = q(1, 1);
        for s in grid(m.max(n) + 1) {
            for w in grid(m.max(n) + 1) {
                let (at_first, at_second) = match dir {
                    Direction::U => (
                        (t.clone() * s.clone(), w.clone()),
                        (t.clone() + (one.clone() - t.clone()) * s.clone(), w.clone()),
                    ),
                    Direction::V => (
                        (s.clone(), t.clone() * w.clone()),
                        (s.clone(), t.clone() + (one.clone() - t.clone()) * w.clone()),
                    ),
                };
                prop_assert_eq!(point(&first, &s, &w), eval_powers(&a, &at_first.0, &at_first.1));
                prop_assert_eq!(point(&second, &s, &w), eval_powers(&a, &at_second.0, &at_second.1));
            }
        }
        let (end, start) = match dir {
            Direction::U => (Edge::U1, Edge::U0),
            Direction::V => (Edge::V1, Edge::V0),
        };
        prop_assert_eq!(first.boundary(end), second.boundary(start));
        prop_assert_eq!(first.boundary(start), p.boundary(start));
        prop_assert_eq!(second.boundary(end), p.boundary(end));
    }

    /// The antiderivatives are the power form integrated term by term; their derivative is the
    /// patch; the integral over the square is the corner of the double antiderivative.
    #[test]
    fn antiderivatives_and_integral_are_the_term_by_term_integrals(p in rational_patch(3)) {
        let (m, n) = p.degree();
        let a = in_powers(&p);
        let fu = p.antiderivative(Direction::U).unwrap();
        let fv = p.antiderivative(Direction::V).unwrap();
        let fuv = fu.antiderivative(Direction::V).unwrap();
        prop_assert_eq!(fu.degree(), (m + 1, n));
        prop_assert_eq!(fv.degree(), (m, n + 1));
        prop_assert_eq!(&fv.antiderivative(Direction::U).unwrap(), &fuv);
        for u in grid(m + 2) {
            for v in grid(n + 2) {
                prop_assert_eq!(point(&fu, &u, &v), integral_powers(&a, Some(&u), None, (&u, &v)));
                prop_assert_eq!(point(&fv, &u, &v), integral_powers(&a, None, Some(&v), (&u, &v)));
                prop_assert_eq!(point(&fuv, &u, &v), integral_powers(&a, Some(&u), Some(&v), (&u, &v)));
            }
        }
        prop_assert_eq!(&fu.derivative(1, 0).unwrap(), &p);
        prop_assert_eq!(&fv.derivative(0, 1).unwrap(), &p);
        let whole = p.integral().unwrap();
        let one = q(1, 1);
        prop_assert_eq!(whole.iter().cloned().collect::<Vec<_>>(), integral_powers(&a, Some(&one), Some(&one), (&one, &one)));
        prop_assert_eq!(whole, fuv.control_point(m + 1, n + 1).unwrap());
    }

    /// In doubles the same constructions stay within rounding of the exact ones.
    #[test]
    fn doubles_follow_the_exact_constructions(p in rational_patch(5), t in inner(), r in 0usize..=3, s in 0usize..=3) {
        let f = to_f64(&p);
        let tol = 64.0 * f64::EPSILON;
        let e = f.elevate(r, s).unwrap();
        prop_assert!(net_error(&e, &p.elevate(r, s).unwrap()) <= tol);
        for dir in [Direction::U, Direction::V] {
            let (a, b) = f.subdivide(dir, t.to_f64()).unwrap();
            let (x, y) = p.subdivide(dir, Q::from_f64(t.to_f64()).unwrap()).unwrap();
            prop_assert!(net_error(&a, &x) <= tol && net_error(&b, &y) <= tol);
            let g = f.antiderivative(dir).unwrap();
            prop_assert!(net_error(&g, &p.antiderivative(dir).unwrap()) <= tol);
        }
        let (i, x) = (f.integral().unwrap(), p.integral().unwrap());
        for (a, b) in i.iter().zip(x.iter()) {
            prop_assert!((a - b.to_f64()).abs() <= tol * (1.0 + b.to_f64().abs()) * 30.0);
        }
    }
}
