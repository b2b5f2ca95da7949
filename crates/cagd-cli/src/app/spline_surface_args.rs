//! What `bspline-surface` and `nurbs-surface` share: their arguments and how they are read
//! into the operation layer's [`BSplineSurface`] request.
//!
//! The control net is given as for `bezier-patch` (packed `(m+1)×3(n+1)` as the thesis's
//! `ploskevB` takes it, or an Octave `(m+1)×(n+1)×3` array file), as the coordinate matrices
//! `--x`, `--y`, `--z`, or as an octave-nurbs `nrbmak` struct saved with `save -text` (fields
//! `coefs`, the homogeneous `4×nu×nv` array `[w·x; w·y; w·z; w]`, `knots` a cell `{ku, kv}`,
//! `order` `[p+1 q+1]`): reading that struct is this module's translation of an Octave file.

use cagd::grid::PointGrid;
use cagd_octave::literal::LiteralScalar;
use cagd_octave::text_format::{self, Value as OValue};
use cagd_ops::knots::Degree;
use cagd_ops::ops::BSplineSurface;
use clap::Args;
use nalgebra::DMatrix;

use super::answer::op_error;
use super::common::coordinate_net;
use super::read::surface_params;
use super::run::Names;
use crate::args::{MeshArgs, OutputArgs, PlotArgs, StepsArgs, SurfaceParamArgs};
use crate::cx::Cx;
use crate::error::{shape, usage};
use crate::{load_net, load_params, read_text, scalar_from_double, CliError, ErrorKind};

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
    /// The degrees: P for both directions or P,Q (default 3, cubic, or the struct's order − 1).
    #[arg(long, value_name = "P[,Q]", allow_hyphen_values = true)]
    pub degree: Option<String>,
    /// The orders K = P + 1 instead of the degrees: K or K,L.
    #[arg(long, value_name = "K[,L]", allow_hyphen_values = true)]
    pub order: Option<String>,
    /// The knot vector along u (rows of the net): n + p + 1 non-decreasing values for the n
    /// control points along u and the degree p along u; default clamped uniform on [0, 1].
    #[arg(long, value_name = "VALUES", allow_hyphen_values = true)]
    pub uknots: Option<String>,
    /// The knot vector along v (columns of the net): n + q + 1 non-decreasing values for the n
    /// control points along v and the degree q along v; default clamped uniform on [0, 1].
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

/// A surface read from an nrbmak struct: degrees, knots, homogeneous net.
struct NrbStruct<T: LiteralScalar> {
    degrees: (usize, usize),
    knots: (Vec<T>, Vec<T>),
    /// One `nu × nv` matrix per homogeneous coordinate, the weights last.
    homogeneous: Vec<DMatrix<T>>,
}

/// The form of an nrbmak struct.
const STRUCT_FORM: &str =
    "an octave-nurbs surface struct (nrbmak(coefs, {ku, kv})) with coefs 4×nu×nv, knots {ku, kv} and order [p+1 q+1]";

impl SplineSurfaceArgs {
    /// The request, and the weights of an nrbmak struct if the net was one.
    pub(crate) fn request<T: LiteralScalar>(
        &self,
        cx: &mut Cx,
        names: &Names,
    ) -> Result<(BSplineSurface<T>, Option<DMatrix<T>>), CliError> {
        let given = self.degrees(cx, names)?;
        let from_struct = match &self.net {
            Some(net) => read_struct::<T>(cx, net)?,
            None => None,
        };
        let (net, degrees, knots, weights) = match from_struct {
            Some(s) => self.struct_parts(s)?,
            None => (self.net(cx)?, [Degree::Default; 2], self.knots(cx)?, None),
        };
        let op = BSplineSurface {
            net,
            degrees: given.unwrap_or(degrees),
            knots,
            at: surface_params(cx, &self.params)?,
            steps: self.steps.steps,
            drawing: self.plot.plot.is_some(),
            mesh: self.mesh.mesh.is_some(),
        };
        Ok((op, weights))
    }

