//! The 3×3 mask formulation of discrete Coons patches (notes (7)–(9)).

use nalgebra::DMatrix;

use super::discrete::net_degree;
use crate::cost::Cost;
use crate::error::{Error, Result};
use crate::limits::{exact_op_cost, Limits};
use crate::scalar::Scalar;

/// A symmetric 3×3 mask (notes (9)): every interior control point is the weighted sum of its
/// eight neighbours, corner neighbours with weight `α` and edge neighbours with weight `β`,
///
/// ```text
///            ⎡ α  β  α ⎤
///   b_ij  =  ⎢ β  *  β ⎥ ,   b_ij = α (b_{i−1,j−1} + b_{i−1,j+1} + b_{i+1,j−1} + b_{i+1,j+1})
///            ⎣ α  β  α ⎦              + β (b_{i−1,j} + b_{i+1,j} + b_{i,j−1} + b_{i,j+1}).
/// ```
///
/// **The constraint `4α + 4β = 1`.** The construction must commute with affine maps (a patch
/// moved with its boundary must fill in moved): translating every point by `t` adds
/// `(4α + 4β) t` to the right-hand side and `t` to the left, so the weights must sum to one.
/// Every such mask then reproduces bilinear nets `b_ij = a + b i + c j + d ij`: the eight
/// neighbours sum to `8 b_ij` in pairs symmetric about `(i, j)`, in which the `i`, `j` and `ij`
/// terms cancel. [`Mask::new`] enforces the constraint; [`Mask::from_alpha`] sets `β = 1/4 − α`.
///
/// **Coons.** `α = −1/4`, `β = 1/2` (notes (7)–(8)) is the discrete Coons patch: the equation
/// `b_ij = −¼ Σ corners + ½ Σ edges` is `Δ²_i Δ²_j b = 0` (the centred second difference in
/// `i` of the second difference in `j`: the stencil `[1 −2 1] ⊗ [1 −2 1] / 4`), which the
/// discrete Coons net satisfies because each of its terms is linear in `i` or linear in `j`;
/// and the solution is unique (see below). So [`solve_mask`] with [`Mask::coons`] reproduces
/// [`super::discrete_coons`] exactly, which the tests confirm in exact rationals.
///
/// **Solvability.** On a net of degree `(m, n)` the system for the `(m−1)(n−1)` interior
/// points is `A x = r` with `A = I − β E − α D` (`E`, `D`: edge and corner neighbour sums with
/// zero boundary). Its eigenvectors are `sin(pπi/m) sin(qπj/n)`, `1 ≤ p < m`, `1 ≤ q < n`,
/// with eigenvalues
///
/// ```text
/// λ_pq = 1 − 2β (cos θ_p + cos φ_q) − 4α cos θ_p cos φ_q,   θ_p = pπ/m,  φ_q = qπ/n,
/// ```
///
/// so `A` is symmetric and singular exactly when some `λ_pq = 0`. For Coons
/// `λ_pq = (1 − cos θ_p)(1 − cos φ_q) > 0`: always solvable, `A` even positive definite.
/// Masks with a vanishing (or, in floating point, negligible) `λ_pq` are rejected with
/// [`Error::SingularMask`]; e.g. `α = −1/2`, `β = 3/4` on a 4×4 net (`m = n = 3`, where
/// `cos θ_1 = 1/2` gives `λ_11 = 1/2 + α = 0`).
///
/// ```
/// use cagd::coons::Mask;
/// let coons = Mask::<f64>::coons();
/// assert_eq!((coons.alpha(), coons.beta()), (-0.25, 0.5));
/// assert!(Mask::new(0.1, 0.2).is_err()); // 4α + 4β = 1.2
/// let laplace = Mask::from_alpha(0.0)?; // the discrete harmonic (Laplace) mask, β = 1/4
/// assert_eq!(laplace.beta(), 0.25);
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct Mask<T: Scalar = f64> {
    alpha: T,
    beta: T,
}

impl<T: Scalar> Mask<T> {
    /// The discrete Coons mask `α = −1/4`, `β = 1/2` (notes (7)–(8)).
    pub fn coons() -> Self {
        Mask {
            alpha: T::from_ratio(-1, 4),
            beta: T::from_ratio(1, 2),
        }
    }

