//! Tolerances for points that should coincide (corners of a Coons patch, crossings of a Gordon
//! network), and the corner disagreements a check reports. Plain data: the constructions that
//! check (`coons`, `gordon`) and the error type that reports ([`crate::error`]) both use it.

use std::fmt;

use nalgebra::DVector;

use crate::scalar::Scalar;

/// How far apart two points that should coincide may be (corners of a Coons patch, crossings
/// of a Gordon network).
///
/// The gap between two points is the largest coordinate difference (the max norm, as
/// octave-nurbs `nrbcoons` measures it).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Tolerance {
    /// `gap ≤ tol · max(1, largest |coordinate| of the two points)`: relative for large
    /// coordinates, absolute near the origin. The default is `Relative(1e-10)`; for data of
    /// size at most 1 this is exactly octave-nurbs `nrbcoons`'s test (absolute `1e-10`).
    Relative(f64),
    /// `gap ≤ tol`.
    Absolute(f64),
    /// The points must be equal (the natural choice in exact rational arithmetic).
    Exact,
}

impl Default for Tolerance {
    fn default() -> Self {
        Tolerance::Relative(1e-10)
    }
}

impl fmt::Display for Tolerance {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Tolerance::Relative(t) => write!(f, "relative tolerance {t:e}"),
            Tolerance::Absolute(t) => write!(f, "absolute tolerance {t:e}"),
            Tolerance::Exact => write!(f, "exact equality"),
        }
    }
}

impl Tolerance {
    /// Whether the tolerance itself is usable: finite and not negative.
    pub fn is_valid(&self) -> bool {
        match self {
            Tolerance::Relative(t) | Tolerance::Absolute(t) => t.is_finite() && *t >= 0.0,
            Tolerance::Exact => true,
        }
    }

    /// The gap between `p` and `q` (max norm) and the largest gap this tolerance allows for
    /// them; the points pass when `gap <= allowed`.
    ///
    /// ```
    /// use cagd::coons::Tolerance;
    /// use nalgebra::dvector;
    /// let (gap, allowed) = Tolerance::Relative(1e-10).gap(&dvector![100.0, 0.0], &dvector![100.0, 1e-9]);
    /// assert_eq!(gap, 1e-9);
    /// assert!((allowed - 1e-8).abs() < 1e-20); // 1e-10 · 100
    /// ```
    pub fn gap<T: Scalar>(&self, p: &DVector<T>, q: &DVector<T>) -> (T, T) {
        let mut gap = T::zero();
        let mut scale = T::one();
        for (a, b) in p.iter().zip(q.iter()) {
            let d = (a.clone() - b.clone()).abs();
            if d > gap {
                gap = d;
            }
            for s in [a.abs(), b.abs()] {
                if s > scale {
                    scale = s;
                }
            }
        }
        let allowed = match self {
            Tolerance::Relative(t) => T::from_f64(*t).unwrap_or_else(T::zero) * scale,
            Tolerance::Absolute(t) => T::from_f64(*t).unwrap_or_else(T::zero),
            Tolerance::Exact => T::zero(),
        };
        (gap, allowed)
    }
}

/// A corner of the parameter square, in the order of the thesis's `P1..P4`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Corner {
    /// `P1 = x(0,0)`.
    U0V0,
    /// `P2 = x(1,0)`.
    U1V0,
    /// `P3 = x(0,1)`.
    U0V1,
    /// `P4 = x(1,1)`.
    U1V1,
}

impl Corner {
    /// The four corners in the order `P1, P2, P3, P4`.
    pub const ALL: [Corner; 4] = [Corner::U0V0, Corner::U1V0, Corner::U0V1, Corner::U1V1];

    /// `(u, v)` of the corner as `(0|1, 0|1)`.
    pub fn uv(self) -> (usize, usize) {
        match self {
            Corner::U0V0 => (0, 0),
            Corner::U1V0 => (1, 0),
            Corner::U0V1 => (0, 1),
            Corner::U1V1 => (1, 1),
        }
    }

    /// Position `0..4` in `P1..P4`.
    pub fn index(self) -> usize {
        let (i, j) = self.uv();
        i + 2 * j
    }
}

impl fmt::Display for Corner {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (i, j) = self.uv();
        write!(f, "x({i},{j}) (P{})", self.index() + 1)
    }
}

/// One disagreement found by a corner check: two quantities that should be equal at a corner.
#[derive(Debug, Clone, PartialEq)]
pub struct CornerGap {
    /// The corner.
    pub corner: Corner,
    /// The first quantity, e.g. `"c1(0)"`.
    pub first: &'static str,
    /// The second quantity, e.g. `"d1(0)"`.
    pub second: &'static str,
    /// The gap (max norm).
    pub gap: f64,
    /// The largest gap the tolerance allows here.
    pub allowed: f64,
}

impl fmt::Display for CornerGap {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "at {} {} and {} differ by {:e} (allowed {:e})",
            self.corner, self.first, self.second, self.gap, self.allowed
        )
    }
}
