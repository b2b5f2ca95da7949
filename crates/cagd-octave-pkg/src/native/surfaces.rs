//! Coons and Gordon patches and ruled surfaces of Bézier or NURBS curves (octave-nurbs
//! structures), with their parts: the operation layer's requests ([`Coons`], [`Gordon`],
//! [`Ruled`]), as the command line runs them.

use cagd_ops::curves::CurveArg;
use cagd_ops::ops::surface::SurfaceParams;
use cagd_ops::ops::{Coons, Gordon, Ruled};
use cagd_ops::{Params, Role};

use super::curve_value::{curve_value, CURVE_FORM};
use super::{emit_item, native};
use crate::args::Call;
use crate::error::{Kind, PkgError, Result};
use crate::number::{params, Number};
use crate::ops::{execute, Names};
use crate::value::{Sink, Value};

native!(
    /// `[X, rc, rd, rcd] = cagd_coons (c1, c2, d1, d2, u, v)`: the bilinearly blended Coons
    /// patch of four boundary curves (Bézier control points or NURBS structures) on the grid
    /// `u × v`, with its parts.
    coons => coons_t
);

fn coons_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(
        6,
        6,
        "[X, rc, rd, rcd] = cagd_coons (c1, c2, d1, d2, u, v [, \"exact\"])",
    )?;
    call.nargout_max(4)?;
    let mut boundary = Vec::with_capacity(4);
    for (i, name) in ["c1", "c2", "d1", "d2"].into_iter().enumerate() {
        boundary.push(curve_value::<T>(call, call.arg(i), name)?);
    }
    let op =
        Coons {
            at: SurfaceParams {
                u: Params::Given(params::<T>(call, 4, "u")?),
                v: Params::Given(params::<T>(call, 5, "v")?),
                list: false,
            },
            steps: call.nargout > 1,
            ..Coons::new(boundary.try_into().map_err(|_| {
                PkgError::new(Kind::Internal, "cagd_coons: not four boundary curves")
            })?)
        };
    let report = execute(call, COONS_NAMES, &op)?;
    for (k, name) in ["result", "rc", "rd", "rcd"]
        .into_iter()
        .enumerate()
        .take(call.nargout.max(1))
    {
        emit_item(sink, k, &report, name)?;
    }
    Ok(())
}

/// How `cagd_coons` names its arguments.
const COONS_NAMES: Names = &[
    (Role::C1, "c1"),
    (Role::C2, "c2"),
    (Role::D1, "d1"),
    (Role::D2, "d2"),
    (Role::Boundary, "c1/c2/d1/d2"),
    (Role::U, "u"),
    (Role::V, "v"),
    (Role::Grid, "u, v"),
    (Role::Result, "X"),
];

native!(
    /// `[X, C1, C2] = cagd_ruled (c1, c2, u, v)`: the ruled surface `x(u, v) = (1 − v) c1(u) +
    /// v c2(u)` between two curves (Bézier control points or NURBS structures) on the grid
    /// `u × v`, with the two curves at `u`.
    ruled => ruled_t
);

fn ruled_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(
        4,
        4,
        "[X, C1, C2] = cagd_ruled (c1, c2, u, v [, \"exact\"])",
    )?;
    call.nargout_max(3)?;
    let mut op = Ruled::new(
        curve_value::<T>(call, call.arg(0), "c1")?,
        curve_value::<T>(call, call.arg(1), "c2")?,
    );
    op.at = SurfaceParams {
        u: Params::Given(params::<T>(call, 2, "u")?),
        v: Params::Given(params::<T>(call, 3, "v")?),
        list: false,
    };
    op.steps = call.nargout > 1;
    let report = execute(call, RULED_NAMES, &op)?;
    for (k, name) in ["result", "first", "second"]
        .into_iter()
        .enumerate()
        .take(call.nargout.max(1))
    {
        emit_item(sink, k, &report, name)?;
    }
    Ok(())
}

