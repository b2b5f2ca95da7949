//! `krpaGordon` (thesis appendix D, Algoritem 7).

use ndarray::ArrayView2;

use super::lagrange::node_vector;
use super::{
    check_finite_array, check_shape, samples, to_dmatrix, untenzor, PackedNetwork, SampledPatch,
};
use crate::literal::LiteralScalar;
use cagd::error::{Error, Result};
use cagd::gordon::GordonSurface;
use cagd::param::{SampledCurve, Surface};

/// The Gordon surface of a sampled curve network on `linspace(0,1,N)²`: the twin of the
/// thesis's `krpaGordon` (appendix D, Algoritem 7), as fixed in `octave_ref/fixed/krpaGordon.m`.
///
/// **Original:** `function krpaGordon(g_u,g_v,g_uv,x,N)` — no output; it draws the surface.
/// **Fixed Octave:** `[R, P] = krpaGordon(g_u, g_v, g_uv, x_u, x_v, N)`.
///
/// ```text
/// g = g1 + g2 − g12 (Izrek 4.4),   g1(u,v) = Σ_j c_j(u) L_j(v),   g2(u,v) = Σ_i d_i(v) L_i(u),
/// g12(u,v) = Σ_i Σ_j g(u_i, v_j) L_i(u) L_j(v),
/// ```
///
/// `L_i` the Lagrange basis of the nodes `x_u`, `L_j` that of `x_v`.
///
/// # Layout (`m+1` nodes `x_u`, `n+1` nodes `x_v`, `m ≠ n` allowed)
/// - `g_u`: `3 × (n+1)N`, `[c_0 c_1 … c_n]`, the curves `c_j = g(·, v_j)` (functions of `u`)
///   sampled at `t = linspace(0,1,N)`: `g_u(:, j*N + i) = g(t(i), v_j)` (`j` from 0, `i` from 1).
/// - `g_v`: `3 × (m+1)N`, `[d_0 d_1 … d_m]`, the curves `d_i = g(u_i, ·)` sampled at `t`:
///   `g_v(:, i*N + j) = g(u_i, t(j))`.
/// - `g_uv`: `(m+1) × 3(n+1)`, the crossings, `g_uv(i+1, 3j+1:3j+3) = g(u_i, v_j)` — the layout
///   of appendix D's `g_uv = [g00 g10 g20; g01 g11 g21; g02 g12 g22]` (whose printed `g_ab` is
///   `g(u_b, v_a)`).
/// - `x_u`: the nodes `u_0 < … < u_m`; `x_v`: the nodes `v_0 < … < v_n` (rows or columns).
/// - `n`: the number of samples `N` per direction.
/// - result: [`SampledPatch`], `R` (`N × 3N`) and `P` (`N × N × 3`).
///
/// # Bugs of the original fixed here (`octave_ref/BUGS.md`)
/// - **Indexing of the sampled curves:** it took the counts of curves from the numbers of
///   sample columns (`m = size(g_u)(2)` = 3N), and read `g_u(:,l)` — sample `l` of the first
///   curve — as curve `l`. Here curve `c_j` at `t(i)` is `g_u(:, j*N + i)`.
/// - **Crossings as rows:** it added the 1×3 row `g_uv(l, s+c:s+c+2)` to the 3×1 columns `g1`,
///   `g2`, which Octave broadcasts to 3×3; here the crossings are points.
/// - **One node vector, one count:** `x` and the loop bounds served both directions; here
///   `x_u`, `x_v` and the counts are separate.
/// - `g1 = g2 = g12 = 0` is a chained assignment that only Octave accepts; the data script uses
///   `u`, `v` undefined and `u^2` on vectors; the original `Lagrange` it calls is always 0; it
///   returned nothing and grew `R` from `zeros(N,N)`.
///
/// # Native function
/// [`PackedNetwork::unpack`] (the one unpacker of appendix D's data, also behind
/// `cagd gordon --script`), [`PackedNetwork::surface`]
/// ([`GordonSurface::with_points`](cagd::gordon::GordonSurface::with_points)) and
/// [`Surface::eval_grid`] on `linspace(0,1,N)²`. Each curve is a
/// [`SampledCurve`](cagd::param::SampledCurve) through its samples at `t` and, where a node is
/// not a sample parameter, its crossing `g_uv` at the node (so it returns every sample and
/// every crossing exactly); the network is checked where a node is a sample parameter
/// (relative tolerance `1e-10`, see [`Tolerance`](cagd::coons::Tolerance)). The native surface
/// blends with the barycentric Lagrange basis, the Octave code with products: on
/// well-conditioned nodes (the thesis's, and every network of the differential test) the
/// values agree within the crate's tolerance (4 ULPs or 1e-14 relative to the scale of the
/// grid). For clustered nodes the blending amplifies rounding by `κ = Λ_u + Λ_v + Λ_u Λ_v`
/// (Lebesgue constants, see
/// [`GordonSurface::conditioning`](cagd::gordon::GordonSurface::conditioning)), and both
/// results — ours and Octave's — are then within `κ·ε` of the exact surface, not necessarily
/// within 1e-14 of each other (`crates/cagd-octave/tests/it/octave_compat.rs` checks both against exact rational
/// arithmetic for such networks).
///
/// # Errors
/// [`Error::ShapeMismatch`] for a node vector that is not a row or column, or a network matrix
/// of the wrong size (named); [`Error::TooFewPoints`] for `N < 2`; [`Error::TooFewCurves`]
/// for fewer than 2 nodes in a direction;
/// [`Error::DuplicateNodes`], [`Error::UnsortedNodes`] (the native surface wants increasing
/// nodes; the fixed Octave accepts any order) and [`Error::NonFinite`] for bad nodes or values;
/// [`Error::NetworkMismatch`] when a crossing is not where its curves pass.
///
/// ```
/// use cagd_octave::compat::krpa_gordon;
/// use ndarray::{array, Array2};
/// // The plane g(u, v) = (u, v, u + v) cut at u, v ∈ {0, 1} (a Coons network), N = 3.
/// let g = |u: f64, v: f64| [u, v, u + v];
/// let t = [0.0, 0.5, 1.0];
/// let nodes = [0.0, 1.0];
/// let g_u = Array2::from_shape_fn((3, 6), |(c, k)| g(t[k % 3], nodes[k / 3])[c]);
/// let g_v = Array2::from_shape_fn((3, 6), |(c, k)| g(nodes[k / 3], t[k % 3])[c]);
/// let g_uv = Array2::from_shape_fn((2, 6), |(i, k)| g(nodes[i], nodes[k / 3])[k % 3]);
/// let x = array![[0.0, 1.0]];
/// let s = krpa_gordon(g_u.view(), g_v.view(), g_uv.view(), x.view(), x.view(), 3)?;
/// assert_eq!(s.p.dim(), (3, 3, 3));
/// assert_eq!(s.r.row(1).to_vec(), vec![0.5, 0.0, 0.5, 0.5, 0.5, 1.0, 0.5, 1.0, 1.5]);
/// # Ok::<(), cagd::Error>(())
/// ```
pub fn krpa_gordon<T: LiteralScalar>(
    g_u: ArrayView2<'_, T>,
    g_v: ArrayView2<'_, T>,
    g_uv: ArrayView2<'_, T>,
    x_u: ArrayView2<'_, T>,
    x_v: ArrayView2<'_, T>,
    n: usize,
) -> Result<SampledPatch<T>> {
    let (surface, t) = krpa_gordon_surface(g_u, g_v, g_uv, x_u, x_v, n)?;
    let p = crate::arrays::to_array3(surface.eval_grid(&t, &t));
    let r = untenzor(p.view())?;
    Ok(SampledPatch { r, p })
}