    /// The net of NET or of `--x`, `--y`, `--z`.
    fn net<T: LiteralScalar>(&self, cx: &Cx) -> Result<PointGrid<T>, CliError> {
        match (&self.net, &self.x) {
            (Some(text), _) => load_net::<T>(cx, "NET", text, None),
            (None, Some(_)) => coordinate_net(cx, [&self.x, &self.y, &self.z], None),
            (None, None) => Err(usage(
                "NET",
                "missing",
                "a control net NET, an nrbmak struct file, or the coordinate matrices --x, --y, --z",
            )),
        }
    }

    /// `--uknots` and `--vknots`, if given.
    fn knots<T: LiteralScalar>(&self, cx: &Cx) -> Result<[Option<Vec<T>>; 2], CliError> {
        let read = |argument: &str, given: &Option<String>| {
            given
                .as_ref()
                .map(|text| load_params::<T>(cx, argument, text))
                .transpose()
        };
        Ok([
            read("--uknots", &self.uknots)?,
            read("--vknots", &self.vknots)?,
        ])
    }

    /// The net, degrees, knots and weights of an nrbmak struct (which has its own knots).
    #[allow(clippy::type_complexity)]
    fn struct_parts<T: LiteralScalar>(
        &self,
        s: NrbStruct<T>,
    ) -> Result<
        (
            PointGrid<T>,
            [Degree; 2],
            [Option<Vec<T>>; 2],
            Option<DMatrix<T>>,
        ),
        CliError,
    > {
        for (arg, set) in [("--uknots", &self.uknots), ("--vknots", &self.vknots)] {
            if set.is_some() {
                return Err(usage(
                    arg,
                    "has no effect: the nrbmak struct has its own knots",
                    "the struct alone, or a packed net with --uknots/--vknots",
                ));
            }
        }
        let mut h = s.homogeneous;
        let w = h.pop().unwrap_or_else(|| DMatrix::zeros(0, 0));
        let (nu, nv) = w.shape();
        let net = PointGrid::from_shape_fn((nu, nv, h.len()), |(i, j, k)| {
            h[k][(i, j)].clone() / w[(i, j)].clone()
        });
        let degrees = [Degree::Degree(s.degrees.0), Degree::Degree(s.degrees.1)];
        Ok((net, degrees, [Some(s.knots.0), Some(s.knots.1)], Some(w)))
    }

    /// `P` or `P,Q` of `--degree`, `K` or `K,L` of `--order` (at most one), for both
    /// directions.
    fn degrees(&self, cx: &Cx, names: &Names) -> Result<Option<[Degree; 2]>, CliError> {
        let parse = |argument: &str, given: &Option<String>| {
            given
                .as_ref()
                .map(|text| whole_numbers(cx, argument, text))
                .transpose()
        };
        let (degree, order) = (
            parse("--degree", &self.degree)?,
            parse("--order", &self.order)?,
        );
        if degree.is_none() && order.is_none() {
            return Ok(None);
        }
        let direction = |k: usize| {
            let pick =
                |v: &Option<Vec<usize>>| v.as_ref().map(|v| v.get(k).copied().unwrap_or(v[0]));
            Degree::either(pick(&degree), pick(&order)).map_err(|e| op_error(names, e))
        };
        Ok(Some([direction(0)?, direction(1)?]))
    }
}

/// One or two whole numbers separated by a comma (`3` or `3,2`).
fn whole_numbers(cx: &Cx, argument: &str, text: &str) -> Result<Vec<usize>, CliError> {
    let form = "one whole number for both directions, or two separated by a comma: 3 or 3,2";
    let values: Vec<f64> =
        cagd_octave::literal::parse_params_with(&format!("[{}]", text.trim()), &cx.limits)
            .map_err(|e| CliError::literal(argument, e, form))?;
    let ok = !values.is_empty()
        && values.len() <= 2
        && values
            .iter()
            .all(|x| *x >= 0.0 && x.fract() == 0.0 && *x < 1e6);
    if !ok {
        return Err(shape(argument, format!("`{}`", text.trim()), form));
    }
    Ok(values.into_iter().map(|x| x as usize).collect())
}