    /// The mask with corner weight `alpha` and edge weight `beta`.
    ///
    /// # Errors
    /// [`Error::MaskNotAffine`] unless `4α + 4β = 1` (to `8ε·max(1, 4|α|, 4|β|)`, `ε` the `f64`
    /// machine epsilon, so that decimal input such as `α = 0.05, β = 0.2` passes in `f64`);
    /// [`Error::NonFinite`] for a non-finite weight.
    pub fn new(alpha: T, beta: T) -> Result<Self> {
        crate::error::check_finite("mask weights (alpha, beta)", [&alpha, &beta])?;
        let four = T::from_usize(4);
        let sum = four.clone() * alpha.clone() + four.clone() * beta.clone();
        let mut scale = T::one();
        for s in [
            (four.clone() * alpha.clone()).abs(),
            (four * beta.clone()).abs(),
        ] {
            if s > scale {
                scale = s;
            }
        }
        let slack = T::from_f64(8.0 * f64::EPSILON).unwrap_or_else(T::zero) * scale.clone();
        // Written so that an overflow (4α or 4β infinite, their sum NaN) fails the check
        // instead of slipping through a comparison with NaN.
        let affine = scale.is_finite_value() && (sum.clone() - T::one()).abs() <= slack;
        if !affine {
            return Err(Error::MaskNotAffine {
                alpha: alpha.to_f64(),
                beta: beta.to_f64(),
                sum: sum.to_f64(),
            });
        }
        Ok(Mask { alpha, beta })
    }

    /// The affine mask with corner weight `alpha` and edge weight `β = 1/4 − α`.
    ///
    /// # Errors
    /// [`Error::NonFinite`] for a NaN or infinite `alpha`; [`Error::Overflow`] when `β`
    /// overflows (`alpha` near `−f64::MAX`).
    ///
    /// ```
    /// use cagd::coons::Mask;
    /// assert_eq!(Mask::from_alpha(0.0)?.beta(), 0.25);
    /// assert!(Mask::from_alpha(f64::NAN).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn from_alpha(alpha: T) -> Result<Self> {
        crate::error::check_finite("mask weight alpha", std::iter::once(&alpha))?;
        let beta = T::from_ratio(1, 4) - alpha.clone();
        crate::error::check_overflow("mask weight beta = 1/4 − alpha", std::iter::once(&beta))?;
        Ok(Mask { alpha, beta })
    }

    /// The corner weight `α`.
    pub fn alpha(&self) -> T {
        self.alpha.clone()
    }

    /// The edge weight `β`.
    pub fn beta(&self) -> T {
        self.beta.clone()
    }

    /// The eigenvalue `λ_pq` of smallest modulus of the system on a net of degree `(m, n)`
    /// (see the type docs), as `(p, q, λ_pq)` in `f64`; `None` if the net has no interior.
    /// It looks at every mode, `(m − 1)(n − 1)` of them: pass the degrees of a net held in
    /// memory.
    ///
    /// ```
    /// use cagd::coons::Mask;
    /// let (p, q, lambda) = Mask::<f64>::coons().smallest_eigenvalue(3, 3).unwrap();
    /// assert_eq!((p, q), (1, 1));
    /// assert!((lambda - 0.25).abs() < 1e-15); // (1 − cos π/3)² = 1/4
    /// ```
    pub fn smallest_eigenvalue(&self, m: usize, n: usize) -> Option<(usize, usize, f64)> {
        let (a, b) = (self.alpha.to_f64(), self.beta.to_f64());
        let mut best: Option<(usize, usize, f64)> = None;
        for p in 1..m {
            let cp = (p as f64 * std::f64::consts::PI / m as f64).cos();
            for q in 1..n {
                let cq = (q as f64 * std::f64::consts::PI / n as f64).cos();
                let lambda = 1.0 - 2.0 * b * (cp + cq) - 4.0 * a * cp * cq;
                let better = match best {
                    None => true,
                    Some((_, _, l)) => lambda.abs() < l.abs(),
                };
                if better {
                    best = Some((p, q, lambda));
                }
            }
        }
        best
    }

    /// The cost of [`solve_mask`] on a net of degree `(m, n)`, one coordinate: banded
    /// elimination of the `N = (m−1)(n−1)` unknowns with half-bandwidth `w = min(m, n)`,
    /// `N (w+1)²` operations, on numbers that grow as the elimination proceeds (grow it by the
    /// size of the net and the mask).
    ///
    /// How they grow depends on the mask, measured in exact arithmetic (the band's entries
    /// after each pivot, nets of `n × n` ones, `bench/discrete_coons_exact.sh`,
    /// docs/PERFORMANCE.md):
    /// - the **Coons mask** (`α = −β²`, the tensor product of two 1-D masks: `α = −1/4`,
    ///   `β = 1/2` is the only affine one) keeps its numbers small (at most 19 bits for
    ///   `n = 15`) and its band mostly zero: the operations took 60–160 ns each (N × N nets of
    ///   random digits, N = 40…120), so each weighs a sixteenth of
    ///   [`exact_op_cost`](crate::limits::exact_op_cost) ([`Cost::cheaper_when_exact`]);
    /// - **every other mask** (the Laplace mask `α = 0`, `β = 1/4` among them) builds numbers of
    ///   about 3 bits per unknown (at most 192 bits for `n = 10`, 1 032 for `n = 20`: the
    ///   determinants of the leading blocks), so the operations are weighed at `3N` bits: the
    ///   estimate is then 1.0–1.4 times the run time in nanoseconds for n = 12…40 (both grow
    ///   as n⁷: fitted exponents 6.95 and 6.87), and ones(30, 90) — 70 s before, estimated at
    ///   1.3·10⁸ — is 1.2·10¹¹, refused at once.
    ///
    /// [`solve_mask`] refuses the estimate above `limits.max_work` before it starts, and in
    /// exact arithmetic meters the elimination as it runs as well (every operation weighed by
    /// the size of its operands), so an estimate that is too low still stops at the limit.
    ///
    /// ```
    /// use cagd::coons::Mask;
    /// let c = Mask::<f64>::coons().solve_cost(4, 3);
    /// assert_eq!(c.ops(), 3 * 2 * 16);
    /// assert_eq!(c.weigh(true), 96 * 1016 / 16);
    /// // The Laplace mask: 6 unknowns, numbers of 18 bits.
    /// let laplace = Mask::<f64>::new(0.0, 0.25).unwrap().solve_cost(4, 3);
    /// assert_eq!((laplace.ops(), laplace.bits()), (96, 18));
    /// assert_eq!(laplace.weigh(true), 96 * 1016);
    /// ```
    pub fn solve_cost(&self, m: usize, n: usize) -> Cost {
        let inner = m.min(n).saturating_sub(1) as u128;
        let outer = m.max(n).saturating_sub(1) as u128;
        let unknowns = inner.saturating_mul(outer);
        let ops = unknowns.saturating_mul((inner + 2).saturating_pow(2));
        if self.is_tensor_product() {
            Cost::new(ops, 0).cheaper_when_exact(16)
        } else {
            Cost::new(ops, unknowns.saturating_mul(BITS_PER_UNKNOWN))
        }
    }

    /// Whether `α = −β²`: the mask is the tensor product of two one-dimensional ones (the
    /// Coons mask), whose elimination keeps its numbers small.
    fn is_tensor_product(&self) -> bool {
        (self.alpha.clone() + self.beta.clone() * self.beta.clone()).is_zero()
    }

    fn singular(&self, m: usize, n: usize, p: usize, q: usize, eigenvalue: f64) -> Error {
        Error::SingularMask {
            alpha: self.alpha.to_f64(),
            beta: self.beta.to_f64(),
            m,
            n,
            p,
            q,
            eigenvalue,
        }
    }
}

