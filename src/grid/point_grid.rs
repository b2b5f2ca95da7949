//! [`PointGrid`]: the points of a surface on a parameter grid, or a control net, as one
//! contiguous array.

use std::ops::{Index, IndexMut};

use crate::error::{Error, Limit, Result};

/// An array of shape `(nu, nv, d)` in row-major order: entry `[[a, b, c]]` is coordinate `c` of
/// the point at `(us[a], vs[b])` of a grid, or of the control point `b_{a,b}` of a net.
///
/// This is the layout of `P(i,j,:)` in the thesis function `ploskevB` and of the net `tenzor`
/// returns; the memory order is the one [`crate::Surface::eval_grid_into`] writes
/// (`out[(a·nv + b)·d + c]`). The Octave layer converts it to and from Octave-shaped arrays.
///
/// ```
/// use cagd::grid::PointGrid;
/// let g = PointGrid::from_shape_fn((2, 3, 1), |(a, b, _)| (10 * a + b) as f64);
/// assert_eq!(g.dim(), (2, 3, 1));
/// assert_eq!(g[[1, 2, 0]], 12.0);
/// assert_eq!(g.point(1, 2), &[12.0]);
/// assert_eq!(g.as_slice(), &[0.0, 1.0, 2.0, 10.0, 11.0, 12.0]);
/// ```
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PointGrid<T> {
    shape: [usize; 3],
    data: Vec<T>,
}

impl<T> PointGrid<T> {
    /// A grid of shape `(nu, nv, d)` whose entry `[[a, b, c]]` is `f((a, b, c))`.
    ///
    /// # Panics
    /// If `nu · nv · d` entries cannot be held (the product overflows `usize`, or the memory
    /// cannot be reserved): a panic naming the shape, never an abort.
    /// [`try_from_shape_fn`](Self::try_from_shape_fn) answers [`Error::TooLarge`] instead.
    pub fn from_shape_fn(
        shape: (usize, usize, usize),
        f: impl FnMut((usize, usize, usize)) -> T,
    ) -> Self {
        Self::try_from_shape_fn(shape, f).unwrap_or_else(|e| panic!("{e}"))
    }

    /// [`from_shape_fn`](Self::from_shape_fn) for a shape that may not fit in memory.
    ///
    /// # Errors
    /// [`Error::TooLarge`] (limit `Elements`) when `nu · nv · d` overflows or its memory
    /// cannot be reserved (`try_reserve`), before `f` is called.
    ///
    /// ```
    /// use cagd::grid::PointGrid;
    /// assert!(PointGrid::try_from_shape_fn((1 << 20, 1 << 20, 3), |_| 0.0).is_err());
    /// assert_eq!(PointGrid::try_from_shape_fn((1, 2, 1), |(_, b, _)| b)?.as_slice(), &[0, 1]);
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn try_from_shape_fn(
        (nu, nv, d): (usize, usize, usize),
        mut f: impl FnMut((usize, usize, usize)) -> T,
    ) -> Result<Self> {
        let requested = (nu as u128 * nv as u128).saturating_mul(d as u128);
        let limit = (isize::MAX as usize / std::mem::size_of::<T>().max(1)) as u128;
        let too_large = || Error::TooLarge {
            what: "point grid",
            requested,
            limit,
            which: Limit::Elements,
        };
        let len = usize::try_from(requested).map_err(|_| too_large())?;
        let mut data = Vec::new();
        data.try_reserve_exact(len).map_err(|_| too_large())?;
        // An empty grid may still have 2⁴⁰ × 2⁴⁰ rows and columns: no loop over them.
        if len == 0 {
            return Ok(PointGrid {
                shape: [nu, nv, d],
                data,
            });
        }
        for a in 0..nu {
            for b in 0..nv {
                for c in 0..d {
                    data.push(f((a, b, c)));
                }
            }
        }
        Ok(PointGrid {
            shape: [nu, nv, d],
            data,
        })
    }

