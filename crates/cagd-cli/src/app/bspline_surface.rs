//! `bspline-surface` (and the shared part of `nurbs-surface`): tensor-product B-spline and
//! NURBS surfaces (the CAD notes §1.2–1.3, the lecture notes "B-spline plocha").
//!
//! The control net is given as for `bezier-patch` (packed `(m+1)×3(n+1)` as the thesis's
//! `ploskevB` takes it, or an Octave `(m+1)×(n+1)×3` array file), or as an octave-nurbs
//! `nrbmak` struct saved with `save -text` (fields `coefs`, the homogeneous `4×nu×nv` array
//! `[w·x; w·y; w·z; w]`, `knots` a cell `{ku, kv}`, `order` `[p+1 q+1]`).

use cagd::bspline::{basis_all, BSplineSurface, KnotVector};
use cagd::grid::PointGrid;
use cagd::limits::Limits;
use cagd::nurbs::NurbsSurface;
use cagd::Surface;
use cagd_octave::literal::LiteralScalar;
use cagd_octave::text_format::{self, Value as OValue};
use clap::Args;
use nalgebra::DMatrix;

use crate::args::{MeshArgs, OutputArgs, PlotArgs, StepsArgs, SurfaceParamArgs};
use crate::plot::{Colour, Figure};
use crate::{
    load_net, load_params, read_text, samples, scalar_from_double, CliError, ErrorKind,
    PendingWrites, Report, Value,
};

use super::bezier::point_mode;
use super::common::*;
use super::work::{bits, check_work, weigh};
use super::Outcome;
use cagd::cost::polynomial_bits;
use cagd::cost::Cost;

/// The arguments of `bspline-surface` and `nurbs-surface`.
#[derive(Debug, Args)]
pub struct SplineSurfaceArgs {
    /// The control net: packed (m+1)×3(n+1) as ploskevB takes it (row i = [P_i0 P_i1 … P_in],
    /// x y z side by side), an Octave (m+1)×(n+1)×3 array file, or an Octave save -text file
    /// holding an octave-nurbs nrbmak struct (FILE or FILE:NAME).
    #[arg(value_name = "NET", allow_hyphen_values = true)]
    pub net: Option<String>,
    /// Instead of NET: the x coordinates of the control points, an (m+1)×(n+1) matrix with
    /// entry (i, j) of P_ij (i along u; the lecture notes' X_S has its rows along v: pass its
    /// transpose).
    #[arg(
        long,
        value_name = "MATRIX",
        allow_hyphen_values = true,
        conflicts_with = "net"
    )]
    pub x: Option<String>,
    /// The y coordinates (with --x).
    #[arg(
        long,
        value_name = "MATRIX",
        allow_hyphen_values = true,
        requires = "x"
    )]
    pub y: Option<String>,
    /// The z coordinates (with --x and --y).
    #[arg(
        long,
        value_name = "MATRIX",
        allow_hyphen_values = true,
        requires = "y"
    )]
    pub z: Option<String>,
    /// The degrees: P for both directions or P,Q (default 3, or the struct's order − 1).
    #[arg(long, value_name = "P[,Q]", allow_hyphen_values = true)]
    pub degree: Option<String>,
    /// The orders K = P + 1 instead of the degrees: K or K,L.
    #[arg(long, value_name = "K[,L]", allow_hyphen_values = true)]
    pub order: Option<String>,
    /// The knot vector along u (rows of the net); default clamped uniform on [0, 1].
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub uknots: Option<String>,
    /// The knot vector along v (columns of the net); default clamped uniform on [0, 1].
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub vknots: Option<String>,
    #[command(flatten)]
    pub params: SurfaceParamArgs,
    #[command(flatten)]
    pub steps: StepsArgs,
    #[command(flatten)]
    pub output: OutputArgs,
    #[command(flatten)]
    pub plot: PlotArgs,
    #[command(flatten)]
    pub mesh: MeshArgs,
}

/// A tensor-product B-spline surface (the CAD notes, the lecture notes).
#[derive(Debug, Args)]
#[command(after_help = "\
Input: the control net packed (m+1)×3(n+1) as for bezier-patch, an Octave (m+1)×(n+1)×3 array
file, or an Octave save -text file with an octave-nurbs nrbmak struct (weights all 1);
--degree P or P,Q (or --order), --uknots and --vknots (default clamped uniform).
Layout: single --u and --v give the 3×1 point; otherwise the grid nu×nv×3, or --list. Parameters
default to --n samples of the domain; outside it the surface is not defined (an error). --steps
prints the knots and the basis values N_i,p(u), N_j,q(v).