/// How many bits the numbers of an exact elimination gain per unknown, for masks other than the
/// Coons mask (measured: the largest entry of the band had 3.0–3.2 bits per unknown for nets of
/// 10 × 10 to 20 × 20 points with the Laplace mask).
const BITS_PER_UNKNOWN: u128 = 3;

/// Relative size below which an eigenvalue of the mask system counts as zero.
const SINGULAR_EIGENVALUE: f64 = 1e-12;

/// Fills the interior of a Bézier net from its boundary by the mask `mask`: solves the linear
/// system "mask equation at every interior point" (notes: "zgornjo enačbo zapišemo za vsako
/// notranjo kontrolno točko in rešimo pridobljen sistem enačb").
///
/// `net` holds one `(m+1) × (n+1)` matrix per coordinate (entry `(i, j)` is coordinate `k` of
/// `b_ij`); only the boundary is read. With [`Mask::coons`] the result is the discrete Coons
/// net ([`super::discrete_coons`]).
///
/// **Solver.** Numbering the unknowns along the shorter side of the interior, the matrix is
/// banded with half-bandwidth `w = min(m, n)`; it is factored by banded Gaussian elimination
/// with partial pivoting in `O((m−1)(n−1) w²)` operations and `O((m−1)(n−1) w)` memory, written
/// over the [`Scalar`] so that it also runs in exact rationals (where nalgebra's dense LU, which
/// needs a floating-point field, does not apply). A dense LU would need `((m−1)(n−1))²` memory:
/// 768 MB already for a net of degree 100.
///
/// # Errors
/// Those of the net ([`Error::ShapeMismatch`], [`Error::TooFewPoints`], [`Error::NonFinite`]);
/// [`Error::SingularMask`] when the system is singular: some eigenvalue `λ_pq` is below
/// `1e-12 · (1 + 4|α| + 4|β|)` in modulus, or elimination meets an exactly zero pivot;
/// [`Error::TooLarge`] when the band would hold more than
/// `limits.max_system_entries` numbers or the elimination would take more than
/// `limits.max_work` operations ([`Limits`]).
///
/// ```
/// use cagd::coons::{discrete_coons, solve_mask, Mask};
/// use cagd::Limits;
/// use nalgebra::DMatrix;
/// // A 5×4 net whose boundary is z = sin(i) + cos(j) + i·j.
/// let z = DMatrix::from_fn(5, 4, |i, j| (i as f64).sin() + (j as f64).cos() + (i * j) as f64);
/// let by_mask = solve_mask(&[z.clone()], &Mask::coons(), &Limits::default()).unwrap();
/// let by_formula = discrete_coons(&[z]).unwrap();
/// assert!((&by_mask[0] - &by_formula[0]).amax() < 1e-14);
/// ```
pub fn solve_mask<T: Scalar>(
    net: &[DMatrix<T>],
    mask: &Mask<T>,
    limits: &Limits,
) -> Result<Vec<DMatrix<T>>> {
    let (m, n) = net_degree("mask net", net)?;
    let mut out = net.to_vec();
    if m < 2 || n < 2 {
        return Ok(out);
    }
    // Sizes first: the eigenvalue search below visits every one of the (m−1)(n−1) modes.
    // The band stores size × (3w + 1) entries, w = min(m, n): refuse what would not fit.
    limits.check_system(
        "mask net",
        (m as u128 - 1) * (n as u128 - 1) * (3 * m.min(n) as u128 + 1),
    )?;
    let Some((p, q, lambda)) = mask.smallest_eigenvalue(m, n) else {
        return Ok(out);
    };
    let scale = 1.0 + 4.0 * mask.alpha.to_f64().abs() + 4.0 * mask.beta.to_f64().abs();
    if lambda.abs() <= SINGULAR_EIGENVALUE * scale {
        return Err(mask.singular(m, n, p, q, lambda));
    }

    // Unknown numbering: inner index along the shorter interior side.
    let inner_is_j = n <= m;
    let (outer_len, inner_len) = if inner_is_j {
        (m - 1, n - 1)
    } else {
        (n - 1, m - 1)
    };
    let size = outer_len * inner_len;
    let w = inner_len + 1;
    let index = |i: usize, j: usize| -> usize {
        if inner_is_j {
            (i - 1) * inner_len + (j - 1)
        } else {
            (j - 1) * inner_len + (i - 1)
        }
    };
    // Banded elimination: about size · w² operations per coordinate, on numbers as large as
    // the net's and the mask's grown by the elimination (Mask::solve_cost).
    let exact = crate::grid::exact::is_rational::<T>();
    let input_bits = crate::cost::max_bits(
        net.iter()
            .flat_map(|c| c.iter())
            .chain([&mask.alpha, &mask.beta]),
    );
    let estimate = mask
        .solve_cost(m, n)
        .times(net.len() as u128)
        .grown(input_bits)
        .weigh(exact);
    limits.check_work("mask net", estimate)?;
    let dims = net.len();
    let mut band = Band::new(size, w);
    let mut rhs = DMatrix::from_element(size, dims, T::zero());
    for i in 1..m {
        for j in 1..n {
            let r = index(i, j);
            band.set(r, r, T::one());
            for di in [-1i64, 0, 1] {
                for dj in [-1i64, 0, 1] {
                    if di == 0 && dj == 0 {
                        continue;
                    }
                    let weight = if di != 0 && dj != 0 {
                        mask.alpha.clone()
                    } else {
                        mask.beta.clone()
                    };
                    let (ni, nj) = ((i as i64 + di) as usize, (j as i64 + dj) as usize);
                    if ni == 0 || ni == m || nj == 0 || nj == n {
                        for (k, b) in net.iter().enumerate() {
                            rhs[(r, k)] =
                                rhs[(r, k)].clone() + weight.clone() * b[(ni, nj)].clone();
                        }
                    } else {
                        let c = index(ni, nj);
                        band.set(r, c, -weight);
                    }
                }
            }
        }
    }
    // In exact arithmetic the elimination is metered as well, by the sizes its numbers reach.
    let budget = exact.then_some(u128::from(limits.max_work));
    let x = match band.solve(rhs, budget) {
        Solved::Done(x) => x,
        Solved::Singular => return Err(mask.singular(m, n, p, q, lambda)),
        Solved::OverBudget(spent) => {
            return Err(Error::TooLarge {
                what: "mask net (exact elimination, metered by the size of its numbers)",
                requested: spent,
                limit: u128::from(limits.max_work),
                which: crate::limits::Limit::Work,
            })
        }
    };
    for i in 1..m {
        for j in 1..n {
            let r = index(i, j);
            for (k, o) in out.iter_mut().enumerate() {
                o[(i, j)] = x[(r, k)].clone();
            }
        }
    }
    crate::error::check_overflow("mask net", out.iter().flat_map(|c| c.iter()))?;
    Ok(out)
}

