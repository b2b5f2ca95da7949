//! Polynomial curves and surfaces in monomial form, exact in any scalar: the test data of the
//! Coons and Gordon tests (boundary curves, cross-boundary derivatives and networks cut from a
//! known surface).
#![allow(dead_code)]

use cagd::{Curve, Scalar};
use nalgebra::DVector;
use num_rational::BigRational;

pub type Q = BigRational;

/// `n/d` as an exact rational.
pub fn q(n: i64, d: i64) -> Q {
    <Q as Scalar>::from_ratio(n, d)
}

/// A vector of rationals from integer pairs.
pub fn qv(parts: &[(i64, i64)]) -> DVector<Q> {
    DVector::from_iterator(parts.len(), parts.iter().map(|&(n, d)| q(n, d)))
}

/// `p(t) = Σ_k coeffs[k] t^k`.
#[derive(Debug, Clone, PartialEq)]
pub struct Poly<T: Scalar> {
    pub coeffs: Vec<DVector<T>>,
}

impl<T: Scalar> Poly<T> {
    pub fn new(coeffs: Vec<DVector<T>>) -> Self {
        assert!(!coeffs.is_empty());
        Poly { coeffs }
    }

    pub fn derivative(&self) -> Poly<T> {
        let d = self.coeffs[0].len();
        if self.coeffs.len() == 1 {
            return Poly::new(vec![DVector::from_element(d, T::zero())]);
        }
        Poly::new(
            self.coeffs[1..]
                .iter()
                .enumerate()
                .map(|(k, c)| c.map(|x| x * T::from_usize(k + 1)))
                .collect(),
        )
    }
}

impl<T: Scalar> Curve<T> for Poly<T> {
    fn dim(&self) -> usize {
        self.coeffs[0].len()
    }
    /// `[0, 1]`, the domain the constructions take their curves on.
    fn domain(&self) -> (T, T) {
        (T::zero(), T::one())
    }
    fn eval(&self, t: T) -> DVector<T> {
        let mut acc = self.coeffs.last().unwrap().clone();
        for c in self.coeffs.iter().rev().skip(1) {
            acc = acc.zip_map(c, |x, y| x * t.clone() + y);
        }
        acc
    }
    /// Horner's rule: `2 · degree` operations per coordinate.
    fn point_cost(&self, param_bits: u128) -> cagd::cost::Cost {
        let n = self.coeffs.len() as u128;
        cagd::cost::Cost::new(2 * n * self.dim() as u128, n * (param_bits + 1))
    }
}

impl<T: Scalar> cagd::CurveDeriv<T> for Poly<T> {
    fn eval_derivative(&self, t: T) -> DVector<T> {
        self.derivative().eval(t)
    }
}

/// `S(u, v) = Σ_a Σ_b coeffs[a][b] u^a v^b`.
#[derive(Debug, Clone, PartialEq)]
pub struct PolySurface<T: Scalar> {
    pub coeffs: Vec<Vec<DVector<T>>>,
}

impl<T: Scalar> PolySurface<T> {
    pub fn new(coeffs: Vec<Vec<DVector<T>>>) -> Self {
        PolySurface { coeffs }
    }

    pub fn dim(&self) -> usize {
        self.coeffs[0][0].len()
    }

    fn zero(&self) -> DVector<T> {
        DVector::from_element(self.dim(), T::zero())
    }

    /// `∂^r_u ∂^s_v S`.
    pub fn partial(&self, r: usize, s: usize) -> PolySurface<T> {
        let falling = |n: usize, k: usize| (0..k).fold(1usize, |p, i| p * (n - i));
        let mut coeffs = Vec::new();
        for a in r..self.coeffs.len() {
            let mut row = Vec::new();
            for b in s..self.coeffs[a].len() {
                let f = T::from_usize(falling(a, r) * falling(b, s));
                row.push(self.coeffs[a][b].map(|x| x * f.clone()));
            }
            if row.is_empty() {
                row.push(self.zero());
            }
            coeffs.push(row);
        }
        if coeffs.is_empty() {
            coeffs.push(vec![self.zero()]);
        }
        PolySurface { coeffs }
    }

    pub fn eval(&self, u: &T, v: &T) -> DVector<T> {
        self.curve_at_u(u).eval(v.clone())
    }

    /// The curve `v ↦ S(u0, v)`.
    pub fn curve_at_u(&self, u0: &T) -> Poly<T> {
        let nb = self.coeffs.iter().map(Vec::len).max().unwrap();
        let mut out = vec![self.zero(); nb];
        let mut pow = T::one();
        for row in &self.coeffs {
            for (b, c) in row.iter().enumerate() {
                out[b] = out[b].zip_map(c, |x, y| x + y * pow.clone());
            }
            pow = pow * u0.clone();
        }
        Poly::new(out)
    }

    /// The curve `u ↦ S(u, v0)`.
    pub fn curve_at_v(&self, v0: &T) -> Poly<T> {
        Poly::new(
            self.coeffs
                .iter()
                .map(|row| {
                    let mut acc = self.zero();
                    let mut pow = T::one();
                    for c in row {
                        acc = acc.zip_map(c, |x, y| x + y * pow.clone());
                        pow = pow * v0.clone();
                    }
                    acc
                })
                .collect(),
        )
    }
}

/// A deterministic pseudo-random rational in [-k, k] with denominator 64 (for exact data).
pub fn lcg_rational(state: &mut u64, k: i64) -> Q {
    *state = state
        .wrapping_mul(6364136223846793005)
        .wrapping_add(1442695040888963407);
    let r = ((*state >> 33) % (2 * 64 * k as u64 + 1)) as i64 - 64 * k;
    q(r, 64)
}

/// A random polynomial surface of degree (p, q) in dimension d with rational coefficients.
pub fn random_surface(state: &mut u64, p: usize, qd: usize, d: usize) -> PolySurface<Q> {
    PolySurface::new(
        (0..=p)
            .map(|_| {
                (0..=qd)
                    .map(|_| DVector::from_fn(d, |_, _| lcg_rational(state, 2)))
                    .collect()
            })
            .collect(),
    )
}
