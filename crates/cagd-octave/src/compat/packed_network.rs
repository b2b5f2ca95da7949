//! Appendix D's packed curve network (`g_u`, `g_v`, `g_uv`, nodes), unpacked in one place:
//! [`krpa_gordon`](super::krpa_gordon) and the command line's `cagd gordon --script` both read
//! their networks through [`PackedNetwork::unpack`], so the same data gives the same surface.

use nalgebra::{DMatrix, DVector};

use cagd::coons::Tolerance;
use cagd::error::{Error, Result};
use cagd::gordon::GordonSurface;
use cagd::lagrange::check_nodes;
use cagd::param::{Curve, SampledCurve};
use cagd::Scalar;

/// A Gordon network as appendix D's data script packs it, unpacked into sampled curves.
///
/// # Layout (`m+1` nodes `x_u`, `n+1` nodes `x_v`)
/// - `g_u`: `3 × (n+1)N`, `[c_0 c_1 … c_n]`, the curves `c_j = g(·, v_j)` (functions of `u`)
///   side by side, each sampled at `N ≥ 2` parameters `u` (`linspace(0,1,N)` in the thesis);
/// - `g_v`: `3 × (m+1)N'`, `[d_0 d_1 … d_m]`, the curves `d_i = g(u_i, ·)` (functions of `v`),
///   each sampled at `N' ≥ 2` parameters `v`;
/// - `g_uv`: `(m+1) × 3(n+1)`, the crossings, `g_uv(i+1, 3j+1:3j+3) = g(u_i, v_j)` (appendix D's
///   `g_uv = [g00 g10 g20; g01 g11 g21; g02 g12 g22]`, whose printed `g_ab` is `g(u_b, v_a)`);
/// - `x_u`, `x_v`: the nodes, strictly increasing, at least 2 each (appendix D uses one `x`
///   for both).
///
/// # Nodes that are not sample parameters
/// Each network curve is the polyline through its samples ([`SampledCurve`]) **with its
/// crossings added as vertices where a node is not one of its sample parameters**: the curve
/// `d_i` gets the point `g(u_i, v_j)` at `v = v_j`, the curve `c_j` the point `g(u_i, v_j)` at
/// `u = u_i`. Where a node is a sample parameter the sample stays, and building the surface
/// checks it against the crossing ([`Error::NetworkMismatch`] beyond the tolerance). So the
/// thesis's own data (`N = 10`, nodes `[0 0.5 1]`: 0.5 is not in `linspace(0,1,10)`) is
/// accepted, the crossing at 0.5 known exactly, as the thesis's `krpaGordon` uses it (it blends
/// `g_uv` at the nodes and the samples at the grid). The crossings are trusted where they are
/// added: a crossing off its sampled curve there is not detected, only a kink appears.
///
/// ```
/// use cagd_octave::compat::PackedNetwork;
/// use cagd::Surface;
/// use nalgebra::DMatrix;
/// // The plane g(u, v) = (u, v, u + v) at nodes {0, 1/2, 1}, sampled at N = 2 (u, v ∈ {0, 1}).
/// let g = |u: f64, v: f64| [u, v, u + v];
/// let (x, t) = ([0.0, 0.5, 1.0], [0.0, 1.0]);
/// let g_u = DMatrix::from_fn(3, 6, |c, k| g(t[k % 2], x[k / 2])[c]);
/// let g_v = DMatrix::from_fn(3, 6, |c, k| g(x[k / 2], t[k % 2])[c]);
/// let g_uv = DMatrix::from_fn(3, 9, |i, k| g(x[i], x[k / 3])[k % 3]);
/// let net = PackedNetwork::unpack(&g_u, &g_v, &g_uv, x.to_vec(), x.to_vec(), |_, n| cagd::linspace(0.0, 1.0, n))?;
/// // The crossing at 1/2 was added to every curve: 2 samples + 1 crossing.
/// assert_eq!(net.curves_at_u()[0].params(), &[0.0, 0.5, 1.0]);
/// let p = net.surface()?.eval(0.25, 0.5);
/// assert!((p - nalgebra::dvector![0.25, 0.5, 0.75]).amax() < 1e-15);
/// # Ok::<(), cagd::Error>(())
/// ```
#[derive(Debug, Clone)]
pub struct PackedNetwork<T: Scalar = f64> {
    u_nodes: Vec<T>,
    v_nodes: Vec<T>,
    u_samples: Vec<T>,
    v_samples: Vec<T>,
    curves_at_u: Vec<SampledCurve<T>>,
    curves_at_v: Vec<SampledCurve<T>>,
    points: Vec<Vec<DVector<T>>>,
}