/// A square matrix of size `n` with `w` sub- and superdiagonals, stored with room for the `w`
/// extra superdiagonals that partial pivoting creates: row `r` keeps columns `r − w ..= r + 2w`.
struct Band<T: Scalar> {
    n: usize,
    w: usize,
    data: DMatrix<T>,
}

impl<T: Scalar> Band<T> {
    fn new(n: usize, w: usize) -> Self {
        Band {
            n,
            w,
            data: DMatrix::from_element(n, 3 * w + 1, T::zero()),
        }
    }

    fn get(&self, r: usize, c: usize) -> T {
        self.data[(r, c + self.w - r)].clone()
    }

    fn set(&mut self, r: usize, c: usize, value: T) {
        self.data[(r, c + self.w - r)] = value;
    }

    /// Solves `A X = B` by Gaussian elimination with partial pivoting; `None` on an exactly
    /// zero pivot.
    /// Solves the system for the right-hand sides `b` (one per column). With a `budget`, every
    /// elimination update is charged two exact operations on numbers the size of its result
    /// ([`exact_op_cost`]), and the solve stops once the total passes the budget.
    fn solve(mut self, mut b: DMatrix<T>, budget: Option<u128>) -> Solved<T> {
        let mut spent = 0u128;
        let (n, w) = (self.n, self.w);
        for k in 0..n {
            let last_row = (k + w).min(n - 1);
            let last_col = (k + 2 * w).min(n - 1);
            let mut pivot = k;
            let mut best = self.get(k, k).abs();
            for r in k + 1..=last_row {
                let a = self.get(r, k).abs();
                if a > best {
                    best = a;
                    pivot = r;
                }
            }
            if best.is_zero() {
                return Solved::Singular;
            }
            if pivot != k {
                for c in k..=last_col {
                    let (x, y) = (self.get(k, c), self.get(pivot, c));
                    self.set(k, c, y);
                    self.set(pivot, c, x);
                }
                b.swap_rows(k, pivot);
            }
            let diag = self.get(k, k);
            for r in k + 1..=last_row {
                let a = self.get(r, k);
                if a.is_zero() {
                    continue;
                }
                let factor = a / diag.clone();
                self.set(r, k, T::zero());
                for c in k + 1..=last_col {
                    let v = self.get(r, c) - factor.clone() * self.get(k, c);
                    if budget.is_some() {
                        spent = spent.saturating_add(2 * exact_op_cost(v.bits()));
                    }
                    self.set(r, c, v);
                }
                for j in 0..b.ncols() {
                    b[(r, j)] = b[(r, j)].clone() - factor.clone() * b[(k, j)].clone();
                    if budget.is_some() {
                        spent = spent.saturating_add(2 * exact_op_cost(b[(r, j)].bits()));
                    }
                }
            }
            if budget.is_some_and(|limit| spent > limit) {
                return Solved::OverBudget(spent);
            }
        }
        for k in (0..n).rev() {
            let last_col = (k + 2 * w).min(n - 1);
            let diag = self.get(k, k);
            for j in 0..b.ncols() {
                let mut s = b[(k, j)].clone();
                for c in k + 1..=last_col {
                    s = s - self.get(k, c) * b[(c, j)].clone();
                }
                b[(k, j)] = s / diag.clone();
            }
        }
        Solved::Done(b)
    }
}

