//! Matrix literals, ranges and expressions: parse and evaluate any text, in f64 and exactly,
//! as a matrix, as a parameter list, and as a curve/surface sampled at a few parameters.
#![no_main]

mod common;
use common::fuzz_limits;

use cagd_octave::literal::{parse_matrix_with, parse_params_with, Env, Expr, ParamExpr};
use libfuzzer_sys::fuzz_target;

use num_rational::BigRational;

fuzz_target!(|data: &[u8]| {
    let limits = fuzz_limits();
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let _ = parse_matrix_with::<f64>(text, &limits);
    let _ = parse_params_with::<f64>(text, &limits);
    let _ = parse_matrix_with::<BigRational>(text, &limits);
    let _ = parse_params_with::<BigRational>(text, &limits);
    if let Ok(expr) = Expr::parse_with(text, &limits) {
        let mut env = Env::<f64>::with_limits(limits);
        env.bind_scalar("N", 5.0);
        let _ = expr.eval(&mut env);
    }
    if let Ok(p) = ParamExpr::parse_with(text, &limits) {
        let mut env = Env::<f64>::with_limits(limits);
        let _ = p.sample_curve(&mut env, "t", &[0.0, 0.5, 1.0]);
        let _ = p.sample_curve(&mut env, "u", &[0.25]);
        let _ = p.sample_surface(&mut env, &[0.0, 1.0], &[0.0, 0.5, 1.0]);
        let mut exact = Env::<BigRational>::with_limits(limits);
        let half = BigRational::new(1.into(), 2.into());
        let _ = p.sample_curve(&mut exact, "u", &[half.clone()]);
        let _ = p.sample_surface(&mut exact, &[half.clone()], &[half]);
    }
});
