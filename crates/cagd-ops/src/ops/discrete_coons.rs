//! `discrete-coons`: the interior of a control net from its boundary (thesis end of §4.1, the
//! CAD notes (6)–(8)), by the discrete Coons formula
//!
//! `b_ij = b^u_ij + b^v_ij − b^uv_ij`, `b^u_ij = (1 − i/m) b_0j + (i/m) b_mj`,
//! `b^v_ij = (1 − j/n) b_i0 + (j/n) b_in`, `b^uv_ij` the same blend of the corners
//! ([`cagd::coons::discrete_coons`]),
//!
//! or by an affine mask `b_ij = α·(the 4 diagonal neighbours) + β·(the 4 edge neighbours)`,
//! `α + β = 1/4`, solved for every interior point ([`cagd::coons::solve_mask`]).

use cagd::coons::{
    discrete_coons, discrete_coons_cost, discrete_coons_parts, discrete_coons_parts_cost,
    solve_mask, Mask,
};
use cagd::cost::max_bits;
use cagd::grid::PointGrid;
use cagd::Scalar;
use nalgebra::DMatrix;

use super::surface::grid_f64;
use crate::drawing::{Colour, Drawing};
use crate::error::{lib, Kind, OpError, Result};
use crate::{Answer, Context, Operation, Report, Role, Value};

/// The form of the net.
pub const NET_FORM: &str = "a net of at least 3×3 points";

/// The form of a mask.
pub const MASK_FORM: &str = "two numbers α,β with α + β = 1/4, e.g. -0.25,0.5";

/// The discrete Coons patch (or an affine mask) on the boundary of a net.
///
/// ```
/// use cagd::grid::PointGrid;
/// use cagd_ops::{execute, ops::DiscreteCoons, Context};
/// // A 3×3 height field: only the centre is unknown; (1 + 1)/2 + (1 + 3)/2 − (0 + 0 + 0 + 2)/4.
/// let z = [[0.0, 1.0, 0.0], [1.0, 9.0, 3.0], [0.0, 1.0, 2.0]];
/// let net = PointGrid::from_shape_fn((3, 3, 1), |(i, j, _)| z[i][j]);
/// let answer = execute(&DiscreteCoons::new(net), &mut Context::new(cagd::Limits::default()))?;
/// match answer.report.get("result") {
///     Some(cagd_ops::Value::Grid(g)) => assert_eq!(g[[1, 1, 0]], 2.5),
///     other => panic!("{other:?}"),
/// }
/// # Ok::<(), cagd_ops::OpError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct DiscreteCoons<T> {
    /// The net `(m+1) × (n+1) × d`; only its boundary rows and columns are read.
    pub net: PointGrid<T>,
    /// The mask `(α, β)` to solve instead of the formula.
    pub mask: Option<(T, T)>,
    /// The formula's parts `bu`, `bv`, `buv` as steps (not with a mask).
    pub steps: bool,
    /// A picture: the net as a surface, and as a net.
    pub drawing: bool,
}

impl<T: Scalar> DiscreteCoons<T> {
    /// The discrete Coons formula on `net`, no steps, no picture.
    pub fn new(net: PointGrid<T>) -> Self {
        DiscreteCoons {
            net,
            mask: None,
            steps: false,
            drawing: false,
        }
    }
}

impl<T: Scalar> Operation<T> for DiscreteCoons<T> {
    fn run(&self, cx: &mut Context) -> Result<Answer<T>> {
        let (m1, n1, d) = self.net.dim();
        cx.check_degree(Role::Net, m1.max(n1).saturating_sub(1))?;
        let (m, n) = (m1.saturating_sub(1), n1.saturating_sub(1));
        let coords: Vec<DMatrix<T>> = (0..d)
            .map(|k| DMatrix::from_fn(m1, n1, |i, j| self.net[[i, j, k]].clone()))
            .collect();
        let net_bits = max_bits(self.net.iter());
        let full = match &self.mask {
            None => {
                let mut cost = discrete_coons_cost(m, n, d);
                if self.steps {
                    cost = cost.and(discrete_coons_parts_cost(m, n, d));
                }
                cx.check_cost(Role::Net, cost.grown(net_bits), T::EXACT)?;
                discrete_coons(&coords).map_err(lib(Role::Net, NET_FORM))?
            }
            Some((alpha, beta)) => {
                if self.steps {
                    return Err(OpError::new(
                        Role::Steps,
                        Kind::Usage,
                        "has no effect with a mask (the mask is solved as one linear system)",
                        "steps without a mask (the parts of the discrete Coons formula)",
                    ));
                }
                let mask =
                    Mask::new(alpha.clone(), beta.clone()).map_err(lib(Role::Mask, MASK_FORM))?;
                if T::EXACT {
                    // The exact band solve on numbers as large as the net's and the mask's;
                    // the library refuses its operation count itself, counting each as one.
                    let bits = net_bits.max(max_bits(&[mask.alpha(), mask.beta()]));
                    let cost = mask.solve_cost(m, n).times(d as u128).grown(bits);
                    cx.check_cost(Role::Net, cost, T::EXACT)?;
                }
                solve_mask(&coords, &mask, &cx.limits).map_err(lib(Role::Net, NET_FORM))?
            }
        };
        let grid = PointGrid::from_shape_fn((m1, n1, d), |(i, j, k)| full[k][(i, j)].clone());
        let mut report = Report::new();
        if self.steps {
            let parts = discrete_coons_parts(&coords).map_err(lib(Role::Net, NET_FORM))?;
            for (name, part) in ["bu", "bv", "buv"].into_iter().zip(parts) {
                let g = PointGrid::from_shape_fn((m1, n1, d), |(i, j, k)| part[k][(i, j)].clone());
                report.push(name, Value::Grid(g));
            }
        }
        let drawing = self.drawing.then(|| {
            let g = grid_f64(&grid);
            Drawing::new("discrete Coons net")
                .surface(g.clone(), "net as a surface")
                .net(g, Colour::Red, "control net")
        });
        report.push("result", Value::Grid(grid));
        Ok(Answer {
            report,
            drawing,
            mesh: None,
        })
    }
}