    /// A grid of shape `(nu, nv, d)` holding `data` in row-major order, or `None` unless
    /// `data.len() == nu · nv · d`.
    pub fn from_vec((nu, nv, d): (usize, usize, usize), data: Vec<T>) -> Option<Self> {
        let len = nu.checked_mul(nv).and_then(|n| n.checked_mul(d))?;
        (len == data.len()).then_some(PointGrid {
            shape: [nu, nv, d],
            data,
        })
    }

    /// The shape `(nu, nv, d)`.
    pub fn dim(&self) -> (usize, usize, usize) {
        (self.shape[0], self.shape[1], self.shape[2])
    }

    /// The shape as a slice `[nu, nv, d]`.
    pub fn shape(&self) -> &[usize] {
        &self.shape
    }

    /// The number of entries `nu · nv · d`.
    pub fn len(&self) -> usize {
        self.data.len()
    }

    /// Whether the grid has no entries.
    pub fn is_empty(&self) -> bool {
        self.data.is_empty()
    }

    /// The coordinates of the point `[a, b]` (`d` entries).
    ///
    /// # Panics
    /// If `a ≥ nu` or `b ≥ nv`.
    pub fn point(&self, a: usize, b: usize) -> &[T] {
        let start = self.offset(a, b, 0);
        &self.data[start..start + self.shape[2]]
    }

    /// All entries in row-major order.
    pub fn as_slice(&self) -> &[T] {
        &self.data
    }

    /// All entries in row-major order, to be written in place.
    pub fn as_mut_slice(&mut self) -> &mut [T] {
        &mut self.data
    }

    /// The entries in row-major order.
    pub fn iter(&self) -> std::slice::Iter<'_, T> {
        self.data.iter()
    }

    /// The entries in row-major order, by value.
    pub fn into_vec(self) -> Vec<T> {
        self.data
    }

    /// Applies `f` to every entry.
    pub fn map<U>(&self, f: impl FnMut(&T) -> U) -> PointGrid<U> {
        PointGrid {
            shape: self.shape,
            data: self.data.iter().map(f).collect(),
        }
    }

    fn offset(&self, a: usize, b: usize, c: usize) -> usize {
        let [nu, nv, d] = self.shape;
        assert!(
            a < nu && b < nv && c < d,
            "index [{a}, {b}, {c}] out of bounds for a grid of shape ({nu}, {nv}, {d})"
        );
        (a * nv + b) * d + c
    }
}

impl<T: Clone> PointGrid<T> {
    /// A grid of shape `(nu, nv, d)` with every entry `value`.
    ///
    /// # Panics
    /// As [`from_shape_fn`](Self::from_shape_fn): a grid that cannot be held (2⁴⁰ points,
    /// say) is a panic naming its size, never an abort; [`try_from_elem`](Self::try_from_elem)
    /// answers [`Error::TooLarge`] instead.
    pub fn from_elem(shape: (usize, usize, usize), value: T) -> Self {
        Self::from_shape_fn(shape, |_| value.clone())
    }

    /// [`from_elem`](Self::from_elem) for a shape that may not fit in memory.
    ///
    /// # Errors
    /// As [`try_from_shape_fn`](Self::try_from_shape_fn).
    ///
    /// ```
    /// use cagd::grid::PointGrid;
    /// assert!(PointGrid::try_from_elem((1 << 40, 1, 1), 0.0).is_err());
    /// # Ok::<(), cagd::Error>(())
    /// ```
    pub fn try_from_elem(shape: (usize, usize, usize), value: T) -> Result<Self> {
        Self::try_from_shape_fn(shape, |_| value.clone())
    }
}

impl<T> Index<[usize; 3]> for PointGrid<T> {
    type Output = T;
    fn index(&self, [a, b, c]: [usize; 3]) -> &T {
        &self.data[self.offset(a, b, c)]
    }
}

impl<T> IndexMut<[usize; 3]> for PointGrid<T> {
    fn index_mut(&mut self, [a, b, c]: [usize; 3]) -> &mut T {
        let k = self.offset(a, b, c);
        &mut self.data[k]
    }
}

impl<'a, T> IntoIterator for &'a PointGrid<T> {
    type Item = &'a T;
    type IntoIter = std::slice::Iter<'a, T>;
    fn into_iter(self) -> Self::IntoIter {
        self.data.iter()
    }
}
