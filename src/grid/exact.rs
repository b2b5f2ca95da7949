//! Fraction-free kernels for exact rational arithmetic ([`BigRational`]).
//!
//! In `BigRational` every operation reduces its result by a gcd of numbers that grow with the
//! degree (the denominators of `t^i` at `t = k/100` reach `100^i`), and those gcds are nearly
//! all of the time of an exact evaluation. Where a whole row of values has one known
//! denominator, the numerators can be formed with integer products and the fraction built
//! already reduced, without any gcd of large numbers. Exact arithmetic gives the same values in
//! any order, so these kernels return exactly what the generic code returns; they are chosen
//! by type (a safe downcast, as the binomials' conversion to a scalar does for `f64`), and for
//! any other scalar the generic code runs.

use std::any::Any;

use num_bigint::BigInt;
use num_integer::Integer;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

use crate::scalar::Scalar;

/// Whether `T` is [`BigRational`]: exact arithmetic, where every algorithm gives the same
/// values and the one with the fewest operations on the smallest numbers is the fastest.
pub(crate) fn is_rational<T: Scalar>() -> bool {
    std::any::TypeId::of::<T>() == std::any::TypeId::of::<BigRational>()
}

/// `x` as a rational, if `T` is [`BigRational`].
fn rational<T: Scalar>(x: &T) -> Option<&BigRational> {
    (x as &dyn Any).downcast_ref::<BigRational>()
}

/// The Bernstein polynomials `B_i^n(t) = C(n, i) t^i (1 − t)^(n−i)`, `n = out.len() − 1`,
/// written into `out` if `T` is [`BigRational`] (returns `false`, writing nothing, otherwise).
///
/// With `t = a/b` in lowest terms (`b > 0`), `B_i^n(t) = C(n, i) a^i (b − a)^(n−i) / b^n`.
/// `a^i (b − a)^(n−i)` is prime to `b` (so to `b^n`), and with `g = gcd(C(n, i), b^n)` the
/// fraction `(C(n, i)/g · a^i (b − a)^(n−i)) / (b^n/g)` is in lowest terms: `n` products per
/// power, and one gcd with the small binomial per value, instead of the gcds of the
/// triangular recurrence (about `3n²/2` of them, each of numbers of up to `n` times the size
/// of `b`).
pub(crate) fn bernstein_row<T: Scalar>(t: &T, out: &mut [T]) -> bool {
    let Some(t) = rational(t) else {
        return false;
    };
    let Some(n) = out.len().checked_sub(1) else {
        return true;
    };
    let (a, b) = (t.numer(), t.denom());
    let c = b - a;
    let den = num_traits::pow(b.clone(), n);
    // a^i and (b − a)^i, i = 0..=n.
    let powers = |x: &BigInt| {
        let mut p = Vec::with_capacity(n + 1);
        p.push(BigInt::one());
        for i in 1..=n {
            let next = &p[i - 1] * x;
            p.push(next);
        }
        p
    };
    let (pa, pc) = (powers(a), powers(&c));
    let mut binomial = BigInt::one();
    for (i, o) in out.iter_mut().enumerate() {
        if i > 0 {
            // C(n, i) = C(n, i − 1) · (n − i + 1) / i, exactly.
            binomial = binomial * BigInt::from(n - i + 1) / BigInt::from(i);
        }
        let numer = &pa[i] * &pc[n - i];
        let value = if numer.is_zero() {
            BigRational::zero()
        } else {
            let g = binomial.gcd(&den);
            let (num, d) = (&binomial / &g * numer, &den / &g);
            debug_assert!(d.is_positive());
            BigRational::new_raw(num, d)
        };
        if let Some(slot) = (o as &mut dyn Any).downcast_mut::<BigRational>() {
            *slot = value;
        }
    }
    true
}

