//! N-d arrays with Octave's elementwise arithmetic (automatic broadcasting) and the one
//! indexing `nrbdeval` uses, `w(ones (3, 1), :, …)`, so that its formulas give octave-nurbs'
//! values and sizes for every shape of parameters it takes.

use super::error::{NurbsError, Result};

/// A real array: Octave's size (at least 2 entries, trailing ones dropped) and its values.
#[derive(Debug, Clone, PartialEq)]
pub struct Nd {
    /// The size.
    pub dims: Vec<usize>,
    /// The values, column-major.
    pub data: Vec<f64>,
}

/// Octave's size: trailing ones dropped down to 2 entries.
fn chop(mut dims: Vec<usize>) -> Vec<usize> {
    while dims.len() > 2 && dims.last() == Some(&1) {
        dims.pop();
    }
    while dims.len() < 2 {
        dims.push(1);
    }
    dims
}

impl Nd {
    /// The array of size `dims` holding `data`.
    pub fn new(dims: &[usize], data: Vec<f64>) -> Self {
        Nd {
            dims: chop(dims.to_vec()),
            data,
        }
    }

    /// `x(ones (3, 1), :, …, :)` with `colons` colons: the first row repeated three times,
    /// the dimensions past the last index folded into it, as Octave indexes.
    pub fn rows3(&self, colons: usize) -> Nd {
        let d1 = self.dims[0].max(1);
        let rest = self.data.len() / d1;
        let mut dims = vec![3];
        for k in 1..colons {
            dims.push(self.dims.get(k).copied().unwrap_or(1));
        }
        dims.push(self.dims.get(colons..).map_or(1, |r| r.iter().product()));
        let mut data = Vec::with_capacity(3 * rest);
        for c in 0..rest {
            let x = self.data[d1 * c];
            data.extend([x, x, x]);
        }
        Nd::new(&dims, data)
    }

    /// `self op other`, elementwise with broadcasting.
    ///
    /// # Errors
    /// [`NurbsError::Refused`] for sizes Octave cannot broadcast ("nonconformant arguments").
    pub fn zip(&self, other: &Nd, op: impl Fn(f64, f64) -> f64) -> Result<Nd> {
        if self.dims == other.dims {
            return Ok(Nd {
                dims: self.dims.clone(),
                data: self
                    .data
                    .iter()
                    .zip(&other.data)
                    .map(|(&x, &y)| op(x, y))
                    .collect(),
            });
        }
        let n = self.dims.len().max(other.dims.len());
        let a: Vec<usize> = (0..n)
            .map(|k| self.dims.get(k).copied().unwrap_or(1))
            .collect();
        let b: Vec<usize> = (0..n)
            .map(|k| other.dims.get(k).copied().unwrap_or(1))
            .collect();
        let mut dims = Vec::with_capacity(n);
        for k in 0..n {
            dims.push(match (a[k], b[k]) {
                (x, y) if x == y => x,
                (1, y) => y,
                (x, 1) => x,
                _ => {
                    return Err(NurbsError::refused(
                        "tt",
                        format!(
                            "nonconformant arguments (op1 is {}, op2 is {}) in nrbdeval's formulas",
                            size_str(&self.dims),
                            size_str(&other.dims)
                        ),
                    ))
                }
            });
        }
        let total: usize = dims.iter().product();
        let mut data = Vec::with_capacity(total);
        let mut idx = vec![0usize; n];
        for _ in 0..total {
            let (mut ia, mut ib, mut sa, mut sb) = (0, 0, 1, 1);
            for k in 0..n {
                ia += sa * if a[k] == 1 { 0 } else { idx[k] };
                ib += sb * if b[k] == 1 { 0 } else { idx[k] };
                sa *= a[k];
                sb *= b[k];
            }
            data.push(op(self.data[ia], other.data[ib]));
            for k in 0..n {
                idx[k] += 1;
                if idx[k] < dims[k] {
                    break;
                }
                idx[k] = 0;
            }
        }
        Ok(Nd::new(&dims, data))
    }

    /// `self + other`.
    pub fn add(&self, other: &Nd) -> Result<Nd> {
        self.zip(other, |x, y| x + y)
    }

    /// `self - other`.
    pub fn sub(&self, other: &Nd) -> Result<Nd> {
        self.zip(other, |x, y| x - y)
    }

    /// `self .* other`.
    pub fn mul(&self, other: &Nd) -> Result<Nd> {
        self.zip(other, |x, y| x * y)
    }

    /// `self ./ other`.
    pub fn div(&self, other: &Nd) -> Result<Nd> {
        self.zip(other, |x, y| x / y)
    }

    /// `s * self`.
    pub fn scale(&self, s: f64) -> Nd {
        Nd {
            dims: self.dims.clone(),
            data: self.data.iter().map(|x| s * x).collect(),
        }
    }

    /// `self .^ 2`.
    pub fn sq(&self) -> Nd {
        Nd {
            dims: self.dims.clone(),
            data: self.data.iter().map(|x| x * x).collect(),
        }
    }
}

fn size_str(dims: &[usize]) -> String {
    dims.iter()
        .map(usize::to_string)
        .collect::<Vec<_>>()
        .join("x")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn broadcasting_and_rows3_as_octave() {
        // w = [1 2 3] (1x3): w(ones(3,1),:) is 3x3 with rows [1 2 3].
        let w = Nd::new(&[1, 3], vec![1.0, 2.0, 3.0]);
        assert_eq!(
            w.rows3(1).data,
            vec![1.0, 1.0, 1.0, 2.0, 2.0, 2.0, 3.0, 3.0, 3.0]
        );
        // A column w (3x1): w(ones(3,1),:) is 3x1, all w(1) (octave-nurbs divides by it).
        let c = Nd::new(&[3, 1], vec![1.0, 2.0, 3.0]);
        assert_eq!(c.rows3(1).dims, vec![3, 1]);
        assert_eq!(c.rows3(1).data, vec![1.0, 1.0, 1.0]);
        // 1 x 2 x 2 with two colons: 3 x 2 x 2.
        let g = Nd::new(&[1, 2, 2], vec![1.0, 2.0, 3.0, 4.0]);
        assert_eq!(g.rows3(2).dims, vec![3, 2, 2]);
        // 3x4 ./ 3x1 broadcasts; 3x4 ./ 3x2 does not.
        let a = Nd::new(&[3, 4], vec![2.0; 12]);
        assert_eq!(a.div(&c).unwrap().data[2], 2.0 / 3.0);
        assert!(a.div(&Nd::new(&[3, 2], vec![1.0; 6])).is_err());
    }
}
