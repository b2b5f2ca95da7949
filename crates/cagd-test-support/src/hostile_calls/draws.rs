//! Where the arguments come from, and the kinds of argument drawn: ordinary values, values at
//! the ends of the `f64` range (±1.7·10³⁰⁸, 5·10⁻³²⁴), NaN, ±∞ and any 64 bits; increasing
//! sequences that are ordinary, equally spaced, a few subnormals apart, spread over the whole
//! range of doubles or one ULP apart; sizes up to `usize::MAX`.

use std::cell::Cell;

use nalgebra::{DMatrix, DVector};

/// Where the arguments come from: a seeded 64-bit LCG (the property test), or the bytes of a
/// fuzzer's input, read front to back and continued by the LCG when they run out (the `library`
/// fuzz target, so that every byte the fuzzer mutates changes one choice or one value).
/// Behind a shared reference, so that arguments can be drawn inside the argument lists of other
/// draws.
pub struct Draws<'a> {
    bytes: Cell<&'a [u8]>,
    state: Cell<u64>,
}

impl<'a> Draws<'a> {
    /// Draws from the LCG seeded with `seed`.
    pub fn seeded(seed: u64) -> Self {
        Draws {
            bytes: Cell::new(&[]),
            state: Cell::new(seed | 1),
        }
    }

    /// Draws from `bytes`, then from an LCG.
    pub fn from_bytes(bytes: &'a [u8]) -> Self {
        Draws {
            bytes: Cell::new(bytes),
            state: Cell::new(1),
        }
    }

    fn lcg(&self) -> u64 {
        let x = self
            .state
            .get()
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.state.set(x);
        x
    }

    /// Up to `n` bytes of the input as a little-endian number, or none left.
    fn take(&self, n: usize) -> Option<u64> {
        let bytes = self.bytes.get();
        if bytes.is_empty() {
            return None;
        }
        let (head, rest) = bytes.split_at(n.min(bytes.len()));
        self.bytes.set(rest);
        Some(
            head.iter()
                .rev()
                .fold(0u64, |acc, &b| (acc << 8) | u64::from(b)),
        )
    }

    /// 64 arbitrary bits.
    pub fn bits(&self) -> u64 {
        self.take(8).unwrap_or_else(|| self.lcg())
    }

    /// A number in `[0, 1)`.
    pub fn unit(&self) -> f64 {
        (self.bits() >> 11) as f64 / (1u64 << 53) as f64
    }

    /// A number in `[-1, 1)`.
    pub fn signed(&self) -> f64 {
        2.0 * self.unit() - 1.0
    }

    /// A choice among `n ≥ 1` (one byte of the input, for `n ≤ 256`).
    pub fn below(&self, n: usize) -> usize {
        match self.take(if n <= 256 { 1 } else { 8 }) {
            Some(b) => (b % n as u64) as usize,
            None => {
                ((((self.lcg() >> 11) as f64 / (1u64 << 53) as f64) * n as f64) as usize).min(n - 1)
            }
        }
    }

    /// One of `items`.
    pub fn pick<T: Clone>(&self, items: &[T]) -> T {
        items[self.below(items.len())].clone()
    }
}

/// Magnitudes at the ends of the range of doubles, and ordinary ones.
pub const EXTREMES: [f64; 12] = [
    f64::MAX,
    -f64::MAX,
    1.7e308,
    -1.5e308,
    1e308,
    1e154,
    2.2e-308,
    1e-320,
    5e-324,
    -5e-324,
    0.0,
    1.0,
];

/// A value for an argument: ordinary, tiny, huge, non-finite, or any 64 bits.
pub fn value(rng: &Draws) -> f64 {
    match rng.below(16) {
        0 => f64::NAN,
        1 => f64::INFINITY,
        2 => f64::NEG_INFINITY,
        3 | 4 => f64::from_bits(rng.bits()),
        5..=7 => rng.pick(&EXTREMES),
        _ => 10.0 * rng.signed(),
    }
}

/// A finite value: ordinary, or at the ends of the range of doubles.
pub fn finite(rng: &Draws) -> f64 {
    match rng.below(8) {
        0..=2 => rng.pick(&EXTREMES),
        3 => {
            let x = f64::from_bits(rng.bits());
            if x.is_finite() {
                x
            } else {
                0.5
            }
        }
        _ => 10.0 * rng.signed(),
    }
}

/// A value that is finite most of the time.
pub fn mostly_finite(rng: &Draws) -> f64 {
    if rng.below(12) == 0 {
        value(rng)
    } else {
        finite(rng)
    }
}

/// A size or index: mostly small, sometimes at or near `usize::MAX`, or just above every
/// default limit (10⁷ + 1: more samples, a higher degree, more grid points than
/// `Limits::DEFAULT` allows). Sizes between are left out on purpose: what the limits allow
/// there runs for seconds in a test build, which is the caller's to pay for, not a finding.
pub fn size(rng: &Draws) -> usize {
    match rng.below(12) {
        0 => usize::MAX,
        1 => usize::MAX / 2 + 1,
        2 => 1 << 40,
        3 => 10_000_001,
        _ => rng.below(6),
    }
}

/// A degree for data drawn for degree `p` (knots, control points): `p` mostly, sometimes any
/// [`size`] (up to `usize::MAX`: `p + 1` and `2p + 2` overflow).
pub fn degree(rng: &Draws, p: usize) -> usize {
    if rng.below(6) == 0 {
        size(rng)
    } else {
        p
    }
}