/// The Gordon surface of sampled curves that `krpaGordon` evaluates.
pub type SampledGordon<T> = GordonSurface<SampledCurve<T>, T>;

/// [`krpa_gordon`] up to its grid: the Gordon surface of the network, checked, and the
/// samples `t = linspace(0,1,N)` at which `krpaGordon` evaluates it on `t × t`. For a caller
/// that evaluates the grid itself (band by band, between which it may be interrupted).
///
/// # Errors
/// As [`krpa_gordon`].
pub fn krpa_gordon_surface<T: LiteralScalar>(
    g_u: ArrayView2<'_, T>,
    g_v: ArrayView2<'_, T>,
    g_uv: ArrayView2<'_, T>,
    x_u: ArrayView2<'_, T>,
    x_v: ArrayView2<'_, T>,
    n: usize,
) -> Result<(SampledGordon<T>, Vec<T>)> {
    let u_nodes = node_vector("krpa_gordon: x_u", &x_u)?;
    let v_nodes = node_vector("krpa_gordon: x_v", &x_v)?;
    let (mu, nv) = (u_nodes.len(), v_nodes.len());
    check_shape("krpa_gordon: g_u", &g_u, Some(3), Some(nv * n))?;
    check_shape("krpa_gordon: g_v", &g_v, Some(3), Some(mu * n))?;
    check_shape("krpa_gordon: g_uv", &g_uv, Some(mu), Some(3 * nv))?;
    if n < 2 {
        return Err(Error::TooFewPoints {
            what: "krpa_gordon: N",
            min: 2,
            found: n,
        });
    }
    check_finite_array("krpa_gordon: g_u", &g_u)?;
    check_finite_array("krpa_gordon: g_v", &g_v)?;
    check_finite_array("krpa_gordon: g_uv", &g_uv)?;
    let network = PackedNetwork::unpack(
        &to_dmatrix(&g_u),
        &to_dmatrix(&g_v),
        &to_dmatrix(&g_uv),
        u_nodes,
        v_nodes,
        |_, count| samples::<T>(count),
    )?;
    Ok((network.surface()?, samples::<T>(n)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use ndarray::{array, Array2};

    /// The network of `g(u, v) = (u, v, u² v)` at the given nodes, sampled at N points.
    fn network(xu: &[f64], xv: &[f64], n: usize) -> (Array2<f64>, Array2<f64>, Array2<f64>) {
        let g = |u: f64, v: f64| [u, v, u * u * v];
        let t = cagd::linspace::linspace(0.0, 1.0, n);
        let g_u = Array2::from_shape_fn((3, xv.len() * n), |(c, k)| g(t[k % n], xv[k / n])[c]);
        let g_v = Array2::from_shape_fn((3, xu.len() * n), |(c, k)| g(xu[k / n], t[k % n])[c]);
        let g_uv = Array2::from_shape_fn((xu.len(), 3 * xv.len()), |(i, k)| {
            g(xu[i], xv[k / 3])[k % 3]
        });
        (g_u, g_v, g_uv)
    }

    #[test]
    fn separate_nodes_off_the_sample_grid_reproduce_the_surface() {
        // Degree (2, 1) in (u, v): three u nodes and two v nodes reproduce it exactly.
        let (xu, xv) = ([0.0, 0.3, 1.0], [0.1, 0.7]);
        let (g_u, g_v, g_uv) = network(&xu, &xv, 5);
        let s = krpa_gordon(
            g_u.view(),
            g_v.view(),
            g_uv.view(),
            array![xu].view(),
            array![xv].view(),
            5,
        )
        .unwrap();
        let t = cagd::linspace::linspace(0.0, 1.0, 5);
        for i in 0..5 {
            for j in 0..5 {
                let want = [t[i], t[j], t[i] * t[i] * t[j]];
                for (c, w) in want.iter().enumerate() {
                    assert!((s.p[[i, j, c]] - w).abs() < 1e-14, "({i},{j},{c})");
                }
            }
        }
    }

    #[test]
    fn bad_networks_are_errors() {
        let (xu, xv) = ([0.0, 0.5, 1.0], [0.0, 1.0]);
        let (g_u, g_v, mut g_uv) = network(&xu, &xv, 3);
        let (x_u, x_v) = (array![xu], array![xv]);
        let e = krpa_gordon(
            g_v.view(),
            g_u.view(),
            g_uv.view(),
            x_u.view(),
            x_v.view(),
            3,
        )
        .unwrap_err();
        assert!(
            matches!(
                e,
                Error::ShapeMismatch {
                    what: "krpa_gordon: g_u",
                    ..
                }
            ),
            "{e:?}"
        );
        let e = krpa_gordon(
            g_u.view(),
            g_v.view(),
            g_uv.view(),
            x_v.view(),
            x_u.view(),
            3,
        )
        .unwrap_err();
        assert!(matches!(e, Error::ShapeMismatch { .. }), "{e:?}");
        let e = krpa_gordon(
            g_u.view(),
            g_v.view(),
            g_uv.view(),
            x_u.view(),
            x_v.view(),
            1,
        )
        .unwrap_err();
        assert!(
            matches!(e, Error::ShapeMismatch { .. } | Error::TooFewPoints { .. }),
            "{e:?}"
        );
        // A crossing off its curves (u = 0.5 and v = 0 are both sample parameters).
        g_uv[[1, 2]] += 0.25;
        let e = krpa_gordon(
            g_u.view(),
            g_v.view(),
            g_uv.view(),
            x_u.view(),
            x_v.view(),
            3,
        )
        .unwrap_err();
        assert!(matches!(e, Error::NetworkMismatch { .. }), "{e:?}");
        let unsorted = array![[0.0, 1.0, 0.5]];
        let e = krpa_gordon(
            g_u.view(),
            g_v.view(),
            g_uv.view(),
            unsorted.view(),
            x_v.view(),
            3,
        )
        .unwrap_err();
        assert!(matches!(e, Error::UnsortedNodes { .. }), "{e:?}");
    }
}