/// How a band solve ended.
enum Solved<T: Scalar> {
    /// The solution.
    Done(DMatrix<T>),
    /// A zero pivot: the system is singular.
    Singular,
    /// The metered work (exact arithmetic) passed the budget: this much was spent.
    OverBudget(u128),
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solve_cost_is_the_band_elimination_and_what_solve_mask_refuses() {
        let mask = Mask::<f64>::coons();
        // A 101 × 51 net: 99 · 49 unknowns, half-bandwidth 50.
        assert_eq!(mask.solve_cost(100, 50).ops(), 99 * 49 * 51 * 51);
        assert_eq!(mask.solve_cost(50, 100), mask.solve_cost(100, 50));
        assert_eq!(mask.solve_cost(1, 7).ops(), 0);
        let net = vec![DMatrix::<f64>::zeros(101, 51)];
        let limits = Limits {
            max_work: (99 * 49 * 51 * 51 - 1) as u64,
            ..Limits::default()
        };
        assert!(matches!(
            solve_mask(&net, &mask, &limits),
            Err(Error::TooLarge { requested, .. }) if requested == 99 * 49 * 51 * 51
        ));
        // Exactly, a sixteenth of an exact operation each (the Coons mask keeps its numbers
        // small).
        let c = mask.solve_cost(3, 3).grown(64);
        assert_eq!(
            c.weigh(true),
            4 * 16 * crate::limits::exact_op_cost(64) / 16
        );
    }