/// The dimension of appendix D's points (x y z side by side in `g_uv`).
const DIM: usize = 3;

impl<T: Scalar> PackedNetwork<T> {
    /// Unpacks `g_u`, `g_v`, `g_uv` (see the [layout](Self)) with the nodes `x_u`, `x_v`.
    /// `sample_params("u", N)` gives the `N` parameters at which each curve of `g_u` is
    /// sampled, `sample_params("v", N')` those of `g_v` (`N`, `N'` follow from the widths of
    /// the matrices; the thesis samples at `linspace(0,1,N)`, a data script may define `u` and
    /// `v`).
    ///
    /// # Errors
    /// [`Error::TooFewCurves`] for fewer than 2 nodes in a direction (as
    /// [`GordonSurface::new`]); [`Error::ShapeMismatch`] naming `g_u`, `g_v` or `g_uv` when a
    /// matrix does not fit the
    /// node counts (`found` says its size and the count, `expected` the layout);
    /// [`Error::NonFinite`], [`Error::DuplicateNodes`], [`Error::UnsortedNodes`] for nodes
    /// (`x_u`, `x_v`) that are not finite and strictly increasing; the errors of
    /// [`SampledCurve::new`] for sample parameters or samples it refuses (fewer than 2, not
    /// finite, not strictly increasing); [`Error::NonFinite`] for a NaN or infinite crossing.
    pub fn unpack(
        g_u: &DMatrix<T>,
        g_v: &DMatrix<T>,
        g_uv: &DMatrix<T>,
        x_u: Vec<T>,
        x_v: Vec<T>,
        sample_params: impl Fn(&'static str, usize) -> Vec<T>,
    ) -> Result<Self> {
        let (mu, nv) = (x_u.len(), x_v.len());
        for (what, count) in [
            ("Gordon curves g(u_i, v)", mu),
            ("Gordon curves g(u, v_j)", nv),
        ] {
            if count < 2 {
                return Err(Error::TooFewCurves {
                    what,
                    min: 2,
                    found: count,
                });
            }
        }
        let n_u = samples_per_curve("g_u", g_u, nv, "g(u, v_j)", "v_j")?;
        let n_v = samples_per_curve("g_v", g_v, mu, "g(u_i, v)", "u_i")?;
        if g_uv.nrows() != mu || g_uv.ncols() != DIM * nv {
            return Err(Error::ShapeMismatch {
                what: "g_uv",
                expected: "k_u × 3k_v: row i holds g(u_i, v_j) for j = 1..k_v, x y z side by side"
                    .into(),
                found: format!("{}×{} for {mu} × {nv} nodes", g_uv.nrows(), g_uv.ncols()),
            });
        }
        check_nodes("x_u", &x_u, 2)?;
        check_nodes("x_v", &x_v, 2)?;
        cagd::error::check_finite("g_uv", g_uv.iter())?;
        let points: Vec<Vec<DVector<T>>> = (0..mu)
            .map(|i| {
                (0..nv)
                    .map(|j| DVector::from_fn(DIM, |c, _| g_uv[(i, DIM * j + c)].clone()))
                    .collect()
            })
            .collect();
        let u_samples = sample_params("u", n_u);
        let v_samples = sample_params("v", n_v);
        // d_i = g(u_i, ·): samples g_v(:, i*N' ..), crossings g(u_i, v_j) at v_j.
        let curves_at_u = (0..mu)
            .map(|i| {
                let crossings = x_v.iter().zip(&points[i]);
                with_crossings(
                    &v_samples,
                    g_v.columns(i * n_v, n_v).into_owned(),
                    crossings,
                )
            })
            .collect::<Result<Vec<_>>>()?;
        // c_j = g(·, v_j): samples g_u(:, j*N ..), crossings g(u_i, v_j) at u_i.
        let curves_at_v = (0..nv)
            .map(|j| {
                let crossings = x_u.iter().zip(points.iter().map(|row| &row[j]));
                with_crossings(
                    &u_samples,
                    g_u.columns(j * n_u, n_u).into_owned(),
                    crossings,
                )
            })
            .collect::<Result<Vec<_>>>()?;
        Ok(PackedNetwork {
            u_nodes: x_u,
            v_nodes: x_v,
            u_samples,
            v_samples,
            curves_at_u,
            curves_at_v,
            points,
        })
    }

    /// The nodes `u_0 < … < u_m`.
    pub fn u_nodes(&self) -> &[T] {
        &self.u_nodes
    }

    /// The nodes `v_0 < … < v_n`.
    pub fn v_nodes(&self) -> &[T] {
        &self.v_nodes
    }

    /// The parameters at which `g_u` is sampled (in `u`), as given, without crossings.
    pub fn u_samples(&self) -> &[T] {
        &self.u_samples
    }

    /// The parameters at which `g_v` is sampled (in `v`), as given, without crossings.
    pub fn v_samples(&self) -> &[T] {
        &self.v_samples
    }

    /// The curves `d_i = g(u_i, ·)`, one per node `u_i` (from `g_v`, crossings added).
    pub fn curves_at_u(&self) -> &[SampledCurve<T>] {
        &self.curves_at_u
    }

    /// The curves `c_j = g(·, v_j)`, one per node `v_j` (from `g_u`, crossings added).
    pub fn curves_at_v(&self) -> &[SampledCurve<T>] {
        &self.curves_at_v
    }

    /// The crossings, `points()[i][j] = g(u_i, v_j)`.
    pub fn points(&self) -> &[Vec<DVector<T>>] {
        &self.points
    }

    /// The Gordon surface of the network ([`GordonSurface::with_points`], crossings given,
    /// the network checked with the default [`Tolerance`]).
    ///
    /// # Errors
    /// Those of [`GordonSurface::with_points`], notably [`Error::NetworkMismatch`] when a
    /// sample at a node is not its crossing.
    pub fn surface(&self) -> Result<GordonSurface<SampledCurve<T>, T>> {
        GordonSurface::with_points(
            self.u_nodes.clone(),
            self.v_nodes.clone(),
            self.curves_at_u.clone(),
            self.curves_at_v.clone(),
            self.points.clone(),
            Tolerance::default(),
        )
    }
}

/// The number of samples per curve of a packed matrix of `count` curves side by side.
fn samples_per_curve<T: Scalar>(
    what: &'static str,
    m: &DMatrix<T>,
    count: usize,
    curves: &str,
    node: &str,
) -> Result<usize> {
    if m.nrows() != DIM || m.ncols() % count != 0 || m.ncols() / count < 2 {
        return Err(Error::ShapeMismatch {
            what,
            expected: format!(
                "3 × k·N: the k curves {curves}, one per node {node}, of N ≥ 2 samples each, side by side"
            ),
            found: format!("{}×{} for {count} nodes", m.nrows(), m.ncols()),
        });
    }
    Ok(m.ncols() / count)
}

/// The polyline through `samples` (one point per column) at `params`, with each crossing
/// `(node, point)` whose node is not a sample parameter added as a vertex. Its domain is that
/// of the samples, `[params[0], params[last]]`, also when a node lies outside it.
fn with_crossings<'a, T: Scalar>(
    params: &[T],
    samples: DMatrix<T>,
    crossings: impl Iterator<Item = (&'a T, &'a DVector<T>)>,
) -> Result<SampledCurve<T>> {
    let curve = SampledCurve::new(params.to_vec(), samples)?;
    let mut params = curve.params().to_vec();
    let mut columns: Vec<DVector<T>> = curve
        .samples()
        .column_iter()
        .map(|c| c.into_owned())
        .collect();
    for (node, point) in crossings {
        if !params.contains(node) {
            let at = params.partition_point(|p| p < node);
            params.insert(at, node.clone());
            columns.insert(at, point.clone());
        }
    }
    if columns.len() == curve.params().len() {
        return Ok(curve);
    }
    let (start, end) = curve.domain();
    SampledCurve::new(params, DMatrix::from_columns(&columns))?.with_domain(start, end)
}