/// The points `Σ_i B_i^n(t) b_i` of a Bézier curve at the parameters `ts` (`local` maps a
/// parameter to `t`), written into `out` one after the other, if `T` is [`BigRational`]
/// (returns `false`, writing nothing, otherwise). `control` holds the `n + 1` control points
/// one after the other, `d` numbers each.
///
/// With `Q` the least common denominator of the control points (once per call), `b_i = z_i/Q`
/// with integer `z_i`, and `t = a/b` in lowest terms, each coordinate is the integer
/// `Σ_i C(n, i) a^i (b − a)^(n−i) z_i` over `b^n Q`, reduced once: `d` gcds per point instead
/// of de Casteljau's (or the Bernstein sums') hundreds. Long batches run on several threads.
pub(crate) fn bezier_points<T: Scalar>(
    control: &[T],
    d: usize,
    local: impl Fn(&T) -> T + Sync,
    ts: &[T],
    out: &mut [T],
) -> bool {
    if !is_rational::<T>() || d == 0 || control.is_empty() {
        return false;
    }
    let values: Vec<&BigRational> = control.iter().filter_map(rational).collect();
    if values.len() != control.len() {
        return false;
    }
    let n = control.len() / d - 1;
    let q = values.iter().fold(BigInt::one(), |l, x| l.lcm(x.denom()));
    let z: Vec<BigInt> = values
        .iter()
        .map(|x| x.numer() * (&q / x.denom()))
        .collect();
    let mut binomials = vec![BigInt::one(); n + 1];
    for i in 1..=n {
        binomials[i] = &binomials[i - 1] * BigInt::from(n - i + 1) / BigInt::from(i);
    }
    let block = 64;
    let work = ts.len().saturating_mul((n + 1) * (d + 4) * 64);
    // Exact numbers are always finite: the scan for overflow has nothing to find.
    let _ = crate::grid::for_each_row(
        "exact Bézier points",
        out,
        block * d,
        work,
        || (),
        |_, r, chunk| {
            for (u, x) in ts[r * block..].iter().zip(chunk.chunks_exact_mut(d)) {
                let t = local(u);
                let Some(t) = rational(&t) else {
                    continue;
                };
                let (a, b) = (t.numer(), t.denom());
                let c = b - a;
                let mut pc = Vec::with_capacity(n + 1);
                pc.push(BigInt::one());
                for i in 1..=n {
                    let next = &pc[i - 1] * &c;
                    pc.push(next);
                }
                // w_i = C(n, i) a^i (b − a)^(n−i), a^i built up along i.
                let mut pa = BigInt::one();
                let mut sums = vec![BigInt::zero(); d];
                for i in 0..=n {
                    if i > 0 {
                        pa *= a;
                    }
                    let w = &binomials[i] * &pa * &pc[n - i];
                    for (s, zk) in sums.iter_mut().zip(&z[i * d..(i + 1) * d]) {
                        *s += &w * zk;
                    }
                }
                let den = num_traits::pow(b.clone(), n) * &q;
                for (o, s) in x.iter_mut().zip(sums) {
                    if let Some(slot) = (o as &mut dyn Any).downcast_mut::<BigRational>() {
                        *slot = BigRational::new(s, den.clone());
                    }
                }
            }
        },
    );
    true
}