Example:
  cagd bspline-surface net.txt --degree 2 --n 20 --plot surface.png --mesh surface.stl")]
pub struct BSplineSurfaceCommand {
    #[command(flatten)]
    pub args: SplineSurfaceArgs,
}

/// A surface read from an nrbmak struct: degrees, knots, homogeneous net.
struct NrbStruct<T: LiteralScalar> {
    degrees: (usize, usize),
    knots: (Vec<T>, Vec<T>),
    /// One `nu × nv` matrix per homogeneous coordinate, the weights last.
    homogeneous: Vec<DMatrix<T>>,
}

const STRUCT_FORM: &str =
    "an octave-nurbs surface struct (nrbmak(coefs, {ku, kv})) with coefs 4×nu×nv, knots {ku, kv} and order [p+1 q+1]";

/// The nrbmak struct of an Octave text file, if the file holds one (`FILE` or `FILE:NAME`).
fn read_struct<T: LiteralScalar>(
    limits: &Limits,
    text: &str,
) -> Result<Option<NrbStruct<T>>, CliError> {
    let trimmed = text.trim();
    let (path, name) = match trimmed.rsplit_once(':') {
        Some((p, n)) if std::path::Path::new(p).is_file() => (p, Some(n)),
        _ => (trimmed, None),
    };
    if !std::path::Path::new(path).is_file() {
        return Ok(None);
    }
    let contents = read_text(limits, "NET", path)?;
    if !contents
        .lines()
        .take(20)
        .any(|l| l.trim_start().starts_with("# name:"))
    {
        return Ok(None);
    }
    let shown = format!("NET {trimmed}");
    let data =
        |problem: String| CliError::new(shown.clone(), problem, STRUCT_FORM, ErrorKind::Data);
    let ws = text_format::read_text_with(&contents, limits).map_err(|e| data(e.to_string()))?;
    let found = ws.iter().find(|(n, v)| {
        matches!(v, OValue::Struct(_)) && v.field("coefs").is_some() && name.is_none_or(|m| m == *n)
    });
    let Some((_, s)) = found else {
        return Ok(None);
    };
    let coefs = s
        .field("coefs")
        .and_then(|c| c.to_array_with(limits))
        .ok_or_else(|| data("`coefs` is not numeric".into()))?;
    let shape = coefs.shape().to_vec();
    if shape.len() != 3 || shape[0] != 4 {
        return Err(data(format!(
            "`coefs` is {shape:?}, not a surface's 4×nu×nv"
        )));
    }
    let knot_list: Vec<Vec<T>> = match s.field("knots") {
        Some(OValue::Cell(c)) if c.len() == 2 => c
            .iter()
            .map(|k| {
                k.to_array_with(limits)
                    .ok_or_else(|| data("a knot vector is not numeric".into()))?
                    .iter()
                    .map(|x| {
                        scalar_from_double::<T>(*x)
                            .ok_or_else(|| data("a knot is not finite".into()))
                    })
                    .collect()
            })
            .collect::<Result<_, _>>()?,
        _ => return Err(data("`knots` is not a cell {ku, kv}".into())),
    };
    let (nu, nv) = (shape[1], shape[2]);
    let mut homogeneous = Vec::with_capacity(4);
    for k in 0..4 {
        let mut m = DMatrix::from_element(nu, nv, T::zero());
        for i in 0..nu {
            for j in 0..nv {
                m[(i, j)] = scalar_from_double::<T>(coefs[[k, i, j]])
                    .ok_or_else(|| data("a coefficient is not finite".into()))?;
            }
        }
        homogeneous.push(m);
    }
    let order = |k: usize, count: usize, default: usize| -> usize {
        s.field("order")
            .and_then(|o| o.to_array_with(limits))
            .and_then(|o| o.iter().nth(k).copied())
            .filter(|x| *x >= 1.0 && x.fract() == 0.0)
            .map(|x| x as usize - 1)
            .unwrap_or(default.min(count.saturating_sub(1)))
    };
    let (ku, kv) = (knot_list[0].clone(), knot_list[1].clone());
    let p = order(0, nu, ku.len().saturating_sub(nu + 1));
    let q = order(1, nv, kv.len().saturating_sub(nv + 1));
    Ok(Some(NrbStruct {
        degrees: (p, q),
        knots: (ku, kv),
        homogeneous,
    }))
}