#[cfg(test)]
mod tests {
    use super::*;
    use num_rational::BigRational as Q;

    /// The network of `g(u, v) = (u, v, u² v)` at the given nodes, sampled at N points.
    fn network(xu: &[f64], xv: &[f64], n: usize) -> [DMatrix<f64>; 3] {
        let g = |u: f64, v: f64| [u, v, u * u * v];
        let t = cagd::linspace(0.0, 1.0, n);
        [
            DMatrix::from_fn(3, xv.len() * n, |c, k| g(t[k % n], xv[k / n])[c]),
            DMatrix::from_fn(3, xu.len() * n, |c, k| g(xu[k / n], t[k % n])[c]),
            DMatrix::from_fn(xu.len(), 3 * xv.len(), |i, k| g(xu[i], xv[k / 3])[k % 3]),
        ]
    }

    fn unpack(
        [g_u, g_v, g_uv]: &[DMatrix<f64>; 3],
        xu: &[f64],
        xv: &[f64],
    ) -> Result<PackedNetwork> {
        PackedNetwork::unpack(g_u, g_v, g_uv, xu.to_vec(), xv.to_vec(), |_, n| {
            cagd::linspace(0.0, 1.0, n)
        })
    }

    #[test]
    fn crossings_are_added_only_where_a_node_is_not_a_sample() {
        let (xu, xv) = ([0.0, 0.3, 1.0], [0.5, 0.7]);
        let net = unpack(&network(&xu, &xv, 3), &xu, &xv).unwrap();
        // g(u_i, ·) sampled at 0, 0.5, 1: 0.5 is a sample, 0.7 is added.
        assert_eq!(net.curves_at_u()[1].params(), &[0.0, 0.5, 0.7, 1.0]);
        assert_eq!(
            net.curves_at_u()[1].samples().column(2).as_slice(),
            &[0.3, 0.7, 0.3 * 0.3 * 0.7]
        );
        // g(·, v_j) sampled at 0, 0.5, 1: 0 and 1 are samples, 0.3 is added.
        assert_eq!(net.curves_at_v()[0].params(), &[0.0, 0.3, 0.5, 1.0]);
        assert_eq!(
            (net.u_samples(), net.v_samples()),
            (&[0.0, 0.5, 1.0][..], &[0.0, 0.5, 1.0][..])
        );
        assert_eq!(net.points()[2][1].as_slice(), &[1.0, 0.7, 0.7]);
        let s = net.surface().unwrap();
        assert_eq!((s.u_nodes(), s.v_nodes()), (&xu[..], &xv[..]));
    }