/// The nrbmak struct of an Octave text file, if the file holds one (`FILE` or `FILE:NAME`).
fn read_struct<T: LiteralScalar>(cx: &Cx, text: &str) -> Result<Option<NrbStruct<T>>, CliError> {
    let trimmed = text.trim();
    let (path, name) = match trimmed.rsplit_once(':') {
        Some((p, n)) if std::path::Path::new(p).is_file() => (p, Some(n)),
        _ => (trimmed, None),
    };
    if !std::path::Path::new(path).is_file() {
        return Ok(None);
    }
    let contents = read_text(cx, "NET", path)?;
    if !contents
        .lines()
        .take(20)
        .any(|l| l.trim_start().starts_with("# name:"))
    {
        return Ok(None);
    }
    let shown = format!("NET {trimmed}");
    let data = |problem: String| CliError::new(&shown, problem, STRUCT_FORM, ErrorKind::Data);
    let ws = text_format::read_text_with(&contents, &cx.limits).map_err(|e| data(e.to_string()))?;
    let found = ws.iter().find(|(n, v)| {
        matches!(v, OValue::Struct(_)) && v.field("coefs").is_some() && name.is_none_or(|m| m == *n)
    });
    match found {
        Some((_, s)) => nrb_struct(cx, s, &data).map(Some),
        None => Ok(None),
    }
}

/// The surface of an nrbmak struct `s`; `data` words a problem with it.
fn nrb_struct<T: LiteralScalar>(
    cx: &Cx,
    s: &OValue,
    data: &dyn Fn(String) -> CliError,
) -> Result<NrbStruct<T>, CliError> {
    let limits = &cx.limits;
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
    let (ku, kv) = struct_knots(cx, s, data)?;
    let order = |k: usize, count: usize, default: usize| -> usize {
        s.field("order")
            .and_then(|o| o.to_array_with(limits))
            .and_then(|o| o.iter().nth(k).copied())
            .filter(|x| *x >= 1.0 && x.fract() == 0.0)
            .map(|x| x as usize - 1)
            .unwrap_or(default.min(count.saturating_sub(1)))
    };
    let p = order(0, nu, ku.len().saturating_sub(nu + 1));
    let q = order(1, nv, kv.len().saturating_sub(nv + 1));
    Ok(NrbStruct {
        degrees: (p, q),
        knots: (ku, kv),
        homogeneous,
    })
}

/// The knot vectors `{ku, kv}` of an nrbmak struct.
fn struct_knots<T: LiteralScalar>(
    cx: &Cx,
    s: &OValue,
    data: &dyn Fn(String) -> CliError,
) -> Result<(Vec<T>, Vec<T>), CliError> {
    let Some(OValue::Cell(c)) = s.field("knots") else {
        return Err(data("`knots` is not a cell {ku, kv}".into()));
    };
    if c.len() != 2 {
        return Err(data("`knots` is not a cell {ku, kv}".into()));
    }
    let mut out = Vec::with_capacity(2);
    for k in c.iter() {
        let values = k
            .to_array_with(&cx.limits)
            .ok_or_else(|| data("a knot vector is not numeric".into()))?;
        let knots: Vec<T> = values
            .iter()
            .map(|x| scalar_from_double::<T>(*x).ok_or_else(|| data("a knot is not finite".into())))
            .collect::<Result<_, _>>()?;
        out.push(knots);
    }
    let kv = out.pop().unwrap_or_default();
    let ku = out.pop().unwrap_or_default();
    Ok((ku, kv))
}
