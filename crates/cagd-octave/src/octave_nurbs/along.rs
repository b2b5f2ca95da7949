//! One direction of a tensor-product NURBS as a univariate B-spline: how octave-nurbs'
//! `nrbkntins`, `nrbdegelev` and `nrbderiv` apply `bspkntins`, `bspdegelev` and `bspderiv` to
//! surfaces and volumes (`permute` and `reshape` the coefficients so that the direction is the
//! last, apply, and back). Each row of that matrix is transformed on its own with the same
//! numbers, so the order of the rows does not change a value; here they are gathered without
//! the permutation.

use super::error::Result;

/// Coefficients `4 × n_1 × … × n_D` (column-major) with `sizes = [n_1, …, n_D]`.
#[derive(Debug, Clone, PartialEq)]
pub struct Net {
    /// The values, column-major.
    pub data: Vec<f64>,
    /// `n_1, …, n_D`.
    pub sizes: Vec<usize>,
}

impl Net {
    /// `lead × n_k × trail`: the sizes before and after direction `k` (with the 4 rows).
    fn split(&self, k: usize) -> (usize, usize, usize) {
        let lead = 4 * self.sizes[..k].iter().product::<usize>();
        let trail = self.sizes[k + 1..].iter().product();
        (lead, self.sizes[k], trail)
    }

    /// Applies `f` to direction `k`: `f(rows, cols, c)` transforms the `rows × cols` matrix
    /// `c` (column-major; a column per control point of that direction) and returns the new
    /// matrix and its number of columns.
    ///
    /// # Errors
    /// `f`'s.
    pub fn along<F>(&self, k: usize, f: F) -> Result<Net>
    where
        F: FnOnce(usize, usize, &[f64]) -> Result<(Vec<f64>, usize)>,
    {
        let (lead, n, trail) = self.split(k);
        let rows = lead * trail;
        let mut m = vec![0.0; rows * n];
        for t in 0..trail {
            for i in 0..n {
                let src = &self.data[lead * (i + n * t)..lead * (i + n * t + 1)];
                m[lead * t + rows * i..lead * (t + 1) + rows * i].copy_from_slice(src);
            }
        }
        let (out, n2) = f(rows, n, &m)?;
        let mut data = vec![0.0; lead * n2 * trail];
        for t in 0..trail {
            for i in 0..n2 {
                data[lead * (i + n2 * t)..lead * (i + n2 * t + 1)]
                    .copy_from_slice(&out[lead * t + rows * i..lead * (t + 1) + rows * i]);
            }
        }
        let mut sizes = self.sizes.clone();
        sizes[k] = n2;
        Ok(Net { data, sizes })
    }

    /// `size (coefs)`: `[4, n_1, …]` (a curve `[4, n]`).
    pub fn dims(&self) -> Vec<usize> {
        let mut d = vec![4];
        d.extend_from_slice(&self.sizes);
        d
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn along_the_second_direction_of_a_volume() {
        // 4 × 2 × 3 × 2: reverse the control points of direction 2 (k = 1).
        let data: Vec<f64> = (0..48).map(f64::from).collect();
        let net = Net {
            data: data.clone(),
            sizes: vec![2, 3, 2],
        };
        let out = net
            .along(1, |rows, cols, c| {
                let mut r = vec![0.0; rows * cols];
                for i in 0..cols {
                    r[rows * i..rows * (i + 1)]
                        .copy_from_slice(&c[rows * (cols - 1 - i)..rows * (cols - i)]);
                }
                Ok((r, cols))
            })
            .unwrap();
        let at =
            |d: &[f64], c: usize, i: usize, j: usize, l: usize| d[c + 4 * (i + 2 * (j + 3 * l))];
        for (c, i, j, l) in [(0, 0, 0, 0), (3, 1, 2, 1), (2, 0, 1, 1)] {
            assert_eq!(at(&out.data, c, i, j, l), at(&data, c, i, 2 - j, l));
        }
    }
}