    #[test]
    fn band_solver_pivots() {
        // [[0 1 0], [1 0 1], [0 1 1]] x = [1, 2, 3] needs a row swap at the first step;
        // x = (0, 1, 2).
        let mut band = Band::<f64>::new(3, 1);
        for (r, c, v) in [
            (0, 1, 1.0),
            (1, 0, 1.0),
            (1, 2, 1.0),
            (2, 1, 1.0),
            (2, 2, 1.0),
        ] {
            band.set(r, c, v);
        }
        let Solved::Done(x) = band.solve(DMatrix::from_column_slice(3, 1, &[1.0, 2.0, 3.0]), None)
        else {
            panic!("solvable")
        };
        assert_eq!(x.as_slice(), &[0.0, 1.0, 2.0]);
    }

    #[test]
    fn band_solver_reports_an_exactly_singular_matrix() {
        let mut band = Band::<f64>::new(2, 1);
        for (r, c, v) in [(0, 0, 1.0), (0, 1, 2.0), (1, 0, 2.0), (1, 1, 4.0)] {
            band.set(r, c, v);
        }
        assert!(matches!(
            band.solve(DMatrix::from_element(2, 1, 1.0), None),
            Solved::Singular
        ));
    }

    #[test]
    fn the_exact_elimination_is_estimated_by_its_growth_and_metered() {
        use num_rational::BigRational;
        let q = |n: i64, d: i64| <BigRational as Scalar>::from_ratio(n, d);
        let laplace = Mask::new(q(0, 1), q(1, 4)).unwrap();
        let coons = Mask::<BigRational>::coons();
        // A net of 30 × 30 ones (the 70-second case of ones(30, 90)): 28² unknowns, 3 bits each.
        let (m, n) = (29, 29);
        assert_eq!(laplace.solve_cost(m, n).bits(), 28 * 28 * 3);
        assert_eq!(coons.solve_cost(m, n).bits(), 0);
        let net = vec![DMatrix::from_element(30, 30, q(1, 1)); 3];
        let err = solve_mask(&net, &laplace, &Limits::default()).unwrap_err();
        assert!(
            matches!(err, Error::TooLarge { which: crate::limits::Limit::Work, requested, .. } if requested > 100_000_000_000),
            "{err:?}"
        );
        // The Coons mask on the same net stays cheap, and gives the ones back.
        let solved = solve_mask(&net, &coons, &Limits::default()).unwrap();
        assert!(solved[0].iter().all(|x| *x == q(1, 1)));
        // Past an estimate that let it start, the meter stops the elimination at the limit.
        let small = vec![DMatrix::from_fn(8, 8, |i, j| q((i * j % 7) as i64, 3)); 1];
        let estimate = laplace.solve_cost(7, 7).grown(3).weigh(true);
        let limits = Limits {
            max_work: estimate as u64,
            ..Limits::default()
        };
        match solve_mask(&small, &laplace, &limits) {
            Ok(_) => {}
            Err(Error::TooLarge { what, .. }) => assert!(what.contains("metered"), "{what}"),
            Err(e) => panic!("{e:?}"),
        }
    }
}