/// `P` or `P,Q` of `--degree` (or `K`/`K,L` of `--order`, minus one).
fn degrees(args: &SplineSurfaceArgs, limits: &Limits) -> Result<Option<(usize, usize)>, CliError> {
    let parse = |arg: &str, text: &str| -> Result<Vec<usize>, CliError> {
        let form = "one whole number for both directions, or two separated by a comma: 3 or 3,2";
        let values: Vec<f64> =
            cagd_octave::literal::parse_params_with(&format!("[{}]", text.trim()), limits)
                .map_err(|e| CliError::literal(arg, e, form))?;
        let ok = !values.is_empty()
            && values.len() <= 2
            && values
                .iter()
                .all(|x| *x >= 0.0 && x.fract() == 0.0 && *x < 1e6);
        if !ok {
            return Err(shape(arg, format!("`{}`", text.trim()), form));
        }
        Ok(values.into_iter().map(|x| x as usize).collect())
    };
    let (values, minus) = match (&args.degree, &args.order) {
        (Some(_), Some(_)) => {
            return Err(usage(
                "--order",
                "cannot be used together with --degree",
                "only one of them (the order k is the degree p + 1)",
            ))
        }
        (Some(d), None) => (parse("--degree", d)?, 0),
        (None, Some(o)) => (parse("--order", o)?, 1),
        (None, None) => return Ok(None),
    };
    if values.contains(&0) && minus == 1 {
        return Err(shape(
            "--order",
            "order 0".into(),
            "orders k ≥ 1 (the degree p = k − 1)",
        ));
    }
    let p = values[0] - minus;
    let q = values.get(1).map_or(p, |q| q - minus);
    Ok(Some((p, q)))
}

/// The parameters along one direction: given, or `--n` samples of the domain `[a, b]`; an
/// error outside the domain (a B-spline is not defined there).
fn domain_params<T: LiteralScalar>(
    limits: &Limits,
    argument: &str,
    given: &Option<String>,
    n: Option<usize>,
    (a, b): (T, T),
) -> Result<Vec<T>, CliError> {
    let values: Vec<T> = match given {
        Some(t) => load_params(limits, argument, t)?,
        None => {
            let unit: Vec<T> = samples(limits, n.unwrap_or(DEFAULT_SAMPLES), 2)?;
            unit.into_iter()
                .map(|x| a.clone() + x * (b.clone() - a.clone()))
                .collect()
        }
    };
    if let Some(x) = values.iter().find(|x| **x < a || **x > b) {
        return Err(shape(
            argument,
            format!("{} is outside the domain [{a}, {b}]", crate::number_text(x)),
            "parameters inside the domain [u_p, u_n] of the knot vector",
        ));
    }
    Ok(values)
}