    #[test]
    fn shapes_nodes_and_samples_are_checked() {
        let (xu, xv) = ([0.0, 0.5, 1.0], [0.0, 1.0]);
        let net = network(&xu, &xv, 3);
        let [g_u, g_v, g_uv] = net.clone();
        let swapped = [g_v.clone(), g_u.clone(), g_uv.clone()];
        assert!(matches!(
            unpack(&swapped, &xu, &xv),
            Err(Error::ShapeMismatch { what: "g_u", .. })
        ));
        let e = unpack(&[g_u.clone(), g_v.clone(), g_uv.transpose()], &xu, &xv).unwrap_err();
        assert!(
            matches!(e, Error::ShapeMismatch { what: "g_uv", .. }),
            "{e:?}"
        );
        assert!(matches!(
            unpack(&net, &xu, &[0.5]),
            Err(Error::TooFewCurves { found: 1, .. })
        ));
        assert!(matches!(
            unpack(&net, &[0.0, 1.0, 0.5], &xv),
            Err(Error::UnsortedNodes { what: "x_u", .. })
        ));
        assert!(matches!(
            unpack(&net, &xu, &[1.0, 1.0]),
            Err(Error::DuplicateNodes { what: "x_v", .. })
        ));
        let mut bad = g_uv.clone();
        bad[(0, 0)] = f64::NAN;
        assert!(matches!(
            unpack(&[g_u.clone(), g_v.clone(), bad], &xu, &xv),
            Err(Error::NonFinite { what: "g_uv", .. })
        ));
        // Sample parameters that do not increase are the sampled curve's error.
        let e = PackedNetwork::unpack(&g_u, &g_v, &g_uv, xu.to_vec(), xv.to_vec(), |_, n| {
            vec![0.0; n]
        })
        .unwrap_err();
        assert!(matches!(e, Error::InvalidArgument { .. }), "{e:?}");
    }

    #[test]
    fn exact_networks_unpack_exactly() {
        let q = |n: i64, d: i64| <Q as Scalar>::from_ratio(n, d);
        let g = |u: &Q, v: &Q| [u.clone(), v.clone(), u.clone() * u.clone() * v.clone()];
        let t = [q(0, 1), q(1, 2), q(1, 1)];
        let x = [q(0, 1), q(1, 3), q(1, 1)];
        let g_u = DMatrix::from_fn(3, 9, |c, k| g(&t[k % 3], &x[k / 3])[c].clone());
        let g_v = DMatrix::from_fn(3, 9, |c, k| g(&x[k / 3], &t[k % 3])[c].clone());
        let g_uv = DMatrix::from_fn(3, 9, |i, k| g(&x[i], &x[k / 3])[k % 3].clone());
        let net =
            PackedNetwork::unpack(&g_u, &g_v, &g_uv, x.to_vec(), x.to_vec(), |_, _| t.to_vec())
                .unwrap();
        let s = net.surface().unwrap();
        use cagd::Surface;
        // Degree 2 in u and 1 in v: reproduced exactly at the nodes' crossings.
        assert_eq!(
            s.eval(q(1, 3), q(1, 3)),
            DVector::from_vec(g(&q(1, 3), &q(1, 3)).to_vec())
        );
    }
}