/// `Σ_i w_i x_i` over the pairs of `terms`, if `T` is [`BigRational`] (`None` otherwise):
/// every product `w_i x_i` brought to the least common denominator `L` of all of them (one
/// lcm per term), the numerators summed as integers, the sum reduced once. About `m + 1`
/// gcds for `m` terms, where `m` products and sums in rationals take about `5m`.
pub(crate) fn dot<'a, T: Scalar + 'a>(terms: impl Iterator<Item = (&'a T, &'a T)>) -> Option<T> {
    if !is_rational::<T>() {
        return None;
    }
    let mut parts: Vec<(BigInt, BigInt)> = Vec::new();
    let mut l = BigInt::one();
    for (w, x) in terms {
        let (w, x) = (rational(w)?, rational(x)?);
        if w.is_zero() || x.is_zero() {
            continue;
        }
        let den = w.denom() * x.denom();
        l = l.lcm(&den);
        parts.push((w.numer() * x.numer(), den));
    }
    let mut sum = BigInt::zero();
    for (num, den) in parts {
        sum += num * (&l / den);
    }
    let value = BigRational::new(sum, l);
    let boxed: Box<dyn Any> = Box::new(value);
    boxed.downcast::<T>().ok().map(|x| *x)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dots_equal_the_sums_of_products() {
        let q = |n: i64, d: i64| <BigRational as Scalar>::from_ratio(n, d);
        let w = [q(1, 3), q(-2, 7), q(0, 1), q(5, 12), q(9, 1)];
        let x = [q(3, 4), q(1, 6), q(2, 5), q(-7, 10), q(0, 1)];
        let naive = w.iter().zip(&x).fold(q(0, 1), |s, (a, b)| s + a * b);
        assert_eq!(dot(w.iter().zip(&x)), Some(naive));
        assert_eq!(dot(w[..0].iter().zip(&x)), Some(q(0, 1)));
        assert_eq!(dot([0.5].iter().zip(&[2.0])), None);
    }

    /// De Casteljau in rationals on the control points (`d` numbers each) at `t`.
    fn de_casteljau(control: &[BigRational], d: usize, t: &BigRational) -> Vec<BigRational> {
        let mut work = control.to_vec();
        let n = control.len() / d - 1;
        let s = BigRational::one() - t;
        for r in 1..=n {
            for i in 0..=n - r {
                for k in 0..d {
                    work[i * d + k] = &s * &work[i * d + k] + t * &work[(i + 1) * d + k];
                }
            }
        }
        work.truncate(d);
        work
    }

    #[test]
    fn bezier_points_equal_de_casteljau() {
        let q = |n: i64, d: i64| <BigRational as Scalar>::from_ratio(n, d);
        // A cubic in 2-D with fractional control points, on the interval [−1/2, 3].
        let control: Vec<BigRational> = [
            (1, 3),
            (-2, 1),
            (5, 7),
            (0, 1),
            (3, 2),
            (1, 5),
            (-4, 9),
            (2, 1),
        ]
        .iter()
        .map(|&(n, d)| q(n, d))
        .collect();
        let (a, b) = (q(-1, 2), q(3, 1));
        let local = |u: &BigRational| (u - &a) / (&b - &a);
        let ts = [q(-1, 2), q(0, 1), q(1, 3), q(37, 100), q(3, 1), q(5, 1)];
        let mut out = vec![BigRational::zero(); ts.len() * 2];
        assert!(bezier_points(&control, 2, local, &ts, &mut out));
        for (t, x) in ts.iter().zip(out.chunks_exact(2)) {
            assert_eq!(x, de_casteljau(&control, 2, &local(t)), "t = {t}");
        }
    }

    #[test]
    fn bernstein_rows_equal_the_products_and_are_reduced() {
        let q = |n: i64, d: i64| <BigRational as Scalar>::from_ratio(n, d);
        for (k, d) in [(0, 1), (1, 1), (1, 3), (37, 100), (-2, 7), (9, 4), (5, 10)] {
            let t = <BigRational as Scalar>::from_ratio(k, d);
            for n in [0, 1, 2, 5, 20] {
                let mut fast = vec![BigRational::zero(); n + 1];
                assert!(bernstein_row(&t, &mut fast));
                // C(n, i) t^i (1 − t)^(n−i) in rationals, for comparison.
                let s = BigRational::one() - &t;
                let mut c = BigRational::one();
                for (i, x) in fast.iter().enumerate() {
                    if i > 0 {
                        c *= q((n - i + 1) as i64, i as i64);
                    }
                    let slow =
                        &c * num_traits::pow(t.clone(), i) * num_traits::pow(s.clone(), n - i);
                    assert_eq!(*x, slow, "t = {t}, n = {n}, i = {i}");
                }
                for x in &fast {
                    assert!(x.denom().is_positive());
                    assert!(x.numer().gcd(x.denom()).is_one(), "{x} not reduced");
                }
            }
        }
        let mut f = [0.0; 3];
        assert!(!bernstein_row(&0.5, &mut f));
        assert!(!bezier_points(&[0.0, 1.0], 1, |u| *u, &[0.5], &mut f[..1]));
        assert_eq!(f, [0.0; 3]);
    }
}
