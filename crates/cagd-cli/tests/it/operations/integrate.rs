//! Integrals: of the Bernstein polynomials, of a B-spline by its basis integrals, and the
//! arguments that would have no effect refused by name.

use cagd_ops::bspline_arg::{BSplineArg, SplineDegree};
use cagd_ops::ops::Integrate;
use cagd_ops::{execute, Context, Kind, Params, Role};
use nalgebra::DMatrix;
use num_rational::BigRational;

fn q(n: i64, d: i64) -> BigRational {
    BigRational::new(n.into(), d.into())
}

fn nothing() -> Integrate<BigRational> {
    Integrate {
        control: None,
        ..Integrate::curve(DMatrix::zeros(1, 1))
    }
}

#[test]
fn bernstein_integrals_up_to_one_half() {
    // ∫₀^½ B_i^3 = 15/64, 11/64, 5/64, 1/64 (together ½); ∫₀¹ B_i^3 = 1/4.
    let op = Integrate {
        bernstein: Some(3),
        t: Some(Params::Given(vec![q(1, 2)])),
        ..nothing()
    };
    let answer = execute(&op, &mut Context::new(cagd::Limits::default())).unwrap();
    let values = answer.report.matrix("result").unwrap();
    assert_eq!(
        values.iter().cloned().collect::<Vec<_>>(),
        [q(15, 64), q(11, 64), q(5, 64), q(1, 64)]
    );
    assert_eq!(answer.report.matrix("integral").unwrap()[0], q(1, 4));
}

#[test]
fn a_clamped_quadratic_b_spline_integrates_by_its_basis_integrals() {
    // 6 N_{0,2} on 0,0,0,½,1,1,1: ∫ N_{0,2} = 1/6, so the integral is 1.
    let op = Integrate {
        bspline: Some(BSplineArg {
            degree: SplineDegree::Degree(2),
            knots: Some([0, 0, 0, 1, 2, 2, 2].map(|x| q(x, 2)).to_vec()),
        }),
        steps: true,
        ..Integrate::curve(DMatrix::from_row_slice(
            1,
            4,
            &[q(6, 1), q(0, 1), q(0, 1), q(0, 1)],
        ))
    };
    let answer = execute(&op, &mut Context::new(cagd::Limits::default())).unwrap();
    assert_eq!(answer.report.matrix("integral").unwrap()[0], q(1, 1));
    assert_eq!(
        answer
            .report
            .matrix("basis_integrals")
            .unwrap()
            .iter()
            .cloned()
            .collect::<Vec<_>>(),
        [q(1, 6), q(1, 3), q(1, 3), q(1, 6)]
    );
}

#[test]
fn arguments_without_effect_are_refused_naming_them() {
    let cx = &mut Context::new(cagd::Limits::default());
    let index = Integrate {
        index: Some(1),
        ..Integrate::curve(DMatrix::from_row_slice(1, 2, &[q(0, 1), q(1, 1)]))
    };
    let e = execute(&index, cx).unwrap_err();
    assert_eq!((e.role, e.kind), (Role::Index, Kind::Usage));
    let both = Integrate {
        bernstein: Some(2),
        ..index.clone()
    };
    let e = execute(&both, cx).unwrap_err();
    assert_eq!((e.role, e.kind), (Role::Control, Kind::Usage));
    let e = execute(&nothing(), cx).unwrap_err();
    assert_eq!(
        (e.role, e.kind, e.problem.as_str()),
        (Role::Control, Kind::Usage, "missing")
    );
}