/// How `cagd_ruled` names its arguments.
const RULED_NAMES: Names = &[
    (Role::First, "c1"),
    (Role::Second, "c2"),
    (Role::Boundary, "c1, c2"),
    (Role::U, "u"),
    (Role::V, "v"),
    (Role::Grid, "u, v"),
    (Role::Result, "X"),
];

/// The curves held by the cell argument `i` (`what` names it).
fn curve_cell<T: Number>(
    call: &Call<'_, '_>,
    i: usize,
    what: &'static str,
) -> Result<Vec<CurveArg<T>>> {
    match call.arg(i) {
        Value::Cell { items, .. } => items
            .iter()
            .map(|item| curve_value::<T>(call, item, what))
            .collect(),
        other => Err(PkgError::arg(
            Kind::Class,
            what,
            format!("{} is not accepted", other.class()),
            &format!("a cell array of curves, one per node: {CURVE_FORM}"),
        )),
    }
}

native!(
    /// `[X, g1, g2, g12] = cagd_gordon (cu, cv, un, vn, u, v)`: the Gordon surface of a
    /// network of curves (Bézier control points or NURBS structures) on the grid `u × v`, with
    /// its parts.
    gordon => gordon_t
);

fn gordon_t<T: Number>(call: &Call<'_, '_>, sink: &mut dyn Sink) -> Result<()> {
    call.nargin(
        6,
        6,
        "[X, g1, g2, g12] = cagd_gordon (cu, cv, un, vn, u, v [, \"exact\"])",
    )?;
    call.nargout_max(4)?;
    let mut op = Gordon::new(
        curve_cell::<T>(call, 0, "cu")?,
        curve_cell::<T>(call, 1, "cv")?,
    );
    op.u_nodes = Some(params::<T>(call, 2, "un")?);
    op.v_nodes = Some(params::<T>(call, 3, "vn")?);
    op.at = SurfaceParams {
        u: Params::Given(params::<T>(call, 4, "u")?),
        v: Params::Given(params::<T>(call, 5, "v")?),
        list: false,
    };
    op.steps = call.nargout > 1;
    let report = execute(call, GORDON_NAMES, &op)?;
    for (k, name) in ["result", "g1", "g2", "g12"]
        .into_iter()
        .enumerate()
        .take(call.nargout.max(1))
    {
        emit_item(sink, k, &report, name)?;
    }
    Ok(())
}

/// How `cagd_gordon` names its arguments.
const GORDON_NAMES: Names = &[
    (Role::UCurves, "cu"),
    (Role::VCurves, "cv"),
    (Role::UNodes, "un"),
    (Role::VNodes, "vn"),
    (Role::Network, "cu/cv"),
    (Role::U, "u"),
    (Role::V, "v"),
    (Role::Grid, "u, v"),
    (Role::Result, "X"),
];

#[cfg(test)]
mod tests {
    use super::{coons, gordon};
    use crate::args::Call;
    use crate::value::{Real, Value, VecSink};
    use cagd::Limits;

    /// Calls `f` as Octave would with `args` and `nargout` outputs.
    fn call(
        f: fn(&Call<'_, '_>, &mut dyn crate::value::Sink) -> crate::error::Result<()>,
        args: &[Value<'_>],
        nargout: usize,
        out: &mut VecSink,
    ) -> crate::error::Result<()> {
        f(
            &Call::new("cagd_test", args, nargout, Limits::default()),
            out,
        )
    }

    /// The homogeneous coefficients of the quarter circle (weights 1, 1, 2) at height `z`:
    /// points (1, 0, z), (1, 1, z), (0, 1, z).
    fn arc_coefs(z: f64) -> Vec<f64> {
        vec![1.0, 0.0, z, 1.0, 1.0, 1.0, z, 1.0, 0.0, 2.0, 2.0 * z, 2.0]
    }

    const KNOTS: [f64; 6] = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0];

