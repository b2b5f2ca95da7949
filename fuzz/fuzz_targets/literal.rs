//! Matrix literals, ranges and expressions: parse and evaluate any text, in f64 and exactly,
//! as a matrix, as a parameter list, and as a curve/surface sampled at a few parameters.
#![no_main]

mod common;
use common::small_limits;

use cagd::octave::literal::{parse_matrix, parse_params, Env, Expr, ParamExpr};
use libfuzzer_sys::fuzz_target;

use num_rational::BigRational;

fuzz_target!(|data: &[u8]| {
    small_limits();
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    let _ = parse_matrix::<f64>(text);
    let _ = parse_params::<f64>(text);
    let _ = parse_matrix::<BigRational>(text);
    let _ = parse_params::<BigRational>(text);
    if let Ok(expr) = Expr::parse(text) {
        let mut env = Env::<f64>::new();
        env.bind_scalar("N", 5.0);
        let _ = expr.eval(&mut env);
    }
    if let Ok(p) = ParamExpr::parse(text) {
        let mut env = Env::<f64>::new();
        let _ = p.sample_curve(&mut env, "t", &[0.0, 0.5, 1.0]);
        let _ = p.sample_curve(&mut env, "u", &[0.25]);
        let _ = p.sample_surface(&mut env, &[0.0, 1.0], &[0.0, 0.5, 1.0]);
        let mut exact = Env::<BigRational>::new();
        let half = BigRational::new(1.into(), 2.into());
        let _ = p.sample_curve(&mut exact, "u", &[half.clone()]);
        let _ = p.sample_surface(&mut exact, &[half.clone()], &[half]);
    }
});