/// A size the callee allocates: small, or one no machine can hold (`usize::MAX`, 2⁴⁰, …),
/// which must be refused before anything is allocated (sizes in between are allowed and
/// merely slow).
pub fn memory(rng: &Draws) -> usize {
    match rng.below(10) {
        0 => usize::MAX,
        1 => usize::MAX / 2 + 1,
        2 => 1 << 40,
        _ => rng.below(6),
    }
}

/// A small size, for arguments that are allocated by the test itself.
pub fn small(rng: &Draws) -> usize {
    rng.below(6)
}

/// A count of nodes or curves: small, or 1001 (the equally spaced nodes whose Lagrange weights
/// leave the range of doubles).
pub fn count(rng: &Draws) -> usize {
    match rng.below(16) {
        0 => 1001,
        1 => 60,
        _ => rng.below(7),
    }
}

/// `n` values drawn by [`value`].
pub fn values(rng: &Draws, n: usize) -> Vec<f64> {
    (0..n).map(|_| value(rng)).collect()
}

/// `n` values drawn by [`mostly_finite`].
pub fn finites(rng: &Draws, n: usize) -> Vec<f64> {
    (0..n).map(|_| mostly_finite(rng)).collect()
}

/// A vector of `n` [`mostly_finite`] values.
pub fn vector(rng: &Draws, n: usize) -> DVector<f64> {
    DVector::from_vec(finites(rng, n))
}

/// A `rows × cols` matrix: entries drawn one by one, or all of one extreme magnitude with
/// alternating signs (control points ±1.7·10³⁰⁸), or ordinary numbers.
pub fn matrix(rng: &Draws, rows: usize, cols: usize) -> DMatrix<f64> {
    match rng.below(4) {
        0 => {
            let x = rng.pick(&EXTREMES);
            DMatrix::from_fn(rows, cols, |i, j| if (i + j) % 2 == 0 { x } else { -x })
        }
        1 => DMatrix::from_fn(rows, cols, |_, _| 10.0 * rng.signed()),
        _ => DMatrix::from_fn(rows, cols, |_, _| mostly_finite(rng)),
    }
}

/// `n` increasing values: ordinary, equally spaced on `[0, 1]`, a few subnormals apart
/// (`0, 5e-324, 1e-323, …`), spread from −10³⁰⁸ to 10³⁰⁸, one ULP apart, or unsorted with
/// repeats and non-finite values.
pub fn ordered(rng: &Draws, n: usize) -> Vec<f64> {
    let last = n.saturating_sub(1).max(1) as f64;
    match rng.below(7) {
        0 => (0..n).map(|k| k as f64 / last).collect(),
        1 => (0..n)
            .map(|k| f64::from_bits(k as u64 * (1 + rng.below(3) as u64)))
            .collect(),
        2 => (0..n)
            .map(|k| -1e308 + 1e308 * (2.0 * k as f64 / last))
            .map(|x| x.clamp(-1e308, 1e308))
            .collect(),
        3 => {
            let mut x = 10.0 * rng.signed();
            (0..n)
                .map(|_| {
                    let y = x;
                    x = f64::from_bits(x.to_bits().wrapping_add(if x >= 0.0 {
                        1
                    } else {
                        u64::MAX
                    }));
                    y
                })
                .collect()
        }
        4 => values(rng, n),
        _ => {
            let mut v = finites(rng, n);
            v.sort_by(f64::total_cmp);
            v.dedup();
            v
        }
    }
}

/// A knot vector of `n` knots: [`ordered`] values with their ends repeated (clamped), subnormal
/// interior knots (`[0 0 0 5e-324 1e-320 …]`), or anything.
pub fn knots(rng: &Draws, n: usize) -> Vec<f64> {
    match rng.below(5) {
        0 if n >= 2 => {
            let p = 1 + rng.below(3);
            let inner = ordered(rng, n.saturating_sub(2 * p).max(2));
            let (a, b) = (inner[0], inner[inner.len() - 1]);
            let mut k = vec![a; p];
            k.extend(inner);
            k.extend(std::iter::repeat_n(b, p));
            k.truncate(n);
            k
        }
        1 => {
            let mut k = vec![0.0; 3];
            k.extend([5e-324, 1e-320, 1e-310, 1.0, 1.0, 1.0]);
            k.truncate(n);
            k
        }
        2 => values(rng, n),
        _ => {
            let mut k = finites(rng, n);
            k.sort_by(f64::total_cmp);
            k
        }
    }
}

/// `n` weights: all of one extreme magnitude (10³⁰⁸ or 5·10⁻³²⁴ each), ordinary positive
/// numbers, or anything.
pub fn weights(rng: &Draws, n: usize) -> Vec<f64> {
    match rng.below(4) {
        0 => vec![rng.pick(&[1e308, 1.7e308, 5e-324, 1e-320, 1e-300]); n],
        1 => (0..n).map(|_| 0.1 + rng.unit()).collect(),
        2 => (0..n)
            .map(|_| rng.pick(&[1e308, 5e-324, 1.0, 1e-300]))
            .collect(),
        _ => values(rng, n),
    }
}

/// A parameter: anything, or in `[0, 1]`, or at a domain end.
pub fn parameter(rng: &Draws) -> f64 {
    match rng.below(4) {
        0 => value(rng),
        1 => rng.pick(&[0.0, 1.0, 0.5]),
        _ => rng.unit(),
    }
}

/// `n` parameters drawn by [`parameter`].
pub fn parameters(rng: &Draws, n: usize) -> Vec<f64> {
    (0..n).map(|_| parameter(rng)).collect()
}
