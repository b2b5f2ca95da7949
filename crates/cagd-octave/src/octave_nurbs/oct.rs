//! Arrays with Octave's indexing, for the ports of octave-nurbs' `.m` algorithms: indices
//! from 1, a read outside the array fails (as Octave's "index (i): out of bound"), a write
//! outside it grows the array with zeros (as Octave's assignment does).

use super::error::{NurbsError, Result};

/// A column-major matrix indexed as in Octave.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct OctMat {
    what: &'static str,
    rows: usize,
    cols: usize,
    data: Vec<f64>,
}

impl OctMat {
    /// `zeros (rows, cols)` (negative sizes count as 0, as in Octave).
    pub(crate) fn zeros(what: &'static str, rows: i64, cols: i64) -> Self {
        let (rows, cols) = (rows.max(0) as usize, cols.max(0) as usize);
        OctMat {
            what,
            rows,
            cols,
            data: vec![0.0; rows * cols],
        }
    }

    /// The matrix `rows × cols` of `data` (column-major).
    pub(crate) fn from_data(what: &'static str, rows: usize, cols: usize, data: &[f64]) -> Self {
        OctMat {
            what,
            rows,
            cols,
            data: data.to_vec(),
        }
    }

    pub(crate) fn cols(&self) -> usize {
        self.cols
    }

    /// The values, column-major.
    pub(crate) fn into_data(self) -> Vec<f64> {
        self.data
    }

    fn out_of_bound(&self, index: i64, bound: usize) -> NurbsError {
        NurbsError::Index {
            what: self.what,
            index,
            bound,
        }
    }

    /// `a(r, c)`.
    pub(crate) fn get(&self, r: i64, c: i64) -> Result<f64> {
        if r < 1 || r as usize > self.rows {
            return Err(self.out_of_bound(r, self.rows));
        }
        if c < 1 || c as usize > self.cols {
            return Err(self.out_of_bound(c, self.cols));
        }
        Ok(self.data[(r as usize - 1) + self.rows * (c as usize - 1)])
    }

    /// `a(:, c)`.
    pub(crate) fn col(&self, c: i64) -> Result<Vec<f64>> {
        if c < 1 || c as usize > self.cols {
            return Err(self.out_of_bound(c, self.cols));
        }
        let c = c as usize - 1;
        Ok(self.data[self.rows * c..self.rows * (c + 1)].to_vec())
    }

    /// Grows the matrix to at least `rows × cols`.
    fn grow(&mut self, rows: usize, cols: usize) {
        if rows <= self.rows && cols <= self.cols {
            return;
        }
        let (nr, nc) = (rows.max(self.rows), cols.max(self.cols));
        let mut data = vec![0.0; nr * nc];
        for c in 0..self.cols {
            data[nr * c..nr * c + self.rows]
                .copy_from_slice(&self.data[self.rows * c..self.rows * (c + 1)]);
        }
        self.rows = nr;
        self.cols = nc;
        self.data = data;
    }

    /// `a(r, c) = x`.
    pub(crate) fn set(&mut self, r: i64, c: i64, x: f64) -> Result<()> {
        if r < 1 {
            return Err(self.out_of_bound(r, self.rows));
        }
        if c < 1 {
            return Err(self.out_of_bound(c, self.cols));
        }
        self.grow(r as usize, c as usize);
        let rows = self.rows;
        self.data[(r as usize - 1) + rows * (c as usize - 1)] = x;
        Ok(())
    }

    /// `a(:, c) = x` (`x` has one value per row, or is empty when the matrix has no rows).
    pub(crate) fn set_col(&mut self, c: i64, x: &[f64]) -> Result<()> {
        if c < 1 {
            return Err(self.out_of_bound(c, self.cols));
        }
        self.grow(x.len(), c as usize);
        let rows = self.rows;
        let c = c as usize - 1;
        self.data[rows * c..rows * c + x.len()].copy_from_slice(x);
        Ok(())
    }
}

/// A vector indexed as in Octave.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct OctVec {
    what: &'static str,
    data: Vec<f64>,
}

impl OctVec {
    /// `zeros (1, n)`.
    pub(crate) fn zeros(what: &'static str, n: i64) -> Self {
        OctVec {
            what,
            data: vec![0.0; n.max(0) as usize],
        }
    }

    /// A vector of `data`.
    pub(crate) fn from_data(what: &'static str, data: &[f64]) -> Self {
        OctVec {
            what,
            data: data.to_vec(),
        }
    }

    pub(crate) fn into_data(self) -> Vec<f64> {
        self.data
    }

    /// `v(i)`.
    pub(crate) fn get(&self, i: i64) -> Result<f64> {
        if i < 1 || i as usize > self.data.len() {
            return Err(NurbsError::Index {
                what: self.what,
                index: i,
                bound: self.data.len(),
            });
        }
        Ok(self.data[i as usize - 1])
    }

    /// `v(i) = x`.
    pub(crate) fn set(&mut self, i: i64, x: f64) -> Result<()> {
        if i < 1 {
            return Err(NurbsError::Index {
                what: self.what,
                index: i,
                bound: self.data.len(),
            });
        }
        if i as usize > self.data.len() {
            self.data.resize(i as usize, 0.0);
        }
        self.data[i as usize - 1] = x;
        Ok(())
    }
}

/// An integer that octave-nurbs' `.m` code uses as an index or a loop bound.
///
/// # Errors
/// [`NurbsError::Refused`] unless `x` is an integer (Octave's "subscripts must be either
/// integers 1 to (2^63)-1 or logicals").
pub(crate) fn integer(what: &'static str, x: f64) -> Result<i64> {
    if x.fract() != 0.0 || !x.is_finite() || x.abs() > 1e15 {
        return Err(NurbsError::refused(
            what,
            format!("{x} is not an integer (octave-nurbs indexes with it)"),
        ));
    }
    Ok(x as i64)
}