/// A B-spline or NURBS surface (`weights` for `nurbs-surface`: a `--weights` matrix, or the
/// struct's).
pub fn spline_surface<T: LiteralScalar>(
    limits: &Limits,
    args: &SplineSurfaceArgs,
    weights: Option<&str>,
    rational: bool,
) -> Result<Outcome, CliError> {
    let given = degrees(args, limits)?;
    let from_struct = match &args.net {
        Some(net) => read_struct::<T>(limits, net)?,
        None => None,
    };
    let (degrees, knots, mut coords, struct_weights) = match from_struct {
        Some(s) => {
            for (arg, set) in [("--uknots", &args.uknots), ("--vknots", &args.vknots)] {
                if set.is_some() {
                    return Err(usage(
                        arg,
                        "has no effect: the nrbmak struct has its own knots",
                        "the struct alone, or a packed net with --uknots/--vknots",
                    ));
                }
            }
            let mut h = s.homogeneous;
            let w = h.pop().expect("four coordinates");
            let points: Vec<DMatrix<T>> =
                h.into_iter().map(|c| c.zip_map(&w, |x, w| x / w)).collect();
            (
                given.unwrap_or(s.degrees),
                (Some(s.knots.0), Some(s.knots.1)),
                points,
                Some(w),
            )
        }
        None => {
            let net = match &args.net {
                Some(text) => load_net::<T>(limits, "NET", text, None)?,
                None if args.x.is_some() => {
                    coordinate_net(limits, [&args.x, &args.y, &args.z], None)?
                }
                None => {
                    return Err(usage(
                        "NET",
                        "missing",
                        "a control net NET, an nrbmak struct file, or the coordinate matrices --x, --y, --z",
                    ))
                }
            };
            let (nu, nv, d) = net.dim();
            let coords = (0..d)
                .map(|k| DMatrix::from_fn(nu, nv, |i, j| net[[i, j, k]].clone()))
                .collect();
            let ku = match &args.uknots {
                Some(k) => Some(load_params::<T>(limits, "--uknots", k)?),
                None => None,
            };
            let kv = match &args.vknots {
                Some(k) => Some(load_params::<T>(limits, "--vknots", k)?),
                None => None,
            };
            (given.unwrap_or((3, 3)), (ku, kv), coords, None)
        }
    };
    let (p, q) = degrees;
    check_degree(limits, "--degree", p.max(q))?;
    let (nu, nv) = coords[0].shape();
    let clamped = |deg: usize, count: usize, arg: &str| -> Result<Vec<T>, CliError> {
        KnotVector::<T>::clamped_uniform(deg, count)
            .map(|k| k.as_slice().to_vec())
            .map_err(lib(arg, "at least p+1 control points along each direction"))
    };
    let ku = match knots.0 {
        Some(k) => k,
        None => clamped(p, nu, "NET")?,
    };
    let kv = match knots.1 {
        Some(k) => k,
        None => clamped(q, nv, "NET")?,
    };
    let w: Option<DMatrix<T>> = match (weights, struct_weights) {
        (Some(text), _) => {
            let m = crate::load_matrix::<T>(limits, "--weights", text, None)?;
            Some(m)
        }
        (None, Some(w)) => Some(w),
        (None, None) => None,
    };
    let form = "degrees p, q with at least p+1 × q+1 control points and n+p+1 non-decreasing knots per direction";
    enum Kind<T: LiteralScalar> {
        Plain(BSplineSurface<T>),
        Rational(NurbsSurface<T>),
    }
    let surface = match (&w, rational) {
        (Some(w), true) => Kind::Rational(
            NurbsSurface::new(p, q, ku.clone(), kv.clone(), coords.clone(), w.clone())
                .map_err(lib("NET/--weights/--uknots/--vknots", form))?,
        ),
        (Some(w), false) => {
            if w.iter().any(|x| *x != T::one()) {
                return Err(usage(
                    "NET",
                    "the nrbmak struct has weights other than 1",
                    "cagd nurbs-surface for a rational surface",
                ));
            }
            Kind::Plain(
                BSplineSurface::new(p, q, ku.clone(), kv.clone(), std::mem::take(&mut coords))
                    .map_err(lib("NET/--degree/--uknots/--vknots", form))?,
            )
        }
        (None, true) => {
            return Err(usage(
                "--weights",
                "missing",
                "an (m+1)×(n+1) matrix of positive weights, one per control point (or an nrbmak struct)",
            ))
        }
        (None, false) => Kind::Plain(
            BSplineSurface::new(p, q, ku.clone(), kv.clone(), std::mem::take(&mut coords))
                .map_err(lib("NET/--degree/--uknots/--vknots", form))?,
        ),
    };
    let domain = match &surface {
        Kind::Plain(s) => s.domain(),
        Kind::Rational(s) => s.homogeneous().domain(),
    };
    let single = point_mode(limits, &args.params);
    let us = domain_params(
        limits,
        "--u",
        &args.params.u,
        args.params.n,
        domain.0.clone(),
    )?;
    let vs = domain_params(
        limits,
        "--v",
        &args.params.v,
        args.params.n,
        domain.1.clone(),
    )?;
    check_grid(limits, us.len(), vs.len())?;
    let pictures = args.plot.plot.is_some() || args.mesh.mesh.is_some();
    let (pus, pvs) = if single && pictures {
        (
            T::linspace(&domain.0 .0, &domain.0 .1, 21),
            T::linspace(&domain.1 .0, &domain.1 .1, 21),
        )
    } else {
        (Vec::new(), Vec::new())
    };
    // Per point the two bases ((p+1)², (q+1)²) and (p+1)(q+1)·(d+1) products.
    let d = if rational { 4u128 } else { 3 };
    let per =
        (p as u128 + 1).pow(2) + (q as u128 + 1).pow(2) + 2 * (p as u128 + 1) * (q as u128 + 1) * d;
    let knot_bits = bits(&ku).max(bits(&kv));
    let net_bits = match &surface {
        Kind::Plain(s) => s
            .coordinates()
            .iter()
            .map(|c| bits(c.iter()))
            .max()
            .unwrap_or(0),
        Kind::Rational(s) => s
            .homogeneous()
            .coordinates()
            .iter()
            .map(|c| bits(c.iter()))
            .max()
            .unwrap_or(0),
    };
    let grid_work = |us: &[T], vs: &[T]| {
        weigh::<T>(Cost::new(
            us.len() as u128 * vs.len() as u128 * per,
            polynomial_bits(p, bits(us) + 3 * knot_bits, 0)
                + polynomial_bits(q, bits(vs) + 3 * knot_bits, net_bits),
        ))
    };
    check_work(
        limits,
        "--u/--v",
        grid_work(&us, &vs).saturating_add(grid_work(&pus, &pvs)),
    )?;
    let eval_grid = |us: &[T], vs: &[T]| -> Result<PointGrid<T>, CliError> {
        let dim = match &surface {
            Kind::Plain(s) => s.dim(),
            Kind::Rational(s) => s.dim(),
        };
        let mut out = vec![T::zero(); us.len() * vs.len() * dim];
        match &surface {
            Kind::Plain(s) => s.eval_grid_into(us, vs, &mut out),
            Kind::Rational(s) => s.eval_grid_into(us, vs, &mut out),
        }
        .map_err(lib("--u/--v", "parameters inside the domain"))?;
        Ok(PointGrid::from_vec((us.len(), vs.len(), dim), out).expect("the grid's length"))
    };
    let grid = eval_grid(&us, &vs)?;
    let mut report = Report::new();
    if args.steps.steps {
        let basis = |deg: usize, n: usize, knots: &[T], at: &[T]| -> Result<DMatrix<T>, CliError> {
            let mut rows = Vec::with_capacity(at.len());
            for t in at {
                rows.push(
                    basis_all(deg, n, knots, t)
                        .map_err(lib("--u/--v", "parameters inside the domain"))?,
                );
            }
            Ok(DMatrix::from_fn(at.len(), n, |i, j| rows[i][j].clone()))
        };
        report.push("knots_u", Value::Matrix(row(&ku)));
        report.push("knots_v", Value::Matrix(row(&kv)));
        report.push("basis_u", Value::Matrix(basis(p, nu, &ku, &us)?));
        report.push("basis_v", Value::Matrix(basis(q, nv, &kv, &vs)?));
    }
    report.push("u", Value::Matrix(row(&us)));
    report.push("v", Value::Matrix(row(&vs)));
    if single && !args.params.list {
        let (_, _, dim) = grid.dim();
        report.push(
            "result",
            Value::Matrix(DMatrix::from_fn(dim, 1, |k, _| grid[[0, 0, k]].clone())),
        );
    } else {
        push_surface(
            &mut report,
            "result",
            (&us, &vs),
            grid.clone(),
            args.params.list,
        );
    }
    let mut files = PendingWrites::new();
    if pictures {
        let g = if single { eval_grid(&pus, &pvs)? } else { grid };
        let g = grid_f64(&g);
        if let Some(path) = &args.plot.plot {
            let net_coords: Vec<DMatrix<T>> = match &surface {
                Kind::Plain(s) => s.coordinates().to_vec(),
                Kind::Rational(s) => {
                    let h = s.homogeneous().coordinates();
                    let w = &h[h.len() - 1];
                    h[..h.len() - 1]
                        .iter()
                        .map(|c| c.zip_map(w, |x, w| x / w))
                        .collect()
                }
            };
            let net = PointGrid::from_shape_fn((nu, nv, net_coords.len()), |(i, j, k)| {
                net_coords[k][(i, j)].to_f64()
            });
            let title = if rational {
                "NURBS surface"
            } else {
                "B-spline surface"
            };
            let figure = Figure::new(title).surface(g.clone(), "surface").net(
                net,
                Colour::Red,
                "control net",
            );
            add_plot(&mut files, "--plot", path, &figure)?;
        }
        if let Some(path) = &args.mesh.mesh {
            add_mesh(&mut files, "--mesh", path, &g)?;
        }
    }
    finish(&report, &args.output, files, Vec::new())
}

/// A B-spline surface.
pub fn bspline_surface<T: LiteralScalar>(
    limits: &Limits,
    cmd: &BSplineSurfaceCommand,
) -> Result<Outcome, CliError> {
    spline_surface::<T>(limits, &cmd.args, None, false)
}
