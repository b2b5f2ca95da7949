//! Matrix literals, ranges and expressions: parse and evaluate any text, in f64 and exactly,
//! as a matrix, as a parameter list, and as a curve/surface sampled at a few parameters.
#![no_main]

use cagd::octave::literal::{parse_matrix, parse_params, Env, Expr, ParamExpr};
use libfuzzer_sys::fuzz_target;

/// Fuzzing runs with smaller limits than the defaults (10⁴ elements instead of 4·10⁶): the
/// instrumented build is 10–50 times slower, and at the default sizes linear work (an exact
/// range of a million elements) would pass the 10-second timeout without being a bug. The
/// limits themselves are what is exercised.
fn small_limits() {
    static ONCE: std::sync::Once = std::sync::Once::new();
    ONCE.call_once(|| {
        cagd::limits::Limits {
            max_elements: 10_000,
            max_iterations: 10_000,
            max_samples: 1_000,
            max_grid_points: 10_000,
            max_work: 5_000_000,
            max_system_entries: 100_000,
            ..cagd::limits::Limits::default()
        }
        .set_current();
    });
}

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