    /// `nrbmak (coefs, [0 0 0 1 1 1])` as the package receives it.
    fn nurbs(coefs: &[f64]) -> Value<'_> {
        Value::Struct {
            fields: vec![
                (
                    "form",
                    Value::Char {
                        dims: &[1, 7],
                        bytes: b"B-NURBS",
                    },
                ),
                (
                    "coefs",
                    Value::Real(Real {
                        dims: &[4, 3],
                        data: coefs,
                    }),
                ),
                (
                    "knots",
                    Value::Real(Real {
                        dims: &[1, 6],
                        data: &KNOTS,
                    }),
                ),
                (
                    "order",
                    Value::Real(Real {
                        dims: &[1, 1],
                        data: &[3.0],
                    }),
                ),
            ],
        }
    }

    fn real<'a>(dims: &'a [usize], data: &'a [f64]) -> Value<'a> {
        Value::Real(Real { dims, data })
    }

    #[test]
    fn coons_takes_nurbs_boundaries_exactly() {
        // The cylinder over the quarter circle: x(1/2, 1/4) = (3/5, 4/5, 1/4), as
        // (1/4 + 1/2, 1/2 + 2/4) / (1/4 + 1/2 + 2/4) by hand.
        let (a0, a1) = (arc_coefs(0.0), arc_coefs(1.0));
        let d1 = [1.0, 0.0, 0.0, 1.0, 0.0, 1.0];
        let d2 = [0.0, 1.0, 0.0, 0.0, 1.0, 1.0];
        let exact = Value::Char {
            dims: &[1, 5],
            bytes: b"exact",
        };
        let mut args = vec![
            nurbs(&a0),
            nurbs(&a1),
            real(&[3, 2], &d1),
            real(&[3, 2], &d2),
            real(&[1, 1], &[0.5]),
            real(&[1, 1], &[0.25]),
        ];
        let mut out = VecSink::default();
        call(coons, &args, 1, &mut out).unwrap();
        let x = out.get(0).data();
        assert!((x[0] - 0.6).abs() < 1e-15 && (x[1] - 0.8).abs() < 1e-15 && x[2] == 0.25);
        args.push(exact);
        call(coons, &args, 1, &mut out).unwrap();
        assert_eq!(out.get(0).items(), ["3/5", "4/5", "1/4"]);
    }

    #[test]
    fn gordon_takes_cells_of_nurbs_and_bezier_curves() {
        // Three lines of the cylinder and its two quarter circles: at u = 1/4 the circle is
        // (9/16 + 6/16, 6/16 + 2/16) / (17/16) = (15/17, 8/17).
        let (a0, a1) = (arc_coefs(0.0), arc_coefs(1.0));
        let lines = [
            [1.0, 0.0, 0.0, 1.0, 0.0, 1.0],
            [0.6, 0.8, 0.0, 0.6, 0.8, 1.0],
            [0.0, 1.0, 0.0, 0.0, 1.0, 1.0],
        ];
        let cu = Value::Cell {
            dims: &[1, 3],
            items: lines.iter().map(|l| real(&[3, 2], l)).collect(),
        };
        let cv = Value::Cell {
            dims: &[1, 2],
            items: vec![nurbs(&a0), nurbs(&a1)],
        };
        let args = [
            cu,
            cv,
            real(&[1, 3], &[0.0, 0.5, 1.0]),
            real(&[1, 2], &[0.0, 1.0]),
            real(&[1, 1], &[0.25]),
            real(&[1, 1], &[0.75]),
            Value::Char {
                dims: &[1, 5],
                bytes: b"exact",
            },
        ];
        let mut out = VecSink::default();
        call(gordon, &args, 2, &mut out).unwrap();
        assert_eq!(out.get(0).items(), ["15/17", "8/17", "3/4"]);
        // The bad input is named as the usage line names it, worded as the command line does.
        let bad = [0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 1.0, 0.0, 0.0];
        let mut args = args.to_vec();
        args[1] = Value::Cell {
            dims: &[1, 2],
            items: vec![nurbs(&bad), nurbs(&a1)],
        };
        let e = call(gordon, &args, 1, &mut out).unwrap_err();
        assert!(e.to_string().contains("cv: "), "{e}");
        assert_eq!(e.identifier(), "cagd:weights");
    }
}
